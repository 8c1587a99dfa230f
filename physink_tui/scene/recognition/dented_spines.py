"""A square bracket whose spine dents or bulges toward its opening about halfway, kept as the rules' bracket; no I/O.

Issue 25: hcira pixelfac/user01's left bracket 5 (its spine bulging toward the opening, its top corner rounded over the
whole arm) and jonathanzhang53/s02's left bracket 1 (its spine dented in, its lower arm flicked back at the lift) are
read by the rules as a bracket's polyline of four vertices, and the learned ranker, which takes the spine's turn back
for a curve's bends, made both curves. `round_brackets.kept_bracket` does not hold them: a spine turning back by more
than `round_brackets.TURN_BACK_DEG` is no `round_brackets.rounded_bracket`. What tells such a spine from a curly
brace's (whose polyline the rules may read alike, and which the ranker rightly re-reads) is which way it turns in its
middle: a brace's point turns with its curls, away from them, flanked by turns back half as sharp; a dent or a bump
toward the opening turns back against the corners, flanked by turns with them half as sharp. A parenthesis or an arc
the rules cut into four vertices turns with its corners all along its middle.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

VERTEX_BEND = (30.0, 150.0)
"""Only a polyline whose two inner vertices turn the same way, each by this much (degrees; as
`round_brackets.VERTEX_BEND`), is looked at."""
JUDGED_POINTS = 128
"""The stroke is judged resampled to this many points, smoothed, its end hooks cut (a flick at the lift, as
`recognize` judges an open stroke)."""
ARM_SHARE = 0.12
"""Each arm, from its end to its corner along the stroke, holds at least this share of the path (the spine, between
the corners, the most): a brace's curl, which the rules may take for an arm, holds 8-10 % of it
(`tests/penmodels/brace_habits`' flat-pointed braces through a mouse; hat359/user2's right braces), a bracket's arm
with its bend 13 % and more (as `round_brackets.SPLAYED_ARM_SHARE`: a curl is no arm)."""
SPINE_OVER_ARM = 1.3
"""...and the spine is at least this many times as long as the longer arm along the stroke: a square bracket's spine
is its long side (the pen models' dented, bumped and jogged brackets 1.69 times their longer arm and more, people's
kept brackets 1.57 and 1.61), while a brace the rules cut at its point and at one curl makes one of its halves the
"spine" and the other the "arm", about as long (`tests/penmodels/brace_habits`' wide chevrons through the mouse and
the tiny mouse, 0.8-1.12 on tuning seeds)."""
MIDDLE_CUT = 0.2
"""The spine's middle is judged without this share of it at each end (its bends into the arms)."""
DENT_DEG = (10.0, 90.0)
"""The spine's middle turns back against the corners, within `stroke_geometry.POINT_SPAN` of the path, by this much
(degrees: a dent or a bulge toward the opening; a right angle and more is a Sigma's point, not a spine's dent)..."""
C_BOW_DEG = 10.0
"""...and, in all, by no more than this the way the corners turn (a parenthesis' or an arc's middle turns with its
ends all along)."""


def vertex_turns(points: tuple[tuple[float, float], ...]) -> np.ndarray:
    """The turn at each inner vertex of a polyline (degrees, signed: positive clockwise on a y-down screen)."""
    v = np.diff(np.asarray(points, dtype=float), axis=0)
    cross, dot = v[:-1, 0] * v[1:, 1] - v[:-1, 1] * v[1:, 0], (v[:-1] * v[1:]).sum(axis=1)
    turns: np.ndarray = np.degrees(np.arctan2(cross, dot))
    return turns


def _span_turns(run: np.ndarray, span: float) -> tuple[float, float]:
    """The most ``run`` (points equally spaced) turns within any stretch ``span`` long along it, each way: the largest
    positive net turn and the largest negative one (degrees, both given as they are signed)."""
    step = sg.path_length(run) / (len(run) - 1)
    w = max(1, round(span / step)) if step > 0 else 1
    done = np.concatenate([[0.0], np.add.accumulate(np.degrees(sg.turning(run)))])
    moved = done[w:] - done[:-w] if w < len(done) else done[-1:] - done[:1]
    return float(moved.max()), float(moved.min())


def kept_bracket(found: Recognition, unit: np.ndarray, noise: float, views: StrokeViews | None = None,
                 placed: tuple[np.ndarray, float] | None = None) -> bool:
    """Whether the rules read a square bracket of four vertices whose spine (the polyline's middle side, the longest of
    the three along the stroke) dents or bulges toward the opening halfway (`DENT_DEG`, not a brace's point nor a
    parenthesis' bow, `C_BOW_DEG`): not asked of the learned ranker (`recognize`). ``unit``: the stroke's points at
    unit size, ``noise`` the pen's in those units; ``views``: its `stroke_views.StrokeViews`, where made; ``placed``:
    the ``origin`` and ``scale`` that took the stroke to ``unit`` (the polyline is in the stroke's own units), None
    where the polyline is at unit size already."""
    if found.kind != "polyline" or not isinstance(found.geometry, Polyline) or len(found.geometry.points) != 4:
        return False
    turns = vertex_turns(found.geometry.points)
    if not (turns[0] * turns[1] > 0 and all(VERTEX_BEND[0] <= abs(t) <= VERTEX_BEND[1] for t in turns)):
        return False  # no bracket's two bends (an N, a zig-zag)
    vertices = np.asarray(found.geometry.points, dtype=float)
    if placed is not None:
        vertices = (vertices - placed[0]) / placed[1]
    views = StrokeViews(unit) if views is None else views
    work = views.hooks_cut(JUDGED_POINTS)
    at = sorted(int(np.argmin(np.hypot(*(work - v).T))) for v in vertices[1:3])
    steps = np.hypot(*np.diff(work, axis=0).T)
    sides = (steps[:at[0]].sum(), steps[at[0]:at[1]].sum(), steps[at[1]:].sum())
    if sides[1] < SPINE_OVER_ARM * max(sides[0], sides[2]) or min(sides[0], sides[2]) < ARM_SHARE * sum(sides):
        return False  # a brace the rules cut at its point (its halves as long as each other), or at its curls
    spine = work[at[0]:at[1] + 1]
    cut = round(MIDDLE_CUT * len(spine))
    middle = spine[cut:len(spine) - cut]
    if len(middle) < 3:
        return False
    way = math.copysign(1.0, float(turns[0]))
    most, least = _span_turns(middle, sg.POINT_SPAN * sg.path_length(work))
    along, back = (most, -least) if way > 0 else (-least, most)
    bow = way * float(np.degrees(sg.turning(middle).sum()))
    return DENT_DEG[0] <= back <= DENT_DEG[1] and back > along and bow <= C_BOW_DEG
