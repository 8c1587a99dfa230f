"""Whether a stroke is a closed loop, and which loop: a gap or an overshoot at the ends, a polygon the pen left before
closing it, a lumpy circle whose lumps are not sides; the fitting and ranking are `recognize`'s."""

from __future__ import annotations

import enum
import itertools
import math

import numpy as np

from physink_tui.scene.recognition import (
    end_crossings,
    open_shapes,
    open_stars,
    pen_noise,
    shape_corners,
    shape_turning,
)
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.candidates import ellipse_distances
from physink_tui.scene.recognition.loop_ends import HOOKED_TURN, SMALL_LOOP, cut_ends, turned_by_hooks
from physink_tui.scene.recognition.polygon_checks import SHARP_CORNER, SHARP_SHARE, crossings
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse

LUMPY_SIDES = 4
"""A closed stroke that turns smoothly all round (`open_shapes.SMOOTH`, judged as open strokes are, on 32 to 40
points a few noise widths apart: `shape_turning.coarse_turning`) is offered
no polygon of `LUMPY_SIDES` sides or more: a lumpy circle drawn with a mouse (sparse points, flat stretches) fits
a quad, pentagon or hexagon closely, but a drawn polygon turns at its corners."""
LUMPY_ASPECT = 0.5
"""Only a loop whose fitted ellipse is at least this wide for its length is judged lumpy-round (an oval drawn by a
person is rarely flatter than 2:1; a thin box is far flatter)."""


FAR_FROM_ROUND = 2.0
"""A closed loop whose fitted ellipse misses it by more than this many times the most a round stroke may miss
(`open_shapes.round_error`: its normalised RMS radial error) is no circle or ellipse, however its sides fail as a
polygon's: a star, a scribble. Measured (fits of the closed loops read round and labelled round): the 949 of the design
sets at most 1.10 of that allowance, the 207 of the fourth group (opened, not designed on) at most 1.19; a drawn
star's outline with deep points misses its ellipse by 2.7-3.2 of it (a regular triangle, sides at half its radius, by
about 2)."""
TURNS_BACK = 180.0
"""A closed loop that turns back against its own sense by this many degrees in all (on its coarse turning,
`shape_turning.coarse_turning`: 32-40 points a few noise widths apart) is no circle or ellipse: a star's outline turns
back at each inner corner (a regular star's outline, whatever its points and depth, by 360 degrees in all, less the
rounding its corners get), while an oval turns one way all round; a six- or seven-pointed star fits an ellipse within
`FAR_FROM_ROUND` (a hexagram's inner corners are at 0.58 of its tips' radius) and needs more sides than
`candidates.MAX_SIDES`. Measured on the closed loops read round and labelled round: the design sets' 949 turn back at
most 88 degrees (a dent where the ends meet), the fourth group's 207 at most 43."""


def no_round_shape(loop: np.ndarray, noise: float, ellipse: EllipseFit | None) -> bool:
    """Whether a closed loop is no circle or ellipse whatever the ranking would say: its `fit_ellipse` misses it by
    more than `FAR_FROM_ROUND` times `open_shapes.round_error`, or it turns back by `TURNS_BACK` in all (a star) and its
    ellipse misses it by more than `WITHIN_ROUND` of that error (a tremor turns a slow hand's circle back too)."""
    allowed = open_shapes.round_error(ellipse, noise) if ellipse is not None else 0.0
    if ellipse is not None and ellipse[4] > FAR_FROM_ROUND * allowed:
        return True
    return (ellipse is None or ellipse[4] > WITHIN_ROUND * allowed) and turned_back(loop, noise) >= TURNS_BACK


WITHIN_ROUND = 0.8
"""A closed loop whose ellipse misses it by no more than this share of what a round stroke may
(`open_shapes.round_error`) is not refused as a star for turning back (`TURNS_BACK`): a slow, unsteady hand's tremor
(4-7 Hz at 180-300 px/s: waves 25-75 px long) makes a circle's coarse turning wiggle back by up to 850 degrees in all,
but its ellipse misses it by 0.1-0.65 of that allowance (the pen models' circles, ovals, eggs and lumpy circles drawn
by `penmodels.hurried.SHAKY_SLOW`, tuning seeds 0-29), while a star's outline misses its ellipse by 1.01-2.4 of it (the
pen models' five- to seven-pointed stars, every pen, the same seeds); between the two. Held-back seeds 1000-1029: the
slow hand's round shapes 0.05-0.71, the stars 0.79-2.49 (one six-pointed star through a coarse device at 0.79)."""


