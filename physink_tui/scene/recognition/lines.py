"""How far a person's straight line strays by the pen and hand alone (the noise at its farthest, a hook at an end),
told from a bow drawn on purpose (a circle explains it) and from a mark's short arm; no classification, no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.shape_fits import fit_circle, fit_line

CIRCULAR_BOW = 0.5
"""A stroke whose farthest point from its best circle (`shape_fits.fit_circle`) is under this share of its farthest
point from its best line bows one way, smoothly, as an arc does: the circle takes away at least half of what strays
from the line. A hook, a tremor's wobble or a corner does not fit a circle so (`benchmarks/bench_lines.py`, tuning
seeds: the pen models' arcs of 20-90 degrees 0.00-0.38 (0.9 where the slow shaky hand draws them), their short hooked
and shaky lines 0.4-40, most over 1)."""


def wobble_reach(n: int) -> float:
    """How many noise widths the pen's own wobble takes a straight stroke off its line at the farthest of its ``n``
    judged points: the largest of n draws of a noise of unit spread is about sqrt(2 ln n) (2.8 at 48 points, 3.2 at
    160), and a slow tremor, smooth between points, reaches as far through the smoothing that white noise does not.

    >>> round(wobble_reach(48), 2), round(wobble_reach(160), 2)
    (2.78, 3.19)
    """
    return math.sqrt(2 * math.log(max(n, 2)))


def circular_bow(pts: np.ndarray) -> bool:
    """Whether ``pts`` bow off their line the way an arc does (`CIRCULAR_BOW`).

    >>> a = np.linspace(-0.3, 0.3, 48)
    >>> circular_bow(np.column_stack([np.sin(a), np.cos(a)]))
    True
    >>> hooked = np.vstack([[[-2.0, 3.0]], np.column_stack([np.linspace(0, 20, 47), np.zeros(47)])])
    >>> circular_bow(hooked)
    False
    """
    centre, direction, _ = fit_line(pts)
    rel = pts - centre
    off_line = float(np.abs(rel[:, 0] * direction[1] - rel[:, 1] * direction[0]).max())
    middle, radius, _ = fit_circle(pts)
    if not math.isfinite(radius) or off_line == 0.0:
        return False
    return float(np.abs(np.hypot(*(pts - middle).T) - radius).max()) < CIRCULAR_BOW * off_line


HOOK_REACH = 8.0
"""A hook where the pen lands or lifts is at most this many noise widths of path long, whatever the stroke's length: a
hand's landing and flick (mmg's 596 lines, stylus and finger: the piece at an end heading off the line is 0 at the
median, 3-4 px at the 95th percentile, 9-10 px at the 99th)."""
HOOK_SHARE = 1 / 3
"""... and at most this share of the stroke's path (a longer piece is a mark's arm)."""


def unhooked(raw: np.ndarray, noise: float) -> list[np.ndarray]:
    """``raw`` without a hook's length (`HOOK_REACH`, `HOOK_SHARE`) of path at its start, and without one at its end
    (``noise`` in ``raw``'s units), each to be judged by the line test again; none where the stroke is too short, nor
    an end whose cut piece is a mark's arm (`_arm`). A short line's hook is a large share of it, more than
    `stroke_geometry.remove_hooks` cuts (a tenth of the path). Both ends at once only where both pieces are hooks
    (`_hooked_both`: to opposite sides, or neither standing square off the rest as an arm does): short pieces
    standing square off both ends to one side are a square bracket's arms (hcira Subject3's, 5-12 px on a 215 px
    spine; the pen models' tiny brackets), and a hand hooks one end far more often than both (mmg's lines: the start
    2 %, the end 13 %), but a short line hooked at both ends is read as a polyline otherwise (`benchmarks/
    bench_lines.py`' short-hooked family: 14-18 of 60 by the careful pen, issue 25, session 26)."""
    steps = sg.step_lengths(raw)
    along = np.concatenate([[0.0], np.add.accumulate(steps)])
    length = float(along[-1])
    cut = min(HOOK_REACH * noise, HOOK_SHARE * length)
    if not cut > 0 or sharp_corner(raw, noise):
        return []  # too short, or a mark's corner (a short arm's) where a hook would be
    at_head, at_tail = _at(raw, along, cut), _at(raw, along, length - cut)  # where each cut falls, between points
    head = np.vstack([raw[along < cut], at_head])  # each piece from the stroke's end inwards
    tail = np.vstack([raw[along > length - cut][::-1], at_tail])
    after_head = np.vstack([at_head, raw[along > cut]])
    before_tail = np.vstack([raw[along < length - cut], at_tail])
    pieces = [rest for piece, rest, inward in ((head, after_head, after_head), (tail, before_tail, before_tail[::-1]))
              if len(rest) >= 2 and not _arm(piece, inward)]
    if cut <= BOTH_HOOKS_SHARE * length and length - 2 * cut >= BOTH_HOOKS_MIDDLE * noise:
        middle = np.vstack([at_head, raw[(along > cut) & (along < length - cut)], at_tail])
        if len(middle) >= 2 and _hooked_both(head, tail, middle, noise) and end_curl(raw, noise) >= HOOK_CURL_DEG:
            pieces.append(middle)
    return pieces


LINE_TEST_POINTS = (48, 160)
LINE_TEST_STEP = 3.0
"""The line test (`open_shapes._line`) judges a stroke resampled to steps this many noise widths long, but to no fewer
and no more points than these (`line_test_points`)."""


def line_test_points(length: float, noise: float) -> int:
    """How many points the line test resamples a stroke of path ``length`` to (``noise``: the pen's jitter it steps by,
    `LINE_TEST_STEP`, `LINE_TEST_POINTS`)."""
    fewest, most = LINE_TEST_POINTS
    return int(min(most, max(fewest, length / (LINE_TEST_STEP * noise)))) if noise > 0 else fewest


def beyond_wobble(raw: np.ndarray, noise: float, pen: float) -> bool:
    """Whether no piece `unhooked` may leave of ``raw`` can pass the line test (`open_shapes._line`, stepping by
    ``noise``) as straight within the pen's own wobble (``pen``): each such piece strays farther from any line than
    `wobble_reach` at the test's most points. Asked before `unhooked` (whose corner test costs more) where no line was
    found as drawn, when a piece passes only within the wobble. The points of ``raw`` farther along its path than a cut
    from both ends are in every piece; a triangle of three of them (the first, the last, the farthest from the line
    joining those two) strays from any line by half its least altitude at least, and the test's points (resampled by
    steps of h, `line_test_points`, and smoothed: `stroke_geometry.smooth` averages five of them) come within 2.5 h of
    each point of the piece's path, so they stray by that less at least (a hair's margin for rounding)."""
    d = raw[1:] - raw[:-1]
    along = np.concatenate([[0.0], np.add.accumulate(np.hypot(d[:, 0], d[:, 1]))])  # as `unhooked` measures it
    length = float(along[-1])
    cut = min(HOOK_REACH * pen, HOOK_SHARE * length)
    inner = raw[(along > cut) & (along < length - cut)]
    if len(inner) < 3 or not cut > 0:
        return False
    first, last = inner[0], inner[-1]
    chord = last - first
    area = np.abs((inner[:, 0] - first[0]) * chord[1] - (inner[:, 1] - first[1]) * chord[0])  # twice the triangle's
    k = int(np.argmax(area))
    longest = max(float(np.hypot(*chord)), float(np.hypot(*(inner[k] - first))), float(np.hypot(*(inner[k] - last))))
    if not longest > 0:
        return False
    fewest, most = LINE_TEST_POINTS
    # the longest step of any piece (no longer than ``raw``): n = `line_test_points` of the piece's length
    step = max(1.1 * LINE_TEST_STEP * noise, length / (most - 1)) if noise > 0 else length / (fewest - 1)
    least = float(area[k]) / longest / 2 - 2.5 * step
    return least > (1 + 1e-6) * wobble_reach(most) * pen


def ends_may_span(raw: np.ndarray, noise: float, diag: float) -> bool:
    """Whether a piece `unhooked` leaves of ``raw`` (``diag``: its `stroke_geometry.bbox_diagonal`; ``noise`` as
    `unhooked`'s) could have its ends half its own diagonal apart, which the line test asks first
    (`open_shapes._line`): cutting c of path from an end moves that end by c at most and shrinks the diagonal by c at
    most (what is cut lies along c of path from the new end), and no cut is longer than `HOOK_REACH` noise widths; a
    piece may be cut at both ends (`_hooked_both`), so the ends must be at least half the diagonal less 3 c apart.
    Asked before `unhooked`, whose corner test costs more (a closed shape's or a curl's ends are close); a hair's
    margin for rounding."""
    return float(np.hypot(*(raw[-1] - raw[0]))) + 3.0 * HOOK_REACH * noise >= 0.5 * diag * (1 - 1e-6)


BOTH_HOOKS_SHARE = 0.25
"""Hooks are cut at both ends of a stroke (`unhooked`) only where each cut is at most this share of its path: the line
left is at least half the stroke. A small parenthesis, 16-20 px tall, would lose 60 % of its path to the cuts and
leave a straight bit of its bow (`tests/test_small_marks.py`' small-paren seed 24: 0.39 left); the short-hooked
lines of `benchmarks/bench_lines.py` keep 0.63-0.81. Such a cut must also find an end curling as a hook does
(`end_curl`, `HOOK_CURL_DEG`: a parenthesis bends off at its ends more gently, small-paren seed 5 by 29 and 25 degrees
with 0.53 left)."""
BRACE_BOW = 1.5
"""... and only where the line left between them does not bow away from the side both hooks stand off to (either way,
where they stand off to opposite sides) by this many of the pen's noise widths (`open_marks.HOOKED_STRAIGHT`'s floor):
a small curly brace's ends curl to one side and its point stands off to the other (`benchmarks/bench_brace_habits.py`,
20-40 px braces through whole pixels: 1.2-4.8 noise widths; tall thin braces by a mouse: 2-12), where the middle of a
line hooked at both ends strays by the pen's noise alone (0-1.4 for the careful and hurried pens)."""
BOTH_HOOKS_MIDDLE = 3 * HOOK_REACH
"""... and where at least this many noise widths of path are left between the cuts: between two curls closer together,
the mark is as likely a tiny curly brace, 20-40 px, whose flat point is lost in whole pixels (`benchmarks/
bench_brace_habits.py`' flat-point braces through whole pixels: 15-28 left, 14 of 240 tuning readings lost without
this floor), or a small parenthesis; the short-hooked lines of `benchmarks/bench_lines.py` leave 27-75."""
HOOK_BACK_DEG = 110.0
"""Where the pen lands or lifts with a hook at both ends of a short line, each hook may be straight enough for a mark's
arm (`_arm`) but comes in from behind the line's end: the cut piece leaves the rest at this angle or more (the pen
models' hooks turned back 100-160 degrees: 90-133 where `_arm` takes them for arms, 12 of 16 at 110 or more), where a
bracket's arm stands square to its spine (the pen models' tiny, small and short-arm brackets: 57-100 degrees, 10 of
319 arms over 105; `benchmarks/bench_lines.py`'s short-hooked family, issue 25, session 26)."""
HOOKS_SPLAY_DEG = 50.0
"""Where both hooks stand off to one side, their chords (each from where it is cut out to the stroke's end) must also
splay apart by this angle or more (`_splay`): a hook where the pen lands and one where it lifts each come in from
behind the line's end, so they open away from each other like a C's (the pen models' same-side hooks on tuning seeds:
60-118 degrees where the cut gave a line back), where a square bracket's arms run about parallel off its spine, a
cut piece of spine tilting them a little (`tests/test_bracket_habits.py`' short-armed bracket through the mouse)."""
MIDDLE_SPREAD = 2.0
"""... and the line left between two hooks to one side must lie within this many noise widths across its chord, both
sides together: a line's middle strays by the pen's noise alone (the tuning gains 0.0-1.7), where a tiny square-cornered
brace drawn through whole pixels keeps its lost point as a bow both ways (2.2, `benchmarks/bench_brace_habits.py`,
`tests/test_square_braces.py`)."""



def _hooked_both(head: np.ndarray, tail: np.ndarray, middle: np.ndarray, noise: float) -> bool:
    """Whether ``head`` and ``tail`` (each from an end of the stroke inwards) are both hooks where the pen landed and
    lifted, not a bracket's arms nor a brace's curls: each stands off ``middle``'s chord farther than the pen's own
    wobble reaches (`wobble_reach`, ``noise`` in their units: an end running on straight is no hook, and cutting it
    would move the line's end), the middle does not bow away from them (`BRACE_BOW`), and they stand off to opposite
    sides (a bracket's arms stand off to the same side), or splay apart (`HOOKS_SPLAY_DEG`) about a middle straight
    within the pen's noise (`MIDDLE_SPREAD`), neither a mark's short arm (`_arm`) unless turned back past square
    (`HOOK_BACK_DEG`)."""
    chord = middle[-1] - middle[0]
    norm = float(np.hypot(*chord))
    if norm == 0.0:
        return False
    unit = chord / norm

    def left_of_chord(pts: np.ndarray) -> np.ndarray:
        off: np.ndarray = (pts[:, 1] - middle[0][1]) * unit[0] - (pts[:, 0] - middle[0][0]) * unit[1]
        return off

    offs = [left_of_chord(piece) for piece in (head, tail)]
    far = [float(off[int(np.argmax(np.abs(off)))]) for off in offs]
    if any(abs(f) <= wobble_reach(len(piece)) * noise for f, piece in zip(far, (head, tail), strict=True)):
        return False
    bow = left_of_chord(middle)
    away = np.abs(bow) if far[0] * far[1] < 0 else -np.sign(far[0]) * bow  # off the line, away from the hooks
    if float(away.max()) >= BRACE_BOW * noise:
        return False
    if far[0] * far[1] < 0:
        return True
    if _splay(head, tail) < HOOKS_SPLAY_DEG:
        return False
    if float(np.ptp(bow)) >= MIDDLE_SPREAD * noise:
        return False
    return all(angle is None or not _arm_angle(angle) or angle >= HOOK_BACK_DEG
               for angle in (_stand_off(head, middle), _stand_off(tail, middle[::-1])))


def _splay(head: np.ndarray, tail: np.ndarray) -> float:
    """The angle (degrees) between ``head``'s and ``tail``'s chords, each from where it was cut out to the stroke's
    end: 0 where they run parallel."""
    angle = sg.angle_deg(head[0] - head[-1], tail[0] - tail[-1])
    return 0.0 if angle is None else angle


def _at(pts: np.ndarray, along: np.ndarray, where: float) -> np.ndarray:
    """The point ``where`` along the path of ``pts`` (``along``: the path length at each point), as a row."""
    return np.column_stack([np.interp(where, along, pts[:, 0]), np.interp(where, along, pts[:, 1])])


def _arm(piece: np.ndarray, rest: np.ndarray) -> bool:
    """Whether ``piece`` (from an end of the stroke to where ``rest`` runs on) is a mark's short arm, not a hook:
    straight (`stroke_geometry.ARM_STRAIGHT`) and standing off the rest's chord at `stroke_geometry.ARM_ANGLE_DEG`
    (a tiny check's first arm, 10 px on a 20 px mark, itt lvht1203's check04, or a square bracket's); a hook curls
    back or runs on nearly in line."""
    angle = _stand_off(piece, rest)
    return angle is not None and _arm_angle(angle)


def _arm_angle(angle: float) -> bool:
    """Whether a straight end piece standing off the rest at ``angle`` (degrees) does so as a mark's arm does."""
    return sg.ARM_ANGLE_DEG[0] <= angle <= sg.ARM_ANGLE_DEG[1]


def _stand_off(piece: np.ndarray, rest: np.ndarray) -> float | None:
    """The angle (degrees) between ``piece``'s chord, from where ``rest`` runs on to the stroke's end, and the way
    ``rest`` runs on; None where ``piece`` is not straight (`stroke_geometry.ARM_STRAIGHT`) or either has no length."""
    if len(piece) < 2:
        return None
    if len(piece) > 2 and sg.chord_deviation(piece) >= sg.ARM_STRAIGHT:
        return None
    return sg.angle_deg(piece[0] - piece[-1], rest[-1] - rest[0])


INK_STEP = 3.0
"""`ink` is measured along steps this many noise widths long (`open_shapes`' line test judges on such steps)."""


def ink(pts: np.ndarray, noise: float) -> float:
    """The path length of ``pts`` along steps at least `INK_STEP` noise widths long: the ink of the stroke's shape,
    not of the pen's wobble between points closer than that (the line test resamples a short stroke to 48 points, a
    fraction of a noise width apart on a 20 px line, where a slow shaky hand's tremor and sensor noise add 20-90 % to
    the path of a straight line: `benchmarks/bench_lines.py`'s shaky pen).

    >>> zigzag = np.array([[x, 0.5 * (x % 2)] for x in range(0, 31)], dtype=float)
    >>> round(ink(zigzag, 1.0), 1), round(float(np.hypot(*np.diff(zigzag, axis=0).T).sum()), 1)
    (30.1, 33.5)
    """
    steps = sg.step_lengths(pts)
    length = float(steps.sum())
    k = int(min(len(pts), max(2, length / (INK_STEP * noise) + 1))) if noise > 0 else len(pts)
    return length if k >= len(pts) else float(np.hypot(*np.diff(sg.resample(pts, k), axis=0).T).sum())


def within_wobble(pts: np.ndarray, stray: float, noise: float) -> bool:
    """Whether ``pts`` (the line test's smoothed points without hooks, whose farthest point strays ``stray`` off their
    line, in their units, as ``noise``, the pen's) stray no farther than the pen's own wobble reaches (`wobble_reach`
    noise widths), do not bow as an arc does (`circular_bow`) and turn nowhere by a mark's corner (`sharp_corner`)."""
    return stray < wobble_reach(len(pts)) * noise and not circular_bow(pts) and not sharp_corner(pts, noise)


CORNER_DEG = 90.0
"""A stroke turning this much or more between chords `HOOK_REACH` noise widths long (shorter at its ends, down to
`CORNER_CHORD`) has a mark's corner: a check's or a tick's point, a bracket's or a brace's, however short its arm. A
hook where a hand lands or lifts curls onto the line, turning less (the pen models' hooks 20-80 degrees where they
join it; one doubling back is `stroke_geometry.remove_hooks`' or `open_marks.retraced_ends`'). Dollar1's checks drawn
20-40 px across by a mouse (`bench_device_stress`'s tiny mouse: a short arm of 5-8 px) turn 95-125 degrees."""
CORNER_CHORD = 4.0
"""...each chord at least this many noise widths long (half a hook's reach): a slow shaky hand's tremor where it lands
turns sharply between shorter ones (chords of 2-3 noise widths took 8-16 of the shaky pen's 60 tuning lines)."""


def sharp_corner(pts: np.ndarray, noise: float) -> bool:
    """Whether ``pts`` turn by `CORNER_DEG` or more anywhere, between the chords from `HOOK_REACH` noise widths of
    path before each point and to as far after it (``noise`` in their units).

    >>> tick = np.vstack([np.column_stack([np.zeros(7), np.arange(7.0)]), np.column_stack([np.arange(1, 25.0),
    ...                   6 - 0.8 * np.arange(1, 25.0)])])
    >>> sharp_corner(tick, 1.0), sharp_corner(np.column_stack([np.arange(30.0), np.zeros(30)]), 1.0)
    (True, False)
    """
    along = sg.along(pts)
    reach = HOOK_REACH * noise
    back = _at_each(pts, along, np.maximum(along - reach, 0.0))
    ahead = _at_each(pts, along, np.minimum(along + reach, along[-1]))
    u, v = pts - back, ahead - pts
    nu, nv = np.hypot(*u.T), np.hypot(*v.T)
    ok = (nu >= CORNER_CHORD * noise) & (nv >= CORNER_CHORD * noise)
    if not ok.any():
        return False
    cos = (u[ok] * v[ok]).sum(axis=1) / (nu[ok] * nv[ok])
    return bool((cos <= math.cos(math.radians(CORNER_DEG))).any())


def _at_each(pts: np.ndarray, along: np.ndarray, where: np.ndarray) -> np.ndarray:
    """The points ``where`` along the path of ``pts`` (``along``: the path length at each point)."""
    return np.column_stack([np.interp(where, along, pts[:, 0]), np.interp(where, along, pts[:, 1])])


HOOK_TURN_DEG = 20.0
"""An end piece `HOOK_REACH` noise widths long whose chord turns this much from the way the stroke runs on from it is
hooked (the pen landing or lifting); an arc's end turns by its sweep over that short piece, a few degrees."""


def without_hooked_ends(pts: np.ndarray, noise: float) -> np.ndarray:
    """``pts`` (equally spaced, ``noise`` in their units) without an end piece `HOOK_REACH` noise widths long that turns
    off the way the stroke runs on (`HOOK_TURN_DEG`): what a circle is fitted to when `open_marks.swung_line` asks
    whether a circle explains a bow. The hurried hand's small hooks on arcs of 45-66 degrees made the circle miss the
    arcs' ends, and they were read as swung lines (`benchmarks/bench_lines.py`); gtiwari's mouse lines have none.

    >>> arc = np.column_stack([np.cos(np.linspace(0, 1, 60)), np.sin(np.linspace(0, 1, 60))]) * 100
    >>> hooked = np.vstack([arc[:1] + [[-4.0, -2.0]], arc])
    >>> len(without_hooked_ends(hooked, 1.0)) < len(hooked), len(without_hooked_ends(arc, 1.0)) == len(arc)
    (True, True)
    """
    along = sg.along(pts)
    reach = HOOK_REACH * noise
    head = int(np.count_nonzero(along <= reach))
    tail = int(np.count_nonzero(along >= along[-1] - reach))
    lo = head - 1 if _turns_off(pts, head) else 0
    hi = len(pts) - tail + 1 if _turns_off(pts[::-1], tail) else len(pts)
    return pts[lo:hi] if hi - lo >= len(pts) // 2 else pts


def _turns_off(pts: np.ndarray, k: int) -> bool:
    """Whether the first ``k`` of ``pts`` head off the way the next ``2 k`` run on by `HOOK_TURN_DEG` or more."""
    if k < 2 or 3 * k > len(pts):
        return False
    angle = sg.angle_deg(pts[k - 1] - pts[0], pts[3 * k - 2] - pts[k - 1])
    return angle is not None and angle >= HOOK_TURN_DEG


HOOK_CURL_DEG = 35.0
"""A hook where the pen landed or lifted curls: near an end (within `HOOK_REACH` noise widths and a chord of
`CORNER_CHORD` more) the path turns by this much or more between chords `CORNER_CHORD` noise widths long either side
of a point. A parenthesis bends off at its ends more gently (the pen models' small bows whose middle a line explains:
18-31 degrees there; short lines hooked at both ends: 34-78, `open_marks.hooked_straight`)."""


def end_curl(pts: np.ndarray, noise: float) -> float:
    """The sharpest turn (degrees) between chords `CORNER_CHORD` noise widths long either side of a point of ``pts``
    near an end (`HOOK_CURL_DEG`), 0 where the stroke is too short to have such a point.

    >>> line = np.column_stack([np.linspace(0.0, 40.0, 41), np.zeros(41)])
    >>> hooked = np.vstack([[[-3.0, 3.0], [-2.0, 1.0], [-1.0, 0.2]], line])
    >>> round(end_curl(line, 1.0)), end_curl(hooked, 1.0) > HOOK_CURL_DEG
    (0, True)
    """
    along = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    length, span = float(along[-1]), CORNER_CHORD * noise
    near = ((np.minimum(along, length - along) <= (HOOK_REACH + CORNER_CHORD) * noise)
            & (along >= span) & (along <= length - span))
    if not near.any():
        return 0.0
    at = along[near]
    u = pts[near] - _at_each(pts, along, at - span)
    v = _at_each(pts, along, at + span) - pts[near]
    norms = np.hypot(*u.T) * np.hypot(*v.T)
    ok = norms > 0
    if not ok.any():
        return 0.0
    cos = (u[ok] * v[ok]).sum(axis=1) / norms[ok]
    return math.degrees(math.acos(float(np.clip(cos.min(), -1.0, 1.0))))
