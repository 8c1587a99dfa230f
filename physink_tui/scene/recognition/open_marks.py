"""Open marks drawn loosely by a hurried hand: zig-zag teeth between a lead-in and a tail, lines begun backwards or
swung.

The open-stroke rules (`open_shapes`) ask every side of a polyline to be straight and every corner sharp, and a line
to end where its extent ends; these tests say when a reader still sees the mark: a zig-zag's teeth whatever its ends
do (`sawtooth`), a line without the piece its pen ran or hooked back along (`retraced_ends`), a line whose middle the
hand's swing bowed one way and back (`swung_line`), a line drawn out and back whole, which closes a loop no reader
takes for an ellipse (`out_and_back`). No I/O.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np

from physink_tui.scene.recognition import bowed_lines, lead_ins, lines, shape_turning
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Ellipse, Line, Recognition
from physink_tui.scene.recognition.shape_fits import fit_circle, fit_line

SAW_TEETH = 4
"""A zig-zag has at least this many sharp corners in a row, joined by even sides: three teeth (two corners make an N,
three a brace's tip drawn as a spike: the arm's end, the point, the next arm's start)."""
SAW_TURN_DEG = 90.0
"""Each of a zig-zag's corners turns the path by at least a right angle (`stroke_geometry.DIP_TURN_DEG`: the teeth's
points; a brace's shoulders, where its tip leaves and rejoins the stroke, turn 60-85 degrees)."""
SAW_ROUND = 0.5
"""A zig-zag's points are sharp: each does its turning within this share of its shorter side
(`stroke_features.corner_roundness`; a wobbly brace's bends take 0.5-0.9 of theirs)."""
SAW_EVEN = 1.5
"""A zig-zag is drawn with a rhythm: each side between its teeth is at most this many times as long as the side drawn
alike before it (two back: a sawtooth's drop and the next drop, its slanted rise and the next), or as short; a brace's
arm is two to four times its tip's sides. At 2 people's uneven sawtooth teeth pass too (5 more zig-zags), and so do
the braces one person draws as sharp teeth (2 lost): issue 25, fifth pass, in docs/BENCHMARKS.md."""
SWUNG_STRAY = 0.09
"""A line swung by the hand strays from its fitted line by less than this share of its length (twice the line test's
`open_shapes.LINE`; a circular arc of 60 degrees strays 0.09)."""
SWUNG_INK = 1.05
"""... with at most this much ink for its chord (a circular arc of 60 degrees has 1.047: a wave big enough to be meant
has more)."""
SWUNG_FAR = 0.105
SWUNG_FAR_INK = 1.06
"""... or up to this stray and this ink where it lies slanted and bends to one side near its end, not about its middle
(`bowed_lines.end_bent`): `SWUNG_STRAY` and `SWUNG_INK` are a bow's figures, and what strays beyond them there is a
curl the cuts left where the pen lifted (the `sign` set's ST5022 writers' lines so curled: 0.05-0.095 stray,
1.035-1.056 ink; issue 25, session 38)."""
ONE_WAY = 0.8
"""A stroke whose net turning is over this share of all its turning turns one way (an arc: `open_shapes`' arc test)."""
SWUNG_TURN_DEG = 90.0
"""... and its heading from start to end turns by less than a right angle (a square bracket's or a tick's short arms
kept at its ends turn it by a right angle or more)."""
FLICK_SAG = 0.09
"""A stroke turning one way may still be a swung line where it bows off its chord (start to end) by less than this share
of it, about as far as a circular arc of 41 degrees (tan(10.25 deg) / 2), deepest in the middle of the chord
(`FLICK_MIDDLE`), and a circle does not explain its bow (`SWUNG_ARC`): a fast flick of the wrist on a Tablet PC bows a
line one way, its bend not spread evenly as an arc's is (issue 25, session 36: the `sign` set's ST5022 writers' lines
read as arcs bow 0.05-0.13 of their chord, where the circle misses by 0.13-0.6 of the line's error; the stroke
generator's and the pen models' arcs 0.00-0.15). Deeper, or curled near an end, it is a parenthesis or an arc: of
`benchmarks/bench_paren_habits.py`' parentheses passing the other tests (tuning seeds), the lopsided ones that bow this
little bow deepest within 0.18-0.23 of the chord from an end (one, 0.42, curls at both ends: `FLICK_END_DEG`), the
shallow and small ones bow 0.10 and more; people's quarter arcs (the `sign` set's curve labels) 0.37 and more. A
parenthesis as shallow, flat in the middle, curls at both ends (`FLICK_END_DEG`)."""
FLICK_MIDDLE = 0.35
"""... deepest no nearer an end of its chord than this share of it (`FLICK_SAG`): a lopsided parenthesis is deepest
0.15-0.35 of its height from one end (`tests/penmodels/paren_habits.py`; at 0.25, chosen first on tuning seeds where
those that bow this little are deepest 0.18-0.23 from an end, two held-seed ones drawn by the careful pen were taken and
`tests/test_paren_habits.py`' held floor failed: the margin is the model's whole range, not its tuning seeds')."""
FLICK_END_DEG = 6.0
"""... and running on straight at one end: the chord of its first (or last) tenth of path heads within this many degrees
of the next fifth's. The wrist bends a flick where it starts or ends its swing; a parenthesis, even one flat in the
middle, curls at both ends (`tests/penmodels/math_marks.py`' parentheses 6-30 % deep: where they pass the tests above,
4.5-13.8 degrees at the straighter end, 1 of 12 under 6 on tuning seeds; the `sign` lines 0.1-12.4, 32 of 52)."""
SWUNG_POINT_DEG = 2 * sg.POINT_TURN_DEG
"""... and no stretch of `stroke_geometry.POINT_SPAN` of its middle three fifths turns by this much (a brace's tip, in
the middle, turns 69 degrees and more there; a swung line's wobble less)."""
SWUNG_ARC = 0.15
"""... and a circle explains its bow no better than this share of the line's error (`fit_circle`'s farthest point
against the fitted line's): a bow a circle fits closer is an arc drawn so (arcs of 40-60 degrees by the stroke
generator: 0.03-0.09 at the 10th-90th percentile; gtiwari's mouse-swung lines 0.16-0.78)."""
SWUNG_WOBBLE = 1.5
"""... nor, whatever the bow's size, by less than this many of the pen's noise widths (its stated noise): a circle
missing a bow by no more than the pen's own wobble explains it. Parentheses 15-60 px tall bow a few pixels, and the
circle misses the hurried hand's by 0.5-2 px, most under 1.5 (`benchmarks/bench_paren_habits.py`); of the 53 design
and fourth-group strokes `swung_line` takes, the circle misses every one by 2.4 noise widths or more (mmg:10's fast
stylus line 2.4, gtiwari's mouse lines 3.1 and more)."""
HOOKED_STRAIGHT = SWUNG_WOBBLE
"""... unless a line explains the bow as closely, within this many of the pen's noise widths (the same floor), and an
end curls as a hook where the pen landed or lifted does (`lines.HOOK_CURL_DEG`): then there is no bow for the circle to
explain, only a line whose hooks the cut left part of (`hooked_straight`). A short line hooked at both ends, the hurried
hand's through a coarse device among them, lost to `SWUNG_WOBBLE` (issue 25, session 25: `benchmarks/bench_lines.py`'s
short-hooked family). What the cuts leave of such lines strays 0.3-2.2 noise widths from its line, of the pen models'
parentheses 0.13-10; those under 1.5 (a small bow flat in the middle) bend off at their ends by 31 degrees or less."""
SAW_REACH = 3
"""A corner's turn is summed over this many resampled points either side of it (`stroke_features.corner_turns`)."""


def signed_turns(th: np.ndarray, corners: list[int], reach: int = SAW_REACH) -> list[float]:
    """Signed net turning (degrees) right at each inner corner (left positive), over ``reach`` points either side."""
    n = len(th) + 2
    out = []
    for c in corners[1:-1]:
        lo, hi = max(c - reach, 1), min(c + reach, n - 2)
        out.append(math.degrees(float(th[lo - 1:hi].sum())))
    return out


def sawtooth(work: np.ndarray, th: np.ndarray, corners: list[int], straight_runs: list[bool],
             roundness: list[float]) -> bool:
    """Whether `SAW_TEETH` or more inner corners in a row each turn by `SAW_TURN_DEG` or more, no rounder than
    `SAW_ROUND`, each the other way from the one before, joined by straight sides each within `SAW_EVEN` of the one
    drawn alike two before: a zig-zag's teeth. The sides before the first tooth and after the last (a lead-in drawn as
    the pen gathers speed, a tail that curls off as it leaves the paper) may be anything: a hurried hand draws its
    zig-zag's teeth sharp and its ends loosely. A brace's tip (the arm's end, the point, the next arm's start) also
    turns each way in turn, but is three corners, and the next side is a long arm, not a tooth like the tip's."""
    return teeth_run(work, th, corners, straight_runs, roundness) >= SAW_TEETH


def teeth_run(work: np.ndarray, th: np.ndarray, corners: list[int], straight_runs: list[bool],
              roundness: list[float]) -> int:
    """The longest run of a zig-zag's teeth points (`sawtooth`)."""
    turns = signed_turns(th, corners)
    sides = [sg.path_length(work[a:b + 1]) for a, b in itertools.pairwise(corners)]
    run = best = 0
    for i, t in enumerate(turns):
        tooth = abs(t) >= SAW_TURN_DEG and roundness[i] <= SAW_ROUND
        # side i runs from inner corner i - 1 to inner corner i; side i - 1 is the tooth side before it
        follows = (run > 0 and (t > 0) != (turns[i - 1] > 0) and straight_runs[i]
                   and (run < 3 or _like(sides[i], sides[i - 2])))
        run = run + 1 if tooth and follows else (1 if tooth else 0)
        best = max(best, run)
    return best


def sawtooth_vertices(points: Sequence[tuple[float, float]]) -> bool:
    """`sawtooth` on a polyline's vertices (the rules' reading): `SAW_TEETH` or more inner vertices in a row each
    turning by `SAW_TURN_DEG` or more, each the other way from the one before, joined by sides each within `SAW_EVEN`
    of the one two before (the rules already judged the sides straight and the corners sharp)."""
    if len(points) < SAW_TEETH + 2:
        return False
    v = np.diff(np.asarray(points, dtype=float), axis=0)
    sides = np.hypot(v[:, 0], v[:, 1])
    if not (sides > 0).all():
        return False
    turns = np.degrees(np.arctan2(v[:-1, 0] * v[1:, 1] - v[:-1, 1] * v[1:, 0], (v[:-1] * v[1:]).sum(axis=1)))
    run = 0
    for i, t in enumerate(turns.tolist()):
        tooth = abs(t) >= SAW_TURN_DEG
        follows = (run > 0 and (t > 0) != (turns[i - 1] > 0)
                   and (run < 3 or _like(sides[i], sides[i - 2])))
        run = run + 1 if tooth and follows else (1 if tooth else 0)
        if run >= SAW_TEETH:
            return True
    return False


def _like(a: float, b: float) -> bool:
    """Whether two sides of a zig-zag drawn alike (a drop and the next drop, a rise and the next rise) are within
    `SAW_EVEN` of each other's length."""
    return max(a, b) <= SAW_EVEN * min(a, b)


RETRACE_SHARE = 0.2
"""A line may begin (or end) by running back along itself for up to this share of its path: the pen landing and
sliding backwards before it sets off (mmg:10's fast stylus lines), not a mark of its own."""
RETRACE_OFF = 0.03
"""Such a lead-in stays within this share of the line's length (plus the pen's noise) of the line: it doubles back along
it, where a tick's short arm stands off it."""


RETRACE_NEAR = 0.15
"""Only a stroke whose every point lies within this share of its start-to-end distance of that chord (plus the noise)
is looked at: a line's points never stand further off (a cheap test, made first)."""


def retraced_ends(raw: np.ndarray, noise: float) -> np.ndarray | None:
    """The stroke without a lead-in or a tail that runs back along it (`RETRACE_SHARE`, `RETRACE_OFF`) or is a hook
    turned back off it (`BACK_HOOK_SHARE`, `BACK_HOOK_DEG`), or, where the pen landed, is a long lead-in before a line
    drawn level or downhill (`lead_ins.lead_in`), or None when neither end does, or either end's piece is neither:
    between its points farthest back and farthest on along its start-to-end direction. A stroke whose other end is
    such a lead-in, the stroke drawn backwards (a long piece turned back along a line drawn level or uphill, where the
    pen lifted), is cut as the stroke drawn backwards is: a lead-in and a line read the same drawn either way."""
    if not _near_chord(raw, noise):
        return None  # no line: some point stands far off the chord (checked first: most strokes are no line)
    kept, _ = _cut_ends(raw, noise)
    if kept is None:
        back, led = _cut_ends(raw[::-1], noise, lead_in_only=True)
        if back is not None and led:
            kept = back[::-1]
    return kept


def _near_chord(raw: np.ndarray, noise: float) -> bool:
    """Whether every point of ``raw`` lies within `RETRACE_NEAR` of its start-to-end distance of that chord (plus the
    noise), as a line's do, whichever end it was drawn from."""
    chord = raw[-1] - raw[0]
    norm = float(np.hypot(*chord))
    if norm == 0.0:
        return False
    rel = raw - raw[0]
    stray = float(np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]).max())
    return not stray > RETRACE_NEAR * norm * norm + noise * norm


