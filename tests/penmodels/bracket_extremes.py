"""Square brackets at the edges of how people draw them (issue 25: the held-back people read brackets 89-90 %), the
habits `bracket_habits` and `mouse_habits` leave out: both arms leaning in past square (the heading sweeps 207-243
degrees), sharp or swung round, both leaning out as a trapezoid's sides do, corners rounded over the whole arm, tiny
brackets, a kinked spine, arms of very unequal length; in canvas pixels, seeded; no motion, no noise (the pens draw
them: `benchmarks/bench_bracket_extremes.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.bracket_habits import _bracket, _corner_radii, _frame, _verts, sized_bracket
from penmodels.open_marks import Mark, Point, _placed

EXPECTED = {"swept-past-bracket": "polyline", "swept-round-bracket": "polyline",
            "splayed-trapezoid-bracket": "polyline", "whole-arm-rounded-bracket": "polyline",
            "tiny-bracket": "polyline", "kinked-spine-bracket": "polyline", "lopsided-arm-bracket": "polyline"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: a square bracket is three straight sides, a
polyline, however its corners are turned)."""


def swept_past_bracket(seed: int) -> Mark:
    """A bracket whose arms both lean in 14-31 degrees past square (the heading sweeps 207-243 degrees, as a hand
    swinging round a bracket's corners carries on), arms 0.2-0.45 of the spine; corners sharp or rounded over up to
    0.4 of the arm (half the time each)."""
    rng = random.Random(f"swept-past-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.2, 0.45))
    tilts = (rng.uniform(14, 31), rng.uniform(14, 31))
    pts = _bracket(_verts(h, a1, a2, *tilts), _corner_radii(rng, a1, a2, 0.4), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("swept-past-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def swept_round_bracket(seed: int) -> Mark:
    """A bracket whose arms both lean in 14-31 degrees past square and whose corners a mouse or a hurried hand swings
    round over 0.4-0.8 of each arm (the heading sweeps 207-243 degrees, on the smoothed stroke 200-240, with no sharp
    corner to find), arms 0.2-0.45 of the spine."""
    rng = random.Random(f"swept-round-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.2, 0.45))
    tilts = (rng.uniform(14, 31), rng.uniform(14, 31))
    radii = (rng.uniform(0.4, 0.8) * a1, rng.uniform(0.4, 0.8) * a2)
    pts = _bracket(_verts(h, a1, a2, *tilts), radii, (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("swept-round-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def splayed_trapezoid_bracket(seed: int) -> Mark:
    """A bracket whose arms both lean out 15-30 degrees (a trapezoid without its fourth side; the heading turns
    120-150 degrees), arms 0.2-0.45 of the spine; corners sharp or rounded over up to 0.3 of the arm."""
    rng = random.Random(f"splayed-trapezoid-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.2, 0.45))
    tilts = (-rng.uniform(15, 30), -rng.uniform(15, 30))
    pts = _bracket(_verts(h, a1, a2, *tilts), _corner_radii(rng, a1, a2, 0.3), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("splayed-trapezoid-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def whole_arm_rounded_bracket(seed: int) -> Mark:
    """A bracket whose corners a mouse rounds over 0.85-1.0 of each arm (no straight piece of arm left, only a bend
    into the spine: pixelfac/user01's left brackets 5 and 10), arms 0.2-0.4 of a straight spine (bowed up to 2 %),
    each bend reaching as far down the spine as along its arm."""
    rng = random.Random(f"whole-arm-rounded-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.2, 0.4))
    radii = (rng.uniform(0.85, 1.0) * a1, rng.uniform(0.85, 1.0) * a2)
    pts = _bracket(_verts(h, a1, a2), radii, (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("whole-arm-rounded-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def tiny_bracket(seed: int) -> Mark:
    """A tiny bracket, 18-40 px tall (text-sized beside a formula, a finger on a phone), arms 0.3-0.5 of the spine;
    corners sharp or rounded over up to 0.3 of the arm: a pixel of the pen's tremor is a tenth of an arm."""
    return sized_bracket("tiny-bracket", seed, (18, 40), (0.3, 0.5))


def kinked_spine_bracket(seed: int) -> Mark:
    """A bracket whose spine kinks once, 8-20 degrees, at 0.3-0.7 of its length (the hand re-grips mid-stroke, its
    two pieces each straight), arms 0.2-0.45 of the spine; corners sharp or rounded over up to 0.25 of the arm."""
    rng = random.Random(f"kinked-spine-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.2, 0.45))
    e0, c1, c2, e3 = _verts(h, a1, a2)
    at = rng.uniform(0.3, 0.7)
    kink = math.radians(rng.uniform(8, 20)) / 2 * rng.choice((-1.0, 1.0))
    # the kink point stands off the straight spine so each piece turns half the kink from the straight line
    off = math.tan(kink) * min(at, 1 - at) * h
    c1k, c2k = (c1[0], c1[1]), (c2[0], c2[1])
    mid = (off, c1[1] + at * h)
    radii = _corner_radii(rng, a1, a2, 0.25)
    top = _bracket([e0, c1k, mid, mid], (radii[0], 0.0), (0.0, 0.0, 0.0))
    bottom = _bracket([mid, mid, c2k, e3], (0.0, radii[1]), (0.0, 0.0, 0.0))
    pts: list[Point] = [p for p in top if p != mid] + [mid] + [p for p in bottom[1:] if p != mid]
    return Mark("kinked-spine-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def lopsided_arm_bracket(seed: int) -> Mark:
    """A bracket with arms of very unequal length: the long one 0.3-0.6 of the spine, the short one 0.2-0.45 of the
    long one (at least 14 px), either drawn first; corners sharp or rounded over up to 0.25 of the arm."""
    rng = random.Random(f"lopsided-arm-bracket:{seed}")
    h = rng.uniform(120, 320)
    long_arm = rng.uniform(0.3, 0.6) * h
    short = max(14.0, rng.uniform(0.2, 0.45) * long_arm)
    a1, a2 = (long_arm, short) if rng.random() < 0.5 else (short, long_arm)
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.25), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("lopsided-arm-bracket", _placed(rng, pts, rng.random() < 0.5), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "swept-past-bracket": swept_past_bracket, "swept-round-bracket": swept_round_bracket,
    "splayed-trapezoid-bracket": splayed_trapezoid_bracket,
    "whole-arm-rounded-bracket": whole_arm_rounded_bracket, "tiny-bracket": tiny_bracket,
    "kinked-spine-bracket": kinked_spine_bracket, "lopsided-arm-bracket": lopsided_arm_bracket}
