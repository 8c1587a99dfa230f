"""Ranks a stroke's candidate shapes: each scored by fit error against complexity (BIC-style), the best whose shape
stays within the stroke's bounds and follows its outline wins, the best of each other kind become alternatives;
when none fits, keeps the stroke as drawn (`or_freeform`); `recognize` decides which candidates compete and on
what points.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from physink_tui.scene.recognition.beautify import shape_points, within
from physink_tui.scene.recognition.candidates import Candidate, Pending
from physink_tui.scene.recognition.polygon_checks import follows_the_outline
from physink_tui.scene.recognition.polygon_fit import candidate_vertices
from physink_tui.scene.recognition.primitives import Ellipse, Geometry, Line, Polygon, Polyline, Recognition


@dataclass(frozen=True, slots=True)
class Weights:
    """The ranking's numbers: what a unit of complexity costs against fit error, and the noise floor.

    Attributes:
        complexity: score added per parameter of a shape, times log of the effective sample count (BIC's 0.5
            is the textbook value; larger prefers simpler shapes).
        relative_noise: hand inaccuracy as a share of the stroke's size; the error floor is the larger of
            this and the pen's absolute noise.
        round_corner: see below.
    """

    complexity: float = 2.5
    relative_noise: float = 0.003
    round_corner: float = 0.8
    """A polyline's corners do most of their turning within this share of their shorter side (a bend rounder
    than that is a curve's: a brace, a question mark)."""


DEFAULT_WEIGHTS = Weights()
EFFECTIVE_SAMPLES = 64
"""How many independent samples a stroke's fit error is taken to rest on, whatever its point count."""
BOUNDS_MARGIN = 0.05
"""A beautified shape must stay within the stroke's bounding box grown by this share of its diagonal."""
BOX_MARGIN = 0.1
"""A box may reach this share of the diagonal past the stroke's bounds: squaring a quad whose corners are within the
box's tolerance (`beautify.box_geometry`, 24 degrees) moves its corners out, and a hurried hand slants a box's
upright sides by up to 20 degrees (a parallelogram sheared so, squared, pokes out by 6-9 % of its diagonal, whatever
its aspect; at `BOUNDS_MARGIN` a box sheared by more than about 11 degrees fell back to the quad drawn)."""

