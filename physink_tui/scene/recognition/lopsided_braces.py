"""A lopsided curly brace whose short half runs straight from its point to its end read as a brace; no I/O.

Issue 25: curly braces read as polylines. Some hands draw a brace's long half as a bracket's (an end arm turned at a
square corner onto a straight spine) and its short half as one straight slant from the point back to the end, with no
curl (itt GixD42's and hcira pixelfac/user01's right braces): the point lies 0.6-0.9 of the way along, the two halves
are nothing alike, and the rules for braces (`bracket_marks.brace_point`: halves alike; `angular_braces`: both arms
parallel to the line joining the ends) pass it by. What a reader sees is still a brace's layout against the line
joining its ends: the stroke on one side of it, running along it; the long half's spine parallel to it, standing off
it (the end arm carries it off); the point, where the spine bends out, standing well past the spine; the short half
straight. A check's or a v's long arm slants from the line to the point (no spine parallel to it); a square bracket's
spine stands as far out as anything (no point past it); a zig-zag crosses the line or runs back along it.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import angular_braces
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

SHORT_HALF = (0.1, 0.4)
"""The short half, from the point (the stroke's farthest from the line joining its ends) to its end, is this share of
the path (a brace's halves alike are about half each: `angular_braces`, `bracket_marks.brace_point`)."""
SHORT_STRAIGHT = 0.12
"""The short half beyond its first fifth (the point's rounding) strays from its chord by less than this share of it
(`bracket_marks.BRACKET_STRAIGHT`): a slant, no curl."""
SPINE = (0.2, 0.8)
"""The long half's spine is the piece this far along it from its end towards the point (shares of the half's path),
past the end arm and short of the bend out to the point."""
SPINE_OFF = angular_braces.ARM_OFF / 2
"""The spine stays off the line joining the ends all along, by at least this share of it (half what it stands off
at its median, `angular_braces.ARM_OFF`): a zig-zag's spine comes back to the line between its teeth."""
END_OFF = 0.08
"""The long half's end stands off the spine's line by at least this share of the line joining the ends (its end arm;
as `angular_braces.ARM_OFF`)."""
POINT_PAST = 0.05
"""The point stands past the spine's line, away from the long half's end, by at least this share of that line."""
SHORT_SLANT_DEG = (15.0, 90.0 - angular_braces.ARM_DEG)
"""The short half heads this many degrees off the line joining the ends: it slants back from the point (a brace's arm
running along the line is `angular_braces`' case), less than square to the spine (which runs within
`angular_braces.ARM_DEG` of the line): a square bracket's arm turns off the spine at a right angle."""


def lopsided_brace(work: np.ndarray, lobes: list[float], noise: float = 0.0, coarse: np.ndarray | None = None,
                   ) -> bool:
    """Whether the open stroke ``work`` (resampled, hooks cut, as `open_shapes.classify_open` judges it; ``lobes`` its
    `stroke_features.lobes`) is a lopsided brace with a straight short half, by its layout (`laid_out`) and turning
    both ways (two lobes or more; `angular_braces.POINT_LOBE_DEG` where few events sampled the point); ``noise``: the
    pen's, in ``work``'s units; ``coarse``: its `shape_turning.coarse_turning` at that noise, where already known."""
    if len(lobes) < 2 and len(angular_braces.point_lobes(work, noise, coarse)) < 2:
        return False
    return laid_out(work)


def laid_out(work: np.ndarray) -> bool:
    """Whether ``work`` is laid out as a lopsided brace against the line joining its ends: on one side of it
    (`angular_braces.ONE_SIDE`) and running along it (`angular_braces.NO_RETURN`); its point (the farthest from it,
    under `angular_braces.MAX_DEPTH` of it) ends a long half holding a spine parallel to the line
    (`angular_braces.ARM_DEG`, `angular_braces.ARM_INK`), standing off it (`angular_braces.ARM_OFF`) and standing
    `angular_braces.PAST_ARMS` times less far out than the point; the short half (`SHORT_HALF`) straight
    (`SHORT_STRAIGHT`), slanting back to its end (`SHORT_SLANT_DEG`). The same whichever end it was drawn from."""
    frame = angular_braces.chord_frame(work)
    if frame is None:
        return False
    chord, unit, across = frame
    k = int(np.abs(across).argmax())
    depth = float(across[k])
    sign = math.copysign(1.0, depth)
    if (abs(depth) >= angular_braces.MAX_DEPTH * chord
            or float(np.max(-sign * across)) > angular_braces.ONE_SIDE * chord):
        return False
    along = (work - work[0]) @ unit
    if float(np.max(np.maximum.accumulate(along) - along)) >= angular_braces.NO_RETURN * chord:
        return False
    cum = sg.along(work)
    length = float(cum[-1])
    at = float(cum[k])
    long_first = 2 * at >= length
    short_len = length - at if long_first else at
    if not SHORT_HALF[0] * length <= short_len <= SHORT_HALF[1] * length:
        return False
    # each half from its end towards the point
    from_end = cum if long_first else length - cum
    long_len = length - short_len
    on_spine = (from_end >= SPINE[0] * long_len) & (from_end <= SPINE[1] * long_len)
    spine = work[on_spine]  # in drawing order
    short = work[k:] if long_first else work[:k + 1][::-1]  # from the point to its end
    short = short[len(short) // 5:]
    if len(spine) < 3 or len(short) < 3:
        return False
    if (not angular_braces.arm_heading_ok(spine, unit)
            or sg.path_length(spine) > angular_braces.ARM_INK * float(np.hypot(*(spine[-1] - spine[0])))):
        return False
    if sg.chord_deviation(short) >= SHORT_STRAIGHT:
        return False
    d = short[-1] - short[0]
    slant = math.degrees(math.acos(max(-1.0, min(1.0, abs(float(d @ unit)) / max(float(np.hypot(*d)), 1e-12)))))
    if not SHORT_SLANT_DEG[0] <= slant <= SHORT_SLANT_DEG[1]:
        return False
    off_line = sign * across[on_spine]
    stand = sg.median(off_line)
    if (stand < angular_braces.ARM_OFF * chord or float(off_line.min()) < SPINE_OFF * chord
            or abs(depth) < angular_braces.PAST_ARMS * stand):
        return False
    # against the spine's own line: the long half's end is carried off it by its end arm (a check's long arm runs on
    # straight to its end), and the point stands out past it (a bracket's spine runs straight into its corner)
    way = spine[-1] - spine[0]
    normal = np.array([way[1], -way[0]]) / max(float(np.hypot(*way)), 1e-12)
    centre = spine.mean(axis=0)
    long_end = work[0] if long_first else work[-1]
    end_off = float((long_end - centre) @ normal)
    past = -math.copysign(1.0, end_off) * float((work[k] - centre) @ normal)
    return abs(end_off) >= END_OFF * chord and past >= POINT_PAST * chord


def kept_brace(found: Recognition, unit: np.ndarray, noise: float, views: StrokeViews | None = None) -> bool:
    """Whether the rules read a curve from a stroke (``unit``: its points at unit size, ``noise`` the pen's in those
    units) laid out as a lopsided brace (`laid_out`, judged as `angular_braces.kept_brace` judges its own): not asked of
    the learned ranker (`recognize`), which sees its square corner and straight runs as a polyline's. ``views``: the
    stroke's `stroke_views.StrokeViews`, where made."""
    if found.kind != "curve" or not _roughly_lopsided(unit):
        return False
    views = StrokeViews(unit) if views is None else views
    work = views.hooks_cut(angular_braces.JUDGED_POINTS)
    # the layout first: the lobes cost more
    return laid_out(work) and len(views.cut_lobes(angular_braces.JUDGED_POINTS, noise)) >= 2


def _roughly_lopsided(pts: np.ndarray) -> bool:
    """A cheap first look at the points as given (unevenly spaced, hooks and all), before they are resampled: the
    farthest from the line joining the ends leaves a short half of at most twice `SHORT_HALF`'s upper share of the
    path, at least half its lower, and nothing strays across that line by more than twice `angular_braces.ONE_SIDE`
    (a hook where the pen landed may)."""
    if len(pts) < 3:
        return False
    chord = float(np.hypot(*(pts[-1] - pts[0])))
    if chord == 0.0:
        return False
    unit = (pts[-1] - pts[0]) / chord
    rel = pts - pts[0]
    across = rel[:, 0] * unit[1] - rel[:, 1] * unit[0]
    k = int(np.abs(across).argmax())
    if float(np.max(-math.copysign(1.0, float(across[k])) * across)) > 2 * angular_braces.ONE_SIDE * chord:
        return False
    steps = sg.step_lengths(pts)
    length = float(steps.sum())
    short = min(float(steps[:k].sum()), length - float(steps[:k].sum()))
    return SHORT_HALF[0] / 2 * length <= short <= min(0.5, 2 * SHORT_HALF[1]) * length
