"""A square bracket whose corners a hand rounded off, both of them, read as the bracket (three straight sides); no I/O.

Issue 25: "square brackets as curves". A hand in a hurry, or a mouse, swings round a bracket's corners instead of
stopping at them; with both corners rounded the corner finder finds none (or finds them too round), and the open-stroke
rules read a curve (`bracket_marks.rounded_bracket_corners` covers one corner rounded and one sharp). What a reader
sees is what makes a bracket: a long straight spine, a straight arm at each end, each joined to the spine by a bend of
about a right angle, the same way round (a half turn in all). Judged on the stroke's headings: the spine is its
longest run of nearly one heading (`FLAT_DEG`), the arms its runs of nearly one heading at each end. An arc or a
parenthesis turns evenly (no long run of one heading); a question mark's hook turns by far more than a right angle
before its stem; a brace turns both ways; a U's round bottom is one bend of a half turn, not two of a right angle.
"""

from __future__ import annotations

import collections
import itertools
import math
import statistics

import numpy as np

from physink_tui.scene.recognition import shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

POINTS = 64
"""The stroke is judged resampled to this many points, lightly smoothed (`stroke_geometry.smooth`)."""
HALF_TURN = (145.0, 245.0)
"""A bracket's heading turns by half a turn from its first arm to its last (degrees; as `bracket_marks.HALF_TURN_SLACK`:
a hand slants its arms; up to 245 where a hand swinging round both corners carries each arm on 14-31 degrees in past
square, 207-243 in all, session 24's `tests/penmodels/bracket_extremes`: each bend still turns `BEND_DEG`)."""
SPLAYED_TURN = 120.0
"""...or by as little as this when a wrist swinging a mouse splays its arms out (8-20 degrees each: such a bracket turns
140-164 degrees, measured on the smoothed stroke 120-145; session 22's `tests/penmodels/mouse_habits` splayed
brackets), if its arms are long and its spine straight (`SPLAYED_ARM_SHARE`, `SPLAYED_SPINE_BOW`)..."""
SPLAYED_ARM_SHARE = 0.1
"""...each arm's straight run at least this share of the path (a brace's curls turning as little hold 5-9 % of it, a
splayed bracket's arms 13 % and more: a curl is no arm)..."""
SPLAYED_SPINE_BOW = 0.055
"""...and the spine bowing less than this share of its chord (`stroke_geometry.chord_deviation`: a parenthesis whose end
the pen flicked off straight bows 0.057-0.06 there, a splayed bracket's spine 0.02-0.05)."""
FLAT_DEG = 30.0
"""A straight run's headings all lie within this many degrees of each other (a side's wobble; an arc of 30 degrees)."""
SPINE_SHARE = 0.3
"""The spine, the stroke's longest straight run, holds at least this share of the path (a semicircle's longest run of
`FLAT_DEG` holds a sixth of it; a bracket's spine, its arms up to half of it, its corners rounded, over 0.4)."""
BEND_DEG = (50.0, 130.0)
"""Each bend, from an arm's heading to the spine's, turns by about a right angle (a question mark's hook turns 150
degrees and more before its stem)."""
ARM_FLAT = 0.4
"""Each arm keeps a straight run of at least this share of the arm (the run, plus the bend up to the spine)..."""
ROUND_ARM_FLAT = 0.25
"""...or of this share, when the spine is straight to its middle: a corner rounded over the whole arm, as a mouse
swings round it (a quarter round's last third lies within `FLAT_DEG`), keeps no more, and its spine has no point
(`ROUND_ARM_POINT_DEG`) nor bows as much as a parenthesis (`SPLAYED_SPINE_BOW`), and each arm with its bend is
shorter than the spine (a brace's half, point and curl taken for an arm by a device's few events is longer), and it
turns a full `HALF_TURN` (a small parenthesis through a coarse device's few straight pieces turns 135)..."""
ROUND_ARM_POINT_DEG = 6.0
"""...its spine's middle three fifths turning by less than this within `stroke_geometry.POINT_SPAN` (degrees: such
brackets' spines 1-6 by the hurried hand, a flat-pointed brace's rounded point 5-19, `tests/penmodels/brace_habits`)."""
ARM_SHARE = 0.04
"""... and that run is at least this share of the path (a hook where the pen landed is no arm)."""
MARGIN = 0.05
"""A corner is put where the arm's and the spine's lines meet, unless that lies farther than this share of the
diagonal outside the stroke's bounds (arms nearly parallel to the spine); then at the bend's middle."""
HOOK_SEGMENTS = 4
"""A hook where the pen landed or lifted spans at most this many of the `POINTS` segments at an end (about 6 % of the
path: the hurried hand's 2-5 px hooks, a flick off an arm); the bracket is judged from where its arm begins. The
stroke's own hook cut (`stroke_geometry.remove_hooks`) keeps a hook followed at once by a round corner, as on a
bracket whose short arm runs into a rounded corner."""
TURN_BACK_DEG = 45.0
"""Between its hooks a bracket turns one way: its heading never comes back by more than this (degrees; a hand's wobble
along a side; a brace's point or an S turns back by a right angle and more)."""


