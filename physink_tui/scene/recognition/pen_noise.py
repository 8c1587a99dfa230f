"""The pen's own wobble measured on a stroke (`jitter`), and the bends a shape the stroke's size makes between its
points (`shape_bend`), against which a sparse stroke's jitter is judged; no classification, no I/O."""

from __future__ import annotations

import math

import numpy as np

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
    t, d2, norm = t[ok], d2[ok], norm[ok]
    # the bend across the path, d2 . (-t_y, t_x) / |t| (white noise: successive bends anticorrelated, var 6 s^2 each)
    bend = d2[:, 0] * (-t[:, 1] / norm) + d2[:, 1] * (t[:, 0] / norm)
    return float(1.4826 * median(np.abs(bend[1:] - bend[:-1])) / math.sqrt(20))


def shape_bend(pts: np.ndarray) -> float:
    """How much a round shape as big as the stroke bends its path between neighbouring points, in the points' units:
    a circle d across (the bounding box's diagonal) turns its path by 2/d a unit length, so over a median step s it
    bends by 2 s^2/d; a shape with corners bends more where they fall. Dense tablet strokes give a few hundredths of
    a unit; a trackpad's 8-25 events round a box, tens of units.

    >>> square = np.array([[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]], dtype=float)
    >>> round(shape_bend(square), 2)
    14.14
    """
    if len(pts) < 2:
        return 0.0
    d = pts[1:] - pts[:-1]
    step = median(np.hypot(d[:, 0], d[:, 1]))
    size = bbox_diagonal(pts)
    return 2 * step * step / size if size > 0 else 0.0
