"""Strokes drawn the way the students of benchmarks/student_sets.py drew them with a mouse (issue 25): straight runs
between sharp cusps, few points, a hook where the pen lands. A brace or a question mark drawn so is still a curve,
a box whose start is hooked or that stops at its last corner short of its start is still a box, and a delete mark
whose ends happen to meet is an open polyline, not a bow-tie polygon."""

from __future__ import annotations

import math
import random

import numpy as np
import pytest

from physink_tui.scene.recognition.recognize import recognize_stroke

SEEDS = range(40)


def _mouse(path: list[tuple[float, float]], rng: random.Random, step: tuple[float, float] = (4.0, 14.0),
           ) -> list[tuple[float, float]]:
    """Points along the polyline ``path`` one motion event apart (the hand's speed varies: ``step`` px apart, as
    few as a mouse reports), rounded to whole pixels, turned and placed at random."""
    pts = np.asarray(path, dtype=float)
    seg = np.hypot(*np.diff(pts, axis=0).T)
    at = np.concatenate([[0.0], np.cumsum(seg)])
    out, s = [], 0.0
    while s < at[-1]:
        out.append(s)
        s += rng.uniform(*step)
    out.append(at[-1])
    xy = np.column_stack([np.interp(out, at, pts[:, 0]), np.interp(out, at, pts[:, 1])])
    a = rng.uniform(-0.25, 0.25)  # a person draws these about upright
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    xy = xy @ rot.T + np.array([rng.uniform(50, 400), rng.uniform(50, 400)])
    return [(float(x), float(y)) for x, y in np.round(xy)]


def _arc(cx: float, cy: float, r: float, a0: float, a1: float, n: int = 12) -> list[tuple[float, float]]:
    return [(cx + r * math.cos(a), cy + r * math.sin(a)) for a in np.linspace(a0, a1, n)]


def mouse_brace(seed: int) -> list[tuple[float, float]]:
    """A curly brace of straight runs: a curled end, a straight spine, a pointed tip out and back, a straight spine,
    a curled end (120-320 px tall, left or right facing)."""
    rng = random.Random(f"mouse-brace:{seed}")
    h = rng.uniform(120, 320)
    tip = rng.uniform(0.08, 0.16) * h
    curl = rng.uniform(0.06, 0.12) * h
    side = rng.choice((-1, 1))
    lean = rng.uniform(-0.04, 0.04) * h
    path = [(side * curl, 0.0), (side * 0.3 * curl, 0.1 * curl), (0.0, curl)]  # the top end, curled
    path += [(lean, 0.5 * h - 0.25 * tip), (-side * tip, 0.5 * h), (lean, 0.5 * h + 0.25 * tip)]  # spine and tip
    path += [(0.0, h - curl), (side * 0.3 * curl, h - 0.1 * curl), (side * curl, h)]
    return _mouse(path, rng)


def mouse_question_mark(seed: int) -> list[tuple[float, float]]:
    """A question mark drawn with sharp turns: a straight stroke along the top, a cusp, the body bowing down round a
    half circle, a cusp into the straight stem (100-260 px tall)."""
    rng = random.Random(f"mouse-question-mark:{seed}")
    h = rng.uniform(100, 260)
    r = rng.uniform(0.22, 0.3) * h
    path = [(-r * rng.uniform(0.6, 1.0), -r * rng.uniform(0.0, 0.3)), (0.0, -r)]  # the top, straight
    path += _arc(0.0, 0.0, r, -math.pi / 2, math.pi / 2 * rng.uniform(0.8, 1.0))[1:]  # the body, one cusp in
    path += [(path[-1][0] - rng.uniform(0.0, 0.1) * r, h - 2 * r)]  # the stem, straight down from another cusp
    return _mouse(path, rng)