def _cut_ends(raw: np.ndarray, noise: float, lead_in_only: bool = False) -> tuple[np.ndarray | None, bool]:
    """`retraced_ends` as drawn (the stroke's points near its chord already: `_near_chord`), and whether the piece cut
    where the pen landed is a long lead-in (`lead_ins.lead_in`); with ``lead_in_only`` (asked of the stroke drawn
    backwards, whose cut counts only where that piece is a long lead-in) (None, False) as soon as it cannot be one."""
    chord = raw[-1] - raw[0]
    along = (raw - raw[0]) @ (chord / float(np.hypot(*chord)))
    lo, hi = int(np.argmin(along)), int(np.argmax(along))
    if (lo == 0 and hi == len(raw) - 1) or lo >= hi or (lead_in_only and lo == 0):
        return None, False  # (no piece where the pen landed: no lead-in, ``led`` would be False)
    length = sg.path_length(raw)
    kept = raw[lo:hi + 1]
    cuts = sg.path_length(raw[:lo + 1]), sg.path_length(raw[hi:])
    if len(kept) < 2:
        return None, False
    a, b = kept[0], kept[-1]
    span = float(np.hypot(*(b - a)))
    if span == 0.0:
        return None, False
    unit = (b - a) / span
    led = lo > 0 and lead_ins.lead_in(raw[:lo + 1], a, unit, length)  # a long lead-in run back along a level line
    if lead_in_only and not led:
        return None, False
    if (sum(cuts) > (lead_ins.LEAD_TOTAL if led else RETRACE_SHARE) * length
            and (led or max(cuts) > BACK_HOOK_SHARE * length)):
        return None, False  # (both ends' hooks may together be more: `BACK_HOOK_SHARE`)
    ends = ((raw[:lo + 1], a, unit, BACK_HOOK_LANDED_SHARE), (raw[hi:][::-1], b, -unit, BACK_HOOK_SHARE))
    for k, (end, turn, back, share) in enumerate(ends):  # each end's piece, from its end
        off = np.abs((end[:, 0] - a[0]) * unit[1] - (end[:, 1] - a[1]) * unit[0])
        if (float(off.max()) > RETRACE_OFF * span + noise and not (k == 0 and led)
                and not lead_ins.turned_back(end, turn, back, share * length, BACK_HOOK_DEG)):
            return None, False
    return kept, led


