"""A bound `stroke_geometry.bbox_diagonal` cannot exceed, in two reductions: where it settles a comparison, the
diagonal's 32 projections need not be made."""

from __future__ import annotations

import numpy as np

MARGIN = 1e-12
"""Relative slack over the rounding of the projections (a few units in the last place, 1e-16 each)."""


def diameter_bound(pts: np.ndarray) -> float:
    """An upper bound on `stroke_geometry.bbox_diagonal` of ``pts`` (an (n, 2) float array): the points' width plus
    their height (at least their diameter, the least an extent across them in any direction can be at most), with
    `MARGIN` of it and of their largest coordinates for the projections' rounding; NaN where a coordinate is."""
    least, most = np.minimum.reduce(pts, axis=0), np.maximum.reduce(pts, axis=0)  # (`.min(axis=0)`'s own reduction)
    x0, y0 = float(least[0]), float(least[1])
    x1, y1 = float(most[0]), float(most[1])
    size = max(abs(x0), abs(x1)) + max(abs(y0), abs(y1))
    return ((x1 - x0) + (y1 - y0) + MARGIN * size) * (1.0 + MARGIN)
