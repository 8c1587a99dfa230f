"""A closed loop the ranking read round, read after all as the polygon it was drawn as when its corners are sharp."""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition.candidates import Candidate, Pending
from physink_tui.scene.recognition.polygon_checks import SHALLOW_CORNER_DEG, corners_of, sharp_corners, typical_step
from physink_tui.scene.recognition.polygon_fit import PolygonFit
from physink_tui.scene.recognition.primitives import Polygon, Recognition
from physink_tui.scene.recognition.ranking import BOX_MARGIN, Weights, bic_score, bounds, inside

CORNERS_EXPLAIN = 0.5
"""A polygon read after all where a round shape won the ranking leaves at most this share of the round shape's error:
its corners are what the round shape missed (the pen models' hexagons and octagons, regular: under 0.21 of it). A
lumpy circle's polygon through a few sharp bends leaves most of it (people's lumpy circles in the design sets: 0.6-0.9;
the pen models' octagons drawn so irregular that a corner turns under 35 degrees, read with fewer sides: 0.45-0.98)."""


def cornered_after_all(ranked: Recognition, polygons: list[Pending], round_rss: float, raw: np.ndarray,
                       noise: float, diag: float, sigma: float, weights: Weights) -> Recognition:
    """A loop read round whose polygon of four sides or more explains most of the round shape's error
    (`CORNERS_EXPLAIN`) and turns at its corners (`polygon_checks.sharp_corners`): a hexagon, an octagon or a rounded
    rectangle drawn, whose every vertex the complexity penalty charges as if it might be noise on a round shape. The
    best-scored such polygon (a box where squaring it stays within the stroke); ``ranked`` when there is none.
    ``polygons``: every closed polygonal fit (`candidates.polygonal`), ``raw``: the stroke's own points."""
    if ranked.kind is None:
        return ranked
    lo, hi = bounds(raw, noise, diag)
    box_lo, box_hi = bounds(raw, noise, diag, BOX_MARGIN)
    explained = CORNERS_EXPLAIN * round_rss
    n = len(polygons[0].fits[0].points) if polygons and polygons[0].fits else 1
    step = typical_step(raw)
    for pending in sorted((p for p in polygons if p.params >= 2 * 4 and p.rss <= explained),
                          key=lambda p: bic_score(p, n, sigma, weights)):
        # the best fit of that many sides is judged, before building (which judges every corner: the costlier part)
        sharp = [f for f in pending.fits[:1] if f.rss <= explained and sharp_corners(f, step)]
        if not sharp:
            continue
        for c, fit in [*_built(pending), *_shallow(pending, noise)]:
            if c.kind == "box" and not inside(c.geometry, box_lo, box_hi) and c.fallback is not None:
                c = c.fallback
            if any(fit is f for f in sharp) and inside(c.geometry, *((box_lo, box_hi) if c.kind == "box"
                                                                    else (lo, hi))):
                return Recognition(c.kind, ranked.confidence, c.geometry, ((ranked.kind, 1.0 - ranked.confidence),))
    return ranked


def _built(pending: Pending) -> list[tuple[Candidate, PolygonFit]]:
    """The box or polygon the ranking would have built from ``pending``, with the fit it came from."""
    out = []
    for c in pending.build():
        fit = next((f for f in pending.fits if f.rss == c.rss), None)
        if c.kind in ("box", "polygon") and fit is not None:
            out.append((c, fit))
    return out


def _shallow(pending: Pending, noise: float) -> list[tuple[Candidate, PolygonFit]]:
    """Polygons of five sides or more from ``pending``'s fits whose flattest vertices turn under
    `polygon_checks.MIN_CORNER_DEG` (down to `SHALLOW_CORNER_DEG`); `sharp_corners` then asks them to be sharp."""
    if pending.params < 2 * 5:
        return []
    for f in pending.fits:
        corners = corners_of(f, closed=True, noise=noise, min_corner_deg=SHALLOW_CORNER_DEG)
        if corners is not None and not corners.hairpins:
            points = tuple((float(x), float(y)) for x, y in corners.vertices)
            return [(Candidate("polygon", Polygon(points), f.rss, pending.params), f)]
    return []