BACK_HOOK_SHARE = 0.15
BACK_HOOK_DEG = 30.0
"""An end piece that strays farther than `RETRACE_OFF` off the line is still the pen landing or lifting where it is a
hook turned back: at most this share of the path, its chord (from where it turns to the stroke's end) within this
angle of the line running back from there (the sign set's Tablet PC pens, ST5022 writers: lines hooked at an end by
3-15 % of their path, the hook's chord 0-30 degrees off the line, `tests/test_back_hooks.py`). A mark's short arm
stands farther off: the design and fourth groups' polylines whose rest is straight once an end piece of at most a
quarter of the path is cut (checks, ticks, v's, carets) stand it off by 38 degrees or more, and by 24-26 only where it
is a fifth of the path or more (issue 25, session 36: docs/BENCHMARKS.md)."""

BACK_HOOK_LANDED_SHARE = 0.125
"""Where the pen landed, a hook is at most this share of the path (`BACK_HOOK_SHARE` holds where it lifted, the pen
sweeping off): the ST5022 writers' lines hooked where the pen landed, 8.5-12.4 % of the path but for one writer's three
(12.7-14.8 %), where it lifted 8-15 %; a barless radical's tick, drawn first and turned sharply into a long rise
within 30 degrees, is 12.8 % of the path or more where this rule would cut it (`tests/penmodels/math_marks.
barless_radical`, extra tuning seeds 2000-2998: issue 25, session 36, wt-hooks2)."""


