"""Issue 25, session 24: circles and ovals drawn small, flat, lumpy, gone round again, with a tail, left open as a
spiral's turn, pointed where the ends meet or flat on one side (`tests/penmodels/circle_habits`), drawn by the pen
models through poor devices (a slow sampler's chords, a mouse, pointer acceleration, a finger, a trackpad:
`benchmarks/bench_circle_habits.py`), read as circles or ellipses.

Floors were measured on the held seeds (1000-1029), read once, at the end; each is this branch's figure.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_circle_habits import EXPECTED, PENS, drawn
from bench_open_marks import HELD_SEEDS

_ALL = dict.fromkeys(PENS, 60)
HELD_FLOORS = {
    "small-circle": {**_ALL, "hurried": 58, "hurried-mouse": 8, "hurried-finger": 56},
    "flat-oval": {**_ALL, "hurried-mouse": 58},
    "wobbly-circle": _ALL,
    "overtraced-circle": {**_ALL, "hurried-fast": 58, "hurried-chords-accel": 56, "hurried-trackpad": 56},
    "tailed-circle": {**_ALL, "hurried-finger": 58},
    "open-spiral-turn": _ALL,
    "pointed-join": _ALL,
    "flat-sided-circle": {**_ALL, "hurried-finger": 58},
    "lopsided-long-oval": _ALL,
    "flicked-oval": {**_ALL, "hurried-coarse": 58, "hurried-mouse": 52, "hurried-fast": 58, "hurried-accel": 58,
                     "hurried-chords-accel": 56, "hurried-trackpad": 56},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are circles or
ellipses, measured on this branch; main 40b8114 read 10 fewer in all (4,716 of 4,800 against 4,726): small circles
through whole pixels 58, overtraced circles through a finger 58, open spiral turns and flat-sided circles through a
trackpad 56 and 58 (curves where a lift hook kept a small loop's ends apart, helices where a finger's landing curled).
The small circles through the busy-event-loop mouse (8 of 60) come as 3-7 bursts of events for the whole circle: a
polygon of 3-7 chords, which the same device makes of a small pentagon, hexagon or octagon too (docs/BENCHMARKS.md).
Lopsided long ovals (session 26, wt-fourth): 600 of 600 (main 7111cdc 588: polygons where the ellipse's miss was
measured along the ray from its centre, `candidates.ellipse_distances`). Ovals closed with a flick off the loop of up
to 1.2 of their half-length (session 27): 578 of 600, as main 9f69154 (polygons and a box through a mouse, chords
and a trackpad); session 26's `tail_runs_off`, measured against the half width, took such ovals for pigtails."""


def reading(stroke: list[tuple[float, float, float]], timed: bool) -> str | None:
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None).kind


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_a_circle_drawn_with_a_hurried_habit_on_a_poor_device_reads_round(family: str, pen: str) -> None:
    got = [reading(drawn(family, pen, seed), timed) for seed in HELD_SEEDS for timed in (True, False)]
    assert sum(k in EXPECTED for k in got) >= HELD_FLOORS[family][pen], got


def test_a_small_circle_whose_lift_hook_left_its_ends_apart_reads_round() -> None:
    """A 10-30 px circle's ends 0.21 of its size apart where the pen lifted with a hook of a few pixels (tuning seed 7
    of the hurried hand; main 40b8114: a curve): without the hook the loop closes."""
    stroke = drawn("small-circle", "hurried", 7)
    assert [reading(stroke, timed) for timed in (True, False)] == [reading(stroke, True)] * 2
    assert reading(stroke, True) in EXPECTED


@pytest.mark.parametrize("family", ["overtraced-circle", "tailed-circle"])
def test_a_circle_with_a_small_curl_where_the_finger_landed_is_no_spring(family: str) -> None:
    """A finger settling where it landed curls once round on the spot (tuning seed 3 through a finger; main 40b8114: a
    helix): the circle and the curl turn far enough for a spring, but the curl is no loop of one."""
    stroke = drawn(family, "hurried-finger", 3)
    assert all(reading(stroke, timed) in EXPECTED for timed in (True, False))