def turned_back(loop: np.ndarray, noise: float) -> float:
    """How far (degrees, in all) a closed loop turns against the sense it turns round in, on its coarse turning."""
    th = shape_turning.coarse_turning(loop, noise)
    sense = 1.0 if float(th.sum()) >= 0.0 else -1.0
    return float(np.degrees(-sense * th[th * sense < 0].sum()))


def lumpy_round(loop: np.ndarray, noise: float, ellipse: EllipseFit | None, raw: np.ndarray, diag: float) -> bool:
    """A closed loop about as wide as it is long (its ellipse, `fit_ellipse` of it, no flatter than `LUMPY_ASPECT`)
    that turns smoothly all round: a circle drawn lumpily, whose lumps are not sides (a thin box's jittery long sides
    are not lumps); or sampled by a few events that it turns at nearly every one of (`pen_noise.turns_at_every_event`:
    a circle by 8-12 events is an octagon to fit, but a drawn polygon runs straight through its events between
    corners)."""
    if ellipse is None or not ellipse[2] >= LUMPY_ASPECT * ellipse[1]:
        return False
    return (sf.turn_concentration(shape_turning.coarse_turning(loop, noise)) < open_shapes.SMOOTH
            or pen_noise.turns_at_every_event(raw, diag))


class LeftOpen(enum.Enum):
    """Which test found a polygon the pen left open (`polygon_left_open`)."""

    SIDES = "straight sides turning most of the way round, the last heading home"
    MANY_SIDES = "many sharp corners, one side missing"  # `many_sided_left_open`
    ROUNDED_CORNERS = "many corners the hand rounded, one side missing"  # `shape_corners`
    STAR = "a star's points and dents in turn, one side missing"  # `open_stars.star_left_open`


def polygon_left_open(work: np.ndarray, diag: float, drawn: np.ndarray | None = None) -> LeftOpen | None:
    """Straight sides turning most of the way round, the last one heading for the start: a polygon the pen
    left before closing it (or a many-sided one left open by a side, `many_sided_left_open`, or such a one whose
    corners the hand rounded, `shape_corners.rounded_many_sided_left_open`, asked of ``drawn``, the stroke's own
    points, where given). Says which of the three closed it, or None: none did."""
    length = sg.path_length(work)
    if length < 1.75 * diag:
        return None
    closure = sf.closure(work, diag)
    if closure >= LEFT_OPEN_CLOSURE:
        return None
    th = sg.turning(work)
    turned = abs(float(np.add.reduce(th)))
    if turned < LEFT_OPEN_TURN - LEFT_OPEN_WOBBLE:
        return None
    if closure < 0.42:
        corners = sf.drop_end_stubs(work, sg.find_corners(work, th=th), length)
        runs = [work[a:b + 1] for a, b in itertools.pairwise(corners)]
        if ((turned >= LEFT_OPEN_TURN or abs(sides_turning(work[corners])) >= LEFT_OPEN_TURN)
                and len(runs) >= 3 and all(sg.chord_deviation(r) < open_shapes.STRAIGHT for r in runs[1:-1])
                and max(sg.chord_deviation(runs[0]), sg.chord_deviation(runs[-1])) < LAST_SIDE_BOW
                and (sf.heading_home(work, corners) or star_run_past_its_start(work, corners)
                     or sf.ran_through_first_corner(work, corners))):
            return LeftOpen.SIDES
    # the corners at every dip, and the bends, each found once for the tests below that look for the same ones
    dips = sf.drop_end_stubs(work, sg.find_corners(work, MANY_SIDED_TURN_DEG, every_dip=True, th=th), length)
    if many_sided_left_open(work, length, dips):
        return LeftOpen.MANY_SIDES
    bent = shape_corners.bends(work)
    if shape_corners.rounded_many_sided_left_open(work, drawn, bent):
        return LeftOpen.ROUNDED_CORNERS
    if open_stars.star_left_open(work, length, dips if open_stars.DENT_DEG == MANY_SIDED_TURN_DEG else None, bent):
        return LeftOpen.STAR
    return None



