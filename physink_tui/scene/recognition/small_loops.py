"""Small loops where a path crosses itself at a corner (a pen circling there), cut out before the coil test."""

from __future__ import annotations

import functools

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg


def remove_small_loops(pts: np.ndarray, max_fraction: float = 0.08, max_size: float = 0.08) -> np.ndarray:
    """Cut out small loops where the path crosses itself within ``max_fraction`` of its points and the
    loop spans at most ``max_size`` of the stroke's size (a pen circling at a corner), keeping the
    crossing point; big loops (a pigtail's, a spring's) stay."""
    n = len(pts)
    if n < 8:
        return pts
    span = max(3, int(max_fraction * n))
    i, j = _pairs(n, span)
    step = pts[1:] - pts[:-1]
    p, r = pts[i], step[i]
    q, s = pts[j], step[j]
    denom = r[:, 0] * s[:, 1] - r[:, 1] * s[:, 0]
    qp = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qp[:, 0] * s[:, 1] - qp[:, 1] * s[:, 0]) / denom
        u = (qp[:, 0] * r[:, 1] - qp[:, 1] * r[:, 0]) / denom
    hit = (denom != 0) & (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1)
    if not hit.any():
        return pts
    diag = sg.bbox_diagonal(pts)
    keep = np.ones(n, dtype=bool)
    out = pts.copy()
    for k in np.flatnonzero(hit)[np.argsort(i[hit], kind="stable")]:
        a, b = int(i[k]), int(j[k])
        if not keep[a] or not keep[b]:
            continue
        loop = pts[a + 1:b + 1]
        if sg.bbox_diagonal(loop) > max_size * diag:
            continue  # a real loop (a pigtail's, a spring's), not a flourish at a corner
        out[a + 1] = p[k] + t[k] * r[k]  # the crossing point replaces the loop
        keep[a + 2:b + 1] = False
    return out[keep]


@functools.lru_cache(maxsize=64)
def _pairs(n: int, span: int) -> tuple[np.ndarray, np.ndarray]:
    """The segments (i, j) of an ``n``-point path that `remove_small_loops` tests for crossing: j - i from 2 to
    ``span``, by gap then by i (the same for every stroke of that many points: made once, read only)."""
    i = np.concatenate([np.arange(0, n - 1 - gap) for gap in range(2, span + 1)])
    j = np.concatenate([np.arange(gap, n - 1) for gap in range(2, span + 1)])
    i.flags.writeable = False
    j.flags.writeable = False
    return i, j
