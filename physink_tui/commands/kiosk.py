"""`physink kiosk`: the headless recording service on a live tablet or a replayed capture; the service itself is
`physink_tui.kiosk`, this module only opens the tablet (or the capture), builds the journal header and handles
the signals.

``--replay CAPTURE.hid [--speed X]`` feeds a capture through the same path as a live tablet, paced by its
timestamps X times faster; the sessions' time is the capture's own (the kiosk's clock is the time of the
capture's latest report), so a replay at any speed records the same sessions, byte for byte.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

from physink_tui.errors import DeviceError, PhysinkError
from physink_tui.formats.journal.entries import JournalDevice, JournalHeader
from physink_tui.formats.outputs import reason
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.readers import check_device_spec, open_reader
from physink_tui.input.journal_compose import header_for_capture
from physink_tui.input.pen.mapping import TabletMapping, mapping_to_header
from physink_tui.input.pen.state import TipThresholds
from physink_tui.input.reconnecting import ReconnectingSource
from physink_tui.input.scripted_sources import CaptureReplaySource
from physink_tui.input.serial_tablets.reader import SerialPenSource
from physink_tui.input.sources import PenSource
from physink_tui.kiosk.hot_zones import HotZones, read_zones
from physink_tui.kiosk.store import SessionStore, parse_size

if TYPE_CHECKING:
    from physink_tui.kiosk.service import Kiosk
    from physink_tui.kiosk.speech import KioskSpeech

CANVAS = (1600.0, 1000.0)
DEVICE_ID = "tablet0"
SERIAL_ID = "serial0"
T = TypeVar("T")
WAIT_S = 1.0
"""Seconds between looks for a tablet while none is plugged in."""


def log(line: str) -> None:
    print(line, flush=True)


def tablet_aspect(device: JournalDevice) -> float:
    """The active area's width over its height: from the descriptor's physical size, else its logical ranges."""
    try:
        layouts = HidPenDecoder(device.descriptor, device.vid, device.pid, name=device.name or None).layouts
    except PhysinkError:
        return CANVAS[0] / CANVAS[1]
    for layout in layouts.values():
        if layout.size_mm is not None and layout.size_mm[1] > 0:
            return layout.size_mm[0] / layout.size_mm[1]
    return CANVAS[0] / CANVAS[1]


def mapping_for(device: JournalDevice, zones: HotZones) -> TabletMapping:
    """The canvas on the tablet's area beside the hot zones, the tablet's proportions kept."""
    aspect = tablet_aspect(device)
    return TabletMapping(canvas_width=CANVAS[0], canvas_height=CANVAS[1], tablet_width=aspect, tablet_height=1.0,
                         area=zones.area)


def _replay_source(path: str, speed: float, zones: HotZones,
                   idle_s: float) -> tuple[PenSource, JournalDevice, JournalHeader]:
    try:
        capture = Capture.from_file(path)
    except OSError as exc:
        raise PhysinkError(f"{path}: cannot read the capture: {reason(exc)}") from None
    if not capture.devices:
        raise PhysinkError(f"{path}: the capture describes no device")
    first = capture.devices[0]
    device = JournalDevice(DEVICE_ID, first.name, first.bus, first.vid, first.pid, first.descriptor)
    header = header_for_capture(Capture((first,), ()), mapping_for(device, zones))
    # a gap longer than --idle ends the session whatever its length: the replay does not wait it out in full
    source = CaptureReplaySource(capture, DEVICE_ID, first.index, realtime=True, speed=speed, max_gap=idle_s + 1.0)
    return source, device, header


def _wait_for(open_fn: Callable[[], T], kiosk: Kiosk) -> T:
    """``open_fn()`` once it stops raising `DeviceError` (the tablet is plugged in), trying every `WAIT_S`; the
    first failure is logged. Raises KeyboardInterrupt when the kiosk is told to stop meanwhile."""
    told = False
    while True:
        try:
            return open_fn()
        except DeviceError as exc:
            if not told:
                log(f"kiosk: waiting for a tablet ({exc})")
                told = True
            if kiosk._stop.wait(WAIT_S):
                raise KeyboardInterrupt from None


def _live_source(spec: str | None, zones: HotZones, kiosk: Kiosk) -> tuple[PenSource, JournalDevice, JournalHeader]:
    """Waits for the tablet (hot-plug), then a source that survives it being unplugged and plugged back."""
    reader = _wait_for(lambda: open_reader(spec, DEVICE_ID), kiosk)
    info = reader.info
    if info is None or not info.descriptor:
        reader.stop()
        where = (spec or DEVICE_ID) if info is None else info.path
        raise DeviceError(f"{where}: its report descriptor is unknown (is it a tablet's hidraw node?), and a journal "
                          "needs one")
    device = JournalDevice(DEVICE_ID, info.name or None, info.bus, info.vid, info.pid, info.descriptor)
    mapping = mapping_for(device, zones)
    thresholds = TipThresholds()
    header = JournalHeader(CANVAS[0], CANVAS[1], (device,), mapping_to_header(mapping), thresholds.down,
                           thresholds.up)
    source = ReconnectingSource(lambda: open_reader(spec, DEVICE_ID), DEVICE_ID, inner=reader)
    return source, device, header


def _serial_source(port: str, zones: HotZones, kiosk: Kiosk) -> tuple[PenSource, TabletMapping, JournalHeader]:
    """Waits for an ISDV4 tablet on ``port``; its samples are in tablet space, mapped by the kiosk after the zones."""
    source = SerialPenSource(port, SERIAL_ID)
    query = _wait_for(source.open, kiosk)
    aspect = query.x_max / query.y_max if query.y_max else CANVAS[0] / CANVAS[1]
    mapping = TabletMapping(canvas_width=CANVAS[0], canvas_height=CANVAS[1], tablet_width=aspect, tablet_height=1.0,
                            area=zones.area)
    thresholds = TipThresholds()
    header = JournalHeader(CANVAS[0], CANVAS[1], (), mapping_to_header(mapping), thresholds.down, thresholds.up)
    return source, mapping, header


def run(args: argparse.Namespace) -> int:
    stop = threading.Event()  # SIGTERM from the first moment: the service's libraries take a while to load
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    from physink_tui.kiosk.service import Kiosk, KioskSettings
    from physink_tui.render.export import Look

    if args.replay is None and not args.serial:
        try:
            check_device_spec(args.device)
        except DeviceError as exc:
            print(f"physink kiosk: {exc}", file=sys.stderr)
            return 2
    zones = read_zones(args.hot_zones)
    max_bytes = None
    if args.max_disk is not None:
        try:
            max_bytes = parse_size(args.max_disk)
        except ValueError as exc:
            print(f"physink kiosk: --max-disk: {exc}", file=sys.stderr)
            return 2
    settings = KioskSettings(args.idle, args.keep, max_bytes, Look(args.video_size[0], args.video_size[1], 30))
    if args.speech and args.replay is not None and args.speed != 1.0:
        print("physink kiosk: --speech listens in real time, so a replay with it needs --speed 1", file=sys.stderr)
        return 2
    kiosk = Kiosk(SessionStore(args.out), zones, settings, log, stop)
    kiosk.recover()
    if args.replay is not None:
        kiosk.use_capture_clock()  # a replay's clock is the capture's own, the microphone's too
    ears = _ears(args, kiosk, kiosk.clock)
    try:
        if args.replay is not None:
            source, device, header = _replay_source(args.replay, args.speed, zones, args.idle)
            log(f"kiosk: replaying {args.replay} at {args.speed:g}x")
            return kiosk.run(source, device, header, replay=True)
        if args.serial:
            serial_source, mapping, header = _serial_source(args.serial, zones, kiosk)
            return kiosk.run(serial_source, None, header, replay=False, mapping=mapping)
        source, device, header = _live_source(args.device, zones, kiosk)
        return kiosk.run(source, device, header, replay=False)
    except KeyboardInterrupt:
        kiosk.stop()
        return 0
    finally:
        if ears is not None:
            ears.stop()


def _ears(args: argparse.Namespace, kiosk: Kiosk, clock: Callable[[], float]) -> KioskSpeech | None:
    """With ``--speech``: the microphone, listening (None when it cannot: the log says why)."""
    if not args.speech:
        return None
    from physink_tui.input.speech.backends import make_recogniser
    from physink_tui.kiosk.speech import KioskSpeech

    ears = KioskSpeech(kiosk.hear, clock, log, recogniser=lambda: make_recogniser(args.vosk_model))
    return ears if ears.start() else None