REST_HOOK_SHARE = 0.05
"""What `retraced_ends` leaves of a stroke may pass as a line the hand's swing bowed (`swung_line`) where the longer
piece it cut is at least this share of the path (`hooked_bow` asks, with the stroke lying slanted and
carrying a hook's ink): a hook where the pen landed or lifted long enough that it, not the bow, refused the whole
stroke (the sign set's ST5022 writers' bowed lines hooked 6-14 % of their path, carrying 1.14-1.39 of their chord in
ink). A shorter piece is the mark's own end, whose cut only moves the circle's fit off a bow it explained: hcira
Subject3's square bracket (2.2 %), ahmadosama's tick (1.1 %), the pen models' ticks (1.8 %) and, on extra tuning seeds
2000-2599, 145 of the 152 parentheses and arcs whose rest so passes (the other 7 stand upright or carry an arc's ink:
issue 25, session 38, docs/BENCHMARKS.md)."""


def long_hook_cut(raw: np.ndarray, kept: np.ndarray) -> bool:
    """Whether the longer end piece `retraced_ends` cut from ``raw`` to leave ``kept`` (a slice of it) is at least
    `REST_HOOK_SHARE` of the path."""
    lo = int(np.flatnonzero((raw == kept[0]).all(axis=1))[0])
    pieces = sg.path_length(raw[:lo + 1]), sg.path_length(raw[lo + len(kept) - 1:])
    return max(pieces) >= REST_HOOK_SHARE * sg.path_length(raw)


