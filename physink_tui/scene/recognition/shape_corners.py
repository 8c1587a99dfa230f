"""Corners at the scale of a stroke's shape: its turning gathered into short bends between straight runs, as a hurried
hand draws a many-sided polygon's corners rounded, where a round shape turns evenly all along."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from physink_tui.scene.recognition.stroke_geometry import resample, turning

STEPS = 40
"""The path is judged on this many points (39 steps): a hexagon's side is six or more steps, an octagon's five."""
STRAIGHT_STEP_DEG = 6.0
"""A step turning less than this is straight: a round shape drawn once round turns 9 degrees a step, most of a turn
left open 7; an octagon's sides, drawn straight, turn a degree or two a step."""
BEND_STEPS = 4
"""A corner is a bend (a run of steps each turning `STRAIGHT_STEP_DEG` or more, the same way) of at most this many steps
(a tenth of the path): a hand rounds a corner over up to a fifth of each side meeting there, half a hexagon's side
left open (eight steps) or two thirds of an octagon's (five or six), and a mouse's sparse points blur it over a step
more; a round shape's turning runs on for many steps."""
CORNER_DEG = 25.0
"""...that turns this much or more in all: an irregular octagon's corners turn 25-65 degrees (`closed_loops`'
`MANY_SIDED_TURN_DEG`)."""


class Bend(NamedTuple):
    """A run of steps of the resampled path (``first``..``last``, the turn at point k + 1 being step k) turning one
    way, ``degrees`` in all (signed)."""

    first: int
    last: int
    degrees: float


def bend_runs(steps: list[float], least: float) -> list[Bend]:
    """The runs of ``steps`` (degrees, one a step) turning ``least`` or more each, the same way, as bends."""
    found: list[Bend] = []
    k = 0
    while k < len(steps):
        if abs(steps[k]) < least:
            k += 1
            continue
        j = k
        while j + 1 < len(steps) and abs(steps[j + 1]) >= least and (steps[j + 1] > 0) == (steps[k] > 0):
            j += 1
        found.append(Bend(k, j, float(sum(steps[k:j + 1]))))
        k = j + 1
    return found


def bends(work: np.ndarray) -> tuple[np.ndarray, np.ndarray, list[Bend]]:
    """The path resampled to `STEPS` points, its turning (degrees, one a step) and its bends: runs of steps turning
    `STRAIGHT_STEP_DEG` or more, each the same way."""
    pts = resample(work, STEPS)
    th = np.degrees(turning(pts))
    return pts, th, bend_runs(th.tolist(), STRAIGHT_STEP_DEG)


def corner_bends(found: list[Bend], longest: int = BEND_STEPS) -> list[Bend]:
    """The bends that are corners: short (under ``longest`` steps) and turning `CORNER_DEG` or more."""
    return [b for b in found if b.last - b.first < longest and abs(b.degrees) >= CORNER_DEG]


AT_CORNERS = 0.7
"""A polygon left open by one side does this share of its turning (or more) at its corners (`corner_bends`): every
turn an outline drawn straight between corners makes is at one, whether drawn sharp or rounded (Quick, Draw!
hexagons and octagons left open: 0.70-0.86), while an arc, a circle left open or a C turns all along."""
STRAIGHT_SHARE = 0.45
"""...and runs straight (`STRAIGHT_STEP_DEG`) for this share of its steps or more: its sides, rounded at the ends by
up to a fifth each, are straight over the rest (Quick, Draw! hexagons and octagons left open: 0.50-0.66), while a round
shape turns at nearly every step (the design sources' circles left open that would pass the rest: 0.29-0.37, dollar1
s04's, drawn fast as a few chords)."""
CORNER_TURN = 0.8
"""...and its corners turn, on the mean, at least this share of what a regular polygon's do (360 / n degrees, n the
corners found and the two the gap closes): a lumpy circle's bends, many and shallow, turn 0.75-0.8 of that for their
number (the design sources' circles above, `penmodels.many_sided` round-left-open through a mouse), a hexagon's or an
octagon's corners 0.84-1.1 (Quick, Draw!)."""
LEAST_CORNERS = 4
"""...at this many corners or more between its ends (`closed_loops.LEFT_OPEN_CORNERS`): a U, a C or a bracket shows
two or three."""
LEFT_OPEN_BEND_STEPS = 5
"""A polygon left open may round a corner over this many steps (one more than `BEND_STEPS`): over up to a third of
each side meeting there, as `rounded_polygons.LONGEST_BEND` allows a closed one (issue 25, session 34: a Quick,
Draw! hexagon's two corners rounded over 5 steps, 82 and 104 degrees, and an octagon's 77, read as a curve and a
polyline); the straight share and the turning at the corners still hold a round shape out."""
ENDS_ON_A_SIDE_DEG = 10.0
"""The stroke's end (and its start) may turn less than this either way on the ring of its sides and the gap: the pen
lifted part-way along its last side, the gap running on along it to the start (or landed part-way along the first);
every corner drawn turns the loop's way. A circle or an arc left open turns its way at both ends of the gap (its
chord), by half the arc left out (issue 25, session 34: the hexagon and the octagon above ended 5 and 3 degrees the
other way, on a line through their start)."""
GAP_SIDES = 1.5
"""...and its gap is no longer than this many times its longest side drawn (`closed_loops.LEFT_OPEN_GAP`)."""


