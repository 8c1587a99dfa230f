"""A closed loop the ranking read round, read after all as the polygon it was drawn as when its corners are sharp."""

from __future__ import annotations

import functools

import numpy as np

from physink_tui.scene.recognition.candidates import Candidate, Pending
from physink_tui.scene.recognition.corner_pace import CORNER_DIPS, slowdowns, slowed_at_corners
from physink_tui.scene.recognition.pen_noise import burst_jumps
from physink_tui.scene.recognition.polygon_checks import (
    SHALLOW_CORNER_DEG,
    SHARP_CORNER,
    corner_roundness_closed,
    corners_of,
    dense_enough,
    sharp_corners,
    typical_step,
)
from physink_tui.scene.recognition.polygon_fit import PolygonFit
from physink_tui.scene.recognition.primitives import Polygon, Recognition
from physink_tui.scene.recognition.ranking import BOX_MARGIN, Weights, bic_score, bounds, inside

CORNERS_EXPLAIN = 0.5
"""A polygon read after all where a round shape won the ranking leaves at most this share of the round shape's error:
its corners are what the round shape missed (the pen models' hexagons and octagons, regular: under 0.21 of it). A
lumpy circle's polygon through a few sharp bends leaves most of it (people's lumpy circles in the design sets: 0.6-0.9;
the pen models' octagons drawn so irregular that a corner turns under 35 degrees, read with fewer sides: 0.45-0.98)."""
TURNS_AT_VERTICES = 0.5
"""A polygon whose vertices the pen slowed at (`corner_pace.slowed_at_corners`) is read as drawn when at its median
vertex the path does 80 % of its turning within this share of the shorter side (`stroke_features.corner_roundness`):
a round loop's turning, spread evenly, takes 0.8 of a side whatever the vertices, a drawn corner a tenth or two, and
one blurred by a mouse's sparse points and the smoothing a third or more (Quick, Draw! octagons: 3-4 vertices of 8 at
0.4 or more, which `polygon_checks.sharp_corners` refuses)."""
CORNERS_EXPLAIN_MOST = 0.1
"""A polygon of five sides or more that leaves at most this share of the round shape's error has drawn corners even
where one or two of them, shallow, were swept round (`MOSTLY_SHARP`): a hurried hand's irregular octagon turns 25-30
degrees at some corners and rounds them over the side (Quick, Draw! octagons: 0.05-0.07 of the round error, one
shallow corner swept). A person's wobbly circle's polygon of 9-10 sides may leave as little (the design sources:
0.02 and up), so the corners must be sharp too."""
MOSTLY_SHARP = 0.7
"""The share of the vertices of such a polygon (`CORNERS_EXPLAIN_MOST`) that must be sharp
(`polygon_checks.SHARP_CORNER`): the Quick, Draw! octagons it reads 0.71-0.88; people's circles whose polygon leaves
under 0.1 of the round error at most 0.62 (the design sources: hcira jonathanzhang53/s04 circle6, ahmadosama Circle
#12; both stay round)."""


def cornered_after_all(ranked: Recognition, polygons: list[Pending], round_rss: float, raw: np.ndarray,
                       noise: float, diag: float, sigma: float, weights: Weights,
                       times: np.ndarray | None = None, corners_told: bool = False) -> Recognition:
    """A loop read round whose polygon of four sides or more explains most of the round shape's error
    (`CORNERS_EXPLAIN`) and turns at its corners (`polygon_checks.sharp_corners`, or, where ``times`` show the pen
    slowed at them, `slowed_corners`, or where ``corners_told``: the loop's turning, gathered at rounded corners,
    already told them, `shape_corners`): a hexagon, an octagon or a rounded rectangle drawn, whose every vertex the
    complexity penalty charges as if it might be noise on a round shape. The best-scored such polygon (a box where
    squaring it stays within the stroke); ``ranked`` when there is none. ``polygons``: every closed polygonal fit
    (`candidates.polygonal`), ``raw``: the stroke's own points, ``times``: one a point of ``raw`` (seconds) or None."""
    if ranked.kind is None:
        return ranked
    lo, hi = bounds(raw, noise, diag)
    box_lo, box_hi = bounds(raw, noise, diag, BOX_MARGIN)
    explained = CORNERS_EXPLAIN * round_rss
    n = len(polygons[0].fits[0].points) if polygons and polygons[0].fits else 1
    step = typical_step(raw)
    paced = functools.cache(lambda: _paced(raw, times, diag))  # asked at most once, only where the rest say no
    for pending in sorted((p for p in polygons if p.params >= 2 * 4 and p.rss <= explained),
                          key=lambda p: bic_score(p, n, sigma, weights)):
        # only the best fit of that many sides is judged, before building (which judges every corner: the costlier)
        best = pending.fits[0] if pending.fits else None
        if best is None or best.rss > explained or not (corners_told or sharp_corners(best, step)
                                                         or slowed_corners(best, step, raw, times)
                                                         or mostly_sharp(best, step, round_rss)
                                                         or (len(best.indices) - 1 >= 5 and paced())):
            continue
        for c in [*_built(pending, best), *_shallow(pending, best, noise)]:
            if c.kind == "box" and not inside(c.geometry, box_lo, box_hi) and c.fallback is not None:
                c = c.fallback
            if inside(c.geometry, *((box_lo, box_hi) if c.kind == "box" else (lo, hi))):
                return Recognition(c.kind, ranked.confidence, c.geometry, ((ranked.kind, 1.0 - ranked.confidence),))
    return ranked