def hooked_bow(raw: np.ndarray, kept: np.ndarray, coarse: np.ndarray, noise: float) -> bool:
    """Whether ``raw``, whose rest ``kept`` (`retraced_ends`' cut) passes as a line the hand's swing bowed, was
    refused as one for the hook the cut took: it lies far off the upright as no parenthesis does
    (`bowed_lines.slanted`), the longer piece cut is a long hook (`long_hook_cut`), and the whole (``coarse``: its
    points as the line test judges them) carries the ink of one (`SWUNG_INK` or more for its chord)."""
    if not (bowed_lines.slanted(raw) and long_hook_cut(raw, kept)):
        return False
    chord = float(np.hypot(*(coarse[-1] - coarse[0])))
    return chord > 0.0 and sg.path_length(coarse) >= SWUNG_INK * (chord + 3 * noise)


def swung_line(coarse: np.ndarray, stray: float, ink: float, noise: float, pen: float | None = None) -> bool:
    """Whether a stroke the line test refused (``coarse``: its smoothed points without hooks; ``stray`` and ``ink``
    its fitted line's error and its length over its chord, the pen's noise allowed) is a line whose middle the hand's
    swing bowed: it strays less than `SWUNG_STRAY` with under `SWUNG_INK` of ink (a little more where it lies slanted
    and curls to one side near its end: `SWUNG_FAR`), turns both ways (one way round, it would be an arc: `ONE_WAY`,
    unless it bows shallowly about its middle, as a flick does: `flicked`), its heading turns less than
    `SWUNG_TURN_DEG` end to end, its middle has no point (`SWUNG_POINT_DEG`) and no circle fits its bow (`SWUNG_ARC`,
    and beyond the pen's own wobble: `SWUNG_WOBBLE`, unless a line fits it as well and a hook curls at an end:
    `hooked_straight`).
    What a person does: a long diagonal drawn with a mouse, or a quick stroke of a wrist, pivots and corrects; a
    reader still sees a line, not a curve. A hook where the pen landed or lifted (its reach in the pen's stated noise
    ``pen``, ``noise`` where not given) is left out of the circle's fit (`lines.without_hooked_ends`)."""
    if stray >= SWUNG_FAR or ink >= SWUNG_FAR_INK or (
            (stray >= SWUNG_STRAY or ink >= SWUNG_INK) and not bowed_lines.end_bent(coarse)):
        return False  # checked first: most strokes are far from straight
    th = shape_turning.coarse_turning(coarse, noise)
    net, every = abs(float(th.sum())), float(np.abs(th).sum())
    if math.degrees(net) >= SWUNG_TURN_DEG or (net > ONE_WAY * every and not (
            flicked(coarse) or bowed_lines.slanted_flick(coarse))):  # (lying far off the upright: no parenthesis)
        return False
    length = sg.path_length(coarse)
    middle = coarse[len(coarse) // 5: len(coarse) - len(coarse) // 5]
    if sg.sharpest_turn(middle, sg.POINT_SPAN * length) >= SWUNG_POINT_DEG:
        return False
    own = noise if pen is None else pen
    bow = lines.without_hooked_ends(coarse, own)  # a hook where the pen landed is no swing
    centre, radius, _ = fit_circle(bow)
    if not math.isfinite(radius):
        return True  # straight enough that no circle fits
    miss = float(np.abs(np.hypot(*(bow - centre).T) - radius).max())
    if miss < SWUNG_ARC * stray * length:
        return False
    return miss >= SWUNG_WOBBLE * own or hooked_straight(coarse, bow, own)  # the pen's own wobble is no swing


def flicked(coarse: np.ndarray) -> bool:
    """Whether ``coarse`` (a stroke turning one way) bows off its chord, start to end, by less than `FLICK_SAG` of it,
    deepest no nearer an end of the chord than `FLICK_MIDDLE` of it, and runs on straight at one end (`FLICK_END_DEG`):
    shallowly enough, about its middle, bent where the wrist started or ended its swing, for a flick (`swung_line` still
    asks that no circle explain the bow).

    >>> x = np.linspace(0.0, 1.0, 101)
    >>> def bent(depth, at):  # straight from its deepest point, ``at`` of the way along, to its end
    ...     return np.column_stack([x, depth * np.where(x < at, np.sin(np.pi / 2 * x / at), (1 - x) / (1 - at))])
    >>> flicked(bent(0.06, 0.45)), flicked(bent(0.12, 0.45)), flicked(bent(0.06, 0.2))  # too deep; deepest at an end
    (True, False, False)
    >>> flicked(np.column_stack([x, 0.06 * (1 - (2 * x - 1) ** 4)]))  # flat in the middle, curled at both ends
    False
    """
    chord = coarse[-1] - coarse[0]
    norm = float(np.hypot(*chord))
    if norm == 0.0:
        return False
    rel = coarse - coarse[0]
    off = np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]) / norm
    k = int(np.argmax(off))
    along = float(rel[k] @ chord) / (norm * norm)
    if not (float(off[k]) < FLICK_SAG * norm and FLICK_MIDDLE <= along <= 1.0 - FLICK_MIDDLE):
        return False
    even = sg.resample(coarse, 100)
    return min(_end_bend(even), _end_bend(even[::-1])) < FLICK_END_DEG