SIDE_CLEAR = 0.2
"""A side is drawn through the device's events where one of them lies at least this share of the side from both its
corners (`drawn_through`): the hand rounds a corner over up to a fifth of each side meeting there (`BEND_STEPS`), so an
event nearer a corner may be the corner's own. A round stroke sampled in bursts (a busy event loop's 2-5 events a few
ms apart, then a gap) or with repeated events turns at each burst, and its chords hold no event clear of their ends
(issue 25, session 27: `benchmarks/bench_circle_gestures.py`' open circles through a mouse, 0.04-0.21 at the side
least drawn through, were polygons), where a polygon's side drawn through the same mouse holds one 0.25 or more of it
from both ends (`benchmarks/bench_many_sided.py`, tuning seeds), and Quick, Draw! hexagons and octagons 0.41-0.5."""


def drawn_through(corners: np.ndarray, drawn: np.ndarray) -> bool:
    """Whether the stroke's own points (``drawn``) hold one or more between each two neighbouring ``corners`` (each
    taken at the drawn point nearest it) standing clear of both (`SIDE_CLEAR`): a polygon's side is drawn straight
    through the device's events between its corners, while a round stroke sampled by a few events (8-12 over a circle,
    evenly in time, or in bursts, or repeated) turns at every one of them, its chords from event to event the device's,
    not sides (`pen_noise.turns_at_every_event`, for closed loops)."""
    d = np.hypot(drawn[None, :, 0] - corners[:, None, 0], drawn[None, :, 1] - corners[:, None, 1])
    at = np.argmin(d, axis=1)
    for k in range(len(corners) - 1):
        lo, hi = sorted((int(at[k]), int(at[k + 1])))
        side = float(np.hypot(*(corners[k + 1] - corners[k])))
        if hi - lo < 2 or side == 0.0:
            return False
        clear = np.minimum(d[k, lo + 1:hi], d[k + 1, lo + 1:hi])
        if float(clear.max()) < SIDE_CLEAR * side:
            return False
    return True


def rounded_many_sided_left_open(work: np.ndarray, drawn: np.ndarray | None = None,
                                 bent: tuple[np.ndarray, np.ndarray, list[Bend]] | None = None) -> bool:
    """Whether an open stroke is a many-sided polygon left open by one side whose corners the hand rounded: it does
    `AT_CORNERS` of its turning at `LEAST_CORNERS` corners or more (`corner_bends`, of up to `LEFT_OPEN_BEND_STEPS`),
    and its sides through those corners (each corner at the middle of its bend) and the gap close a convex outline
    turning the same way at every vertex once round (its ends on a side, `ENDS_ON_A_SIDE_DEG`, or turning that way),
    the gap no longer than `GAP_SIDES` of its longest side; and its sides run straight between
    (`STRAIGHT_SHARE`) and its corners turn as many sides' do (`CORNER_TURN`). ``drawn``, the stroke's own points where
    given, must hold a point between each two corners (`drawn_through`); ``bent``: `bends` of ``work``, where already
    found."""
    pts, th, found = bends(work) if bent is None else bent
    corners = corner_bends(found, LEFT_OPEN_BEND_STEPS)
    total = float(np.abs(th).sum())
    at_corners = sum(abs(b.degrees) for b in corners)
    if (len(corners) < LEAST_CORNERS or total == 0.0 or at_corners < AT_CORNERS * total
            or float(np.mean(np.abs(th) < STRAIGHT_STEP_DEG)) < STRAIGHT_SHARE
            or at_corners / len(corners) < CORNER_TURN * 360.0 / (len(corners) + 2)):
        return False
    at = [0, *((b.first + b.last) // 2 + 1 for b in corners), len(pts) - 1]
    ring = np.vstack([pts[at], pts[at[:1]]])
    sides = np.diff(ring, axis=0)
    lengths = np.hypot(sides[:, 0], sides[:, 1])
    if not lengths[:-1].max() > 0 or lengths[-1] > GAP_SIDES * lengths[:-1].max():
        return False
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    turns = (np.diff(np.append(heading, heading[0])) + math.pi) % (2 * math.pi) - math.pi
    way = math.copysign(1.0, float(turns.sum()))
    ends_on_a_side = np.abs(turns[-2:]) < math.radians(ENDS_ON_A_SIDE_DEG)  # at the stroke's end, and its start
    if not ((turns[:-2] * way > 0).all() and (ends_on_a_side | (turns[-2:] * way > 0)).all()
            and abs(abs(float(turns.sum())) - 2 * math.pi) <= 0.1):
        return False
    return drawn is None or drawn_through(pts[at[1:-1]], drawn)
