"""A tick whose short arm is no longer than a hook's share of the stroke, but longer than a hook is; no I/O.

Issue 25: the open-stroke rules cut a hook at either end of up to a tenth of the path (`stroke_geometry.remove_hooks`,
whatever its size), keeping it only as a tick's arm when it is `stroke_geometry.ARM_SHARE` of the path or more. A tick
drawn fast with a mouse (ahmadosama's Ticks) often has a first arm of 4-6 % of the path: cut as a hook, what is left is
a long arm the hand bowed a little, read as a curve. A hook where the pen lands or lifts is a few noise widths long
whatever the stroke's size (`lines.HOOK_REACH`); a piece at an end several times longer, straight, standing off the
rest at an arm's angle, is the tick's short arm, and the stroke a polyline of two sides when the rest is a straight
side (`open_shapes.straight`) with no point along it and the whole turns one way (`hooked_tick`).
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import lines, open_shapes, shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

READ_AS = frozenset({"curve", "arc", "polyline"})
"""The rules' readings this test is asked of: a curve or an arc (the long arm's bow), or a polyline, which the learned
ranker is then not asked of (it takes such a tick for a curve)."""
POINTS = 128
"""The stroke is judged on this many points along its path, lightly smoothed."""
END_SHARE = 0.1
"""The short arm is looked for within this share of the path from either end: what `stroke_geometry.remove_hooks`
would cut as a hook (its ``max_fraction``)."""
ARM_REACH = 1.5 * lines.HOOK_REACH
"""The short arm is at least this many of the pen's noise widths long: half as long again as a hook a hand makes
landing or lifting (`lines.HOOK_REACH`: mmg's 596 lines' hooks are 9-10 px at the 99th percentile), so no hook is
taken for an arm."""
CORNER_DEG = 45.0
"""Where the short arm meets the rest, the path turns by this much or more within `REACH` points either side (an arm's
angle, `stroke_geometry.ARM_ANGLE_DEG`'s least), and the arms' chords are at least this far from running on in line."""
REACH = 6
"""A corner's turn is taken between the chords this many points either side of it: half `END_SHARE`'s points, as far
as a hand rounds a short arm into the long one."""


def hooked_tick(unit: np.ndarray, noise: float, views: StrokeViews | None = None) -> Recognition | None:
    """A tick drawn with a short first (or last) arm (``unit``: the stroke at unit size, ``noise``: the pen's jitter in
    those units) as the polyline start, point, end; None when it is not one: the sharpest turn within `END_SHARE` of an
    end turns by `CORNER_DEG` or more, the piece from that end to it is straight (`stroke_geometry.ARM_STRAIGHT`) and
    at least `ARM_REACH` noise widths long, the rest is a straight side (`open_shapes.straight`) with no point in its
    middle (`stroke_geometry.POINT_TURN_DEG`), and the stroke turns one way at the coarse scale (one lobe, or none where
    the short arm is too short to make one: `stroke_features.turn_lobes`), a hook's reach (`lines.HOOK_REACH`) left
    out at each end. ``views``: the stroke's `stroke_views.StrokeViews`, where made."""
    if len(unit) < 3 or not noise > 0:
        return None
    pts = (StrokeViews(unit) if views is None else views).smoothed(POINTS)
    length = sg.path_length(pts)
    if not length > 0:
        return None
    within = int(END_SHARE * (POINTS - 1))
    lobes: list[float] | None = None
    for flip in (False, True):
        ordered = pts[::-1] if flip else pts
        c = _arm_corner(ordered, within, noise)
        if c is None:
            continue
        if lobes is None:  # without a hook where the pen landed or lifted, which turns back against the mark
            along = sg.along(pts)
            cut = lines.HOOK_REACH * noise
            lobes = sf.turn_lobes(shape_turning.coarse_turning(pts[(along >= cut) & (along <= length - cut)], noise))
        if len(lobes) <= 1 and _tick(ordered[:c + 1], ordered[c:], noise, length):
            at = len(pts) - 1 - c if flip else c
            points = tuple((float(p[0]), float(p[1])) for p in (pts[0], pts[at], pts[-1]))
            return Recognition("polyline", 0.7, Polyline(points), (("curve", 0.3),))
    return None


def _arm_corner(pts: np.ndarray, within: int, noise: float) -> int | None:
    """The point, within ``within`` points of the start and at least `ARM_REACH` noise widths along the path, where
    the path turns most between the chords `REACH` points either side of it (on the arm's side, from the start at
    most: a hook where the pen landed bends the arm's chord by less than it turns), when that is `CORNER_DEG` or
    more."""
    steps = sg.along(pts[:within + REACH + 1])
    best, best_turn = None, CORNER_DEG
    for c in _may_turn(pts, within):
        if steps[c] < ARM_REACH * noise:
            continue
        turned = sg.angle_deg(pts[c] - pts[max(0, c - REACH)], pts[c + REACH] - pts[c])
        if turned is None:
            continue
        if turned >= best_turn:
            best, best_turn = c, turned
    return best


FIRST_LOOK_SLACK = 1e-6
"""`_may_turn` keeps a point whose chords' cosine is up to this much over `CORNER_DEG`'s: far more than the rounding by
which its arithmetic, done for all points at once, may differ from `_arm_corner`'s own, one point at a time."""


def _may_turn(pts: np.ndarray, within: int) -> list[int]:
    """The points from 1 to ``within`` where the path may turn by `CORNER_DEG` between the chords `REACH` points either
    side (as `_arm_corner` measures it), in order: a first look at all of them at once, with room to spare
    (`FIRST_LOOK_SLACK`), so that `_arm_corner` measures only these, and finds what it would find measuring all."""
    c = np.arange(1, within + 1)
    u, v = pts[c] - pts[np.maximum(c - REACH, 0)], pts[c + REACH] - pts[c]
    norms = np.hypot(u[:, 0], u[:, 1]) * np.hypot(v[:, 0], v[:, 1])
    dots = u[:, 0] * v[:, 0] + u[:, 1] * v[:, 1]
    may: list[int] = c[dots <= (math.cos(math.radians(CORNER_DEG)) + FIRST_LOOK_SLACK) * norms].tolist()
    return may


def _tick(arm: np.ndarray, rest: np.ndarray, noise: float, length: float) -> bool:
    """Whether ``arm`` (from the stroke's end to the corner) is a straight short arm (once a hook where the pen landed,
    `lines.HOOK_REACH` noise widths at most, is left out of it, half the arm at most) and ``rest`` (on from the corner)
    a straight side with no point, their chords (the arm's without the hook) not in line: a hook and the first few
    noise widths of a line are no arm, their chord running on along the line."""
    along = sg.along(arm)
    core = arm[along >= min(lines.HOOK_REACH * noise, along[-1] / 2)]  # without a hook where the pen landed
    if len(core) > 2 and sg.chord_deviation(core) >= sg.ARM_STRAIGHT:
        return False
    if not open_shapes.straight(rest, noise):
        return False
    middle = rest[len(rest) // 5: len(rest) - len(rest) // 5]
    if sg.sharpest_turn(middle, sg.POINT_SPAN * length) >= sg.POINT_TURN_DEG:
        return False
    u, v = core[-1] - core[0], rest[-1] - rest[0]  # the arm's own heading, not a hook's
    norms = float(np.hypot(*u) * np.hypot(*v))
    return norms > 0.0 and float(u @ v) <= math.cos(math.radians(CORNER_DEG)) * norms  # not a bend in a line
