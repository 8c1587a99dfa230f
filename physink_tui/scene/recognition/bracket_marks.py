"""Open marks the general open-stroke rules misjudge: a square bracket with one corner rounded off, a curly brace with
a loop at its point, a tick swung round its point; judged on the open-stroke rules' own corners and turning
(`open_shapes.classify_open`), no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg

HALF_TURN_SLACK = 35.0
"""A square bracket's arms run back the way they came: the whole stroke turns by half a turn, give or take this
(degrees) for arms a hand slants (pixelfac/user01's and klarubbio/s06's rounded brackets turn 165-207 degrees; a
question mark read with one corner, s02's, turns 135)."""
BRACKET_STRAIGHT = 0.12
"""The spine and the arm at the sharp corner stray from their chords by less than this share of the chord, as a
polyline's sides (`open_shapes.STRAIGHT`): the rounded corner is the only bend, not a curl or an arc."""
ROUND_ARM = 0.1
"""The arm beyond the rounded corner is at least this share of the path (an arm, not a hook)."""


def rounded_bracket_corners(work: np.ndarray, th: np.ndarray, corners: list[int], lobes: list[float],
                            ) -> list[int] | None:
    """The four corners of a square bracket of which the finder found only the sharp corner, or None. ``th``: the
    stroke's `stroke_geometry.turning`; ``lobes``: its `stroke_features.lobes` (as in the functions below).

    A hand drawing a bracket quickly often rounds one corner off (over a fifth of the stroke) and keeps the other
    sharp: the finder then finds one corner, and the stroke reads as a curve. What a reader sees is a stroke turning
    one way by about half a turn (`HALF_TURN_SLACK`) whose piece on one side of the sharp corner is a straight arm and
    whose other piece is a straight spine running into a round bend and a last arm (`ROUND_ARM`); the round corner is
    taken where that piece strays farthest from its chord. A question mark or a pigtail turns more or less than half
    a turn, or has no straight spine; an arc has no sharp corner (or a spine bowed like an arc)."""
    if len(corners) != 3:
        return None
    total = abs(math.degrees(float(th.sum())))
    if abs(total - 180.0) > HALF_TURN_SLACK or len(lobes) != 1:
        return None
    c, last = corners[1], len(work) - 1
    length = sg.path_length(work)
    first_longer = sg.path_length(work[:c + 1]) >= sg.path_length(work[c:])
    arm, rest = (work[c:], work[:c + 1]) if first_longer else (work[:c + 1], work[c:])
    a, b = rest[0], rest[-1]
    chord = float(np.hypot(*(b - a)))
    if chord == 0.0:
        return None
    dist = np.abs((rest[:, 0] - a[0]) * (b - a)[1] - (rest[:, 1] - a[1]) * (b - a)[0]) / chord
    k = int(np.argmax(dist))
    if k == 0 or k == len(rest) - 1:
        return None
    # from the sharp corner: the spine, then the round bend and the last arm
    spine, round_arm = (rest[k:], rest[:k + 1]) if first_longer else (rest[:k + 1], rest[k:])
    if not (sg.chord_deviation(arm) < BRACKET_STRAIGHT and sg.chord_deviation(spine) < BRACKET_STRAIGHT
            and sg.path_length(round_arm) >= ROUND_ARM * length):
        return None
    bend = k if first_longer else c + k
    return sorted({0, bend, c, last})


LOOPED_POINT = 180.0
"""A corner turning more than this (degrees) goes round a loop: a v's, a check's or a caret's point turns back at most
half a turn (jd4386/User04's and User05's braces drawn with a small loop at the point turn 222-269 there)."""


def looped_point(th: np.ndarray, corners: list[int], lobes: list[float]) -> bool:
    """Whether the stroke's one corner is a small loop at the point of a stroke turning both ways: a curly brace whose
    point was drawn as a loop (two arms meeting at a corner that turns past half a turn), not a v or a check."""
    if len(corners) != 3 or sf.corner_turns(th, corners)[0] <= LOOPED_POINT:
        return False
    return len(lobes) >= 2


BRACE_DEPTH = 0.35
"""A curly brace's point sticks out from the line joining its ends by less than this share of that line: its arms run
on nearly in line, each within about 35 degrees of it (the braces the rules read as polylines: 0.13-0.35 and a few to
0.45; a v's arms at a right angle stick out 0.5; at 0.5 a bracket of sinarest1608/Subject5 with a dent in its spine is
taken). 0.4 reads four more braces right by the rules, none more shipped, and takes dollar1:s04's right brace 03, which
`tests/test_ranker.py` names as one the ranker, not the rules, reads right: left to the lead's refit."""
ONE_SIDE = 0.03
"""A brace lies on one side of the line joining its ends (its curls and its point on the same side: 0-0.02 of the
line on the other side); a zig-zag's teeth cross it (0.04 and more)."""
POINT_FROM_ENDS = 0.3
"""A brace's point lies at least this share of the path from either end: about halfway (0.42-0.70 of the way along on
the design sources as drawn, 0.30-0.58 drawn from the other end). Either end: a mark is read the same whichever end it
was drawn from (until session 20 the window was 0.42-0.7 from the start, so a check drawn from its long arm's end,
its point 0.59-0.80 of the way along, was taken for a brace: 11 of the design sets' checks reversed)."""
ARMS_ALIKE = 0.65
"""... and the chords from each end to the point are alike, the shorter at least this share of the longer (a brace's
halves mirror each other: 0.67-0.99 at the 5th-95th percentile on dollar1 and itt, where it was chosen; a check's or
tick's short arm is at most 0.59 of its long one there as drawn, 0.16-0.58 at the 5th-95th percentile on all design
sets, and a device's hooks and overshoots lengthen it: at 0.62, 5 of dollar1's checks under `bench_device_stress`'s
transforms were taken for braces, `test_straight_marks`)."""
POINT_NEAR = 0.05
"""The point farthest from the line is a brace's point when a found corner lies within this share of the path of it,
or the path within it turns sharply (`stroke_geometry.POINT_TURN_DEG` within `POINT_SPAN`: hat359/user1's right brace
02, whose small tip the finder missed)."""
NO_RETURN = 0.1
"""A brace runs along the line joining its ends, turning back along it by less than this share of it (0-0.06); an
arrow's barbs run back along its shaft."""


def brace_point(work: np.ndarray, corners: list[int], lobes: list[float]) -> bool:
    """Whether the stroke is a curly brace whose curls or point the finder took for corners between straight sides:
    the point farthest from the line joining its ends is a corner about halfway along (`POINT_FROM_ENDS`,
    `POINT_NEAR`) between halves alike (`ARMS_ALIKE`), sticking out less than `BRACE_DEPTH` of that line, with the whole
    stroke on that side of it (`ONE_SIDE`) and running along it (`NO_RETURN`), and the stroke turns both ways (a v, a
    caret or a tick turns one way). None of these tests depends on which end the stroke was drawn from."""
    if len(corners) < 3:
        return False
    start, end = work[0], work[-1]
    chord = float(np.hypot(*(end - start)))
    if chord == 0.0:
        return False
    rel = work - start
    side = (rel[:, 0] * (end - start)[1] - rel[:, 1] * (end - start)[0]) / chord
    k = int(np.abs(side).argmax())
    depth = float(side[k])
    if abs(depth) >= BRACE_DEPTH * chord or float(np.max(-np.sign(depth) * side)) > ONE_SIDE * chord:
        return False
    along = rel @ (end - start) / chord
    if float(np.max(np.maximum.accumulate(along) - along)) >= NO_RETURN * chord:
        return False
    cum = sg.along(work)
    length = float(cum[-1])
    if min(float(cum[k]), length - float(cum[k])) < POINT_FROM_ENDS * length:
        return False
    halves = float(np.hypot(*(work[k] - start))), float(np.hypot(*(end - work[k])))
    if min(halves) < ARMS_ALIKE * max(halves):
        return False  # a check's short arm and long arm, whichever was drawn first
    near = np.abs(cum - cum[k]) < POINT_NEAR * length
    if (min(abs(float(cum[c] - cum[k])) for c in corners[1:-1]) >= POINT_NEAR * length
            and sg.sharpest_turn(work[near], sg.POINT_SPAN * length) < sg.POINT_TURN_DEG):
        return False  # no corner there, nor a point the finder missed (the label tests' brace point)
    return len(lobes) >= 2


TICK_TURN = (45.0, 150.0)
"""A tick, check or v turns one way by this much in all (degrees; its one lobe at the coarse scale, where a hook the
pen made landing or lifting does not count): its arms meet at 30-135 degrees (a bracket or a U turns half a turn, a
question mark's curl more)."""
TICK_ARMS_DEG = 55.0
"""A tick's arms' chords meet at this angle or more (`open_shapes._tip_in_line`: arms within 45 degrees of in line
are a brace's, running on through its tip)."""
TICK_CONCENTRATED = 0.5
"""A tick's long arm bows less than this share of what it would were the stroke's turning spread evenly along it (an
arc's bow over its chord: a quarter of its turn's tangent, halved): the turning is at the point, not along the arm (a
question mark's stem curves on from its curl)."""
TICK_SHORT = (0.06, 0.45)
"""The shorter arm, the round point included, is this share of the path (`stroke_geometry.ARM_SHARE` to under
half: a v's arms are alike, a tick's short arm shorter)."""
SHORT_ARM_SLACK = 1.1
"""The short arm bows no more than this many times what an arc turning by the stroke's whole turn bows: a hand's short
arm curls into the point a little tighter than a circle does (issue 25, session 34: ahmadosama's Tick #101 1.05,
klarubbio/s06's check06 1.08; the pen models' hooked swung ticks, `benchmarks/bench_mark_habits.py` tuning seeds, 1.01
and 1.03). Of the design and fourth-group strokes `rounded_point` refuses by this bound alone, none other is under 1.3,
nor any of the pen models' parentheses (`benchmarks/bench_paren_habits.py`, tuning seeds); a question mark's or a
parenthesis' curl bows more."""


def rounded_point(work: np.ndarray, th: np.ndarray, lobes: list[float]) -> list[int] | None:
    """The three vertices (start, point, end) of a tick, check or v whose point is a round bend, or None.

    A hand in a hurry swings round a check's point instead of stopping at it: the finder finds no corner there, and
    the stroke reads as a curve. What a reader sees is one bend (the stroke turns one way, `TICK_TURN`) between a
    straight long arm and a short arm, their chords meeting at `TICK_ARMS_DEG` or more; the point is taken where the
    stroke stands farthest from the line joining its ends. The long arm is straight (`BRACKET_STRAIGHT`, and
    `TICK_CONCENTRATED`: the stroke turns at its point, not along the arm) with no point in it
    (`stroke_geometry.POINT_TURN_DEG`: a long brace's tip), and the short arm, which carries the round point, bows no
    more than an arc turning by the stroke's whole turn would (within `SHORT_ARM_SLACK`): the bend is the point, not a
    curl of its own (the turn for these two bounds is the larger of the coarse lobe's and the fine path's: the hurried
    hand's hooks move the fine one either way). An arc turns evenly, so its longer arm is not straight; a brace turns
    both ways or runs on in line."""
    if len(lobes) != 1:
        return None
    total = abs(lobes[0])  # at the coarse scale: a hook where the pen landed or lifted does not count
    if not TICK_TURN[0] <= total <= TICK_TURN[1]:
        return None
    bend = max(total, abs(math.degrees(float(th.sum()))))  # the bend's turn, the fine scale's where that is more
    start, end = work[0], work[-1]
    chord = float(np.hypot(*(end - start)))
    if chord == 0.0:
        return None
    rel = work - start
    k = int(np.abs(rel[:, 0] * (end - start)[1] - rel[:, 1] * (end - start)[0]).argmax())
    if k == 0 or k == len(work) - 1:
        return None
    first, second = work[:k + 1], work[k:]
    length = sg.path_length(work)
    short_first = sg.path_length(first) <= sg.path_length(second)
    short, long = (first, second) if short_first else (second, first)
    share = sg.path_length(short) / length
    u, v = work[k] - start, end - work[k]
    norms = float(np.hypot(*u) * np.hypot(*v))
    if (not TICK_SHORT[0] <= share < TICK_SHORT[1] or norms == 0.0
            or float(u @ v) > math.cos(math.radians(TICK_ARMS_DEG)) * norms):
        return None
    middle = long[len(long) // 5: len(long) - len(long) // 5]
    even = math.tan(math.radians(bend) * (1.0 - share) / 4) / 2  # the long arm's bow, the turning spread evenly
    if (sg.chord_deviation(long) >= min(BRACKET_STRAIGHT, TICK_CONCENTRATED * even)
            or sg.chord_deviation(short) > SHORT_ARM_SLACK * math.tan(math.radians(bend) / 4) / 2
            or sg.sharpest_turn(middle, sg.POINT_SPAN * length) >= sg.POINT_TURN_DEG):
        return None
    return [0, k, len(work) - 1]


CURLING_DEG = 2.5
"""A parenthesis curling tightly near one end and sweeping on gently the rest of the way
(`penmodels.paren_habits.lopsided_paren`) passes `rounded_point`: its long side is the rest of its bow. That side turns
the bend's way all along it: each of the turns between its four quarters' chords is 4-14 degrees that way on the
pen models' parentheses the rules so read. A tick's long arm is straight: it turns less than this (degrees) between
two of its quarters at least (the pen models' hurried swung ticks, `penmodels.mark_habits`: the least of the three
turns -5 to 1), however it is hooked or curled at its far end (pixelfac/user02's check7: 5, 0 and 16 degrees)."""


def curling_arm(work: np.ndarray, point: list[int]) -> bool:
    """Whether the longer arm of ``work`` (start, point and end at the indices ``point``, as `rounded_point` gives them)
    turns the way the stroke bends at the point all along it (`CURLING_DEG` or more between each two of its quarters'
    chords): the rest of a parenthesis' bow, not a tick's arm."""
    k = point[1]
    u, v = work[k] - work[0], work[-1] - work[k]
    way = math.copysign(1.0, float(u[0] * v[1] - u[1] * v[0]))
    first, second = work[:k + 1], work[k:]
    long = second if sg.path_length(second) >= sg.path_length(first) else first  # in drawing order
    quarters = long[np.round(np.linspace(0, len(long) - 1, 5)).astype(int)]
    chords = np.diff(quarters, axis=0)
    if len(long) < 5 or not np.hypot(*chords.T).all():
        return False
    headings = np.arctan2(chords[:, 1], chords[:, 0])
    turns = (np.diff(headings) + math.pi) % (2 * math.pi) - math.pi
    return bool((way * turns >= math.radians(CURLING_DEG)).all())


HOOK_SHARE = 0.1
"""A hook where the pen landed or lifted is at most this share of the path (`stroke_geometry.remove_hooks`'
``max_fraction``)."""


def unhooked_point(work: np.ndarray, corners: list[int], noise: float) -> tuple[tuple[float, float], ...] | None:
    """The start, point and end of a tick swung round its point (`rounded_point`) once a hook the pen made landing or
    lifting is cut where the finder found a corner within `HOOK_SHARE` of the path from that end, or None (also when a
    corner lies elsewhere). `stroke_geometry.remove_hooks` keeps a hook after which the stroke turns on within a tenth
    of the path, as a tick's short arm does into its round point: the hook then adds its turn to the tick's one lobe,
    or a lobe of its own (pixelfac/user02's check7, `penmodels.mark_habits.hooked_swung_tick`). ``work``: the stroke
    as `open_shapes.classify_open` judges it, ``corners`` its corners (ends included), ``noise`` the pen's jitter in
    its units."""
    last = len(work) - 1
    if len(corners) < 3:
        return None
    along = sg.along(work)
    reach = HOOK_SHARE * along[-1]
    first, final = 0, last
    for c in corners[1:-1]:
        if along[c] <= reach:
            first = max(first, c)
        elif along[-1] - along[c] <= reach:
            final = min(final, c)
        else:
            return None  # a corner along the stroke: no tick swung round its point
    kept = work[first:final + 1]
    if (first == 0 and final == last) or len(kept) < 8:
        return None  # no hook to cut (`rounded_point` judges the stroke as it is), or hardly a stroke left
    kept = sg.resample(kept, len(work))
    point = rounded_point(kept, sg.turning(kept), sf.turn_lobes(shape_turning.coarse_turning(kept, noise)))
    if point is None or curling_arm(kept, point):
        return None  # no tick, or a parenthesis' bow curling on round its tight end
    return tuple((float(kept[i][0]), float(kept[i][1])) for i in point)


def swung_tick(work: np.ndarray, th: np.ndarray, lobes: list[float], noise: float) -> bool:
    """Whether ``work`` (the learned ranker's points, `ranker.WORK_POINTS` of them, no corner found; ``th`` its
    turning, ``lobes`` its `stroke_features.turn_lobes`, ``noise`` the pen's jitter in its units) is a tick swung round
    its point (`rounded_point`) as drawn or, as the rules judge it, once a hook where the pen landed or lifted is cut
    (`stroke_geometry.remove_hooks`): a hook curling back at an end adds its own turn to the lobe (pixelfac/user02's
    check7: 241 degrees with its hooks, 116 without), and the rules' tick is then re-read as a curve. The ranker does
    not ask its model about such a tick, but for one whose long arm curls on round the bend (`curling_arm`: a lopsided
    parenthesis, a curve)."""
    point = rounded_point(work, th, lobes)
    if point is not None:
        return not curling_arm(work, point)
    unhooked = sg.remove_hooks(work)
    if len(unhooked) == len(work):
        return False  # no hook cut: the same stroke, already judged
    unhooked = sg.resample(unhooked, len(work))
    point = rounded_point(unhooked, sg.turning(unhooked), sf.turn_lobes(shape_turning.coarse_turning(unhooked, noise)))
    return point is not None and not curling_arm(unhooked, point)
