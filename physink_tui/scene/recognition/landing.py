"""Where a finger or pen dwells as it lands or lifts: points wandering about the stroke's first (or last) point before
it departs (or after it arrives), kept as one point; no classification, no I/O.

A fingertip's contact settles as it lands on a trackpad or touch screen (its centre shifts while the stroke has not
yet left), and wanders again as pressure drops before it lifts; a device reporting every few milliseconds gives a
cluster of points there. Left in, the cluster is a scribble at the stroke's end: its bends read as a shaky hand
(`pen_noise.jitter`'s median counts every point alike, and a short stroke's dozen events are outnumbered) and its
back-and-forth as a hook or a loop.
"""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

DWELL_RADIUS = 0.06
"""A dwell stays within this share of the stroke's diagonal of its end point (or two noise widths, if more)."""
DWELL_PATH = 3.5
"""...and wanders there: its points' path is at least this many times as long as the farthest of them is from the
end point (a stroke that departs straight away travels that far once; a hook out and back twice, three times in whole
pixels' stair steps: `tests/test_swung_lines.py`'s arc that lands with a hook)..."""
DWELL_PATH_CENTRED = 3.0
"""...or at least this many times where they are centred on the end point (their mean within `DWELL_CENTRE` of its
reach of it): a fingertip's contact settling about where it landed or lifted (`benchmarks/device_habits.start_blob`,
`lift_pause`: 3.2-3.4 times its reach), where a pen that creeps off along the stroke, densely sampled, wanders as far
by its jitter but puts its points' mean about halfway out (`tests/test_swung_lines.py`'s arc of 50 degrees, seed 19:
3.1 times, the mean 0.47 of its reach out)..."""
DWELL_CENTRE = 0.25
"""...(`DWELL_PATH_CENTRED`'s share of the dwell's reach)..."""
DWELL_POINTS = 4
"""...over at least this many points..."""
DWELL_BREADTH = 0.4
"""...and spreads about as wide as long (its narrower principal spread at least this share of its wider): a hook at an
end goes out and back along one line, and stays (`stroke_geometry.remove_hooks` judges it)."""


HEAD_POINTS = 16
"""`_dwell` looks for the first point away among this many first: most strokes depart within them."""


def _dwell(pts: np.ndarray, radius: float) -> int:
    """How many points from ``pts[0]`` on stay within ``radius`` of it, wandering there (`DWELL_PATH`, or
    `DWELL_PATH_CENTRED` about it), or 0."""
    head = pts[:HEAD_POINTS] - pts[0]
    away = np.hypot(head[:, 0], head[:, 1]) > radius  # where the first point away lies, as for most strokes
    if not away.any():  # else every point, the same distances
        away = np.hypot(*(pts - pts[0]).T) > radius
        if not away.any():
            return 0
    out = int(away.argmax())
    if out < DWELL_POINTS:
        return 0
    extent = float(np.maximum.reduce(np.hypot(*(pts[:out] - pts[0]).T)))
    path = float(np.add.reduce(sg.step_lengths(pts[:out])))
    if path < DWELL_PATH_CENTRED * extent:
        return 0
    if path < DWELL_PATH * extent and np.hypot(*(pts[:out] - pts[0]).mean(axis=0)) > DWELL_CENTRE * extent:
        return 0  # not about the end point: a pen already moving along the stroke
    spread = np.linalg.eigvalsh(np.cov((pts[:out] - pts[:out].mean(axis=0)).T))
    return out if spread[0] >= DWELL_BREADTH**2 * spread[1] else 0  # about as wide as long: not a hook


def settled(pts: np.ndarray, diag: float, noise: float) -> np.ndarray:
    """Which of ``pts`` (no repeats) to keep: all but a dwell's at either end, where the dwell is kept as its point
    nearest the dwell's centre.

    >>> rng = np.random.default_rng(1)
    >>> line = np.column_stack([np.linspace(0, 100, 20), np.zeros(20)])
    >>> blob = rng.normal(0, 1.5, (8, 2))
    >>> int(settled(np.vstack([blob, line]), 100.0, 1.0).sum())
    19
    >>> int(settled(line, 100.0, 1.0).sum())
    20
    """
    keep = np.ones(len(pts), dtype=bool)
    if len(pts) < 2 * DWELL_POINTS + 3 or diag <= 0:
        return keep
    radius = max(DWELL_RADIUS * diag, 2 * noise)
    for forward in (True, False):
        run = pts if forward else pts[::-1]
        n = _dwell(run, radius)
        if n == 0 or n > len(pts) // 2:
            continue
        centre = run[:n].mean(axis=0)
        stay = int(np.hypot(*(run[:n] - centre).T).argmin())
        drop = np.ones(n, dtype=bool)
        drop[stay] = False
        idx = np.flatnonzero(drop)
        keep[idx if forward else len(pts) - 1 - idx] = False
    return keep
