"""`physink devices`: lists pen tablets (hidraw, USB, ISDV4 serial) and whether they open; reads no reports.

Where it looks can be moved, for tests and for looking at another root (a container's, a chroot's):

* ``PHYSINK_SYSFS_ROOT`` (default ``/sys``): the sysfs whose ``class/hidraw`` is listed;
* ``PHYSINK_DEV_ROOT`` (default ``/dev``): where the ``hidrawN`` nodes named there are opened.

`physink record` reads the same two variables.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable
from typing import Any, TextIO

from physink_tui.errors import DeviceError
from physink_tui.input.hid.hidraw import (
    BUS_BLUETOOTH,
    BUS_I2C,
    BUS_USB,
    HidrawInfo,
    discover_hidraw,
    hidraw_class_dir,
    open_error,
    pen_summaries,
)
from physink_tui.input.hid.vendor_layouts import PROFILES

ENV_SYSFS_ROOT = "PHYSINK_SYSFS_ROOT"
ENV_DEV_ROOT = "PHYSINK_DEV_ROOT"
SERIAL_PROBE_TIMEOUT_S = 0.5
_BUSES = {BUS_USB: "usb", BUS_BLUETOOTH: "bluetooth", BUS_I2C: "i2c"}


def roots_from_env() -> tuple[str, str]:
    """``(sysfs_root, dev_root)`` from ``PHYSINK_SYSFS_ROOT`` and ``PHYSINK_DEV_ROOT`` (defaults /sys, /dev)."""
    return os.environ.get(ENV_SYSFS_ROOT) or "/sys", os.environ.get(ENV_DEV_ROOT) or "/dev"


def describe_hidraw(info: HidrawInfo, check_open: Callable[[str], str | None] = open_error) -> tuple[bool, list[str]]:
    """``(is a tablet, lines)`` for one node: a heading, then for a tablet its pen layouts and whether it opens."""
    bus = _BUSES.get(info.bus, f"bus 0x{info.bus:02x}")
    where = f"{bus} interface {info.interface}" if info.interface is not None else bus
    head = f"  {info.path}  {info.name or '(no name)'}  {info.ids}  {where}"
    summaries = pen_summaries(info)
    profile = PROFILES.get((info.vid, info.pid))
    if not summaries and profile is None:
        reason = "no pen report" if info.descriptor else "no pen report (report descriptor unreadable)"
        return False, [f"{head}  {reason}"]
    lines = [head]
    lines += [f"      pen report {s}" for s in summaries] or ["      no pen report in its descriptor"]
    if profile is not None:
        lines.append(f"      known model: {profile.name} (protocol {profile.protocol})")
    problem = check_open(info.path)
    lines.append("      can open: yes" if problem is None else f"      cannot open: {problem}")
    return True, lines


def hidraw_lines(sysfs_root: str, dev_root: str) -> tuple[int, list[str], set[tuple[int, int]]]:
    """``(tablets found, lines, VID:PIDs that have a hidraw node)``."""
    nodes = discover_hidraw(sysfs_root, dev_root)
    if not nodes:
        return 0, [], set()
    lines = [f"hidraw nodes ({hidraw_class_dir(sysfs_root)}):"]
    tablets = 0
    for info in nodes:
        is_tablet, node_lines = describe_hidraw(info)
        tablets += is_tablet
        lines += node_lines
    return tablets, lines, {(n.vid, n.pid) for n in nodes}


def list_usb() -> list[Any]:
    """Tablet-vendor USB devices through pyusb (`usb_reader.list_usb_tablets`); raises DeviceError if unusable."""
    from physink_tui.input.hid.usb_reader import list_usb_tablets

    return list_usb_tablets()


def usb_lines(with_hidraw: set[tuple[int, int]]) -> tuple[int, list[str], str | None]:
    """``(devices, lines, why pyusb is unusable or None)`` for tablet-vendor USB devices without a hidraw node."""
    try:
        found = [d for d in list_usb() if (d.vid, d.pid) not in with_hidraw]
    except DeviceError as exc:
        return 0, [], str(exc)
    except Exception as exc:  # libusb can fail in many ways (no /dev/bus/usb in a container): say it, go on
        return 0, [], f"pyusb cannot list USB devices: {exc}"
    if not found:
        return 0, [], None
    lines = ["USB devices of tablet vendors without a hidraw node (readable through pyusb):"]
    for d in found:
        profile = PROFILES.get((d.vid, d.pid))
        name = profile.name if profile else d.vendor
        lines.append(f"  bus {d.bus:03d} address {d.address:03d}  {d.vid:04x}:{d.pid:04x}  {name}")
    return len(found), lines, None


def serial_ports() -> list[Any]:
    """``serial.tools.list_ports.comports()``; empty without pyserial."""
    try:
        from serial.tools import list_ports
    except ImportError:
        return []
    return sorted(list_ports.comports(), key=lambda p: p.device)


def isdv4_prober() -> tuple[Callable[..., Any] | None, str]:
    """``(probe_isdv4, "")``, or ``(None, why)`` while `physink_tui.input.serial_tablets.reader` is not available."""
    try:
        from physink_tui.input.serial_tablets.reader import probe_isdv4
    except ImportError as exc:
        return None, f"ISDV4 probing not available ({exc})"
    return probe_isdv4, ""


def _query_text(query: Any) -> str:
    summary = getattr(query, "summary", None)
    return summary() if callable(summary) else str(query)


def serial_lines() -> tuple[int, list[str]]:
    """``(ISDV4 tablets answering, lines)`` for the serial ports."""
    ports = serial_ports()
    if not ports:
        return 0, []
    probe, why_not = isdv4_prober()
    lines = ["serial ports (ISDV4 probe):"]
    found = 0
    for port in ports:
        desc = port.description if port.description and port.description != "n/a" else ""
        head = f"  {port.device}  {desc}".rstrip()
        if probe is None:
            lines.append(f"{head}  not probed: {why_not}")
            continue
        try:
            query = probe(port.device, timeout=SERIAL_PROBE_TIMEOUT_S)
        except DeviceError as exc:
            lines.append(f"{head}  cannot probe: {exc}")
            continue
        except OSError as exc:
            lines.append(f"{head}  cannot probe: {exc.strerror or exc} (serial ports need the dialout group)")
            continue
        if query is None:
            lines.append(f"{head}  no ISDV4 answer")
        elif getattr(query, "has_pen", True):
            found += 1
            lines.append(f"{head}  ISDV4 tablet: {_query_text(query)}")
        else:
            lines.append(f"{head}  ISDV4 touch panel without a pen: {_query_text(query)}")
    return found, lines


def report(out: TextIO, sysfs_root: str, dev_root: str) -> int:
    """Writes the listing; returns how many tablets it found."""
    hid_tablets, hid, with_hidraw = hidraw_lines(sysfs_root, dev_root)
    usb_found, usb, usb_problem = usb_lines(with_hidraw)
    serial_found, serial = serial_lines()
    tablets = hid_tablets + usb_found + serial_found
    usb_where = "USB via pyusb" + (f" ({usb_problem})" if usb_problem else "")
    looked = f"looked in {hidraw_class_dir(sysfs_root)}, {usb_where}, serial ports"
    if not (hid or usb or serial):
        out.write(f"no pen tablets found ({looked})\n")
        return 0
    for section in (hid, usb, serial):
        if section:
            out.write("\n".join(section) + "\n")
    if usb_problem:
        out.write(f"USB: not listed: {usb_problem}\n")
    if not tablets:
        out.write(f"no pen tablets found among these ({looked})\n")
    return tablets


def run(args: argparse.Namespace | None = None) -> int:
    sysfs_root, dev_root = roots_from_env()
    report(sys.stdout, sysfs_root, dev_root)
    return 0
