"""Whether the pen slowed at a closed polygon's vertices, as a hand does at the corners it means; no I/O, no clock.

A hand's speed falls with the radius of the path it is turning (the two-thirds power law): it slows into a corner it
means and runs along a side, while round a circle, whose turning is spread evenly, it keeps an even pace. A mouse or a
finger drawing a circle in a few straight strokes makes a loop that an octagon fits as closely as a drawn octagon (the
design sets' mouse circles), so where the stroke's times are known the pace at the vertices tells them apart.
"""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

SLOW_CORNER = 0.55
"""A closed polygon's vertices were meant when the pen's pace near them (`CORNER_REACH`) is, at the median vertex, under
this share of the stroke's mean pace. Measured where `round_or_cornered.slowed_corners` asks it (a loop read round, a
fit of five sides or more explaining half its error, its median vertex turning within half a side), each stroke's
slowest such fit: the design sets' timed circles at 0.61 or more (one itt mouse circle drawn as a polygon at 0.61, the
next at 0.74), the fourth group's timed circles at 0.75 or more; the Quick, Draw! octagons read round at main
2996772 at 0.37-0.66 (7 under 0.55 become polygons; under 0.6, 9, too near the design circle's 0.61)."""
CORNER_REACH = 0.15
"""The pace at a vertex is taken over the path within this share of the mean side either side of it."""


def pace_at_vertices(vertices: np.ndarray, drawn: np.ndarray, times: np.ndarray) -> np.ndarray | None:
    """The pen's pace near each vertex (the drawn point nearest it), over its mean pace along the whole stroke;
    None where the times do not run forward. ``drawn``: the stroke's points, one a time in ``times`` (seconds)."""
    if len(drawn) < 3 or len(times) != len(drawn) or len(vertices) < 3:
        return None
    t = np.asarray(times, dtype=float)
    if not np.isfinite(t).all() or (np.diff(t) < 0).any() or t[-1] <= t[0]:
        return None
    along = sg.along(drawn)
    length = float(along[-1])
    if length == 0.0:
        return None
    mean_pace = length / float(t[-1] - t[0])
    reach = CORNER_REACH * length / len(vertices)
    nearest = np.argmin(np.hypot(*(drawn[None, :, :] - vertices[:, None, :]).transpose(2, 0, 1)), axis=1)
    lo = np.maximum(along[nearest] - reach, 0.0)
    hi = np.minimum(along[nearest] + reach, length)
    took = np.interp(hi, along, t) - np.interp(lo, along, t)
    with np.errstate(divide="ignore", invalid="ignore"):
        pace = np.where(took > 0, (hi - lo) / took, np.inf) / mean_pace
    return pace


def slowed_at_corners(vertices: np.ndarray, drawn: np.ndarray, times: np.ndarray | None) -> bool:
    """Whether the pen slowed at the vertices (`SLOW_CORNER` at the median one); False without times."""
    if times is None:
        return False
    pace = pace_at_vertices(vertices, drawn, times)
    return pace is not None and sg.median(pace) < SLOW_CORNER


PACE_WINDOW = 0.06
"""The pen's pace along a stroke is taken over this many seconds (a chord between the positions half of it either side;
a mouse's events come in bursts 25-60 ms apart, so a shorter window sees one jump)."""
PACE_STEP = 0.01
"""The pace is taken every this many seconds."""
DIP = 0.7
"""The pen slowed into a corner where its pace falls under this share of its median pace, and it has run on at its
median pace or faster since the last such fall (`slowdowns`)."""
LONGEST = 40.0
"""A stroke drawn over more seconds than this is not judged by its falls (4,000 paces to take: a scribble, or times
not in seconds)."""
CORNER_DIPS = 5
"""A loop in bursts whose pen slowed this many times or more was drawn with corners (`round_or_cornered.paced_corners`).
Pen models through the mouse, tuning seeds, timed, closed strokes read round: circles, ovals, whole notes, wobbly,
flat-sided and lopsided circles and the round boxes 0-5 falls (5 in 2 of 1,660, neither with a polygon of five sides
or more explaining half the round error); hexagons, octagons (and boxes, not asked) 0-8, 120 of 370 at 5 or more."""


def slowdowns(drawn: np.ndarray, times: np.ndarray) -> int | None:
    """How many times the pen's pace (over `PACE_WINDOW`) fell under `DIP` of its median pace, each after running at
    its median pace or faster; None where the times do not run forward or span under three windows or over
    `LONGEST`."""
    t = np.asarray(times, dtype=float)
    if len(t) != len(drawn) or len(t) < 4 or not np.isfinite(t).all() or (np.diff(t) < 0).any():
        return None
    keep = np.concatenate([[True], np.diff(t) > 0])
    pts, t = np.asarray(drawn, dtype=float)[keep], t[keep]
    if len(t) < 4 or not 3 * PACE_WINDOW <= t[-1] - t[0] <= LONGEST:
        return None
    half = PACE_WINDOW / 2
    grid = np.arange(t[0] + half, t[-1] - half, PACE_STEP)
    lo = np.column_stack([np.interp(grid - half, t, pts[:, k]) for k in (0, 1)])
    hi = np.column_stack([np.interp(grid + half, t, pts[:, k]) for k in (0, 1)])
    pace = np.hypot(*(hi - lo).T)
    middle = float(np.median(pace))
    if middle <= 0.0:
        return None
    # each pace under DIP of the median is +1, each at the median or over -1: a fall is a +1 first or after a -1
    marks = np.where(pace < DIP * middle, 1, np.where(pace >= middle, -1, 0))
    marks = marks[marks != 0]
    return int(np.count_nonzero((marks == 1) & np.concatenate([[True], marks[:-1] == -1])))
