"""Gestures a user makes: strokes, taps, dwells, eraser strokes, a device lost mid-stroke, smoothing."""

from __future__ import annotations

import math
import queue
from pathlib import Path

import pytest

from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.pen.gestures import (
    Dwell,
    GestureConfig,
    GestureEngine,
    PenDown,
    ProximityChanged,
    StrokeEnded,
    Tap,
)
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.pen.pen_input import PenInput
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.smoothing import PositionSmoother
from physink_tui.input.scripted_sources import CaptureReplaySource, ProgrammaticPenSource
from physink_tui.input.sources import SourceEnded

RECORDED = Path(__file__).resolve().parent / "recorded_hid"


def s(t: float, x: float, y: float, p: float = 0.0, *, rng: bool = True, eraser: bool = False) -> PenSample:
    return PenSample(t, x, y, p, p > 0, rng, eraser, False, False, None, None, 2)


def run(engine: GestureEngine, samples: list[PenSample]) -> list:
    out = []
    for sample in samples:
        out += engine.feed(sample)
    return out


def line(t0: float, n: int, x0: float, x1: float, p: float = 0.5, dt: float = 0.005) -> list[PenSample]:
    return [s(t0 + i * dt, x0 + (x1 - x0) * i / (n - 1), 0.5, p) for i in range(n)]


def of(kind, gestures: list) -> list:
    return [g for g in gestures if isinstance(g, kind)]


def test_a_stroke_from_pen_down_to_pen_up() -> None:
    samples = [s(0.0, 0.1, 0.5), *line(0.005, 50, 0.1, 0.6), s(0.3, 0.6, 0.5), s(0.35, 0.6, 0.5, rng=False)]
    gestures = run(GestureEngine(), samples)
    kinds = [type(g).__name__ for g in gestures if type(g).__name__ != "PenMove"]
    assert kinds == ["ProximityChanged", "PenDown", "StrokeEnded", "ProximityChanged"]
    (ended,) = of(StrokeEnded, gestures)
    stroke = ended.stroke
    assert len(stroke.points) == 50 and stroke.ended_by == "lift" and not stroke.eraser
    assert stroke.points[0].x == pytest.approx(0.1) and stroke.points[-1].x == pytest.approx(0.6)
    assert all(0 < p.p <= 1 for p in stroke.points)


def test_a_short_still_touch_is_a_tap_not_a_stroke() -> None:
    samples = [s(0.0, 0.3, 0.3)] + [s(0.01 * i, 0.3 + 0.0005 * i, 0.3, 0.4) for i in range(1, 10)]
    gestures = run(GestureEngine(), [*samples, s(0.12, 0.3, 0.3)])
    assert len(of(Tap, gestures)) == 1 and not of(StrokeEnded, gestures)


def test_holding_still_400ms_dwells_then_the_drag_is_marked() -> None:
    hold = [s(0.005 * i, 0.4, 0.4, 0.5) for i in range(100)]  # 0.5 s within the radius
    drag = line(0.5, 40, 0.4, 0.7)
    gestures = run(GestureEngine(), [s(-0.01, 0.4, 0.4), *hold, *drag, s(0.8, 0.7, 0.5)])
    (dwell,) = of(Dwell, gestures)
    assert dwell.t == pytest.approx(0.4, abs=0.006) and (dwell.x, dwell.y) == (0.4, 0.4)
    (ended,) = of(StrokeEnded, gestures)
    assert ended.stroke.dwell_t == dwell.t


def test_moving_before_400ms_never_dwells() -> None:
    gestures = run(GestureEngine(), [*line(0.0, 200, 0.1, 0.9), s(1.2, 0.9, 0.5)])
    assert not of(Dwell, gestures)
    assert of(StrokeEnded, gestures)[0].stroke.dwell_t is None


def test_a_dwell_completes_on_tick_when_a_still_tablet_sends_nothing() -> None:
    engine = GestureEngine()
    run(engine, [s(0.0, 0.4, 0.4), s(0.01, 0.4, 0.4, 0.5)])
    assert not engine.tick(0.2)
    assert of(Dwell, engine.tick(0.45))


def test_eraser_strokes_are_marked() -> None:
    samples = [s(0.0, 0.2, 0.2, eraser=True)] + [
        s(0.01 * i, 0.2 + 0.01 * i, 0.2, 0.6, eraser=True) for i in range(1, 40)
    ] + [s(0.5, 0.6, 0.2, eraser=True)]
    gestures = run(GestureEngine(), samples)
    assert of(PenDown, gestures)[0].eraser
    assert of(StrokeEnded, gestures)[0].stroke.eraser


