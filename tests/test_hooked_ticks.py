"""Issue 25, session 19: a tick drawn fast with a mouse whose short arm is a few percent of the stroke (longer than a
landing hook, shorter than the tenth the open-stroke rules cut as a hook) read as a curve or an arc; now a polyline of
two sides (`recognition.hooked_ticks`). Drawn by both pen models through a whole session (journal -> replay ->
project), it becomes one polyline body through the tick's start, point and end; on `benchmarks/bench_hurried_marks.py`'s
tuning seeds (0-29) the family is read as a polyline at least as often as measured here; people's ticks (ahmadosama)
it was designed on are read so; a line with a landing hook stays a line and a pigtail whose arms cross stays a curve.

People's strokes are read from the cache `benchmarks/public_sets.py` writes (no licence lets the project hold them);
without it that test skips, saying so.
"""

from __future__ import annotations

import math
import random
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.hurried import HurriedPen
from penmodels.hurried_marks import hooked_tick
from penmodels.journal import header as hurried_header
from penmodels.shapes import Curve
from scenarios.thesis import DEVICE, MAPPING
from test_open_marks import cached_rows
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition import hooked_ticks
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_hurried_marks import read
from bench_open_marks import PENS, TUNING_SEEDS

Point = tuple[float, float]


def _journal(pen: str, points: tuple[Point, ...], seed: int) -> tuple[JournalHeader, list[JournalEntry]]:
    """One stroke along ``points`` (canvas pixels) by the hurried hand (a smooth path) or the virtual pen."""
    if pen == "hurried":
        reports = HurriedPen(random.Random(seed)).draw(Curve(points), 0.3)[0]
        return hurried_header(), [_pen_entry(r) for r in reports]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    stroke = Stroke(tuple((x / w, y / h) for x, y in points))
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record([stroke])
    return header_for_capture(capture, MAPPING), capture_entries(capture)


SESSION_TICKS = {"hurried": 4, "virtual": 2}


def session_tick_bodies(pen: str, marks: list, tmp_path) -> tuple[list[tuple[object, np.ndarray, str]], list[str]]:
    """Each of ``marks`` drawn by ``pen`` through a whole session (journal -> replay -> project), asserted to make one
    body: the (mark, outline, what the session told) of each that became a polyline of three points, a tick's body,
    and a line for each that did not."""
    ticks, missed = [], []
    for seed, mark in enumerate(marks, start=1):
        folder = tmp_path / str(seed)
        folder.mkdir()
        project, told = replayed_project(*_journal(pen, mark.points, seed), folder)
        bodies = project.scene.bodies()
        assert len(bodies) == 1, f"{pen} seed {seed}: {bodies}\n{told}"
        outline = np.asarray(bodies[0].outline, dtype=float)
        if bodies[0].shape != "polyline" or len(outline) != 3:
            missed.append(f"seed {seed}: {bodies[0].shape} of {len(outline)} points\n{told}")
        else:
            ticks.append((mark, outline, told))
    return ticks, missed


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
def test_a_tick_with_a_short_first_arm_becomes_a_polyline_body_with_its_point(pen: str, tmp_path) -> None:
    """Of five ticks (seeds 1-5), each becomes one body, and as many as `SESSION_TICKS` says a tick's: measured 4 of 5
    by the hurried hand, 2 of 5 by the virtual pen (the thesis's uclogic tablet), whose other three the line test takes
    for lines, as it cuts the short arm as a hook (not asked of `hooked_ticks`: asked of lines it took mmg's hooked
    lines for ticks). On main (a9aabd6) none became a tick's body: 4 and 2 curves made no body at all, 1 and 3 lines."""
    ticks, missed = session_tick_bodies(pen, [hooked_tick(seed) for seed in range(1, 6)], tmp_path)
    for mark, outline, told in ticks:
        # a short arm and a long one, at a tick's angle (the outline is the body's, in its own units and place)
        arms = np.diff(outline, axis=0)
        short, long = sorted(np.hypot(arms[:, 0], arms[:, 1]))
        drawn_short = min(math.dist(mark.points[0], mark.points[6]), math.dist(mark.points[-1], mark.points[-7]))
        drawn_long = math.dist(mark.points[0], mark.points[-1])
        assert abs(short / long - drawn_short / drawn_long) < 0.05, f"{pen}: arms {short:.3g}, {long:.3g}\n{told}"
        turn = math.degrees(math.acos(float(arms[0] @ arms[1]) / (short * long)))
        assert turn >= 60.0, f"{pen}: the arms turn {turn:.0f} degrees\n{told}"
    assert 5 - len(missed) >= SESSION_TICKS[pen], "\n".join(missed)


POLYLINE_FLOORS = {"careful": 46, "hurried": 50, "hurried-coarse": 44, "hurried-mouse": 18}
"""pen -> of the 60 readings of the hooked-tick family (30 tuning seeds, with and without times), how many are
polylines, measured on this branch less two; main a9aabd6 read 0, 0, 0, 4 (`bench_hurried_marks.py`)."""


@pytest.mark.parametrize("pen", list(POLYLINE_FLOORS))
def test_ticks_with_short_arms_by_the_pen_models_are_polylines(pen: str) -> None:
    got = [read("hooked-tick", pen, seed, timed) for seed in TUNING_SEEDS for timed in (True, False)]
    assert sum(k == "polyline" for k in got) >= POLYLINE_FLOORS[pen], got


@pytest.mark.parametrize("pen", list(PENS))
def test_a_pigtail_whose_arms_cross_as_an_x_stays_a_curve(pen: str) -> None:
    """The control for an x drawn in one stroke and swung round at its far side (tried, not kept: docs/BENCHMARKS.md):
    the same crossing with a round loop is a pigtail (measured 58-60 of 60 curves per pen)."""
    got = [read("ribbon-pigtail", pen, seed, timed) for seed in TUNING_SEEDS for timed in (True, False)]
    assert sum(k == "curve" for k in got) >= 56, got


TICKS = ("AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TrainingData/Tick.xml#14",
         "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TrainingData/Tick.xml#26")
"""ahmadosama's Ticks (a mouse) whose short first arm is 5-6 % of the stroke, 15-23 px: curves on main a9aabd6."""


@pytest.mark.parametrize("file", TICKS, ids=[f.rsplit("#", 1)[1] for f in TICKS])
def test_a_persons_tick_with_a_short_first_arm_is_a_polyline(file: str) -> None:
    row = cached_rows("public-sets/ahmadosama.jsonl").get(file)
    assert row is not None, f"{file} is not in ahmadosama"
    stroke = row["strokes"][0]
    points = [p[:2] for p in stroke]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    assert recognize_stroke(points, times, learned=False).kind == "polyline"
    assert recognize_stroke(points, times).kind == "polyline"


def test_a_line_with_a_landing_hook_is_no_tick() -> None:
    """A 300 px line whose pen landed with a hook of up to `lines.HOOK_REACH` px at a right angle, at 1 px noise: the
    hook is no arm (`hooked_ticks.ARM_REACH`)."""
    for hook in (3.0, 6.0, 8.0):
        pts = [(0.0, -hook), *((float(x), 0.0) for x in np.linspace(0.0, 300.0, 151))]
        pts = np.asarray(pts)
        scale = float(np.abs(pts - pts.mean(axis=0)).max())
        assert hooked_ticks.hooked_tick((pts - pts.mean(axis=0)) / scale, 1.0 / scale) is None, hook
        assert recognize_stroke(pts.tolist()).kind == "line", hook
