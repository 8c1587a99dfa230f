"""The pen's noise judged from a stroke's own points when the caller does not state it, in whatever units they are."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import pen_noise

ROUNDING_JITTER = 0.42
"""The jitter (`pen_noise.jitter`) a pen measures where the only noise is where within each device unit it fell, in
those units: the design sources' pixel strokes, each point moved uniformly within its pixel, measure 0.31-0.57
(10th-90th percentile), median 0.42 (rounded to whole pixels again, 0.0-0.48, median 0.30). A stroke of continuous
coordinates is given the noise a device rounding at that scale would have: its jitter over this."""
FLOOR_OF_DIAGONAL = (1 / 1000, 1 / 50)
"""A noise judged from the jitter is kept within these shares of the stroke's diagonal: a smooth stroke measures next
to no jitter (the floor of a pen as fine as a thousandth of the stroke), a shaky one much (at most a fiftieth, so a
shaky hand is still told from its pen)."""
TYPICAL_OF_DIAGONAL = 1 / 200
"""The noise of a stroke whose jitter tells nothing of its pen (none measured, or no more than the shape's own bends
between sparse points: `recognize.SPARSE_BENDS`) and whose coordinates lie on no lattice: a pixel of a stroke as big
as the design sources' typical one (their pixel strokes are 100-310 px across, 5th-90th percentile, median 188)."""
FINE_LATTICE = 4.0
"""Coordinates on a lattice finer than this share of the noise their jitter shows (a tablet's raw units, 10-50 to a
pixel; fractions of a screen to 4 decimals, a sixth of a pixel) are judged as continuous: the quantum is not the pen's
noise. A shaky hand on whole pixels looks the same once its jitter passes 1.7 px on a stroke over 200 px (the jitter's
noise is kept under a fiftieth of the diagonal): none of the 16,735 design strokes does (every one is judged at its
pixel); at 8 the hurried pen's shapes stored to 4 decimals read as in pixels 380 times of 390, at 4, 388."""


def lattice(pts: np.ndarray, diag: float) -> float:
    """The quantum that every coordinate of ``pts`` is a whole multiple of (from any origin, each axis alike), in the
    points' units: 1 for whole pixels, 0.01 for fractions rounded to two decimals; 0 where there is none (continuous
    floats) or it is under a ten-thousandth of ``diag`` (the stroke's diagonal). Float rounding of the stored numbers
    (float32 included) is allowed for.

    >>> lattice(np.array([[0.0, 0.0], [3.0, 1.0], [5.0, 4.0], [6.0, 9.0]]), 10.8)
    1.0
    >>> round(lattice(np.array([[0.0, 0.0], [0.03, 0.01], [0.05, 0.04], [0.06, 0.09]]), 0.108), 6)
    0.01
    >>> lattice(np.array([[0.0, 0.0], [0.3141, 1.0], [0.52, 0.4], [0.6, 0.97]]), 1.1)
    0.0
    """
    if diag <= 0 or len(pts) < 2:
        return 0.0
    tol = 1e-6 * max(float(np.abs(pts).max()), diag)
    steps = np.concatenate([np.diff(np.unique(pts[:, k])) for k in range(2)])
    steps = steps[steps > tol]
    if steps.size == 0:
        return 0.0
    quantum = float(steps.min())
    smallest = max(diag / 10_000, 2 * tol)
    while quantum >= smallest:  # Euclid's algorithm over all the steps at once
        multiple = np.round(steps / quantum)
        off = np.abs(steps - multiple * quantum)
        # a quantum found from stored (rounded) numbers is off by up to `tol`, once per multiple
        wrong = off > np.minimum(tol * (1 + multiple), 0.05 * quantum)
        if not wrong.any():
            quantum = float(np.dot(multiple, steps) / np.dot(multiple, multiple))  # least squares over every step
            decimal = float(f"{quantum:.6g}")  # stored numbers are decimals: 1 px in float32, 0.02 of a pixel
            quantum = decimal if abs(decimal - quantum) <= 1e-6 * quantum else quantum
            return quantum
        quantum = float(off[wrong].min())
    return 0.0


def stroke_noise(pts: np.ndarray, diag: float, stored: np.ndarray | None = None, *, measured: float | None = None,
                 own_bends: bool = False) -> float:
    """The pen's noise in the points' units judged from the stroke alone (``diag`` its diagonal; ``stored``, where
    given, its coordinates as stored, before any thinning; ``measured`` its `pen_noise.jitter` where already measured;
    ``own_bends`` where that may be the shape's own bends between sparse points): the quantum of the lattice they lie
    on (`lattice`) where that is not far finer than their jitter shows (`FINE_LATTICE`; or the jitter tells nothing):
    whole pixels give 1, scaled ones their scale; otherwise (continuous coordinates, or a lattice far finer than the
    pen) the noise a device rounding at the jitter's scale would have (`ROUNDING_JITTER`, within `FLOOR_OF_DIAGONAL`
    of the diagonal), or where the jitter tells nothing either, the typical share of the diagonal
    (`TYPICAL_OF_DIAGONAL`).

    >>> rng = np.random.default_rng(0)
    >>> a = np.linspace(0, 5, 200)
    >>> circle = np.column_stack([100 * np.cos(a), 100 * np.sin(a)])
    >>> stroke_noise(np.round(circle), 200.0), stroke_noise(np.round(circle) * 0.02, 4.0)
    (1.0, 0.02)
    >>> 0.5 < stroke_noise(circle + rng.uniform(-0.5, 0.5, circle.shape), 200.0) < 2
    True
    >>> stroke_noise(circle, 200.0)  # smooth: next to no jitter, no lattice
    0.2
    """
    quantum = lattice(pts if stored is None else stored, diag)
    measured = pen_noise.jitter(pts) if measured is None else measured
    if own_bends or measured <= 0:  # the jitter tells nothing of the pen
        return quantum if quantum > 0 else TYPICAL_OF_DIAGONAL * diag
    low, high = FLOOR_OF_DIAGONAL
    judged = min(max(measured / ROUNDING_JITTER, low * diag), high * diag)
    if quantum > 0 and quantum >= judged / FINE_LATTICE:
        return quantum
    return judged if math.isfinite(judged) else 0.0