def _longest_flats(heading: list[float]) -> list[tuple[int, int]]:
    """The longest runs ``[a, b)`` of segments whose headings lie within `FLAT_DEG` of each other, all of them where
    several are as long, in drawing order (one pass, the window's least and greatest heading kept in two monotone
    queues): the same runs, whichever end the stroke was drawn from."""
    best, a = [(0, 0)], 0
    low: collections.deque[int] = collections.deque()
    high: collections.deque[int] = collections.deque()
    for b, h in enumerate(heading):
        while low and heading[low[-1]] >= h:
            low.pop()
        while high and heading[high[-1]] <= h:
            high.pop()
        low.append(b)
        high.append(b)
        while heading[high[0]] - heading[low[0]] > FLAT_DEG:
            a += 1
            if low[0] < a:
                low.popleft()
            if high[0] < a:
                high.popleft()
        if b + 1 - a > best[0][1] - best[0][0]:
            best = [(a, b + 1)]
        elif b + 1 - a == best[0][1] - best[0][0]:
            best.append((a, b + 1))
    return best


def _flat_end(run: list[float], start: int = 0) -> int:
    """How many of ``run``'s first segments (from ``start``) keep within `FLAT_DEG` of each other."""
    if start >= len(run):
        return 0
    low = high = run[start]
    for k in range(start, len(run)):
        h = run[k]
        low, high = min(low, h), max(high, h)
        if high - low > FLAT_DEG:
            return k - start
    return len(run) - start


def _side(pts: np.ndarray, drawn: np.ndarray, lo: int, hi: int) -> tuple[np.ndarray, np.ndarray]:
    """A straight run's line, from its segments ``[lo, hi)``: through their points' centroid along their median
    heading (``drawn``: each segment's heading, radians; a bend's few segments at its ends do not tilt it)."""
    angle = statistics.median(drawn[lo:hi].tolist())
    return pts[lo:hi + 1].mean(axis=0), np.array([math.cos(angle), math.sin(angle)])


def _hook(heading: list[float]) -> int:
    """How many of ``heading``'s first segments (degrees) are a hook, `HOOK_SEGMENTS` at most: a lead after which the
    run of one heading (`_flat_end`) reaches on past the run from the very end by at least twice the lead's length (a
    hook hides a whole arm; a bend easing into a rounded corner gains little by a skip), the skip after which the run
    reaches farthest."""
    plain = _flat_end(heading)
    best, skip = plain, 0
    for k in range(1, min(HOOK_SEGMENTS, len(heading) - 1) + 1):
        reach = k + _flat_end(heading, k)
        if reach >= plain + 2 * k and reach > best:
            best, skip = reach, k
    return skip


