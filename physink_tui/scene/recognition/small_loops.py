"""Small loops where a path crosses itself at a corner (a pen circling there), cut out before the coil test."""

from __future__ import annotations

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
    step = pts[1:] - pts[:-1]
    p, r = pts[:-1], step  # segment i (rows), tested against segment i + gap for gap 2..span (`_later`)
    q, s = _later(pts[:-1], span), _later(step, span)
    denom = r[:, 0] * s[..., 1] - r[:, 1] * s[..., 0]
    qp = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qp[..., 0] * s[..., 1] - qp[..., 1] * s[..., 0]) / denom
        u = (qp[..., 0] * r[:, 1] - qp[..., 1] * r[:, 0]) / denom
    hit = (denom != 0) & (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1)  # (no segment past the last: its steps are 0)
    if not np.logical_or.reduce(hit, axis=None):  # (`.any()`'s own reduction)
        return pts
    diag = sg.bbox_diagonal(pts)
    keep = np.ones(n, dtype=bool)
    out = pts.copy()
    gaps, starts = np.nonzero(hit)  # by gap, then by segment
    for g, a in zip(gaps[np.argsort(starts, kind="stable")].tolist(), sorted(starts.tolist()), strict=True):
        b = a + g + 2
        if not keep[a] or not keep[b]:
            continue
        loop = pts[a + 1:b + 1]
        if sg.bbox_diagonal(loop) > max_size * diag:
            continue  # a real loop (a pigtail's, a spring's), not a flourish at a corner
        out[a + 1] = p[a] + t[g, a] * r[a]  # the crossing point replaces the loop
        keep[a + 2:b + 1] = False
    return out[keep]


def _later(rows: np.ndarray, span: int) -> np.ndarray:
    """``rows[i + gap]`` for gap 2..``span`` (first axis) and each row i (second axis), zeros past the last row: a
    read-only view of one padded copy, not a gathered one (each number as ``rows[j]`` holds it)."""
    m = len(rows)
    padded = np.zeros((m + span, 2), dtype=rows.dtype)
    padded[:m] = rows
    out = np.lib.stride_tricks.as_strided(padded[2:], shape=(span - 1, m, 2),
                                          strides=(padded.strides[0], *padded.strides), writeable=False)
    return out