def slowed_corners(fit: PolygonFit, step: float, raw: np.ndarray, times: np.ndarray | None) -> bool:
    """Whether a closed fit of five sides or more has vertices the pen slowed at (`corner_pace.slowed_at_corners`)
    where the path turns (`TURNS_AT_VERTICES`), on points dense enough to tell (`polygon_checks.dense_enough`)."""
    if times is None or len(fit.indices) - 1 < 5 or not dense_enough(fit, step):
        return False
    if float(np.median(corner_roundness_closed(fit))) >= TURNS_AT_VERTICES:
        return False
    return slowed_at_corners(fit.vertices, raw, times)


def _paced(raw: np.ndarray, times: np.ndarray | None, diag: float) -> bool:
    """Whether a loop's points came in bursts (a busy mouse's, `pen_noise.burst_jumps`: too sparse for `dense_enough`)
    and its pen slowed `corner_pace.CORNER_DIPS` times or more (`corner_pace.slowdowns`): a hand slows into each corner
    it means and runs along the sides, and keeps an even pace round a circle (an oval's two ends, a lopsided one's
    three or four, slow it less often). False without times."""
    if times is None or int(np.count_nonzero(burst_jumps(raw, diag)[1])) < 3:
        return False
    falls = slowdowns(raw, times)
    return falls is not None and falls >= CORNER_DIPS


def paced_corners(fit: PolygonFit, raw: np.ndarray, times: np.ndarray | None, diag: float) -> bool:
    """Whether a closed fit of five sides or more belongs to a loop drawn at a corner's pace (`_paced`)."""
    return len(fit.indices) - 1 >= 5 and _paced(raw, times, diag)


def mostly_sharp(fit: PolygonFit, step: float, round_rss: float) -> bool:
    """Whether a closed fit of five sides or more leaves at most `CORNERS_EXPLAIN_MOST` of the round shape's error
    (``round_rss``) and turns sharply at `MOSTLY_SHARP` of its vertices, on points dense enough to tell
    (`polygon_checks.dense_enough`)."""
    if len(fit.indices) - 1 < 5 or fit.rss > CORNERS_EXPLAIN_MOST * round_rss or not dense_enough(fit, step):
        return False
    return float(np.mean(corner_roundness_closed(fit) < SHARP_CORNER)) >= MOSTLY_SHARP


def _built(pending: Pending, best: PolygonFit) -> list[Candidate]:
    """The box or polygon the ranking would have built from ``pending``'s ``best`` fit."""
    return [c for c in pending.build() if c.kind in ("box", "polygon") and c.rss == best.rss]


def _shallow(pending: Pending, best: PolygonFit, noise: float) -> list[Candidate]:
    """The polygon of ``best`` (five sides or more) where its flattest vertices turn under
    `polygon_checks.MIN_CORNER_DEG` (down to `SHALLOW_CORNER_DEG`); `sharp_corners` then asks them to be sharp."""
    if pending.params < 2 * 5:
        return []
    corners = corners_of(best, closed=True, noise=noise, min_corner_deg=SHALLOW_CORNER_DEG)
    if corners is None or corners.hairpins:
        return []
    points = tuple((float(x), float(y)) for x, y in corners.vertices)
    return [Candidate("polygon", Polygon(points), best.rss, pending.params)]
