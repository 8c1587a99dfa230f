"""The pen's own wobble measured on a stroke (`jitter`), and the bends a shape the stroke's size makes between its
points (`shape_bend`), against which a sparse stroke's jitter is judged; no classification, no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import burst_tangents
from physink_tui.scene.recognition.polygon_fit import best_polygons
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse
from physink_tui.scene.recognition.stroke_geometry import bbox_diagonal, median


def jitter(pts: np.ndarray) -> float:
    """The stroke's own pen jitter, in the points' units: how much the path's bend changes from one point to
    the next across the path (median-based), which white noise of spread s makes about s and a smooth curve,
    however tightly it bends or however sparsely it is sampled, makes small; about 0.4 for a tablet that
    rounds to whole pixels.

    >>> line = np.column_stack([np.arange(50.0), np.zeros(50)])
    >>> jitter(line)
    0.0
    """
    if len(pts) < 6:
        return 0.0
    d2 = pts[:-2] - 2 * pts[1:-1] + pts[2:]
    t = pts[2:] - pts[:-2]
    norm = np.hypot(t[:, 0], t[:, 1])
    ok = norm > 0
    if np.count_nonzero(ok) < 3:
        return 0.0
    if not ok.all():  # (where every step moves, the arrays as they are: the same numbers)
        t, d2, norm = t[ok], d2[ok], norm[ok]
    # the bend across the path, d2 . (-t_y, t_x) / |t| (white noise: successive bends anticorrelated, var 6 s^2 each)
    bend = d2[:, 0] * (-t[:, 1] / norm) + d2[:, 1] * (t[:, 0] / norm)
    return float(1.4826 * median(np.abs(bend[1:] - bend[:-1])) / math.sqrt(20))


def shape_bend(pts: np.ndarray) -> float:
    """How much a round shape as big as the stroke bends its path between neighbouring points, in the points' units:
    a circle d across (the bounding box's diagonal) turns its path by 2/d a unit length, so over a step s (the step
    along most of the path, `path_step`) it bends by 2 s^2/d; a shape with corners bends more where they fall. Dense
    tablet strokes give a few hundredths of a unit; a trackpad's 8-25 events round a box, tens of units.

    >>> square = np.array([[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]], dtype=float)
    >>> round(shape_bend(square), 2)
    14.14
    """
    if len(pts) < 2:
        return 0.0
    d = pts[1:] - pts[:-1]
    step = path_step(np.hypot(d[:, 0], d[:, 1]))
    size = bbox_diagonal(pts)
    return 2 * step * step / size if size > 0 else 0.0


END_PATH = 0.1
"""`path_step` judges the events' own step on the path but for this share of it at each end..."""
CLUSTER_STEP = 1 / 3
"""...and leaves out the run of steps at an end shorter than this share of that step: a finger's landing or lift..."""
CLUSTER_STEPS = 2
"""...where the run is this many steps or more (a landing's 4-10 events, a lift's hook of 2-4; a pen slowing as it
starts or stops by a single short step keeps it)."""


def path_step(steps: np.ndarray) -> float:
    """The step between the stroke's points (``steps``, in path order): their median, without a cluster of short steps
    at either end (`CLUSTER_STEPS` or more, each under `CLUSTER_STEP` of the median step of the path's body, its first
    and last `END_PATH` left out).
    However many short steps a finger's landing or a lift's hook adds at an end, a device's few events far apart keep
    their step (a trackpad's 8-25 events with 4-10 more where the finger settled: the plain median is the cluster's, a
    fifth of the events' or less, and a box's corners are then taken for a shaky hand's jitter, read round); a pen that
    only slows towards its ends keeps its median.

    >>> path_step(np.array([1.0, 1.0, 1.0, 1.0, 1.0, 50.0, 50.0, 50.0, 50.0, 50.0, 50.0, 1.0]))
    50.0
    >>> path_step(np.array([20.0, 30.0, 50.0, 50.0, 50.0, 50.0, 30.0, 20.0]))
    40.0
    """
    steps = np.asarray(steps, dtype=float)
    if len(steps) == 0:
        return 0.0
    middle = np.add.accumulate(steps) - steps / 2
    length = float(middle[-1] + steps[-1] / 2)
    body = steps[(middle >= END_PATH * length) & (middle <= (1 - END_PATH) * length)]
    short = steps < CLUSTER_STEP * median(body if len(body) else steps)
    first, last = 0, len(steps)
    while first < last and short[first]:
        first += 1
    while last > first and short[last - 1]:
        last -= 1
    first = first if first >= CLUSTER_STEPS else 0
    last = last if len(steps) - last >= CLUSTER_STEPS else len(steps)
    return median(steps[first:last] if last > first else steps)