def bounds(raw: np.ndarray, noise: float, diag: float, share: float = BOUNDS_MARGIN,
           extent: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The stroke's bounding box grown by ``share`` of its diagonal and the noise; ``extent``: ``raw``'s least and
    greatest x and y, where already found."""
    margin = share * diag + noise
    low, high = (raw.min(axis=0), raw.max(axis=0)) if extent is None else extent
    return low - margin, high + margin


def bic_score(c: Candidate | Pending, n: int, sigma: float, weights: Weights) -> float:
    mse = c.rss / n
    return (EFFECTIVE_SAMPLES * math.log(mse + sigma * sigma)
            + weights.complexity * c.params * math.log(EFFECTIVE_SAMPLES))


def rank(candidates: Sequence[Candidate | Pending], n: int, sigma: float, weights: Weights, raw: np.ndarray,
          noise: float, diag: float, fitted: np.ndarray | None = None, round_share: float = BOUNDS_MARGIN,
          ) -> Recognition:
    """The best-scored candidate whose shape stays within the stroke's bounds, and the best of each other kind
    as alternatives. Pending candidates are built only when the ranking reaches them, and the search stops
    once what is left could not change the answer or its alternatives. An ellipse may reach ``round_share`` of
    the diagonal past the bounds (a lumpy loop's flat stretch: `LUMPY_SIDES`; a circle rounded off from it may not)."""
    heap: list[tuple[float, int, Candidate | Pending]] = []
    for c in candidates:
        if math.isfinite(c.rss):
            heapq.heappush(heap, (bic_score(c, n, sigma, weights), len(heap), c))
    extent = raw.min(axis=0), raw.max(axis=0)  # found once for the three
    lo, hi = bounds(raw, noise, diag, extent=extent)
    round_lo, round_hi = bounds(raw, noise, diag, round_share, extent)
    box_lo, box_hi = bounds(raw, noise, diag, BOX_MARGIN, extent)
    kept: list[tuple[float, Candidate]] = []
    seq = len(heap)
    while heap:
        score, _, c = heapq.heappop(heap)
        if kept and (score - kept[0][0] > SEARCH_SPAN or len({k.kind for _, k in kept}) > 3):
            break
        if isinstance(c, Pending):
            for built in c.build():
                seq += 1
                heapq.heappush(heap, (bic_score(built, n, sigma, weights), seq, built))
        elif not inside(c.geometry, *((round_lo, round_hi) if c.kind == "ellipse" else
                                      (box_lo, box_hi) if c.kind == "box" else (lo, hi))):
            fallback = c.fallback if c.kind != "ellipse" else long_ellipse_as_drawn(c, raw)
            if fallback is not None:  # the quad drawn, where squaring it into a box pokes out of the stroke
                seq += 1
                heapq.heappush(heap, (score, seq, fallback))
        elif keeps_the_outline(c, raw if fitted is None else fitted):
            kept.append((score, c))
    if not kept:
        return Recognition(None, 0.0, None, (), "no shape fits the stroke")
    best_score = kept[0][0]
    weight: dict[str, float] = {}
    for s, c in kept:
        weight.setdefault(c.kind, math.exp(-(s - best_score) / CONFIDENCE_SCALE))
    total = sum(weight.values())
    best = kept[0][1]
    alternatives = tuple((k, round(w / total, 4)) for k, w in weight.items() if k != best.kind)
    return Recognition(best.kind, round(weight[best.kind] / total, 4), best.geometry, alternatives[:3])


LONG_ELLIPSE = 2.5
"""An ellipse this many times as long as it is wide is a long one (`long_ellipse_as_drawn`)."""
END_SLIDE = 0.15
"""How far (a share of its half-length) a long ellipse's fit may have slid or grown past the stroke's own ends."""


def long_ellipse_as_drawn(c: Candidate, raw: np.ndarray) -> Candidate | None:
    """A long ellipse ``c`` whose ends the fit put past the stroke's (a hand draws one end blunter or more pointed
    than an ellipse's, and the fit slides along the long axis towards the blunt end): the same ellipse, its long
    axis spanning the stroke's extent along it, at most `END_SLIDE` of its half-length away; None for any other."""
    g = c.geometry
    if not isinstance(g, Ellipse) or g.rx < LONG_ELLIPSE * g.ry:
        return None
    axis = np.array([math.cos(g.angle), math.sin(g.angle)])
    along = (raw - np.asarray(g.center)) @ axis
    lo, hi = float(along.min()), float(along.max())
    if max(abs(lo + g.rx), abs(hi - g.rx)) > END_SLIDE * g.rx:
        return None
    mid = 0.5 * (lo + hi)
    centre = (g.center[0] + mid * axis[0], g.center[1] + mid * axis[1])
    return Candidate(c.kind, Ellipse(centre, 0.5 * (hi - lo), g.ry, g.angle), c.rss, c.params)


def keeps_the_outline(c: Candidate, drawn: np.ndarray) -> bool:
    """Whether a box candidate follows the whole outline it was fitted to (``drawn``: the closed loop, without a
    tail drawn on past it: `polygon_checks.follows_the_outline`); other kinds are not judged here."""
    return c.kind != "box" or follows_the_outline(shape_points(c.geometry), drawn)


SEARCH_SPAN = 3 * 6.0
"""Candidates scored this much worse than the best are not built (their share of confidence is under e^-3)."""
CONFIDENCE_SCALE = 6.0
"""Score difference that divides a kind's weight by e when confidences are shared out."""


def inside(g: Geometry | None, lo: np.ndarray, hi: np.ndarray) -> bool:
    """Whether the shape ``g`` stays within the box from ``lo`` to ``hi`` (each of its `shape_points`: `within`)."""
    return g is not None and within(g, lo, hi)


FREEFORM_CONFIDENCE = 0.3
"""The confidence of a stroke kept as drawn because no shape fits it."""


def or_freeform(found: Recognition, work: np.ndarray, *, closed: bool, sigma: float) -> Recognition:
    """``found``, or when no shape fits, the stroke as it was drawn: a freeform polygon (closed) or polyline
    through its own most telling points, with a low confidence (never a shape outside the stroke)."""
    if found.kind is not None:
        return found
    keep = candidate_vertices(work[:-1] if closed else work, sigma, limit=16)
    points = tuple((float(x), float(y)) for x, y in work[keep])
    if closed and len(points) >= 3:
        return Recognition("polygon", FREEFORM_CONFIDENCE, Polygon(points), ())
    if len(points) >= 3:
        return Recognition("polyline", FREEFORM_CONFIDENCE, Polyline(points), ())
    return Recognition("line", FREEFORM_CONFIDENCE, Line(points[0], points[-1]), ())
