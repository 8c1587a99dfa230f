"""Finds Linux hidraw nodes through sysfs and says whether we may open them; reads no reports, needs no hidapi.

Each ``/sys/class/hidraw/hidrawN`` links to its HID device (``device/``), which holds the report descriptor
(``report_descriptor``) and a ``uevent`` file such as::

    HID_ID=0003:0000256C:0000006D
    HID_NAME=HUION Huion Tablet_H640P
    HID_PHYS=usb-0000:00:14.0-1/input0

A USB HID device's parent is its USB interface (``1-1:1.0``, holding ``bInterfaceNumber``), whose parent is the
USB device (``1-1``, holding ``busnum`` and ``devnum``). Both roots are parameters, so tests build a fake tree.
"""

from __future__ import annotations

import errno
import os
import re
from dataclasses import dataclass, replace
from pathlib import Path

from physink_tui.errors import DescriptorError
from physink_tui.input.hid.vendor_layouts import (
    PROFILES,
    VID_10MOONS,
    VID_HUION,
    VID_KYE,
    VID_UCLOGIC,
    VID_VEIKK,
    VID_WACOM,
    VID_XPPEN,
)

BUS_USB = 0x03
BUS_BLUETOOTH = 0x05
BUS_I2C = 0x18
VID_WALTOP = 0x172F

TABLET_VENDORS: dict[int, str] = {
    VID_WACOM: "Wacom",
    VID_HUION: "Huion/Gaomon",
    VID_UCLOGIC: "UC-Logic",
    VID_XPPEN: "XP-Pen/Ugee",
    VID_VEIKK: "VEIKK",
    VID_KYE: "KYE/Genius",
    VID_WALTOP: "Waltop",
    VID_10MOONS: "10moons",
}
"""USB vendor ids of pen tablet makers: the ones `packaging/udev/70-physink-tablets.rules` grants access to."""

UDEV_RULES_FILE = "packaging/udev/70-physink-tablets.rules"
UDEV_INSTALL = (
    f"sudo cp {UDEV_RULES_FILE} /etc/udev/rules.d/ && sudo udevadm control --reload && sudo udevadm trigger"
)
"""The install steps of `packaging/udev/README.md`, in one line (run from the PhysInk source tree)."""

_USB_INTERFACE_DIR = re.compile(r"\d+-[\d.]+:\d+\.(\d+)\Z")  # e.g. 1-1.4:1.0 (bus-port:config.interface)
_PHYS_INPUT = re.compile(r"/input(\d+)\Z")  # HID_PHYS=usb-0000:00:14.0-1/input0


@dataclass(frozen=True, slots=True)
class HidrawInfo:
    """One hidraw node as sysfs describes it (or, for `hid_readers`, a USB device read through pyusb).

    Attributes:
        path: the node to open, e.g. ``"/dev/hidraw3"`` (under the ``dev_root`` given); ``"usb:BBB:DDD"`` for a
            device reached through pyusb.
        name: HID_NAME (the kernel's "manufacturer product"), ``""`` when sysfs gives none.
        bus: bus type from HID_ID: 3 USB, 5 Bluetooth, 0x18 I2C.
        vid: vendor id, 0..0xffff.
        pid: product id, 0..0xffff.
        interface: USB interface number, or None when not on USB or not shown in the sysfs path.
        phys: HID_PHYS, e.g. ``"usb-0000:00:14.0-1/input0"``, ``""`` when absent.
        descriptor: the report descriptor as the kernel holds it (after any driver fix-up); empty if unreadable.
        usb_bus: the USB bus number (``busnum``) of the device, or None when not on USB.
        usb_address: the USB device address (``devnum``) on that bus, or None.
    """

    path: str
    name: str
    bus: int
    vid: int
    pid: int
    interface: int | None
    phys: str
    descriptor: bytes
    usb_bus: int | None = None
    usb_address: int | None = None

    @property
    def ids(self) -> str:
        """``"256c:006d"``."""
        return f"{self.vid:04x}:{self.pid:04x}"


def parse_uevent(text: str) -> dict[str, str]:
    """``KEY=value`` lines into a dict.

    >>> parse_uevent("HID_ID=0003:0000256C:0000006D\\nHID_NAME=Tablet\\n")["HID_NAME"]
    'Tablet'
    """
    out = {}
    for line in text.splitlines():
        key, sep, value = line.partition("=")
        if sep:
            out[key.strip()] = value.strip()
    return out


def parse_hid_id(value: str) -> tuple[int, int, int] | None:
    """HID_ID ``"0003:0000256C:0000006D"`` as ``(bus, vid, pid)``; None when malformed.

    >>> parse_hid_id("0003:0000256C:0000006D")
    (3, 9580, 109)
    """
    parts = value.split(":")
    if len(parts) != 3:
        return None
    try:
        bus, vid, pid = (int(p, 16) for p in parts)
    except ValueError:
        return None
    return bus, vid & 0xFFFF, pid & 0xFFFF


def _read_text(path: Path) -> str | None:
    try:
        return path.read_text(errors="replace")
    except OSError:
        return None


def _read_int(path: Path, base: int) -> int | None:
    text = _read_text(path)
    try:
        return int(text.strip(), base) if text is not None else None
    except ValueError:
        return None


