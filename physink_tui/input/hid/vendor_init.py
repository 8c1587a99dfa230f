"""Switches UC-Logic-family tablets to their full pen protocol via pyusb, as hid-uclogic does; reads no reports.

These tablets start in a "mouse mode" whose report 0x09 is coarse. Reading a vendor USB string descriptor (type
STRING, language 0x0409) switches them over and answers with binary parameters instead of text:

* 0xC8 (200), "v2": at least 18 bytes; X and Y maxima 24-bit little-endian at offsets 2 and 5, pressure at 8,
  resolution at 10 (header included). Tablets without v2 stall, or answer with their model name, as some answer
  every unknown string index: a reply made only of printable UTF-16LE ASCII is text, not parameters.
  Huion's "transition" firmware (string 0xC9 = ``HUION_T153_160607``) is not asked for v2.
* 0x64 (100), "v1": at least 12 bytes; X, Y maxima at 2 and 4, pressure at 8, resolution at 10, 16 bits each.
  Reading it is what makes the tablet send report 0x07.

The kernel checks the text-only case for v2 only; it is checked for v1 too here (real v1 maxima are never all
below 256 with printable low bytes). Offsets are parsed by `TabletParams.from_huion_v2` / ``from_uclogic_v1``.
"""

from __future__ import annotations

import errno
import re
from dataclasses import dataclass
from typing import Any, Protocol, TypeGuard

from physink_tui.errors import DeviceError
from physink_tui.input.hid.vendor_layouts import VID_HUION, VID_UCLOGIC, VID_VEIKK, VID_XPPEN, TabletParams

FAMILY_VIDS = frozenset({VID_HUION, VID_UCLOGIC, VID_XPPEN, VID_VEIKK})
"""Vendors whose tablets need the string-descriptor initialisation."""

STRING_V1 = 0x64
STRING_V2 = 0xC8
STRING_FIRMWARE = 0xC9
LANGUAGE_EN_US = 0x0409
REQUEST_GET_DESCRIPTOR = 6
DESCRIPTOR_TYPE_STRING = 3
V1_MIN_LENGTH = 12
V2_MIN_LENGTH = 18
TRANSITION_FIRMWARE = "HUION_T153_160607"
"""Huion firmware that must not be asked for v2 parameters (hid-uclogic skips it too)."""

COMMENT_PREFIX = "physink vendor-init:"
_COMMENT_FIELD = re.compile(r"(\w+)=(\S+)")


class UsbControlDevice(Protocol):
    """The part of a ``usb.core.Device`` used here (tests pass a small fake)."""

    def ctrl_transfer(self, bmRequestType: int, bRequest: int, wValue: int = 0, wIndex: int = 0,
                      data_or_wLength: Any = None, timeout: Any = None) -> Any: ...


@dataclass(frozen=True, slots=True)
class VendorInit:
    """The outcome of a successful initialisation.

    Attributes:
        protocol: ``"huion-v2"`` (report 0x08) or ``"uclogic-v1"`` (report 0x07), as `HidPenDecoder` takes it.
        params: the maxima the tablet declared.
        raw: the string descriptor reply, 2-byte header included.
    """

    protocol: str
    params: TabletParams
    raw: bytes = b""

    def comment(self) -> str:
        """The capture comment (without ``"# "``) from which a later decode takes the protocol and maxima.

        >>> VendorInit("huion-v2", TabletParams(50800, 31750, 8191, 5080)).comment()
        'physink vendor-init: protocol=huion-v2 x_max=50800 y_max=31750 p_max=8191 resolution=5080'
        """
        p = self.params
        return (f"{COMMENT_PREFIX} protocol={self.protocol} x_max={p.x_max} y_max={p.y_max} p_max={p.p_max} "
                f"resolution={p.resolution}")

    @classmethod
    def from_comment(cls, text: str) -> VendorInit | None:
        """Reads back `comment` (a capture's ``#`` line, with or without ``"# "``); None when it is not one.

        >>> init = VendorInit.from_comment("# physink vendor-init: protocol=uclogic-v1 x_max=4000 y_max=2400 p_max=99")
        >>> init.protocol, init.params
        ('uclogic-v1', TabletParams(x_max=4000, y_max=2400, p_max=99, resolution=0))
        """
        body = text.lstrip("#").strip()
        if not body.startswith(COMMENT_PREFIX):
            return None
        fields = dict(_COMMENT_FIELD.findall(body[len(COMMENT_PREFIX):]))
        try:
            numbers = [int(fields.get(k, "0")) for k in ("x_max", "y_max", "p_max", "resolution")]
        except ValueError:
            return None
        protocol = fields.get("protocol")
        if protocol not in ("huion-v2", "uclogic-v1") or not (numbers[0] > 0 and numbers[1] > 0 and numbers[2] > 0):
            return None
        return cls(protocol, TabletParams(*numbers))


def find_vendor_init(comments: tuple[str, ...] | list[str]) -> VendorInit | None:
    """The first vendor-init comment among a capture device's comments (`CaptureDevice.comments`)."""
    for text in comments:
        found = VendorInit.from_comment(text)
        if found is not None:
            return found
    return None


def needs_vendor_init(vid: int) -> bool:
    """Whether tablets of this vendor start in mouse mode and need `initialise`.

    >>> needs_vendor_init(0x256C), needs_vendor_init(0x056A)
    (True, False)
    """
    return vid in FAMILY_VIDS