def corners_told(how: LeftOpen, work: np.ndarray, drawn: np.ndarray) -> bool:
    """Whether a polygon left open (closed by ``how``) has its rounded corners told by its turning
    (`shape_corners.rounded_many_sided_left_open`, asked of ``drawn``): known where that test closed it, asked where an
    earlier one did (its straight sides or sharp corners found first; as until main 9f69154, which read 4 of 60 held
    hexagons to octagons left open through a mouse as circles, `tests/test_many_sided.py`)."""
    return how is LeftOpen.ROUNDED_CORNERS or shape_corners.rounded_many_sided_left_open(work, drawn)

LEFT_OPEN_CLOSURE = 0.75
"""A polygon left open has a gap under this share of its diagonal (`stroke_features.closure`); under 0.42 it may have
any number of sides, from 0.42 on only many sides (`many_sided_left_open`: one side of an irregular hexagon drawn
narrow, 0.5-0.6 of it in Quick, Draw!)."""
LEFT_OPEN_CORNERS = 4
"""A polygon of five sides or more left open by one side (a Quick, Draw! player's hexagon or octagon, the game ending
as it guessed) shows at least this many corners between its ends: it turns only 200-250 degrees, less than
`LEFT_OPEN_TURN`, but its sides and the gap close a convex outline (`many_sided_left_open`); a bracket, a U or a C shows
two or three."""
MANY_SIDED_TURN_DEG = 25.0
"""The corners of such a polygon are found where the path turns this much or more (`stroke_geometry.find_corners`,
every dip: an irregular octagon's corners turn 25-65 degrees, its sides as short as the corner finder's straw); an
arc's turning is spread along it, so the corners must be sharp too (`SHARP_SHARE`)."""
LEFT_OPEN_GAP = 1.5
"""The gap of such a polygon is no longer than this many times its longest side drawn: one side missing (two missing
leave a gap of 1.7-1.9 sides on a regular hexagon, an outline half drawn)."""


def many_sided_left_open(work: np.ndarray, length: float, dips: list[int] | None = None) -> bool:
    """Whether a stroke (``length`` long) of `LEFT_OPEN_CORNERS` corners or more (turning `MANY_SIDED_TURN_DEG` or
    more), sharp ones (`SHARP_SHARE` of them within `polygon_checks.SHARP_CORNER`), its sides straight
    (`open_shapes.STRAIGHT`; the first and last up to `LAST_SIDE_BOW`: the hand swings as it lands and lifts), is a
    polygon left open by one side: the gap (`LEFT_OPEN_GAP`) and the sides make a convex outline, turning the same way
    at every vertex once round. ``dips``: those corners, where already found."""
    corners = (sf.drop_end_stubs(work, sg.find_corners(work, MANY_SIDED_TURN_DEG, every_dip=True), length)
               if dips is None else dips)
    if len(corners) - 2 < LEFT_OPEN_CORNERS:
        return False
    sides = sf.closing_sides(work, corners, open_shapes.STRAIGHT, LAST_SIDE_BOW, LEFT_OPEN_GAP)
    if sides is None:
        return False
    turns = sf.ring_turns(sides)
    if not ((turns > 0).all() or (turns < 0).all()) or abs(abs(float(turns.sum())) - 2 * math.pi) > 0.1:
        return False
    roundness = np.asarray(sf.corner_roundness(work, corners))
    return float(np.mean(roundness < SHARP_CORNER)) >= SHARP_SHARE


STAR_CROSSINGS = 3
"""A star drawn in one stroke crosses its own sides five times (a pentagram); an open mark whose last stroke runs
back across its first (the $1 delete mark, an alpha) crosses once. From this many crossings on, a stroke whose last
side runs on past its start is a star whose last stroke overshot, not an open mark."""


def star_run_past_its_start(work: np.ndarray, corners: list[int]) -> bool:
    """The last side ran on past the start (the start lies behind the end, within `stroke_features.heading_home`'s
    50 degrees of the side's line) and the sides cross one another like a star's."""
    last, home = work[-1] - work[corners[-2]], work[0] - work[-1]
    norms = float(np.hypot(*last) * np.hypot(*home))
    if norms == 0.0 or float(last @ home) / norms > -math.cos(math.radians(50.0)):
        return False
    return crossings(work[corners]) >= STAR_CROSSINGS