SPARSE_STEP_OF_DIAGONAL = 0.08
"""Events whose step (`path_step`) is at least this share of the stroke's diagonal sample it sparsely (a circle by 25
events or fewer; a tablet's dense strokes step a hundredth of it): the path between them is not known."""
EVEN_TURNS = 0.75
"""A sparsely sampled closed stroke that turns at this share of its events or more by at least half its mean turn
(`turns_at_every_event`) has no sides: a box or polygon's events between its corners run straight (of the hcira and
itt strokes sampled by 8-25 events, one in four, 173 of the 187 closed round ones turn so, and none of the boxes or
polygons once round one way; counted before `EVEN_STEPS` was added)."""


EVEN_STEPS = 0.45
"""...and whose events are about evenly spaced (the steps' spread under this share of their mean): a hand going round
at a steady pace, sampled evenly in time; a pen slows into a box's corners, its events bunching there (the design
sources' circles by 8-25 events spread 0.19-0.50, 10th-90th percentile, median 0.32; the hurried pen model's boxes by
10-16 events that turn at every event 0.44-0.51)."""


def turns_at_every_event(pts: np.ndarray, diag: float) -> bool:
    """Whether a closed stroke's points are sparse samples (`SPARSE_STEP_OF_DIAGONAL`) that turn at nearly every one of
    them (`EVEN_TURNS`), spaced about evenly (`EVEN_STEPS`), once round one way: a round shape sampled by a few events,
    whose straight chords are the device's, not sides.

    >>> a = np.linspace(0, 2 * np.pi, 11)
    >>> turns_at_every_event(np.column_stack([np.cos(a), np.sin(a)]), 2 * np.sqrt(2))
    True
    >>> turns_at_every_event(np.array([[0, 0], [1, 0], [2, 0], [2, 1], [2, 2], [1, 2], [0, 2], [0, 1], [0, 0.]]), 2.8)
    False
    """
    if len(pts) < 5 or diag <= 0:
        return False
    d = np.diff(pts, axis=0)
    step = np.hypot(d[:, 0], d[:, 1])
    typical = path_step(step)  # not a finger's landing or lift, whose short steps may outnumber the events'
    first, last = 0, len(step)
    while last - first > 4 and step[first] < typical / 3:  # a hook or the last of a dwell at an end, at this scale
        first += 1
    while last - first > 4 and step[last - 1] < typical / 3:
        last -= 1
    d, step = d[first:last], step[first:last]
    if typical < SPARSE_STEP_OF_DIAGONAL * diag or float(np.std(step)) > EVEN_STEPS * float(np.mean(step)):
        return False
    sides = d[step > 0]
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    signed = (np.diff(heading) + math.pi) % (2 * math.pi) - math.pi  # at each event between the ends
    turn = np.abs(signed)
    if not 1.5 * math.pi <= abs(float(signed.sum())) <= 2.6 * math.pi or float(turn.sum()) > 2.75 * math.pi:
        return False  # not once round one way: a star (twice round) or a figure eight
    return bool(np.mean(turn >= 0.5 * turn.mean()) >= EVEN_TURNS)



