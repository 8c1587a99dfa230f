"""Issue 25, session 28: a round stroke left open whose end flicks off as the pen lifts is read round without the flick
(`recognition.lift_hooks`), and a small round stroke a busy mouse sampled in a few bursts of events is read by its
points, not the chords between bursts (`pen_noise.round_in_bursts`); an arc, a C, a question mark's hook and a box
sampled in bursts at its corners stay what they were.

The gestures are `tests/penmodels/circle_gestures`' tuning seeds (0-29) drawn by `benchmarks/bench_circle_gestures`'
pens; each read round here was read as a curve, a polyline or a polygon by main 0ca43a2. The held floors are in
`tests/test_circle_gestures.py`.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from physink_tui.scene.recognition import lift_hooks, pen_noise
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import bench_bracket_habits
from bench_circle_gestures import EXPECTED, drawn, reading

Points = list[tuple[float, float]]


def _arc(sweep_deg: float, r: float = 100.0) -> Points:
    a = np.radians(np.linspace(0.0, sweep_deg, int(sweep_deg / 2) + 1))
    return [(500 + r * math.cos(t), 400 + r * math.sin(t)) for t in a]


def _flicked(pts: Points, turn_deg: float, length: float) -> Points:
    """``pts`` with a flick at the end: ``length`` more, turning ``turn_deg`` off the heading over five steps."""
    (x0, y0), (x1, y1) = pts[-2], pts[-1]
    heading, out = math.atan2(y1 - y0, x1 - x0), list(pts)
    for k in range(1, 6):
        h = heading + math.radians(turn_deg) * k / 5
        x, y = out[-1]
        out.append((x + length / 5 * math.cos(h), y + length / 5 * math.sin(h)))
    return out


@pytest.mark.parametrize(("family", "pen", "seed"), [
    ("circle-open-hooked", "careful", 2), ("circle-open-hooked", "careful", 5), ("circle-open-hooked", "careful", 7),
    ("oval-open-hooked", "hurried", 4), ("oval-open-hooked", "hurried", 6),
    ("whole-note-open", "hurried", 1), ("whole-note-open", "hurried", 8)])
def test_a_round_stroke_left_open_with_a_flick_at_the_lift_reads_round(family: str, pen: str, seed: int) -> None:
    """Main 0ca43a2: a curve (the flick turns back against the round, or sharply on, and `remove_hooks` keeps it: the
    round path after it is not straight)."""
    for mirror in (False, True):
        for timed in (True, False):
            assert reading(drawn(family, pen, seed, mirror), timed) in EXPECTED


def test_the_flick_is_cut_off_the_round_path_only() -> None:
    arc = np.array(sg.resample(np.array(_arc(300.0)), 80))
    assert lift_hooks.without_flicks(arc, sg.turning(arc)) is None  # nothing turns off a clean arc
    flicked = sg.resample(np.array(_flicked(_arc(300.0), -120.0, 25.0)), 80)
    rest = lift_hooks.without_flicks(flicked, sg.turning(flicked))
    assert rest is not None and 70 <= len(rest) < 80  # the flick (about 5 % of the path) and no more


@pytest.mark.parametrize("turn", [-120.0, 120.0])
def test_a_c_or_a_u_with_a_flick_stays_open(turn: float) -> None:
    """Half a turn with a flick at the lift is an open mark (an arc or a curve), as main reads it."""
    for sweep in (150.0, 180.0):
        assert recognize_stroke(_flicked(_arc(sweep), turn, 15.0)).kind not in EXPECTED


@pytest.mark.parametrize(("family", "seed"), [
    ("whole-note-closed", 2), ("whole-note-closed", 10), ("whole-note-closed", 11),
    ("whole-note-open", 0), ("whole-note-open", 2), ("whole-note-open", 9)])
def test_a_whole_note_through_a_busy_mouse_reads_round(family: str, seed: int) -> None:
    """A 20-40 px note the mouse sampled in 3-7 bursts of events (main 0ca43a2: a polygon or a polyline of the chords
    between bursts)."""
    for mirror in (False, True):
        for timed in (True, False):
            assert reading(drawn(family, "hurried-mouse", seed, mirror), timed) in EXPECTED


def _bursts(at: object, centres: list[float], width: float, k: int = 4) -> Points:
    return [at(c + width * j / (k - 1)) for c in centres for j in range(k)]  # type: ignore[operator]


def _square(u: float) -> tuple[float, float]:
    u %= 1.0
    side, f = int(u * 4), u * 4 - int(u * 4)
    (ax, ay), (bx, by) = [(0, 0), (100, 0), (100, 100), (0, 100), (0, 0)][side:side + 2]
    return (400 + ax + (bx - ax) * f, 300 + ay + (by - ay) * f)


def test_bursts_round_an_ellipse_but_not_a_square_at_its_corners() -> None:
    oval = _bursts(lambda u: (500 + 60 * math.cos(2 * math.pi * u), 400 + 40 * math.sin(2 * math.pi * u)),
                   [0.0, 0.21, 0.4, 0.62, 0.8, 0.98], 0.03)
    assert pen_noise.round_in_bursts(np.array(oval), sg.bbox_diagonal(np.array(oval))) is not None
    assert recognize_stroke(oval).kind in EXPECTED
    square = _bursts(_square, [0.0, 0.23, 0.49, 0.74, 0.98], 0.04)  # each burst turns at a corner
    assert recognize_stroke(square).kind == "box"
    dense = _bursts(_square, [k / 40 for k in range(41)], 0.02)  # no jumps: a box drawn slowly
    assert pen_noise.round_in_bursts(np.array(dense), sg.bbox_diagonal(np.array(dense))) is None


@pytest.mark.parametrize("family", ["small-bracket", "bowed-spine-bracket", "mouse-rounded-bracket"])
def test_a_square_bracket_through_a_busy_mouse_stays_a_polyline(family: str) -> None:
    """An ellipse fits a small bracket's few bursts of events and goes round them by up to 265 degrees (tuning seeds):
    open, a stroke in bursts must go round 300 (`pen_noise.BURST_SWEEP_OPEN`); at 225 these read 32 ellipses."""
    for seed in range(30):
        stroke = bench_bracket_habits.drawn(family, "hurried-mouse", seed)
        for timed in (True, False):
            assert recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None).kind \
                == "polyline", (seed, timed)
