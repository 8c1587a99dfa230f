"""Competing interpretations of one stroke, each with its fit error and complexity; no ranking, no I/O.

Every candidate is measured on the same points (the stroke resampled along its length), so their errors compare:
``rss`` is the summed squared distance of those points to the candidate's shape, in the units the stroke is
judged at, and ``params`` counts the numbers the shape needs (a line 4, a k-segment polyline 2(k+1), a k-gon 2k,
a circle 3, an ellipse 5). `recognize` ranks them. Vertices lie on or next to the stroke's own points, so no
polygonal shape reaches far outside it (a quad's corners are placed where its sides meet, falling back to the fitted
vertices where they would); open strokes' curves and arcs are judged in `open_shapes`.
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from physink_tui.scene.recognition import quads
from physink_tui.scene.recognition.beautify import box_geometry, round_geometry
from physink_tui.scene.recognition.polygon_checks import corners_of, follows_the_outline, split_hairpins
from physink_tui.scene.recognition.polygon_fit import PolygonFit, best_polygons
from physink_tui.scene.recognition.primitives import Box, Geometry, Line, Polygon, Polyline
from physink_tui.scene.recognition.shape_fits import EllipseFit

MAX_SIDES = 10
"""The most sides a polygon or polyline candidate may have."""


@dataclass(frozen=True, slots=True)
class Candidate:
    """One interpretation of a stroke.

    Attributes:
        kind: a recognition kind (`primitives.KINDS`).
        geometry: its beautified shape, in the units the stroke was judged at.
        rss: summed squared distance of the judged points to the shape (those units squared).
        params: how many numbers the shape needs (its complexity).
        fallback: what the same fit stands for when this shape does not stay within the stroke (a box squared
            from a rhombus pokes out of it: the four-sided polygon drawn is kept instead), or None.
    """

    kind: str
    geometry: Geometry
    rss: float
    params: int
    fallback: Candidate | None = None


def _pt(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))


@dataclass(frozen=True, slots=True)
class Pending:
    """Candidates not built yet: their error is known, and building them (judging the corners, beautifying)
    is left until the ranking reaches them.

    Attributes:
        rss: their fit error, as `Candidate.rss`.
        params: the least complexity any of them has.
        build: makes them (possibly none, when the fit's corners are not real ones).
        fits: the polygonal fits they would be built from, least error first (none for other kinds).
    """

    rss: float
    params: int
    build: Callable[[], list[Candidate]]
    fits: tuple[PolygonFit, ...] = ()


def polygonal(work: np.ndarray, *, closed: bool, tolerance: float, noise: float) -> list[Pending]:
    """Lines, polylines, boxes and polygons: the best chain of sides for each number of sides, to be built."""
    fits = best_polygons(work, closed=closed, max_sides=MAX_SIDES, tolerance=tolerance)
    return [Pending(tried[0].rss, 2 * k if closed else 2 * (k + 1),
                    functools.partial(_build_polygonal, k, tried, closed, noise), tuple(tried))
            for k, tried in sorted(fits.items())]


def _build_polygonal(k: int, tried: list[PolygonFit], closed: bool, noise: float) -> list[Candidate]:
    judged = []
    for f in tried:  # least error first; the first whose corners are clean is enough
        judged.append((f, corners_of(f, closed=closed, noise=noise)))
        if judged[-1][1] is not None and not judged[-1][1].hairpins:
            break
    out = []
    if closed:
        capped = next(((f, c) for f, c in judged if c is not None and c.hairpins), None)
        if capped is not None:  # thin walls drawn as hairpins: their ends made flat, two corners each
            verts = split_hairpins(*capped)
            out.append(Candidate("polygon", Polygon(tuple(map(_pt, verts))), capped[0].rss, 2 * len(verts)))
    found = next(((f, c) for f, c in judged if c is not None and not c.hairpins), None)
    if found is None:
        return out
    fit, verts = found[0], found[1].vertices
    if closed:
        drawn = Candidate("polygon", Polygon(tuple(map(_pt, verts))), fit.rss, 2 * k)
        box = box_geometry(verts) if k == 4 else None
        askew = box is None and k == 4 and (box := quads.askew_box(fit.points, fit.indices)) is not None
        squared = _box_from_sides(box, fit) if box is not None else None
        # a box squared from a wall askew leaves no part of the loop out (else the quad drawn stands, as before)
        if (squared is not None and not quads.kept_as_drawn(fit.points, fit.indices, squared.corners)
                and not (askew and not follows_the_outline(squared.corners, fit.points))):
            out.append(Candidate("box", squared, fit.rss, 8, drawn))
        else:  # a polygon; a quad (a trapezoid or a rhombus among them) with its corners where its sides meet
            out.append(_at_side_corners(drawn, fit) if k == 4 else drawn)
    elif k == 1:
        out.append(Candidate("line", Line(_pt(verts[0]), _pt(verts[-1])), fit.rss, 4))
    else:
        out.append(Candidate("polyline", Polyline(tuple(map(_pt, verts))), fit.rss, 2 * (k + 1)))
    return out


def _at_side_corners(drawn: Candidate, fit: PolygonFit) -> Candidate:
    """A four-sided polygon ``drawn`` (its fit's vertices) with its corners where its sides meet
    (`quads.side_corners`: a hand rounds or cuts a corner, the fit's vertex lies inside it), falling back to ``drawn``
    where those poke out of the stroke; ``drawn`` itself where either outline is not convex (a bow tie: a delete mark
    or an alpha fitted with four sides is judged by how it crosses itself, `stroke_features.figure_eight`)."""
    corners = quads.side_corners(fit.points, fit.indices)
    if corners is None or not isinstance(drawn.geometry, Polygon):
        return drawn
    if not (quads.convex(corners) and quads.convex(np.asarray(drawn.geometry.points))):
        return drawn
    return replace(drawn, geometry=Polygon(tuple(map(_pt, corners))), fallback=drawn)


def _box_from_sides(box: Box, fit: PolygonFit) -> Box:
    """The box where its four drawn sides lie: each side's offset is the mean of its middle points across the
    box's axes (a hook or an overshoot at a corner moves no side); the vertices' box when the sides do not
    pair up two by two."""
    c, s = math.cos(box.angle), math.sin(box.angle)
    axes = np.array([[c, s], [-s, c]])
    offsets: list[list[float]] = [[], []]  # across-u sides (positions along v), across-v sides (along u)
    for a, b in itertools.pairwise(fit.indices):
        run = fit.points[a:b + 1]
        k = len(run)
        core = run[k // 6: k - k // 6] if k >= 6 else run
        direction = run[-1] - run[0]
        along_u = abs(float(direction @ axes[0])) >= abs(float(direction @ axes[1]))
        offsets[0 if along_u else 1].append(float((core @ axes[1 if along_u else 0]).mean()))
    if sorted(map(len, offsets)) != [2, 2]:
        return box
    (v0, v1), (u0, u1) = sorted(offsets[0]), sorted(offsets[1])
    centre = axes[0] * (u0 + u1) / 2 + axes[1] * (v0 + v1) / 2
    return Box(_pt(centre), u1 - u0, v1 - v0, box.angle)


def ellipse_distances(pts: np.ndarray, centre: np.ndarray, rx: float, ry: float, angle: float) -> np.ndarray:
    """Distance of each point to the ellipse across it: from the point to the ellipse's tangent where the ray from its
    centre through the point crosses it (exact for a circle; as close as the point lies to the ellipse). The distance
    along that ray alone (until session 26) overstates an elongated ellipse's miss where the ray runs slantwise
    through it, by up to ``1 / cos`` of the angle between the ray and the ellipse's normal (an ellipse 4 times as long
    as wide: about 2x at its shoulders), while a polygon's sides are judged square across them: a hand's flat oval
    (3-4 times as long as wide) lost to a triangle through its two ends)."""
    c, s = math.cos(angle), math.sin(angle)
    rel = pts - centre
    u = rel[:, 0] * c + rel[:, 1] * s
    v = -rel[:, 0] * s + rel[:, 1] * c
    r = np.sqrt((u / rx) ** 2 + (v / ry) ** 2)
    # the gradient of (u/rx)^2 + (v/ry)^2 (halved): the ellipse's normal at the crossing, scaled by 1 / r there
    normal = np.hypot(u / (rx * rx), v / (ry * ry))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(r > 0, np.abs(r - 1.0) * r / np.where(r > 0, normal, 1.0), min(rx, ry))


ACROSS_RATIO = (3 + math.sqrt(5)) / 2
"""An ellipse at least this many times as long as wide has its miss measured across it (`ellipse_distances`), a
rounder one along the ray from its centre (`ray_distances`), as until session 26. At an axis ratio ``k`` the ray runs
slantwise through the ellipse's shoulders and overstates a miss there by up to ``sqrt(1 + ((k - 1/k) / 2) ** 2)``:
1.12 at 1.64 (a coarse device's irregular hexagon fitted), 1.27 at 2.08 (a box drawn with its sides bowed and swung),
1.5 at this ratio (the golden ratio squared, 2.62), 2.0 at 4 (the captured pen ovals, 2.8-4.3; the lopsided long ovals'
pen family, 2.5-4.5). Below it the ray's overstatement is within what the ranking has always been tuned to, and the
polygons and boxes near round (whose ellipse, measured across, would miss them by less) keep their corners
(session 26, wt-fourth: across everywhere lost 2 of 30 irregular hexagons through a coarse device and 1 of 30 bowed
boxes by the hurried hand to the ellipse)."""


def ray_distances(pts: np.ndarray, centre: np.ndarray, rx: float, ry: float, angle: float) -> np.ndarray:
    """Distance of each point to the ellipse along the ray from its centre (exact for a circle)."""
    c, s = math.cos(angle), math.sin(angle)
    rel = pts - centre
    u = rel[:, 0] * c + rel[:, 1] * s
    v = -rel[:, 0] * s + rel[:, 1] * c
    r = np.sqrt((u / rx) ** 2 + (v / ry) ** 2)
    dist = np.hypot(u, v)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(r > 0, np.abs(dist - dist / np.where(r > 0, r, 1.0)), min(rx, ry))


def round_shape(work: np.ndarray, ellipse: EllipseFit | None) -> Candidate | None:
    """A circle or an ellipse through the stroke (closed, or most of the way round), from its `fit_ellipse`."""
    if ellipse is None:
        return None
    centre, rx, ry, angle, _ = ellipse
    if not (math.isfinite(rx) and math.isfinite(ry)) or ry <= 0:
        return None
    across = max(rx, ry) >= ACROSS_RATIO * min(rx, ry)
    rss = float(np.sum((ellipse_distances if across else ray_distances)(work, centre, rx, ry, angle) ** 2))
    geometry, kind = round_geometry(ellipse)
    if kind == "circle":  # rounded off to a circle, a slightly egg-shaped loop pokes out: the ellipse drawn is kept
        drawn, _ = round_geometry(ellipse, circle_ratio=math.inf)
        return Candidate(kind, geometry, rss, 3, Candidate("ellipse", drawn, rss, 5))
    return Candidate(kind, geometry, rss, 5)
