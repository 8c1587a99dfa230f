"""A loop read round that is a box with all four corners rounded, told by how far its corners reach; geometry only.

A rectangle or a square whose every corner a hand swung round by a quarter of its side or more has no sharp corner
left for the polygonal fits to find (`rounded_corners` needs two), and an ellipse fits it better than any polygon: it
reads round. What a circle or an ellipse never does is fill the corners of the smallest rectangle round it: in that
rectangle, scaled to a square of half-side 1, an ellipse reaches (|u| + |v|) / 2 = 1 / sqrt 2 = 0.707 towards each
corner, whatever its aspect, while a box whose corners are rounded by a quarter circle of ``s`` of its shorter side
reaches 1 - (2 - sqrt 2) s towards every one of them (0.85 at s = 0.25, 0.78 at 0.375, a circle again at 0.5), and
more where it is long (its rounding is then a smaller share of the long side). The least of the four reaches
(`corner_reach`) asks it of every corner at once: a lumpy circle may bulge at one diagonal, not at all four.

Measured before the threshold was chosen (issue 25, session 22; docs/BENCHMARKS.md): the 1,156 circles and ellipses
of the 92 design sources and the fourth group (quickdraw, tutorboard) that reach this rule reach at most 0.760 at
their least corner (hcira jonathanzhang53/s06, tutorboard seed170731; the 95th percentile is 0.721), the pen models'
wobbly, flattened, egg-shaped and overshot circles and ellipses at most 0.76, and boxes rounded by 0.25-0.4 of the
side 0.76-0.87.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import Polygon as ShapelyPolygon

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Box, Recognition

CORNER_REACH = 0.78
"""A loop read round is the box round it when its least corner reaches at least this far towards the corner of the
smallest rectangle round it (`corner_reach`): as far as a box's corner rounded by a quarter circle of 0.375 of its
side. People's circles and ellipses in the design sources and the fourth group reach at most 0.760: the margin, 0.02,
is a corner radius of 0.035 of the side."""


def smallest_rectangle(loop: np.ndarray) -> tuple[np.ndarray, float, np.ndarray, np.ndarray] | None:
    """The smallest rectangle round ``loop`` (it lies along a side of the loop's convex hull): its centre, the angle
    of its first axis, its side lengths (along that axis and across it), and the loop's points in it, scaled to the
    square [-1, 1] x [-1, 1]; None for a loop without area."""
    hull = shapely.convex_hull(shapely.multipoints(np.asarray(loop, dtype=float)))
    if not isinstance(hull, ShapelyPolygon) or hull.area <= 0.0:
        return None
    ring = np.asarray(hull.exterior.coords)[:-1]
    edges = sg.succ(ring) - ring
    angles = np.mod(np.arctan2(edges[:, 1], edges[:, 0]), math.pi / 2)
    c, s = np.cos(angles), np.sin(angles)
    along = ring[None, :, 0] * c[:, None] + ring[None, :, 1] * s[:, None]  # edges by hull points
    across = -ring[None, :, 0] * s[:, None] + ring[None, :, 1] * c[:, None]
    areas = (along.max(axis=1) - along.min(axis=1)) * (across.max(axis=1) - across.min(axis=1))
    k = int(np.argmin(areas))
    angle = float(angles[k])
    axes = np.array([[math.cos(angle), math.sin(angle)], [-math.sin(angle), math.cos(angle)]])
    local = loop @ axes.T
    lo, hi = local.min(axis=0), local.max(axis=0)
    size = hi - lo
    if (size <= 0.0).any():
        return None
    centre = ((lo + hi) / 2) @ axes
    return centre, angle, size, (local - (lo + hi) / 2) / (size / 2)


def corner_reach(scaled: np.ndarray) -> float:
    """How far the loop reaches towards the corners of its smallest rectangle (``scaled``: its points in that
    rectangle as the square [-1, 1] x [-1, 1], `smallest_rectangle`): the least, over the four corners, of the
    largest (|u| + |v|) / 2 of the points on that corner's quarter (1 at a sharp corner, 0.707 for an ellipse)."""
    reach = 1.0
    for sx in (-1.0, 1.0):
        for sy in (-1.0, 1.0):
            quarter = scaled[(scaled[:, 0] * sx > 0) & (scaled[:, 1] * sy > 0)]
            if len(quarter) == 0:
                return 0.0
            reach = min(reach, float(np.abs(quarter).sum(axis=1).max()) / 2)
    return reach


def box_rounded_all_round(ranked: Recognition, loop: np.ndarray) -> Recognition:
    """``ranked`` (a circle or an ellipse) read as the box round ``loop`` (the smallest rectangle round it) when every
    corner of the loop reaches `CORNER_REACH` towards that box's corner; ``ranked`` otherwise. The box's sides touch
    the loop and its corners lie beyond it only by what the rounding took off, so it is not asked to stay within the
    stroke's bounds as a box fitted otherwise is (`ranking.BOX_MARGIN`): a square turned 30-45 degrees whose corners
    are rounded by a third of its side pokes out past them by more."""
    if ranked.kind not in ("circle", "ellipse") or len(loop) < 8:
        return ranked
    found = smallest_rectangle(loop)
    if found is None:
        return ranked
    centre, angle, size, scaled = found
    if corner_reach(scaled) < CORNER_REACH:
        return ranked
    box = Box((float(centre[0]), float(centre[1])), float(size[0]), float(size[1]), angle)
    return Recognition("box", ranked.confidence, box, ((str(ranked.kind), 1.0 - ranked.confidence),))