def mouse_box(seed: int, how: str) -> list[tuple[float, float]]:
    """A rectangle 80-300 px a side: started at a corner with a hook where the pen landed (``hooked``: a dash 6-14 %
    of a side from inside the box out to the corner), or started partway along the top and stopped at the corner
    before its start (``short``: the gap runs along the first side, 28-40 % of it)."""
    rng = random.Random(f"mouse-box:{how}:{seed}")
    w, h = rng.uniform(80, 300), rng.uniform(80, 300)
    corners = [(w, 0.0), (w, h), (0.0, h), (0.0, 0.0)]
    if how == "hooked":  # started at a corner: the pen lands inside, dashes out to the corner and goes round
        dash = rng.uniform(0.06, 0.14) * min(w, h)
        a = rng.uniform(0.35, 1.2)
        overshoot = (rng.uniform(0.03, 0.1) * w, 0.0)  # and ends past the corner, along the top again
        path = [(dash * math.cos(a), dash * math.sin(a)), (0.0, 0.0), *corners[:3], (0.0, 0.0), overshoot]
    else:
        gap = rng.uniform(0.28, 0.4) * w
        path = [(gap, 0.0), *corners]
    return _mouse(path, rng)


def mouse_delete_mark(seed: int) -> list[tuple[float, float]]:
    """A delete mark: down one diagonal, across, up the other diagonal crossing the first, and on along the top
    until the pen is back near where it started (60-240 px)."""
    rng = random.Random(f"mouse-delete:{seed}")
    w, h = rng.uniform(60, 240), rng.uniform(60, 240)
    path = [(0.0, 0.0), (w, h), (0.0, h), (w, 0.0), (rng.uniform(0.05, 0.15) * w, rng.uniform(-0.05, 0.05) * h)]
    return _mouse(path, rng)


def mouse_arrow(seed: int) -> list[tuple[float, float]]:
    """An arrow in one stroke: the shaft (120-320 px), one barb drawn out and back along itself, the other barb (the
    head 15-30 % of the shaft, its barbs 25-45 degrees off it); a fast hand's events up to 18 px apart."""
    rng = random.Random(f"mouse-arrow:{seed}")
    length = rng.uniform(120, 320)
    head = rng.uniform(0.15, 0.3) * length
    a = math.radians(rng.uniform(25, 45))
    back = rng.uniform(0.0, 0.04) * head  # the pen comes back to about the tip, not exactly
    path = [(0.0, 0.0), (length, 0.0), (length - head * math.cos(a), -head * math.sin(a)), (length - back, 0.3 * back),
            (length - head * math.cos(a), head * math.sin(a))]
    return _mouse(path, rng, step=(4.0, 18.0))


def _share(kind: str, strokes: list[list[tuple[float, float]]]) -> tuple[float, list[str | None]]:
    got = [recognize_stroke(s).kind for s in strokes]
    return sum(g == kind for g in got) / len(got), got


CASES = {
    "brace": (mouse_brace, "curve", 0.9),
    "question_mark": (mouse_question_mark, "curve", 0.95),
    "box_hooked_start": (lambda seed: mouse_box(seed, "hooked"), "box", 0.9),
    "box_stopped_short": (lambda seed: mouse_box(seed, "short"), "box", 0.95),
    "delete_mark": (mouse_delete_mark, "polyline", 0.95),
    "arrow_retraced_head": (mouse_arrow, "polyline", 0.9),
}
"""name -> (drawing, kind, floor: the share of the 40 seeds read as that kind). Measured when written (issue 25):
braces 28 of 40 (16 before the brace-tip rule, the rest read as polylines), question marks 40, hooked boxes 40 (as
before: the code before the hook rule reads these right too; the students' hooked boxes it read as 5-cornered
polygons are not reproduced by this drawing), boxes stopped short 40 (9 before the gap along the first side closed
them, the rest polylines), delete marks 40 (none before the bow-tie rule: all were 4-cornered polygons). Issue 25's
fourth pass: braces 40 (37 by the rules alone; 37 and 28 at main 20fd666), arrows whose head is a barb drawn out and
back 37 (24 at 20fd666: the head's corners lay in one run of short straws, of which only the lowest was a corner)."""


@pytest.mark.parametrize("name", list(CASES))
def test_a_mark_drawn_with_a_mouse_keeps_its_kind(name: str) -> None:
    make, kind, floor = CASES[name]
    share, got = _share(kind, [make(seed) for seed in SEEDS])
    assert share >= floor, f"{share:.0%} read as {kind}: {got}"
