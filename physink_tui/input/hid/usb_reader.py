"""Reads a tablet's interrupt endpoint through pyusb when it has no hidraw node; no decoding, no device choice.

Also lists the USB devices of tablet vendors for `physink devices`.

Reading this way takes the interface from the kernel: the reader detaches the kernel driver if one is bound,
claims the interface, and gives both back when it ends. Time-outs of ``dev.read`` are not errors (they let the
thread see `stop`); ``ENODEV`` (unplugged) and any other `usb.core.USBError` end the source with a DeviceError.
"""

from __future__ import annotations

import errno
import queue
import time
from dataclasses import dataclass
from typing import Any

from physink_tui.errors import DeviceError
from physink_tui.input.hid.hidraw import BUS_USB, TABLET_VENDORS, UDEV_INSTALL, HidrawInfo
from physink_tui.input.hid.threaded_reader import POLL_TIMEOUT_S, ThreadedReader
from physink_tui.input.sources import RawReport, SourceItem

DEFAULT_PACKET_SIZE = 64
_GONE = (errno.ENODEV, errno.ENOENT, errno.ESHUTDOWN)


def _usb_modules() -> tuple[Any, Any]:
    try:
        import usb.core
        import usb.util
    except ImportError:
        raise DeviceError("pyusb is not installed (pip install pyusb)") from None
    return usb.core, usb.util


def usb_error_message(exc: OSError, ids: str, doing: str) -> str:
    """One line for a USBError met while ``doing`` something with device ``ids``."""
    code = exc.errno
    if code in (errno.EACCES, errno.EPERM):
        return f"no permission to {doing} USB device {ids}; install the udev rule: {UDEV_INSTALL} (then replug)"
    if code == errno.EBUSY:
        return f"USB device {ids} is busy: another program or driver holds interface (cannot {doing} it)"
    if code in _GONE:
        return f"USB device {ids} disappeared"
    return f"cannot {doing} USB device {ids}: {exc}"


class PyusbInterruptReader(ThreadedReader):
    """Reads interrupt IN transfers of one interface through pyusb.

    Args:
        vid, pid: the device; with several alike, ``usb_bus`` and ``usb_address`` pick one.
        interface: the interface number (the pen is interface 0 on UC-Logic-family tablets).
        endpoint: the IN endpoint address (e.g. 0x81); None finds the interface's first interrupt IN endpoint.
        packet_size: bytes per read; None takes the endpoint's wMaxPacketSize.
        usb_device: an already found ``usb.core.Device`` (tests pass a fake).
    """

    kind = "pyusb"

    def __init__(self, vid: int, pid: int, interface: int = 0, endpoint: int | None = None,
                 device_id: str = "tablet0", *, packet_size: int | None = None,
                 timeout_ms: int = int(POLL_TIMEOUT_S * 1000), usb_bus: int | None = None,
                 usb_address: int | None = None, usb_device: Any = None) -> None:
        core, util = _usb_modules()
        ids = f"{vid:04x}:{pid:04x}"
        dev = usb_device if usb_device is not None else _find(core, vid, pid, usb_bus, usb_address)
        self._util = util
        self._dev = dev
        self._interface = interface
        self._detached = False
        self._claimed = False
        try:
            if endpoint is None or packet_size is None:
                found, size = _interrupt_in(dev, interface, util)
                endpoint = found if endpoint is None else endpoint
                packet_size = size if packet_size is None else packet_size
            if dev.is_kernel_driver_active(interface):
                dev.detach_kernel_driver(interface)
                self._detached = True
            util.claim_interface(dev, interface)
            self._claimed = True
        except OSError as exc:  # usb.core.USBError
            self._give_back()
            raise DeviceError(usb_error_message(exc, ids, "claim")) from None
        bus, address = getattr(dev, "bus", None), getattr(dev, "address", None)
        info = HidrawInfo(f"usb:{bus or 0:03d}:{address or 0:03d}", _product(dev, util), BUS_USB, vid, pid,
                          interface, "", _report_descriptor(dev, interface), bus, address)
        super().__init__(device_id, f"USB device {ids} interface {interface}", info)
        self._endpoint = endpoint
        self._packet_size = packet_size
        self._timeout_ms = timeout_ms
        self._timeout_error = getattr(core, "USBTimeoutError", ())

    def _read_loop(self, out: queue.Queue[SourceItem]) -> DeviceError | None:
        dev, put, monotonic = self._dev, out.put, time.monotonic
        while not self._stopping.is_set():
            try:
                data = dev.read(self._endpoint, self._packet_size, self._timeout_ms)
            except self._timeout_error:
                continue
            except OSError as exc:
                if exc.errno == errno.ETIMEDOUT:
                    continue
                if exc.errno in _GONE:
                    return DeviceError(f"{self.what} disappeared ({exc})")
                return DeviceError(f"{self.what} disappeared: read failed: {exc}")
            if len(data):
                put(RawReport(monotonic(), bytes(data), self.device_id))
        return None

    def _release_device(self) -> None:
        self._give_back()

    def _give_back(self) -> None:
        """Release the interface, give it back to the kernel driver, free pyusb's handles; never raises."""
        steps = []
        if self._claimed:
            steps.append(lambda: self._util.release_interface(self._dev, self._interface))
        if self._detached:
            steps.append(lambda: self._dev.attach_kernel_driver(self._interface))
        steps.append(lambda: self._util.dispose_resources(self._dev))
        for step in steps:
            try:
                step()
            except Exception:  # an unplugged device cannot be given back; nothing else to do
                pass
        self._claimed = self._detached = False