LAST_SIDE_BOW = 0.2
"""The last side of a polygon left open may bow this much (of its chord): the hand swings home as it lifts, while the
sides between are drawn straight (`open_shapes.STRAIGHT`); so may the first, where the hand swings as it lands (the
last side of the polygon drawn the other way: until session 31 the first was held straight, and hcira klarubbio s06
triangle03, its last side bowed 0.13, read open drawn backwards)."""
LEFT_OPEN_TURN = 1.15 * math.pi
"""A polygon left open has turned at least this far round: a triangle short of its last side has turned a half turn
and the angle of the corner it did not reach (an equilateral one 1.33 pi; one left open at a 30-degree corner, as
people's triangles have, 1.17 pi: at the 1.25 pi this was until session 23, the pen models' triangles left open at a
corner under 45 degrees read as polylines, `penmodels.triangle_habits`). Measured: no design or fourth-group reading
changed between 1.25 and 1.15 pi."""
LEFT_OPEN_WOBBLE = 0.5 * math.pi
"""How much of that turning a hurried hand's hook or wobble at an end may undo on the path itself; then the turning is
taken from corner to corner, along the sides' chords (the corners the hand meant), not from every wiggle."""


def sides_turning(corners: np.ndarray) -> float:
    """The signed turning of the chain of sides through ``corners`` (radians)."""
    sides = np.diff(corners, axis=0)
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    return float(((np.diff(heading) + math.pi) % (2 * math.pi) - math.pi).sum())


