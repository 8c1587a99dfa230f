"""Reads a stroke the pen closed (or that `recognize` found closed after all) as the outline or round shape its
loop best fits, then as what a person drew after all (a polygon with rounded corners, a box with a bowed side, a
pigtail, a delete mark); finding the loop is `closed_loops`' and `recognize`'s; no I/O."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from physink_tui.scene.recognition import (
    both_laps,
    bowed_sides,
    closed_loops,
    open_marks,
    pen_noise,
    roofs,
    rounded_boxes,
    rounded_corners,
    rounded_polygons,
    run_on_loops,
)
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.candidates import Candidate, Pending, polygonal, round_shape
from physink_tui.scene.recognition.open_reading import OPEN_ROUND_MARGIN, open_reading
from physink_tui.scene.recognition.primitives import Polygon, Recognition
from physink_tui.scene.recognition.ranking import BOUNDS_MARGIN, Weights, bounds, or_freeform, rank
from physink_tui.scene.recognition.round_or_cornered import cornered_after_all
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse
from physink_tui.scene.recognition.stroke_views import StrokeViews


@dataclass(frozen=True, slots=True, eq=False)
class ClosedStroke:
    """A stroke `recognize` found closed: ``raw`` at unit size (``diag`` its `stroke_geometry.bbox_diagonal`,
    ``times`` one a point or None), ``work`` its ``n`` judged points, ``loop`` the closed part and ``ellipse`` where
    already fitted to it."""

    raw: np.ndarray
    work: np.ndarray
    n: int
    loop: np.ndarray
    ellipse: EllipseFit | None
    diag: float
    times: np.ndarray | None
    corners_told: bool
    """A polygon left open, closed by its rounded corners' turning (`closed_loops.corners_told`)."""
    run_on: run_on_loops.AskedOnce
    """The loop, where it is a round loop the pen ran on past its start (`run_on_loops`), asked of ``work`` as
    `recognize` first judged it, at most once (by `recognize` where the stroke was not closed, else here where it
    matters)."""


def closed_reading(stroke: ClosedStroke, noise: float, sigma: float, weights: Weights,
                   views: StrokeViews | None = None) -> Recognition:
    """The reading of a closed ``stroke`` (``noise`` and ``sigma`` as the ranking takes them; ``views`` the stroke's
    `stroke_views.StrokeViews`, where made)."""
    raw, work, n, loop, diag = stroke.raw, stroke.work, stroke.n, stroke.loop, stroke.diag
    polygons = polygonal(loop, closed=True, tolerance=0.5 * sigma, noise=noise)
    ellipse = stroke.ellipse if stroke.ellipse is not None else fit_ellipse(loop)
    # a loop far from any ellipse, or turning back as a star's outline does, is not read round (a star whose
    # shallow inner corners no polygon fit passes, or whose points are more than `candidates.MAX_SIDES` can follow)
    never_round = closed_loops.no_round_shape(loop, noise, ellipse)
    lumpy = not never_round and closed_loops.lumpy_round(loop, noise, ellipse, raw, diag)
    # a lumpy circle's lumps are not sides, nor are the chords between a busy mouse's bursts of events round a loop
    in_bursts = not never_round and pen_noise.round_in_bursts(raw, diag) is not None
    sided = [] if in_bursts else [p for p in polygons if p.params < 2 * closed_loops.LUMPY_SIDES] if lumpy else polygons
    round_fit = None if never_round else round_shape(loop, ellipse)
    candidates: list[Candidate | Pending | None] = [*sided, round_fit]
    ranked = rank([c for c in candidates if c is not None], len(loop), sigma, weights, raw, noise, diag, loop,
                  round_share=OPEN_ROUND_MARGIN if lumpy or in_bursts else BOUNDS_MARGIN)
    if ranked.kind in ("circle", "ellipse") and round_fit is not None:
        ranked = cornered_after_all(ranked, polygons, round_fit.rss, raw, noise, diag, sigma, weights, stroke.times,
                                    stroke.corners_told)
    if (ranked.kind in ("circle", "ellipse") and closed_loops.tail_runs_off(work, loop, ellipse)
            and stroke.run_on() is None):
        return open_reading(raw, work, n, noise, sigma, weights, diag, views, round_too=False)  # a pigtail
    # circle or ellipse either way round (the bounds a circle must stay within asked only of an ellipse)
    ranked = both_laps.round_from_both_laps(ranked, work, ellipse, diag, sigma,
                                            bounds(raw, noise, diag) if ranked.kind == "ellipse" else None)
    ranked = rounded_polygons.polygon_rounded(  # asked of the loop cut from either end
        ranked, loop, raw, lambda: closed_loops.closed_loop(raw[::-1], work[::-1], diag, sigma, fit=False)[:2])
    ranked = rounded_corners.box_as_drawn(ranked, polygons, raw, noise, diag, loop)
    ranked = rounded_corners.box_after_all(ranked, polygons, loop, raw, noise, diag)
    ranked = bowed_sides.box_with_a_bowed_side(ranked, polygons, loop, raw, noise, diag)
    ranked = roofs.pentagon_on_a_box(ranked, polygons, noise)
    ranked = rounded_boxes.box_rounded_all_round(ranked, loop)
    ranked = open_marks.out_and_back(ranked, raw)  # a line drawn out and back closes a slit, no ellipse
    if isinstance(ranked.geometry, Polygon) and sf.figure_eight(np.asarray(ranked.geometry.points)):
        # ends that meet after crossing over: a delete mark or an arrow drawn back to its start, not an outline
        return open_reading(raw, sg.resample(sg.remove_hooks(work), n), n, noise, sigma, weights, diag, views)
    return or_freeform(ranked, loop, closed=True, sigma=sigma)