def test_device_lost_mid_stroke_ends_the_stroke_cleanly() -> None:
    engine = GestureEngine()
    run(engine, [s(0.0, 0.1, 0.5), *line(0.005, 30, 0.1, 0.4)])
    gestures = engine.device_lost(0.2)
    (ended,) = of(StrokeEnded, gestures)
    assert ended.stroke.ended_by == "device-lost" and len(ended.stroke.points) == 30
    assert of(ProximityChanged, gestures) == [ProximityChanged(0.2, False)]
    assert not engine.drawing


def test_timestamps_going_backwards_are_held_and_counted() -> None:
    engine = GestureEngine()
    samples = [s(0.0, 0.1, 0.5), s(0.01, 0.1, 0.5, 0.5), s(0.02, 0.2, 0.5, 0.5), s(0.015, 0.3, 0.5, 0.5),
               s(0.03, 0.4, 0.5, 0.5), s(0.04, 0.4, 0.5)]
    (ended,) = of(StrokeEnded, run(engine, samples))
    times = [p.t for p in ended.stroke.points]
    assert times == sorted(times) and engine.backwards == 1


def test_pen_leaving_range_while_touching_ends_the_stroke_first() -> None:
    gestures = run(GestureEngine(), [s(0.0, 0.1, 0.5), *line(0.01, 30, 0.1, 0.5), s(0.4, 0.5, 0.5, rng=False)])
    names = [type(g).__name__ for g in gestures if type(g).__name__ != "PenMove"]
    assert names[-2:] == ["StrokeEnded", "ProximityChanged"]


def test_smoothing_halves_one_count_jitter_and_lags_at_most_one_sample() -> None:
    smoother = PositionSmoother()
    jitter = [s(0.005 * i, 0.5 + (0.001 if i % 2 else -0.001), 0.5, 0.5) for i in range(20)]
    out = [smoother.apply(x) for x in jitter]
    assert max(abs(o.x - 0.5) for o in out[1:]) < 1e-9
    ramp = [s(0.005 * i, 0.01 * i, 0.5, 0.5) for i in range(20)]
    smoother = PositionSmoother()
    lagged = [smoother.apply(x) for x in ramp]
    for raw, got in zip(ramp[1:], lagged[1:], strict=True):
        assert raw.x - got.x == pytest.approx(0.005)  # half a sample behind a steady movement


def test_virtual_pen_capture_through_the_reader_path_gives_its_strokes() -> None:
    capture = Capture.from_file(RECORDED / "windows-ink-strokes.hid")
    device = capture.devices[0]
    # the virtual pen draws its circle round in active-area units: a square tablet, as the mapping is told
    pen = PenInput(TabletMapping(canvas_width=16, canvas_height=10, tablet_width=1, tablet_height=1))
    pen.add_hid_device("tablet0", HidPenDecoder(device.descriptor, device.vid, device.pid))
    q: queue.Queue = queue.Queue()
    source = CaptureReplaySource(capture, "tablet0")
    source.start(q)
    gestures = []
    while True:
        item = q.get(timeout=60)  # hang guard
        gestures += pen.handle(item)
        if isinstance(item, SourceEnded):
            break
    source.stop()
    strokes = [g.stroke for g in of(StrokeEnded, gestures)]
    assert len(strokes) == 4  # line, box, circle, spring (tests/recorded_hid/make_recordings.py)
    circle = strokes[2]
    xs, ys = [p.x for p in circle.points], [p.y for p in circle.points]
    # the mapping keeps proportions: a circle drawn on the tablet stays round on the 16:10 canvas
    width = (max(xs) - min(xs)) * 16
    height = (max(ys) - min(ys)) * 10
    assert width == pytest.approx(height, rel=0.05)


def test_programmatic_pen_makes_a_stroke() -> None:
    q: queue.Queue = queue.Queue()
    clock = iter(math.fsum([0.01] * i) for i in range(1000))
    mouse = ProgrammaticPenSource("mouse", clock=lambda: next(clock))
    pen = PenInput()
    pen.add_sample_device("mouse", canvas_space=True)
    mouse.start(q)
    mouse.push(0.1, 0.1)
    for i in range(30):
        mouse.push(0.1 + 0.01 * i, 0.1, p=0.6, tip=True)
    mouse.push(0.4, 0.1)
    mouse.stop()
    gestures = []
    while not q.empty():
        gestures += pen.handle(q.get_nowait())
    (ended,) = of(StrokeEnded, gestures)
    assert ended.stroke.points[-1].x == pytest.approx(0.39)


def test_config_is_respected() -> None:
    engine = GestureEngine(GestureConfig(dwell_seconds=0.1))
    gestures = run(engine, [s(0.0, 0.5, 0.5)] + [s(0.01 * i, 0.5, 0.5, 0.5) for i in range(1, 15)])
    assert of(Dwell, gestures)