def _usb_location(hid_dir: Path, phys: str) -> tuple[int | None, int | None, int | None]:
    """(interface, busnum, devnum) from the parents of the HID device directory, else from HID_PHYS."""
    interface = bus = address = None
    iface_dir = hid_dir.parent
    match = _USB_INTERFACE_DIR.match(iface_dir.name)
    if match is not None:
        interface = _read_int(iface_dir / "bInterfaceNumber", 16)
        if interface is None:
            interface = int(match.group(1))
        bus = _read_int(iface_dir.parent / "busnum", 10)
        address = _read_int(iface_dir.parent / "devnum", 10)
    elif phys.startswith("usb-"):
        found = _PHYS_INPUT.search(phys)
        interface = int(found.group(1)) if found else None
    return interface, bus, address


def read_hidraw_node(entry: Path, dev_root: str = "/dev") -> HidrawInfo | None:
    """One ``/sys/class/hidraw/hidrawN`` entry; None when its ``device/uevent`` is missing or has no HID_ID."""
    hid_dir = Path(os.path.realpath(entry / "device"))
    uevent = _read_text(hid_dir / "uevent")
    if uevent is None:
        return None
    fields = parse_uevent(uevent)
    ids = parse_hid_id(fields.get("HID_ID", ""))
    if ids is None:
        return None
    try:
        descriptor = (hid_dir / "report_descriptor").read_bytes()
    except OSError:
        descriptor = b""
    phys = fields.get("HID_PHYS", "")
    interface, usb_bus, usb_address = _usb_location(hid_dir, phys) if ids[0] == BUS_USB else (None, None, None)
    return HidrawInfo(
        path=os.path.join(dev_root, entry.name), name=fields.get("HID_NAME", ""), bus=ids[0], vid=ids[1],
        pid=ids[2], interface=interface, phys=phys, descriptor=descriptor, usb_bus=usb_bus,
        usb_address=usb_address,
    )


def _node_number(name: str) -> int:
    digits = name.removeprefix("hidraw")
    return int(digits) if digits.isdigit() else 1 << 30


def hidraw_class_dir(sysfs_root: str = "/sys") -> Path:
    """``<sysfs_root>/class/hidraw``."""
    return Path(sysfs_root) / "class" / "hidraw"


def discover_hidraw(sysfs_root: str = "/sys", dev_root: str = "/dev") -> list[HidrawInfo]:
    """Every hidraw node sysfs shows, in node-number order; empty when there is no hidraw class (not Linux,
    or no HID device at all). Nodes whose sysfs entry cannot be read are left out."""
    class_dir = hidraw_class_dir(sysfs_root)
    try:
        names = sorted(os.listdir(class_dir), key=_node_number)
    except OSError:
        return []
    found = (read_hidraw_node(class_dir / name, dev_root) for name in names)
    return [info for info in found if info is not None]


def info_for_path(path: str, sysfs_root: str = "/sys", dev_root: str = "/dev") -> HidrawInfo | None:
    """The sysfs description of a hidraw node given by its path (``/dev/hidraw3``), or None."""
    name = os.path.basename(os.path.realpath(path)) if os.path.exists(path) else os.path.basename(path)
    entry = hidraw_class_dir(sysfs_root) / name
    if not entry.exists():
        return None
    info = read_hidraw_node(entry, dev_root)
    return None if info is None else replace(info, path=path)


def pen_summaries(info: HidrawInfo) -> list[str]:
    """One `PenLayout.summary` per pen report the device gives (descriptor plus vendor knowledge); empty when
    it has none or its descriptor cannot be parsed.

    Vendor protocols count: a Huion on a v2 profile gets its report 0x08 layout even before initialisation.
    """
    from physink_tui.input.hid.decoder import HidPenDecoder

    if not info.descriptor:
        return []
    try:
        decoder = HidPenDecoder(info.descriptor, info.vid, info.pid, name=info.name or None)
    except DescriptorError:
        return []
    return [layout.summary() for layout in decoder.layouts.values()]


def descriptor_pen_reports(info: HidrawInfo) -> int:
    """How many pen reports the descriptor itself describes (no vendor knowledge): ranks a tablet's interfaces."""
    from physink_tui.input.hid.descriptor import ReportDescriptor
    from physink_tui.input.hid.pen_layout import pen_layouts

    try:
        return len(pen_layouts(ReportDescriptor.from_bytes(info.descriptor))) if info.descriptor else 0
    except DescriptorError:
        return 0


def is_tablet(info: HidrawInfo) -> bool:
    """A pen layout from the descriptor or vendor knowledge, or a vendor profile for its VID:PID."""
    return bool(pen_summaries(info)) or (info.vid, info.pid) in PROFILES


def permission_message(path: str) -> str:
    """What to do when a device node cannot be opened for lack of permission; one line."""
    return f"permission denied on {path}; to allow it, install the udev rule: {UDEV_INSTALL} (then replug)"


def open_error(path: str) -> str | None:
    """None when ``path`` can be opened for reading, else why not (one line, with the fix when it is permission).

    Checks ``os.access`` and then opens ``O_RDONLY | O_NONBLOCK`` (closing at once), since access() answers for
    the real uid and ACLs granted by ``uaccess`` are only certain once open() succeeds.
    """
    if not os.path.exists(path):
        return f"{path} does not exist (unplugged, or no hidraw support in the kernel)"
    if not os.access(path, os.R_OK):
        return permission_message(path)
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except PermissionError:
        return permission_message(path)
    except OSError as exc:
        if exc.errno == errno.EBUSY:
            return f"{path} is busy (another program holds it exclusively)"
        return f"cannot open {path}: {exc.strerror or exc}"
    os.close(fd)
    return None