BURST_JUMP = 4.0
"""A step between bursts of events (`round_in_bursts`) is at least this many times the stroke's median step..."""
BURST_JUMP_SHARE = 0.08
"""... and this share of its diagonal."""
BURST_PATH = 0.6
"""Such jumps are at least this share of the path (the pen's path between bursts is not known)."""
MOST_BURSTS = 8
"""... and at most this many: a round shape sampled in a few bursts."""
BURST_ROUND = 0.05
"""The stroke's own points (not the chords between them) miss the ellipse fitted to them by at most this (normalised
RMS radial error, `shape_fits.fit_ellipse`)..."""
BURST_ROUND_MOST = 0.1
"""... or by at most this where they lie clearly closer to that ellipse than to any outline of three or four sides
(`BURST_CLOSER`): a whole note 20-40 px across drawn by a hurried hand wobbles off its ellipse by 5-10 % of its size
(the pen models' whole notes through the mouse, tuning seeds), as much as a small box's or a rounded box's points miss
theirs; a box's points lie on its four sides, a note's on its ellipse."""
BURST_CLOSER = 1.3
"""The best polygon of three or four sides through the points (a polyline of two to four where the stroke was left
open) leaves at least this many times the squared distance the ellipse leaves (the pen models' small boxes through the
mouse 0.01-1.25, their whole notes 0.4-6.8, most over 1.3: tuning seeds)."""
BURST_SWEEP = 1.5 * math.pi
"""... and go round its centre one way by at least this much (the pen models' small parentheses through the mouse,
whose few bursts an ellipse fits, go round one 227-247 degrees; their whole notes that the rule reads round, 244-411,
five of 129 under 270: tuning seeds), ..."""
BURST_SWEEP_OPEN = 5 / 3 * math.pi
"""... by this much where the stroke was not closed (`open_reading.open_reading`): the pen models' square brackets
through the mouse go round their points' ellipse by up to 265 degrees (tuning seeds), their open whole notes 244-340."""
BURST_SWEEP_NEAR = 4 / 3 * math.pi
"""... or this much where its ends lie within `BURST_ENDS_NEAR` of each other: a round mark nearly closed (the pen
models' whole notes left open through the mouse go round their ellipse 243-366 degrees, ends 0.08-0.71 of the diagonal
apart; the brackets, parentheses, braces and C's of `bracket_habits`, `bracket_extremes`, `paren_habits`,
`mouse_habits`, `brace_habits` through the mouse whose points an ellipse fits go round it 219-271 degrees with their
ends 0.79-1.0 of the diagonal apart: tuning seeds)."""
BURST_ENDS_NEAR = 0.75
"""The share of the stroke's diagonal within which the ends of a round mark left open lie (`BURST_SWEEP_NEAR`)."""
BURST_GAP = 0.75 * math.pi
"""... leaving no gap round it wider than this."""


def burst_jumps(pts: np.ndarray, diag: float) -> tuple[np.ndarray, np.ndarray]:
    """The steps between ``pts`` and which of them jump between bursts of events (`BURST_JUMP`, `BURST_JUMP_SHARE`)."""
    d = pts[1:] - pts[:-1]
    step = np.hypot(d[:, 0], d[:, 1])
    return step, step >= max(BURST_JUMP * median(step), BURST_JUMP_SHARE * diag)


def round_in_bursts(pts: np.ndarray, diag: float, sweep: float = BURST_SWEEP, closed: bool = True,
                    ) -> EllipseFit | None:
    """The ellipse of a stroke whose points come in a few bursts joined by long jumps (`BURST_JUMP`, `BURST_PATH`,
    `MOST_BURSTS`: a busy mouse's events, whose chords are the device's, not the hand's path) and lie on an ellipse
    (`BURST_ROUND`, or `BURST_ROUND_MOST` and `BURST_CLOSER` or, closed, bursts tangent to it:
    `burst_tangents.tangent_to_one_curve`) going round it one way by ``sweep`` radians or more, no
    gap round it wider than `BURST_GAP`; else None. ``closed``: whether the stroke was read closed (where not, ends
    within `BURST_ENDS_NEAR` of each other need go round no more than `BURST_SWEEP_NEAR`, and may pass by their bursts
    tangent to the ellipse as a closed stroke's do: a whole note left open)."""
    if len(pts) < 8 or diag <= 0:
        return None
    step, jumps = burst_jumps(pts, diag)
    if not 3 <= int(jumps.sum()) <= MOST_BURSTS or float(step[jumps].sum()) < BURST_PATH * float(step.sum()):
        return None
    ellipse = fit_ellipse(pts)
    if ellipse is None or not ellipse[4] <= BURST_ROUND_MOST or not (ellipse[1] > 0 and ellipse[2] > 0):
        return None
    near = not closed and math.dist(pts[0], pts[-1]) <= BURST_ENDS_NEAR * diag
    if near:
        sweep = min(sweep, BURST_SWEEP_NEAR)  # nearly closed
    centre, rx, ry, angle, _ = ellipse
    rel = pts - np.asarray(centre)
    c, s = math.cos(angle), math.sin(angle)
    at = np.arctan2((-rel[:, 0] * s + rel[:, 1] * c) / ry, (rel[:, 0] * c + rel[:, 1] * s) / rx)
    moved = (at[1:] - at[:-1] + math.pi) % (2 * math.pi) - math.pi
    went = abs(float(moved.sum()))
    if went < sweep or went < 0.9 * float(np.abs(moved).sum()):
        return None  # not round one way
    around = np.sort(at % (2 * math.pi))
    gaps = np.diff(np.concatenate([around, around[:1] + 2 * math.pi]))
    if float(gaps.max()) > BURST_GAP:
        return None
    if ellipse[4] <= BURST_ROUND or ((closed or near) and burst_tangents.tangent_to_one_curve(pts, jumps, ellipse)):
        return ellipse
    return ellipse if _closer_to_ellipse(pts, ellipse, closed) else None


