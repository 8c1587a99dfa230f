"""A curly brace drawn as straight runs between cusps (a mouse's, a hurried hand's) read as a brace, a curve; no I/O.

Issue 25: "curly braces ... as polylines". Drawn with a mouse, a brace is straight runs and cusps: a short run for each
end's curl, a long run for each arm, two short runs out to its point and back. The corner finder finds every cusp and
every run is straight, so the open-stroke rules read a polyline unless the point is a short excursion
(`open_shapes.BRACE_TIP`) or sticks out little (`bracket_marks.BRACE_DEPTH`); a mouse's point often sticks out as far
as the curls and is drawn with long runs. What a reader sees is the brace's layout against the line joining its ends:
the stroke runs along that line on one side of it, its arms parallel to it, standing off it by the curls, and its
point, about halfway, sticks out past the arms. A v, a caret or a check has arms slanting from the line to the point; a
square bracket's spine runs parallel but no point sticks out of it; a zig-zag crosses the line or runs back along it.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

POINT_AT = (0.3, 0.7)
"""The point (the stroke's farthest from the line joining its ends) lies this far along the path (shares of it)."""
MAX_DEPTH = 0.75
"""It sticks out from that line by less than this share of the line (a brace is long and thin: its curls and point
stand out 0.1-0.6 of its length)."""
ONE_SIDE = 0.05
"""The stroke strays to the other side of the line by less than this share of it (its curls and point on one side)."""
NO_RETURN = 0.15
"""... and runs back along it by less than this share of it (a mouse's cusps run back a little; an arrow's barbs,
a zig-zag's teeth more)."""
ARM_DEG = 25.0
"""Each arm (between 35 % and 80 % of the way from its end to the point) runs within this many degrees of the line's
direction (a v's or caret's arms slant 30 degrees and more to reach a point half their length out)."""
ARM_INK = 1.3
"""... with at most this much ink for its chord: an arm runs on, bent at most where a curl or the point's run joins it
(a bend of 60 degrees takes 1.15); a zig-zag's teeth between a lead-in and a tail make a layout like a brace's, their
ink twice their chord and more."""
PAST_ARMS = 1.3
"""The point stands this many times as far from the line as the arms do, or farther (a bracket's spine has no point)."""
ARM_OFF = 0.08
"""The arms stand off the line by at least this share of its length: the curls carry them off it."""


def arm_heading_ok(piece: np.ndarray, direction: np.ndarray) -> bool:
    """Whether ``piece`` (a run of the stroke) heads within `ARM_DEG` of ``direction`` (a unit vector)."""
    d = piece[-1] - piece[0]
    norm = float(np.hypot(*d))
    return norm > 0 and float(d @ direction) >= math.cos(math.radians(ARM_DEG)) * norm


POINT_LOBE_DEG = 20.0
"""A brace laid out as one (`laid_out`) turns both ways if a run of its turning the other way from the rest reaches
this many degrees (`stroke_features.lobes` ignores runs under 35 degrees: a wobble). A device's few events sample the
point by one or two, and the stroke then turns out towards it by only 20-35 degrees before turning back (the design
braces by 8-25 events evenly in time, `bench_device_stress`); a parenthesis or an arc laid out so turns one way."""


def point_lobes(work: np.ndarray, noise: float, coarse: np.ndarray | None = None) -> list[float]:
    """`stroke_features.lobes` of ``work`` down to `POINT_LOBE_DEG`; ``coarse``: its `shape_turning.coarse_turning`
    at ``noise``, where already known (the same lobes, not measured again)."""
    if coarse is None:
        return sf.lobes(work, POINT_LOBE_DEG, noise=noise)
    return sf.turn_lobes(coarse, POINT_LOBE_DEG)


def angular_brace(work: np.ndarray, lobes: list[float], noise: float = 0.0, coarse: np.ndarray | None = None) -> bool:
    """Whether the open stroke ``work`` (resampled, hooks cut, as `open_shapes.classify_open` judges it; ``lobes``
    its `stroke_features.lobes`) is a curly brace by its layout: on one side of the line joining its ends
    (`ONE_SIDE`) and running along it (`NO_RETURN`), its point about halfway (`POINT_AT`) standing out less than
    `MAX_DEPTH` of it and `PAST_ARMS` as far as the arms, which run on (`ARM_INK`), parallel to it
    (`ARM_DEG`) and off it (`ARM_OFF`) -- or so against its arms' own line where it was drawn askew (`laid_out`) --
    and turning both ways (two lobes or more: its curls the other way from its point; `POINT_LOBE_DEG` where the
    point was sampled by few events); ``noise``: the pen's, in ``work``'s units; ``coarse``: its
    `shape_turning.coarse_turning` at that noise, where already known."""
    if len(lobes) < 2 and len(point_lobes(work, noise, coarse)) < 2:
        return False  # turning both ways first: most open strokes turn one way, and the layout costs more
    return laid_out(work, noise)


def laid_out(work: np.ndarray, noise: float = 0.0) -> bool:
    """Whether ``work`` is laid out as a brace (`angular_brace`, but for its turning both ways): against the line
    joining its ends (`_chord_layout`) or, where a hand drew the brace askew, against its arms' own line
    (`_arms_layout`; ``noise``, the pen's in ``work``'s units, as it takes it)."""
    return _chord_layout(work) or _arms_layout(work, noise)


def chord_frame(work: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """The line joining ``work``'s ends: its length, its unit vector and each point's signed distance across it; None
    for a stroke too short to judge as a brace or one that ends where it began."""
    if len(work) < 16:
        return None
    start, end = work[0], work[-1]
    chord = float(np.hypot(*(end - start)))
    if chord == 0.0:
        return None
    unit = (end - start) / chord
    rel = work - start
    return chord, unit, rel[:, 0] * unit[1] - rel[:, 1] * unit[0]


def _chord_layout(work: np.ndarray) -> bool:
    """Whether ``work`` is laid out as a brace against the line joining its ends (`angular_brace`)."""
    frame = chord_frame(work)
    if frame is None:
        return False
    chord, unit, across = frame
    start = work[0]
    rel = work - start
    k = int(np.abs(across).argmax())
    depth = float(across[k])
    sign = math.copysign(1.0, depth)
    if abs(depth) >= MAX_DEPTH * chord or float(np.max(-sign * across)) > ONE_SIDE * chord:
        return False
    along = rel @ unit
    if float(np.max(np.maximum.accumulate(along) - along)) >= NO_RETURN * chord:
        return False
    cum = sg.along(work)
    length = float(cum[-1])
    at = float(cum[k])
    if not POINT_AT[0] * length <= at <= POINT_AT[1] * length:
        return False
    arms = (work[(cum >= 0.35 * at) & (cum <= 0.8 * at)],
            work[(cum >= at + 0.2 * (length - at)) & (cum <= at + 0.65 * (length - at))])
    if any(len(arm) < 3 or not arm_heading_ok(arm, unit)
           or sg.path_length(arm) > ARM_INK * float(np.hypot(*(arm[-1] - arm[0]))) for arm in arms):
        return False
    stand = [float(sg.median(sign * (arm[:, 0] - start[0]) * unit[1] - sign * (arm[:, 1] - start[1]) * unit[0]))
             for arm in arms]
    return min(stand) >= ARM_OFF * chord and abs(depth) >= PAST_ARMS * max(stand)


POINT_OUT = 0.08
"""`_arms_layout`: the point stands out from the arms' line by at least this share of the arms' span..."""
POINT_NOISE = 3.0
"""...and by at least this many of the pen's noise widths (a straight line's wobble reaches about three,
`lines.wobble_reach`: a square bracket's spine in whole pixels jogs a pixel or two, which the arms' line, the spine's
own, would take for a point)..."""
PAST_POINT = 1.05
"""...nothing of the stroke stands out farther than this many times the point does (a curl swung wider is a
question mark's hook or an S's bend)..."""
ENDS_BEHIND = 0.25
"""...and each end stands out on the point's side by at most this share of the point's depth: the curls turn the ends
back behind the arms, away from the point."""


def _arms_layout(work: np.ndarray, noise: float = 0.0) -> bool:
    """Whether ``work`` is laid out as a brace against its arms' line, not its chord: a hand that curls one end wider
    than the other, or draws the brace askew, tilts the chord against the arms (hcira's mouse braces: the farthest
    point from the chord is then a curl, an arm heads 35-75 degrees off it), but the arms still run on in line with
    each other. The point is the farthest from the chord within `POINT_AT` of the path; the arms' line joins the
    middles of the runs before and after it (as `_chord_layout` takes them), which head along it (`ARM_DEG`) and run on
    (`ARM_INK`); the point stands out of that line (`POINT_OUT`, `POINT_NOISE` times the pen's ``noise``; under
    `MAX_DEPTH` of the span) farther than anything
    else (`PAST_POINT`), the ends curl back behind it (`ENDS_BEHIND`), and the stroke runs along it (`NO_RETURN`)."""
    frame = chord_frame(work)
    if frame is None:
        return False
    across = frame[2]
    cum = sg.along(work)
    length = float(cum[-1])
    middle = np.flatnonzero((cum >= POINT_AT[0] * length) & (cum <= POINT_AT[1] * length))
    if len(middle) == 0:
        return False
    k = int(middle[np.abs(across[middle]).argmax()])
    at = float(cum[k])
    arms = (work[(cum >= 0.35 * at) & (cum <= 0.8 * at)],
            work[(cum >= at + 0.2 * (length - at)) & (cum <= at + 0.65 * (length - at))])
    if any(len(arm) < 3 for arm in arms):
        return False
    first, last = arms[0].mean(axis=0), arms[1].mean(axis=0)
    span = float(np.hypot(*(last - first)))
    if span == 0.0:
        return False
    along_arms = (last - first) / span
    if any(not arm_heading_ok(arm, along_arms)
           or sg.path_length(arm) > ARM_INK * float(np.hypot(*(arm[-1] - arm[0]))) for arm in arms):
        return False
    off = (work - first) @ np.array([along_arms[1], -along_arms[0]])
    depth = float(off[k])
    out = math.copysign(1.0, depth) * off
    if (not max(POINT_OUT * span, POINT_NOISE * noise) <= abs(depth) < MAX_DEPTH * span
            or float(out.max()) > PAST_POINT * abs(depth)):
        return False
    if max(float(out[0]), float(out[-1])) > ENDS_BEHIND * abs(depth):
        return False
    along = (work - first) @ along_arms
    return float(np.max(np.maximum.accumulate(along) - along)) < NO_RETURN * span


JUDGED_POINTS = 128
"""`kept_brace` judges the stroke resampled to this many points, smoothed, its end hooks cut (as `recognize` judges an
open stroke)."""


def kept_brace(found: Recognition, unit: np.ndarray, noise: float, views: StrokeViews | None = None) -> bool:
    """Whether the rules read a curve from a stroke (``unit``: its points at unit size, ``noise`` the pen's in those
    units) that is an `angular_brace`: not asked of the learned ranker (`recognize`), whose features see a mouse's
    brace as straight runs and sharp corners, a polyline's. ``views``: the stroke's `stroke_views.StrokeViews`,
    where made."""
    if found.kind != "curve":
        return False
    views = StrokeViews(unit) if views is None else views
    work = views.hooks_cut(JUDGED_POINTS)
    # the layout first: the lobes cost more
    return laid_out(work, noise) and len(views.cut_lobes(JUDGED_POINTS, noise)) >= 2