def _find(core: Any, vid: int, pid: int, usb_bus: int | None, usb_address: int | None) -> Any:
    ids = f"{vid:04x}:{pid:04x}"

    def match(dev: Any) -> bool:
        return (usb_bus is None or dev.bus == usb_bus) and (usb_address is None or dev.address == usb_address)

    try:
        dev = core.find(idVendor=vid, idProduct=pid, custom_match=match)
    except core.NoBackendError:
        raise DeviceError(f"cannot look for USB device {ids}: pyusb finds no libusb backend (install libusb-1.0)"
                          ) from None
    if dev is None:
        raise DeviceError(f"USB device {ids} not found")
    return dev


def _interrupt_in(dev: Any, interface: int, util: Any) -> tuple[int, int]:
    """Address and max packet size of the interface's first interrupt IN endpoint."""
    intf = dev.get_active_configuration()[(interface, 0)]
    for ep in intf:
        address = ep.bEndpointAddress
        if (util.endpoint_direction(address) == util.ENDPOINT_IN
                and util.endpoint_type(ep.bmAttributes) == util.ENDPOINT_TYPE_INTR):
            return address, ep.wMaxPacketSize or DEFAULT_PACKET_SIZE
    raise DeviceError(f"USB interface {interface} has no interrupt IN endpoint")


def _report_descriptor(dev: Any, interface: int) -> bytes:
    """GET_DESCRIPTOR(Report) from the interface; empty when the device refuses."""
    try:
        return bytes(dev.ctrl_transfer(0x81, 6, 0x22 << 8, interface, 4096))
    except Exception:  # not a HID interface, or the device stalls: the capture gets no usable R: line
        return b""


def _product(dev: Any, util: Any) -> str:
    try:
        index = dev.iProduct
        return (util.get_string(dev, index) or "") if index else ""
    except Exception:  # strings need the device opened; permissions may forbid it
        return ""


@dataclass(frozen=True, slots=True)
class UsbDevice:
    """A USB device of a tablet vendor as pyusb lists it.

    Attributes:
        bus, address: where it is (``/dev/bus/usb/BBB/DDD``).
        vid, pid: its ids.
        vendor: the vendor's name from `TABLET_VENDORS`.
    """

    bus: int
    address: int
    vid: int
    pid: int
    vendor: str


def list_usb_tablets(find: Any = None) -> list[UsbDevice]:
    """USB devices of the tablet vendors.

    Raises:
        DeviceError: pyusb is missing or has no libusb backend.
    """
    core, _ = _usb_modules()
    find = find or core.find
    try:
        found = list(find(find_all=True))
    except core.NoBackendError:
        raise DeviceError("pyusb finds no libusb backend (install libusb-1.0)") from None
    return sorted((UsbDevice(d.bus, d.address, d.idVendor, d.idProduct, TABLET_VENDORS[d.idVendor])
                   for d in found if d.idVendor in TABLET_VENDORS), key=lambda u: (u.bus, u.address))
