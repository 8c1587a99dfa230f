"""Turning at the scale of a stroke's shape: headings on steps a few pen-noise widths long, so a hand's tremor turns
nothing; the finer measures (points, corners, `turning` itself) are `stroke_geometry`'s."""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition.stroke_geometry import path_length, resample, turning


def coarse_turning(pts: np.ndarray, noise: float, most: int = 40) -> np.ndarray:
    """`turning` on the path resampled to ``most`` points, or fewer when the pen's ``noise`` would make steps
    that short wobble (steps at least six noise widths long, and at least 16 points): how the stroke turns at
    the scale of its shape."""
    n = most if noise <= 0 else int(min(most, max(32, path_length(pts) / (6 * noise))))
    return turning(resample(pts, n))


TREMOR_STEP = 6.0
"""`turning_beyond_tremor` steps at least this many of the pen's noise widths: a hand's tremor of amplitude A (about
the pen's noise) bends two steps s long by up to 2 atan(2A / s), under the 35 degrees of a lobe
(`stroke_features.lobes`) only where s > 6.3 A."""
TREMOR_FEWEST = 16
"""...on at least this many points (a sixteenth of the path a step: a bracket's arm of a fifth of it keeps a step)."""


def turning_beyond_tremor(pts: np.ndarray, noise: float, most: int = 40) -> np.ndarray:
    """`coarse_turning` on steps `TREMOR_STEP` noise widths long down to `TREMOR_FEWEST` points, where
    `coarse_turning` keeps 32 at least: on a stroke of under 192 noise widths of path (a mark 15-60 px tall) its steps
    of 1-2 px let the hand's tremor of about a pixel turn the heading by 30-60 degrees each way between them."""
    n = most if noise <= 0 else int(min(most, max(TREMOR_FEWEST, path_length(pts) / (TREMOR_STEP * noise))))
    return turning(resample(pts, n))