def closed_loop(raw: np.ndarray, work: np.ndarray, diag: float, sigma: float, fit: bool = True,
                 ) -> tuple[bool, np.ndarray, EllipseFit | None]:
    """Whether the stroke closes (judged on the raw ends: a gap, or drawn past its start), the stroke once round (an
    overshoot past the start, or a start before the end, cut at the closest approach), and that loop's `fit_ellipse`
    where it was fitted here (None when it was not: `recognize` fits it then). Unless ``fit``, only the loop is asked:
    a stroke gone round one way and back past its start is cut there once round, whether round or not, no ellipse
    fitted (`rounded_polygons.polygon_rounded`'s cut from the other end)."""
    if sg.path_length(work) < 1.75 * diag:  # the smoothed path: jitter lengthens the raw one
        return False, work, None
    th = sg.turning(work)
    turned = abs(float(np.add.reduce(th)))  # (`.sum()`'s own sum, without its per-call overhead; `th` stays as it is)
    coarse = shape_turning.coarse_turning(work, sigma)
    limit = max(CLOSED_GAP * diag, 4 * sigma)
    once: np.ndarray | None = None  # the stroke once round where it came back to its start, going round one way
    if turned > 2.0 * math.pi and abs(float(np.add.reduce(coarse))) > 0.8 * float(np.add.reduce(np.abs(coarse))):
        loop, back = _once_round(work, th, limit)  # round and round one way: once round is the shape, if round
        # not a lead-in drawn out and back along itself, nor a hook's small loop at an end
        back = back and encloses(loop) and sg.bbox_diagonal(loop) >= SMALL_LOOP * diag
        ellipse = fit_ellipse(loop) if back and fit else None  # fitted only where it may be kept
        if back and (not fit or (ellipse is not None and ellipse[4] < open_shapes.round_error(ellipse, sigma))):
            return True, loop, ellipse
        once = loop if back else None
    if turned > HOOKED_TURN * math.pi and sf.retraced(work, th, diag) and not turned_by_hooks(work):
        return True, sf.one_loop(work, th), None  # a shape gone round twice over the same sides: once is enough
    if (once is not None and TWICE_ROUND < turned < SPIRAL_TURN and self_crossings(work) < STAR_CROSSINGS
            and _beside(work, once, diag)):
        return True, once, None  # gone round again beside the first lap, not over it: the first lap is the shape
    n = len(work)
    gap = float(np.hypot(*(raw[-1] - raw[0])))
    half = max(2, n // 2)  # as many points at either end (an odd count's middle point in neither)
    tail, head = work[n - half:], work[:half]
    d_tail = np.hypot(*(tail - work[0]).T)
    d_head = np.hypot(*(head - work[-1]).T)
    if min(gap, 2 * float(d_tail.min()), 2 * float(d_head.min())) > limit and not ends_cross_or_run_on(work, diag):
        return False, work, None
    if gap > limit and end_crossings.x_run_past(work, diag, CLOSED_GAP):
        return False, work, None  # an x's or a delete mark's end runs on past its start (`end_crossings.RUN_PAST`)
    loop = cut_ends(work, gap, d_tail, d_head)
    if len(loop) < 8:
        return True, work, None
    if sg.bbox_diagonal(loop) < SMALL_LOOP * diag:
        # a loop on a long shaft or between long tails: an arrow's closed head, an x drawn round
        return False, work, None
    return True, loop, None


ENCLOSES = 0.1
"""A stroke once round (`_once_round`) is a loop only where it encloses at least this share of what a circle of its
length would (its isoperimetric quotient, 4 pi area / length^2: a circle 1, a square 0.79, a 3:1 oval 0.73, a 12:1 box
0.22): a pen that lands on a box's first side, runs along it, turns back to the corner and turns again onto it (the
first side drawn twice over, `penmodels.box_habits` ``first-side-redrawn``) has turned a whole turn by the time it is
back at its start, on a sliver of no area (0.00-0.05), which an ellipse as thin fits closely. Nor is a loop once round
smaller than `loop_ends.SMALL_LOOP` of the stroke the shape (as where the ends are cut, `closed_loop`): the hurried
hand's box with its last side drawn twice over, drawn backwards, comes back on a hook's loop 0.09-0.15 of its size.
Measured on the 675 strokes of the design and fourth groups that come back once round: the least quotient is 0.19 (a
star's outline, no round shape); session 23 (wt-corners)."""


def encloses(loop: np.ndarray) -> bool:
    """Whether a closed path encloses an area (`ENCLOSES`), not a sliver drawn out and back along itself."""
    length = sg.path_length(loop) + float(np.hypot(*(loop[-1] - loop[0])))
    x, y = loop[:, 0], loop[:, 1]
    area = 0.5 * abs(float(x @ sg.succ(y) - y @ sg.succ(x)))
    return length > 0.0 and 4 * math.pi * area / (length * length) >= ENCLOSES


def _once_round(work: np.ndarray, th: np.ndarray, limit: float) -> tuple[np.ndarray, bool]:
    """The stroke once round (`stroke_features.one_loop`, from its start, or from its end where only that comes back)
    and whether it came back within ``limit`` of where it began: from both ends where the stroke crosses itself (a
    pigtail's tails cross, and one of them may be short enough to come back), from either end where it does not (a
    circle drawn on past its start and out: once round from its end the overshoot is a lead-in that does not). Asked
    of both ends alike, so that a stroke reads the same drawn either way; but a stroke whose ends meet is judged from
    its start alone, as before (once round from one end may stop short where a hook's turn adds to the count)."""
    loop = sf.one_loop(work, th)
    back = float(np.hypot(*(loop[-1] - loop[0]))) <= limit
    if float(np.hypot(*(work[-1] - work[0]))) <= limit:
        return loop, back
    other = sf.one_loop(work[::-1], -th[::-1])
    back_other = float(np.hypot(*(other[-1] - other[0]))) <= limit
    if back == back_other:
        return loop, back
    if crosses_itself(work):
        return loop, False
    return (loop, True) if back else (other[::-1], True)


CROSSING_POINTS = 48
"""`crosses_itself` judges a path on this many points (a pigtail's crossing is between long runs; a hook's wiggle at an
end is no crossing)."""


def crosses_itself(work: np.ndarray) -> bool:
    """Whether an open path crosses itself (judged on `CROSSING_POINTS` points along it)."""
    return self_crossings(work) > 0


def self_crossings(work: np.ndarray) -> int:
    """How many times an open path crosses itself (judged on `CROSSING_POINTS` points along it)."""
    a = sg.resample(work, CROSSING_POINTS)
    i, j = np.triu_indices(len(a) - 1, 2)
    p, r, q, s = a[i], a[i + 1] - a[i], a[j], a[j + 1] - a[j]
    den = r[:, 0] * s[:, 1] - r[:, 1] * s[:, 0]
    qp = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qp[:, 0] * s[:, 1] - qp[:, 1] * s[:, 0]) / den
        u = (qp[:, 0] * r[:, 1] - qp[:, 1] * r[:, 0]) / den
    return int(np.count_nonzero((den != 0) & (t > 0) & (t < 1) & (u > 0) & (u < 1)))


TWICE_ROUND = 3.0 * math.pi
"""A stroke turning one way more than this (half way round a second time) whose first lap came back to its start
(`_once_round`) is that lap, the rest a second lap drawn beside it (a box gone round twice, the second lap a tenth of
its size out: hcira shriyansnidhish s02 rectangle01, `penmodels.box_slips` ``laps-apart``); a second lap drawn over
the first is `stroke_features.retraced`, a spiral is `coils.helix_or_scribble`'s before this is asked, a star drawn
crossing itself crosses itself `STAR_CROSSINGS` times or more (people's pentagrams come back once round, and lie
within `CLOSED_GAP` of it), and the second lap must lie beside the first (`_beside`)."""
SPIRAL_TURN = 4.5 * math.pi
"""A stroke turning one way this far is past two laps and a quarter of a third: a spiral drawn square (a tutorboard
sample labelled "negative" turns 4.58 pi, each lap inside the last), not a box gone round twice (`TWICE_ROUND`; the
pen models' ``laps-apart`` boxes turn 3.0-4.3 pi, hooks and all)."""
CLOSED_GAP = 0.2
"""A stroke whose ends are closer than this share of its size (or a few noise widths) is closed."""


