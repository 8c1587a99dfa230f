"""Two of the learned ranker's features measured along an open stroke: how its path shares out either side of its
sharpest inner corner (`point_balance`) and how the pen slowed at its corners (`corner_slowdown`); numpy, no I/O."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg


def point_balance(work: np.ndarray, corners: list[int], turns: list[float]) -> float:
    """The path on the shorter side of the sharpest inner corner over the path on its longer side: a check's point
    is off-centre (a short and a long arm), a v's point or a brace's tip in the middle; 0 without an inner corner."""
    if len(corners) < 3:
        return 0.0
    c = corners[1 + int(np.argmax(turns))]
    before, after = sg.path_length(work[:c + 1]), sg.path_length(work[c:])
    return min(before, after) / max(before, after, 1e-12)


def corner_slowdown(raw: np.ndarray, times: Sequence[float] | None, corners: list[int], n: int) -> float | None:
    """The pen's median speed within 5 % of the path round the inner corners over its median speed over the
    whole stroke (a drawn corner slows the pen; a curve's bend less so), or None without usable times."""
    if times is None or len(times) != len(raw) or len(corners) < 3:
        return None
    t = np.asarray(times, dtype=float)
    d = raw[1:] - raw[:-1]
    seg = np.hypot(d[:, 0], d[:, 1])
    dt = t[1:] - t[:-1]
    ok = dt > 0
    if np.count_nonzero(ok) < 8 or not np.isfinite(t).all():
        return None
    s = np.empty(len(raw))
    s[0] = 0.0
    np.add.accumulate(seg, out=s[1:])
    mid = (s[:-1] + s[1:])[ok] / 2 / max(s[-1], 1e-12)
    speed = seg[ok] / dt[ok]
    overall = sg.median(speed)
    if overall <= 0:
        return None
    near = np.zeros(len(mid), dtype=bool)
    for c in corners[1:-1]:
        near |= np.abs(mid - c / (n - 1)) < 0.05
    if not near.any():
        return None
    return min(sg.median(speed[near]) / overall, 3.0)