def is_text_only(data: bytes) -> bool:
    """Whether a string descriptor's payload (after the 2-byte header) is printable ASCII in UTF-16LE.

    >>> is_text_only(b"\\x08\\x03H\\x00U\\x00I\\x00"), is_text_only(b"\\x08\\x03\\x40\\x9c\\x00\\x00")
    (True, False)
    """
    payload = data[2:]
    if len(payload) % 2:
        payload = payload[:-1]
    return all(0x20 <= payload[i] < 0x7F and payload[i + 1] == 0 for i in range(0, len(payload), 2))


def read_raw_string(dev: UsbControlDevice, index: int, ids: str = "", length: int = 256) -> bytes | None:
    """The raw reply to GET_DESCRIPTOR(STRING, ``index``, language 0x0409), header included; None when the device
    stalls (no such string) or does not answer in time.

    Raises:
        DeviceError: no permission, device busy or gone, or any other transfer failure (named).
    """
    try:
        data = dev.ctrl_transfer(0x80, REQUEST_GET_DESCRIPTOR, (DESCRIPTOR_TYPE_STRING << 8) | index,
                                 LANGUAGE_EN_US, length)
    except OSError as exc:  # usb.core.USBError and USBTimeoutError are OSErrors carrying an errno
        raise _transfer_error(exc, index, ids) from None
    return bytes(data) if data is not None else None


class _NotAnswered(DeviceError):
    """A stall or time-out: the string does not exist (internal, turned into None)."""


def _transfer_error(exc: OSError, index: int, ids: str) -> DeviceError:
    code = exc.errno
    where = f"USB device {ids}" if ids else "the USB device"
    if code in (errno.EPIPE, errno.ETIMEDOUT) or type(exc).__name__ == "USBTimeoutError":
        return _NotAnswered(f"{where}: string 0x{index:02x} not answered")
    if code in (errno.EACCES, errno.EPERM):
        from physink_tui.input.hid.hidraw import UDEV_INSTALL  # here: decoding a capture never needs the reader

        return DeviceError(f"no permission to talk to {where} (needed to switch it to its full pen mode); "
                           f"install the udev rule: {UDEV_INSTALL} (then replug)")
    if code == errno.EBUSY:
        return DeviceError(f"{where} is busy: another program or driver holds it (OpenTabletDriver, the vendor's "
                           "driver?); close it and try again")
    if code in (errno.ENODEV, errno.ENOENT):
        return DeviceError(f"{where} disappeared during its initialisation")
    return DeviceError(f"{where}: reading string descriptor 0x{index:02x} failed: {exc}")


def _read_optional(dev: UsbControlDevice, index: int, ids: str, length: int = 256) -> bytes | None:
    try:
        return read_raw_string(dev, index, ids, length)
    except _NotAnswered:
        return None


def _plausible(data: bytes | None, min_length: int) -> TypeGuard[bytes]:
    return (data is not None and len(data) >= min_length and data[1] == DESCRIPTOR_TYPE_STRING
            and not is_text_only(data))


def firmware_version(dev: UsbControlDevice, ids: str = "") -> str:
    """Huion's firmware name (string 0xC9), ``""`` when the device has none."""
    data = _read_optional(dev, STRING_FIRMWARE, ids, 64)
    if not data or len(data) < 2:
        return ""
    return data[2:].decode("utf-16-le", errors="replace").rstrip("\x00")


def initialise(dev: UsbControlDevice, ids: str = "") -> VendorInit | None:
    """Tries v2 (string 0xC8), then v1 (string 0x64); None when the tablet answers neither with parameters.

    Args:
        dev: an open ``usb.core.Device`` (or anything with its ``ctrl_transfer``).
        ids: ``"vid:pid"`` for messages.

    Raises:
        DeviceError: no permission, device busy or gone (`read_raw_string`).
    """
    if firmware_version(dev, ids) != TRANSITION_FIRMWARE:
        data = _read_optional(dev, STRING_V2, ids)
        if _plausible(data, V2_MIN_LENGTH):
            params = TabletParams.from_huion_v2(data)
            if params is not None:
                return VendorInit("huion-v2", params, data)
    data = _read_optional(dev, STRING_V1, ids)
    if _plausible(data, V1_MIN_LENGTH):
        params = TabletParams.from_uclogic_v1(data)
        if params is not None:
            return VendorInit("uclogic-v1", params, data)
    return None


def initialise_usb(vid: int, pid: int, usb_bus: int | None = None, usb_address: int | None = None,
                   find: Any = None) -> VendorInit | None:
    """Finds the tablet through pyusb (by bus and address when given) and runs `initialise` on it.

    Control transfers on endpoint 0 need no interface claim, so the kernel's driver stays bound.

    Args:
        find: ``usb.core.find`` (tests pass their own).

    Raises:
        DeviceError: pyusb or libusb unusable, device not found, no permission, busy.
    """
    ids = f"{vid:04x}:{pid:04x}"
    try:
        import usb.core
        import usb.util
    except ImportError:
        raise DeviceError(f"cannot initialise {ids}: pyusb is not installed") from None
    find = find or usb.core.find

    def match(dev: Any) -> bool:
        return (usb_bus is None or dev.bus == usb_bus) and (usb_address is None or dev.address == usb_address)

    try:
        dev = find(idVendor=vid, idProduct=pid, custom_match=match)
    except usb.core.NoBackendError:
        raise DeviceError(f"cannot initialise {ids}: pyusb finds no libusb backend (install libusb-1.0)") from None
    if dev is None:
        where = f" on bus {usb_bus} address {usb_address}" if usb_bus is not None else ""
        raise DeviceError(f"cannot initialise {ids}: pyusb does not see the device{where}")
    try:
        return initialise(dev, ids)
    finally:
        usb.util.dispose_resources(dev)
