"""`physink record`: a tablet's raw reports into a hid-recorder capture as they come; decodes nothing.

Records until Ctrl-C or until the device goes away. Serial tablets send no HID reports, so they are refused.

The capture starts with comments, then the device header (``R:``, ``N:``, ``P:``, ``I:``), then one ``E:`` line
per report, stamped with the seconds since the first report and flushed at once, so a capture cut short by a
crash or an unplugged tablet is still readable up to its last line. For UC-Logic-family tablets the vendor
initialisation runs first; its result is kept as ``# physink vendor-init: protocol=… x_max=… y_max=… p_max=…``
so a later decode knows the protocol and maxima (`vendor_init.find_vendor_init`).
"""

from __future__ import annotations

import argparse
import queue
import sys
from typing import TextIO

from physink_tui import __version__
from physink_tui.commands.devices import roots_from_env
from physink_tui.errors import CaptureFormatError, DeviceError
from physink_tui.input.captures.capture import Capture, CaptureDevice
from physink_tui.input.captures.writer import event_line as capture_event_line
from physink_tui.input.captures.writer import format_capture
from physink_tui.input.hid.hidraw import BUS_USB, HidrawInfo
from physink_tui.input.hid.readers import open_reader
from physink_tui.input.hid.vendor_init import VendorInit, initialise_usb, needs_vendor_init
from physink_tui.input.sources import PenSource, RawReport, SourceEnded, SourceItem

DEVICE_ID = "tablet0"
EXIT_USAGE = 2
_GET_TIMEOUT_S = 0.25  # the main thread wakes this often, so Ctrl-C is seen even on a quiet tablet


def event_line(t: float, data: bytes) -> str:
    """One ``E:`` line with its newline, as `capture_writer.format_capture` writes it (negative t clamps to 0).

    >>> event_line(1.5, bytes([2, 0x21]))
    'E: 000001.500000 2 02 21\\n'
    """
    return capture_event_line(max(t, 0.0), data) + "\n"


def capture_header(info: HidrawInfo, init: VendorInit | None) -> str:
    """The comments and device lines that open the capture."""
    comments = [f"physink record {__version__}: {info.path}"]
    if init is not None:
        comments.append(init.comment())
    device = CaptureDevice(0, info.name or None, info.phys or None, info.bus, info.vid, info.pid, info.descriptor,
                           tuple(comments))
    return format_capture(Capture((device,), ()))


def vendor_initialise(info: HidrawInfo, err: TextIO) -> VendorInit | None:
    """Runs the vendor initialisation when the family needs it; a failure is a warning (mouse-mode reports are
    still worth recording)."""
    if info.bus != BUS_USB or not needs_vendor_init(info.vid):
        return None
    try:
        init = initialise_usb(info.vid, info.pid, info.usb_bus, info.usb_address)
    except DeviceError as exc:
        print(f"physink record: warning: vendor initialisation failed: {exc}; recording what the tablet sends "
              "without it (mouse mode)", file=err)
        return None
    if init is None:
        print("physink record: the tablet gave no vendor parameters; recording its reports as they are", file=err)
    else:
        p = init.params
        print(f"physink record: vendor initialisation: {init.protocol}, x max {p.x_max}, y max {p.y_max}, "
              f"pressure max {p.p_max}", file=err)
    return init


def record(reader: PenSource, out_file: TextIO, items: queue.Queue[SourceItem]) -> tuple[int, SourceEnded | None]:
    """Writes every report the started ``reader`` puts on ``items`` until it ends or Ctrl-C; returns the count
    and the reader's end (None when interrupted). Stops the reader either way and writes what it had queued."""
    count = 0
    t0: float | None = None
    ended: SourceEnded | None = None

    def write(item: RawReport) -> None:
        nonlocal count, t0
        if t0 is None:
            t0 = item.t
        out_file.write(event_line(item.t - t0, item.data))
        out_file.flush()
        count += 1

    try:
        while ended is None:
            try:
                item = items.get(timeout=_GET_TIMEOUT_S)
            except queue.Empty:
                continue
            if isinstance(item, RawReport):
                write(item)
            elif isinstance(item, SourceEnded):
                ended = item
    except KeyboardInterrupt:
        pass
    finally:
        reader.stop()
        while True:  # reports read before the stop took effect
            try:
                item = items.get_nowait()
            except queue.Empty:
                break
            if isinstance(item, RawReport):
                write(item)
    return count, ended


def run(args: argparse.Namespace) -> int:
    if getattr(args, "serial", None):
        print(f"physink record: {args.serial} is a serial tablet; serial capture is not in hid-recorder format "
              "(serial tablets send no HID reports), so there is nothing to record here", file=sys.stderr)
        return EXIT_USAGE
    sysfs_root, dev_root = roots_from_env()
    reader = open_reader(getattr(args, "device", None), DEVICE_ID, sysfs_root=sysfs_root, dev_root=dev_root)
    info: HidrawInfo | None = getattr(reader, "info", None)
    if info is None or not info.descriptor:
        reader.stop()
        what = info.path if info is not None else str(args.device)
        raise DeviceError(f"cannot record {what}: its report descriptor is unknown (no sysfs entry for it), and a "
                          "capture needs one")
    try:
        out_file = open(args.output, "w", encoding="utf-8", newline="\n")
    except OSError as exc:
        reader.stop()
        raise CaptureFormatError(f"cannot write capture: {exc.strerror or exc}", args.output) from None
    with out_file:
        init = vendor_initialise(info, sys.stderr)
        out_file.write(capture_header(info, init))
        out_file.flush()
        items: queue.Queue[SourceItem] = queue.Queue()
        reader.start(items)
        print(f"physink record: recording {info.name or info.path} ({info.ids}) to {args.output}; Ctrl-C stops",
              file=sys.stderr)
        count, ended = record(reader, out_file, items)
    why = "stopped" if ended is None or ended.error is None else f"the device went away ({ended.error})"
    print(f"wrote {count} reports to {args.output} ({why})")
    return 0