def _half_turn(work: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, int] | None:
    """The stroke resampled (`POINTS`) and smoothed, without a hook at either end (`_hook`), each segment's heading as
    drawn (radians) and from the first, turned the way the stroke turns (degrees), and how many ends had a hook cut,
    when its heading turns by about half a turn (`SPLAYED_TURN` to `HALF_TURN`) from its first arm to its last and
    never back (`TURN_BACK_DEG`); else None."""
    pts = sg.smooth(sg.resample(work, POINTS))
    d = pts[1:] - pts[:-1]  # as np.diff, without its per-call overhead
    drawn = np.unwrap(np.arctan2(d[:, 1], d[:, 0]))
    degrees = np.degrees(drawn)
    # where a hook may end at each end bounds the turn between them: most strokes are no half turn whatever is cut
    first, last = degrees[:HOOK_SEGMENTS + 1], degrees[-HOOK_SEGMENTS - 1:]
    least, most = float(last.min() - first.max()), float(last.max() - first.min())
    if not (most >= SPLAYED_TURN and least <= HALF_TURN[1]) and not (least <= -SPLAYED_TURN and most >= -HALF_TURN[1]):
        return None
    listed = degrees.tolist()
    lead, tail = _hook(listed), _hook(listed[::-1])
    end = len(drawn) - tail
    pts, drawn = pts[lead:end + 1], drawn[lead:end]
    heading = np.degrees(drawn - drawn[0])
    turn = float(heading[-1])
    if not SPLAYED_TURN <= abs(turn) <= HALF_TURN[1]:
        return None
    heading = heading * math.copysign(1.0, turn)
    if float(np.max(np.maximum.accumulate(heading) - heading)) > TURN_BACK_DEG:
        return None
    return pts, drawn, heading, (lead > 0) + (tail > 0)