def hook_kept_apart(work: np.ndarray, unhooked: np.ndarray, diag: float, sigma: float) -> bool:
    """Whether a stroke's ends meet (within `CLOSED_GAP` of its size, or four noise widths) once the hooks where the
    pen landed or lifted are cut (``unhooked``, `stroke_geometry.remove_hooks` of ``work``), and the rest does not
    cross itself (a pigtail's tails cross): a 10-30 px circle's hook of a few pixels is a fifth of its size."""
    if len(unhooked) == len(work):
        return False
    gap = float(np.hypot(*(unhooked[-1] - unhooked[0])))
    return gap <= max(CLOSED_GAP * diag, 4 * sigma) and not crosses_itself(unhooked)


def _beside(work: np.ndarray, lap: np.ndarray, diag: float) -> bool:
    """Whether nine points in ten of ``work`` lie within `CLOSED_GAP` of its size (``diag``) of ``lap``: a second lap
    drawn beside the first, not a scribble's loops wandering off (a Quick, Draw! squiggle's first loop comes back)."""
    d = np.hypot(work[:, None, 0] - lap[None, :, 0], work[:, None, 1] - lap[None, :, 1]).min(axis=1)
    return float(np.quantile(d, 0.9)) < CLOSED_GAP * diag


def ends_cross(work: np.ndarray, diag: float) -> bool:
    """Whether the stroke's ends ran on past each other after closing it: its path crosses itself where each end's
    tail beyond the crossing is no longer than the gap a closed stroke's ends may leave (`CLOSED_GAP` of its size):
    a triangle closed in a hurry, its tails crossing at a corner, however far apart the ends lifted. A delete mark's or
    an x's first and last strokes cross at their middles, far from the ends; a pigtail's crossing is between long
    tails."""
    return end_crossings.crossed_close(work, diag, CLOSED_GAP, CLOSED_GAP)


def ends_cross_or_run_on(work: np.ndarray, diag: float) -> bool:
    """`ends_cross`, or a polygon of four sides or more closed by crossing its ends, one of them run on past the
    crossing by up to `end_crossings.RUN_ON` of its size (`end_crossings.crossed_close`)."""
    return end_crossings.crossed_close(work, diag, CLOSED_GAP, end_crossings.RUN_ON)


TAIL_RUNS_OFF = 1.2
"""A closed stroke whose points run off the ellipse fitted to its loop (once round, its ends cut off:
`loop_ends.cut_ends`, `_once_round`) by more than this many times that ellipse's half-length (its longer half-axis)
has a pigtail's tail, not a round shape's overshoot or flick: the loop itself hugs its ellipse. Measured square across
the ellipse (`candidates.ellipse_distances`), session 27: hcira klarubbio's two pigtails drawn loop first 1.75 and
2.12; the loop-first pigtails of `tests/penmodels/pigtail_habits` (tails 1.6-3 half-lengths) 1.28 and more on the
tuning seeds; ovals closed with a flick of up to 1.2 half-lengths off the loop (`tests/penmodels/circle_habits`
flicked-oval) at most 1.06. Session 26's rule measured the same stray against the half width (1 of it) and took those
ovals for pigtails (a flick leaves a long oval by more than its half width)."""


def tail_runs_off(work: np.ndarray, loop: np.ndarray, ellipse: EllipseFit | None) -> bool:
    """Whether ``work`` (the stroke) runs off the ellipse fitted to ``loop`` (the stroke once round) farther than
    `TAIL_RUNS_OFF` of its half-length: the pen ran on off the loop (a pigtail's tail). False where the loop is the
    whole stroke."""
    if ellipse is None or loop is work or (loop.shape == work.shape and np.array_equal(loop, work)):
        return False
    centre, rx, ry, angle, _ = ellipse
    return float(ellipse_distances(work, centre, rx, ry, angle).max()) > TAIL_RUNS_OFF * max(rx, ry)