def _end_bend(even: np.ndarray) -> float:
    """The angle (degrees) between the chord of the first tenth of ``even`` (100 points equally spaced) and the chord of
    the next fifth (`FLICK_END_DEG`)."""
    angle = sg.angle_deg(even[10] - even[0], even[30] - even[10])
    return 180.0 if angle is None else angle


def hooked_straight(coarse: np.ndarray, bow: np.ndarray, noise: float) -> bool:
    """Whether ``bow`` (``coarse`` without the hooks `lines.without_hooked_ends` cut; ``noise``: the pen's stated
    noise) is straight within `HOOKED_STRAIGHT` noise widths of its line and an end of ``coarse`` curls as a hook does
    (`lines.end_curl`, `lines.HOOK_CURL_DEG`): a line hooked at its ends, not a bow a circle explains."""
    centre, direction, _ = fit_line(bow)
    rel = bow - centre
    if float(np.abs(rel[:, 0] * direction[1] - rel[:, 1] * direction[0]).max()) >= HOOKED_STRAIGHT * noise:
        return False
    return lines.end_curl(coarse, noise) >= lines.HOOK_CURL_DEG


SLIT = 0.08
"""A loop read round whose width is under this share of its length is a line drawn out and back (a Quick, Draw! player's
line gone over twice: 0.03), no ellipse: the thinnest ellipses people drew in the design and fourth groups are 0.19 of
their length (tutorboard captured-chromium-v1, 5:1), the pen models' long ovals 0.23 and more."""


def out_and_back(found: Recognition, raw: np.ndarray) -> Recognition:
    """``found``, or, where it is an ellipse thinner than `SLIT`, the line the pen drew out and back along it: from end
    to end of ``raw`` (the stroke's points) along the ellipse's long axis."""
    shape = found.geometry
    if found.kind != "ellipse" or not isinstance(shape, Ellipse) or not shape.ry < SLIT * shape.rx:
        return found
    axis = np.array([math.cos(shape.angle), math.sin(shape.angle)])
    along = (raw - np.asarray(shape.center)) @ axis
    ends = [np.asarray(shape.center) + axis * float(f(along)) for f in (np.min, np.max)]
    return Recognition("line", found.confidence, Line(*((float(p[0]), float(p[1])) for p in ends)),
                       (("ellipse", round(1.0 - found.confidence, 4)),))