def rounded_bracket(work: np.ndarray, lobes: list[float],
                    turned: tuple[np.ndarray, np.ndarray, np.ndarray, int] | None = None,
                    ) -> tuple[tuple[float, float], ...] | None:
    """The four vertices (start, corner, corner, end) of a square bracket whose corners are rounded off, or None.

    ``work``: the open stroke (hooks and corner loops removed, as `open_shapes.classify_open` judges it); ``lobes``:
    its `stroke_features.lobes` (a bracket turns one way: one lobe, and one more for each hook cut at an end, which
    may turn the other way; between its hooks it turns one way, `TURN_BACK_DEG`). The spine is the longest straight run
    (`SPINE_SHARE`); an arm is the straight run at each end (`ARM_FLAT`, `ARM_SHARE`); each bend between them turns
    about a right angle (`BEND_DEG`), both the same way, half a turn in all (`HALF_TURN`; less, `SPLAYED_TURN`, for
    long arms splayed off a straight spine); the spine's middle
    three fifths have no point (`stroke_geometry.POINT_TURN_DEG` within `stroke_geometry.POINT_SPAN`: a brace's tip,
    small, between arms drawn straight). ``turned``: ``work``'s `_half_turn`, where already found (not None)."""
    if not 1 <= len(lobes) <= 3 or len(work) < 8:
        return None
    found = _half_turn(work) if turned is None else turned
    if found is None or len(lobes) > 1 + found[3]:
        return None
    pts, drawn, heading, _ = found
    n = len(heading)
    listed = heading.tolist()
    runs = _longest_flats(listed)
    # runs as long, each sharing most of its segments with the next, are one spine from the first's start to the last's
    # end (the same, whichever end the stroke was drawn from); runs as long further apart are no one spine (a brace's
    # halves either side of its point)
    a, b = runs[0][0], runs[-1][1]
    if (any(2 * later[0] >= earlier[0] + earlier[1] for earlier, later in itertools.pairwise(runs))
            or runs[0][1] - runs[0][0] < SPINE_SHARE * n or a == 0 or b == n):
        return None
    first = _flat_end(listed[:a])
    last = _flat_end(listed[b:][::-1])
    weakest_arm = min(first / a, last / (n - b))
    if weakest_arm < ROUND_ARM_FLAT or min(first, last) < ARM_SHARE * n:
        return None
    spine_heading = statistics.median(listed[a:b])
    bends = (spine_heading - statistics.median(listed[:first]), statistics.median(listed[n - last:]) - spine_heading)
    if not all(BEND_DEG[0] <= t <= BEND_DEG[1] for t in bends):
        return None
    if sg.chord_deviation(pts[a:b + 1]) >= FLAT_DEG / 180.0:
        return None
    spine = pts[a:b + 1]
    if heading[-1] < HALF_TURN[0] and (min(first, last) < SPLAYED_ARM_SHARE * n
                                       or sg.chord_deviation(spine) >= SPLAYED_SPINE_BOW):
        return None  # short of half a turn: only long arms splayed off a straight spine
    cut = len(spine) // 5
    point = sg.sharpest_turn(spine[cut:len(spine) - cut], sg.POINT_SPAN * sg.path_length(pts))
    if point >= sg.POINT_TURN_DEG or (weakest_arm < ARM_FLAT and (
            point >= ROUND_ARM_POINT_DEG or sg.chord_deviation(spine) >= SPLAYED_SPINE_BOW or max(a, n - b) >= b - a
            or heading[-1] < HALF_TURN[0])):
        return None  # an arm rounded over its whole length: only off a longer spine straight to its middle
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    margin = MARGIN * sg.bbox_diagonal(pts)
    spine_line = _side(pts, drawn, a, b)
    corners = []
    for (lo_seg, hi_seg), bend_mid in (((0, first), (first + a) // 2), ((n - last, n), (b + n - last) // 2)):
        met = sg.line_meet(*_side(pts, drawn, lo_seg, hi_seg), *spine_line)
        at = None if met is None else met[0]
        if at is None or (at < lo - margin).any() or (at > hi + margin).any():
            at = pts[bend_mid]
        corners.append(at)
    return tuple((float(p[0]), float(p[1])) for p in (pts[0], corners[0], corners[1], pts[-1]))


VERTEX_BEND = (30.0, 150.0)
"""`kept_bracket` looks only at a polyline whose two inner vertices turn the same way, each by this much (degrees;
`BEND_DEG` with room for where a fit puts a rounded corner's vertex)."""
JUDGED_POINTS = 128
"""`kept_bracket` judges the stroke resampled to this many points, smoothed, its end hooks cut (as `recognize` judges
an open stroke)."""


def kept_bracket(found: Recognition, unit: np.ndarray, noise: float, views: StrokeViews | None = None) -> bool:
    """Whether the rules read a polyline of four vertices from a stroke (``unit``: its points at unit size, ``noise``
    the pen's in those units) that is a `rounded_bracket`: not asked of the learned ranker (`recognize`), which was
    fitted on people whose round-cornered strokes were mostly curves and takes a bracket's rounded corners for a
    curve's bends. ``views``: the stroke's `stroke_views.StrokeViews`, where made."""
    if found.kind != "polyline" or not isinstance(found.geometry, Polyline) or len(found.geometry.points) != 4:
        return False
    v = np.diff(np.asarray(found.geometry.points, dtype=float), axis=0)
    turns = np.degrees(np.arctan2(v[:-1, 0] * v[1:, 1] - v[:-1, 1] * v[1:, 0], (v[:-1] * v[1:]).sum(axis=1)))
    if not (turns[0] * turns[1] > 0 and all(VERTEX_BEND[0] <= abs(t) <= VERTEX_BEND[1] for t in turns)):
        return False  # checked first, on the polyline's own vertices: no bracket's two bends (an N, a zig-zag)
    views = StrokeViews(unit) if views is None else views
    work = views.hooks_cut(JUDGED_POINTS)
    turned = _half_turn(work)
    if turned is None:
        return False  # checked first: the lobes cost more
    # its lobes counted on steps beyond the pen's tremor (`shape_turning.turning_beyond_tremor`): on the 32 points
    # `stroke_features.lobes` keeps at least, the hurried hand's tremor made lobes of 35-50 degrees between the corners
    # of 18-40 px brackets (`tests/penmodels/bracket_extremes`' tiny ones) and the gate took them for braces or S's
    return rounded_bracket(work, sf.turn_lobes(shape_turning.turning_beyond_tremor(work, noise)), turned) is not None
