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
