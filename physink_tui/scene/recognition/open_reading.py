"""Reads a stroke the pen left open by how it turns (`open_shapes.classify_open`) on points a few noise widths
apart, with what those coarse points miss; closing a stroke and the checks before are `recognize`'s; no I/O."""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import open_shapes, pen_noise, square_braces
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import curve_geometry, round_geometry
from physink_tui.scene.recognition.candidates import polygonal
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.ranking import BOUNDS_MARGIN, Weights, bounds, inside, or_freeform, rank
from physink_tui.scene.recognition.stroke_views import StrokeViews

OPEN_SPACING = 3.0
"""Open strokes are judged on points at least this many noise widths apart."""
OPEN_ROUND_MARGIN = 0.2
"""The share of the stroke's diagonal a circle or ellipse completed from a stroke that stopped short of its start may
reach past the stroke's bounds (`ranking.BOUNDS_MARGIN` for other shapes; a quarter turn short pokes out by about 15 %
of the stroke's diagonal)."""


def open_reading(raw: np.ndarray, work: np.ndarray, n: int, noise: float, sigma: float, weights: Weights,
                 diag: float, views: StrokeViews | None = None, round_too: bool = True) -> Recognition:
    """An open stroke (``raw`` at unit size, ``work`` its ``n`` judged points; ``diag`` its
    `stroke_geometry.bbox_diagonal`, ``noise`` and ``sigma`` as the ranking takes them), judged by how it turns: on
    points a few noise widths apart, jitter makes no corners; where it would be read as a circle or an ellipse left
    open, a curve instead unless ``round_too``."""
    coarse_n = int(min(n, max(64, sg.path_length(work) / (OPEN_SPACING * noise)))) if noise > 0 else n
    found = open_shapes.classify_open(sg.resample(work, coarse_n) if coarse_n < n else work, noise,
                                      weights.round_corner, (raw, diag))
    if found.kind == "polyline" and square_braces.square_brace(raw, noise, views):
        # a brace drawn square-cornered, whose small point these coarse points smoothed away
        found = Recognition("curve", 0.7, curve_geometry(work, sg.find_corners(work)), (("polyline", 0.3),))
    if round_too and found.kind not in ("circle", "ellipse"):
        bursts = pen_noise.round_in_bursts(raw, diag, pen_noise.BURST_SWEEP_OPEN, closed=False)
        if bursts is not None:  # a round stroke left open, sampled in a few bursts: its chords are the device's
            geom, kind = round_geometry(bursts)
            found = Recognition(kind, 0.65, geom, ((str(found.kind), 0.35),))
    round_left_open = found.kind in ("circle", "ellipse")
    if round_left_open and not round_too:  # a loop the pen ran on off: a curve round it and away
        return Recognition("curve", 0.7, curve_geometry(work, sg.find_corners(work)), ((str(found.kind), 0.3),))
    share = OPEN_ROUND_MARGIN if round_left_open else BOUNDS_MARGIN
    if inside(found.geometry, *bounds(raw, noise, diag, share)):
        return found
    ranked = rank(polygonal(work, closed=False, tolerance=0.5 * sigma, noise=noise), len(work), sigma,
                  weights, raw, noise, diag)
    return or_freeform(ranked, work, closed=False, sigma=sigma)