def _closer_to_ellipse(pts: np.ndarray, ellipse: EllipseFit, closed: bool) -> bool:
    """Whether ``pts`` lie clearly closer to ``ellipse`` than to the best polygon of three or four sides through them
    (polyline of two to four where not ``closed``): `BURST_CLOSER`, on summed squared distances."""
    (cx, cy), rx, ry, angle, _ = ellipse
    t = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    c, s = math.cos(angle), math.sin(angle)
    ex, ey = cx + rx * np.cos(t) * c - ry * np.sin(t) * s, cy + rx * np.cos(t) * s + ry * np.sin(t) * c
    near = np.min((pts[:, 0, None] - ex[None]) ** 2 + (pts[:, 1, None] - ey[None]) ** 2, axis=1)
    off = float(near.sum())
    fits = best_polygons(pts, closed=closed, max_sides=4, tolerance=0.0)
    sides = (3, 4) if closed else (2, 3, 4)
    least = min((fits[k][0].rss for k in sides if fits.get(k)), default=math.inf)
    return least >= BURST_CLOSER * off


MERGED_STEP = 0.5
"""`turns_evenly_at_events` takes events nearer each other than this share of the stroke's step (`path_step`) for
one: the pen slowing into a hook or a corner sends its events close together, and the turn it makes there is one turn,
the hand's (a parenthesis hooked at its ends, whose hooks' turns spread over a few close events would pass for a round
stroke's even turning; `penmodels.paren_habits` through the tablet, tuning seeds)."""
EVENT_TURNS = 2 / 3
"""A round stroke of a few events turns at this share of them or more by at least half its mean turn (the pen models'
whole notes left open through a tablet, read round, 0.62-1.0, all but one 0.67 or more; a hooked brace by 10 events
whose curls hold the turning, 0.5-0.62: tuning seeds); an open stroke's ends and uneven sampling keep it under the
closed loop's `EVEN_TURNS`."""


def turns_evenly_at_events(pts: np.ndarray, diag: float, smooth: float) -> bool:
    """Whether ``pts`` are a few events far apart (`SPARSE_STEP_OF_DIAGONAL`: a tablet's event every 15-30 ms under a
    small stroke drawn fast, 7-16 events round a whole note) turning at most of them (`EVENT_TURNS`), under ``smooth``
    of the turning done at the sharpest fifth of them (a fifth rounded up, two at least; as
    `stroke_features.turn_concentration`). A round stroke so sampled turns at every event, more where the device
    happened to leave a longer gap (uneven sampling); the chords between are the device's, so a turning resampled along
    them takes each event for a corner. A bracket or a brace so sampled turns at its corners or curls alone.

    >>> a = np.linspace(0, 1.6 * np.pi, 9)
    >>> turns_evenly_at_events(np.column_stack([np.cos(a), np.sin(a)]), 2.8, 0.55)
    True
    >>> turns_evenly_at_events(np.array([[3, 0], [0, 0], [0, 2], [0, 4], [0, 6], [3, 6.]]), 6.7, 0.55)
    False
    """
    if len(pts) < 5 or diag <= 0:
        return False
    d = np.diff(pts, axis=0)
    typical = path_step(np.hypot(d[:, 0], d[:, 1]))
    if typical < SPARSE_STEP_OF_DIAGONAL * diag:
        return False
    kept = [pts[0]]  # events nearer the last one kept than `MERGED_STEP` of the step are one with it
    for p in pts[1:-1]:
        if math.dist(p, kept[-1]) >= MERGED_STEP * typical:
            kept.append(p)
    if math.dist(pts[-1], kept[-1]) >= MERGED_STEP * typical:
        kept.append(pts[-1])
    sides = np.diff(np.asarray(kept), axis=0)
    if len(sides) < 4:
        return False
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    turn = np.abs((np.diff(heading) + math.pi) % (2 * math.pi) - math.pi)
    total = float(turn.sum())
    if total <= 0 or float(np.mean(turn >= 0.5 * turn.mean())) < EVENT_TURNS:
        return False
    return float(np.sort(turn)[-max(2, math.ceil(len(turn) / 5)):].sum()) < smooth * total
