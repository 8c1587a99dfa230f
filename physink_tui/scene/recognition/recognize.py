"""Recognises one stroke (or an X of two) as a primitive with a beautified geometry; no I/O, no clock.

In PaleoSketch's manner (Paulson & Hammond 2008) the interpretations compete instead of passing a cascade of
hard tests: every candidate (`candidates`: the best line, polyline or polygon for each number of sides, a box,
a circle or an ellipse, an arc, a curve of cubic pieces) is fitted to the same points, and each is scored by
its fit error and its complexity, BIC-style: ``N log(mse + sigma^2) + complexity * params * log N``. The floor
``sigma`` is the larger of the pen's own noise, in absolute units (a pixel or two whatever the shape's size),
and the hand's inaccuracy relative to the shape's size. The best-scored candidate whose shape stays within the
stroke's bounds wins; the others become the alternatives (`ranking`). Springs and scribbles are told apart first.

>>> import math
>>> circle = [(10 * math.cos(a / 20), 10 * math.sin(a / 20)) for a in range(126)]
>>> recognize_stroke(circle).kind
'circle'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from physink_tui.scene.recognition import (
    angular_braces,
    closed_loops,
    dented_spines,
    hooked_ticks,
    landing,
    loop_ends,
    lopsided_braces,
    open_boxes,
    open_shapes,
    pen_lifts,
    pen_noise,
    ranker,
    round_brackets,
    run_on_loops,
    square_braces,
    stairs,
    units,
    waves,
)
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import scale_geometry, x_symbol
from physink_tui.scene.recognition.closed_reading import ClosedStroke, closed_reading
from physink_tui.scene.recognition.coils import COILED, helix_or_scribble
from physink_tui.scene.recognition.open_reading import open_reading
from physink_tui.scene.recognition.primitives import Line, Recognition
from physink_tui.scene.recognition.ranking import DEFAULT_WEIGHTS, Weights
from physink_tui.scene.recognition.small_loops import remove_small_loops
from physink_tui.scene.recognition.stroke_views import StrokeViews

TOO_SHORT = "too short to recognise"
MAX_COORDINATE = 1e150  # beyond this, fitting squares coordinates past what a float holds
SHAKY = 1.5
"""A stroke whose measured jitter is this many times the pen's stated noise is smoothed where it was sampled too,
unless its points are so far apart that the jitter may be the shape's own bends (`SPARSE_BENDS`)."""
SPARSE_BENDS = 2.0
"""A measured jitter (`pen_noise.jitter`) under this many times `pen_noise.shape_bend` (a round shape's
bend between the stroke's points) may be the shape's, not the pen's: on points far apart (a device sampling evenly in
time: 8-25 events over a fast stroke, the pen slowing at corners) successive bends differ by as much again as they
are, and more where a corner falls. Such a jitter is not taken for a shaky hand (a filter one sample wide would cut the
corners to chamfers) and raises the noise floor no further than `SHAKY` times the stated noise (a box's 8-25 events
measure 10-40 px on a 280 px box, whose sides then no longer pay for their corners: read as an ellipse)."""
MIN_SIZE = 3.0
"""A stroke less than this many noise widths across is a dot, not a shape."""
PEN_NOISE = 1.0
"""The pen's jitter in the stroke's units when the caller does not say: a pixel of a canvas in pixels (``noise=None``
judges it from the stroke instead: `units.stroke_noise`)."""


def _clean(points: Sequence[Sequence[float]]) -> tuple[np.ndarray | None, np.ndarray | None, float, str | None]:
    """The stroke's points without repeats, which of the given points they are (None where a long stroke was
    thinned first) and their diagonal (`stroke_geometry.bbox_diagonal`), or why it cannot be recognised."""
    try:
        pts = np.asarray(points, dtype=float)
    except (TypeError, ValueError):
        return None, None, 0.0, "points must be pairs of numbers"
    if pts.ndim != 2 or pts.shape[0] == 0 or pts.shape[1] < 2:
        return None, None, 0.0, f"{TOO_SHORT}: no points" if pts.size == 0 else "points must be pairs of numbers"
    pts = pts[:, :2]
    bad = ~np.isfinite(pts).all(axis=1)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        return None, None, 0.0, (f"coordinates must be finite numbers; point {i} is ({float(pts[i, 0])!r}, "
                                 f"{float(pts[i, 1])!r})")
    if float(np.abs(pts).max()) > MAX_COORDINATE:
        return None, None, 0.0, f"coordinates too large to recognise (beyond {MAX_COORDINATE:g})"
    keep: np.ndarray | None = None
    if len(pts) > sg.MAX_WORKING_POINTS:
        pts = sg.drop_duplicates(sg.resample(sg.drop_duplicates(pts), sg.MAX_WORKING_POINTS))
    else:  # as `stroke_geometry.drop_duplicates`, the kept points' positions remembered for the ranker
        keep = np.ones(len(pts), dtype=bool)
        keep[1:] = ((pts[1:] - pts[:-1]) != 0.0).any(axis=1)
        pts = pts[keep]
    if len(pts) < 2:
        return None, None, 0.0, f"{TOO_SHORT}: a single point"
    size = sg.bbox_diagonal(pts)
    if size == 0.0:
        return None, None, 0.0, f"{TOO_SHORT}: no extent"
    return pts, keep, size, None


def sparse_bends(pts: np.ndarray, noise: float, measured: float | None = None) -> bool:
    """Whether the jitter measured on ``pts`` (the stroke's points without repeats; ``measured`` where already
    measured) exceeds the pen's stated ``noise`` but could be the shape's own bends between sparse points
    (`SPARSE_BENDS`): a device's few events, not a shaky hand."""
    measured = pen_noise.jitter(pts) if measured is None else measured
    return measured > noise and measured <= SPARSE_BENDS * pen_noise.shape_bend(pts)


def sampled_sparsely(points: Sequence[Sequence[float]], noise: float | None = PEN_NOISE) -> bool:
    """`sparse_bends` of a stroke as `recognize_stroke` is given it (False where it cannot be recognised)."""
    with np.errstate(all="ignore"):
        pts, keep, size, _ = _clean(points)
    if pts is None:
        return False
    given = _given(noise, points, pts, size)
    return sparse_bends(_settled(pts, keep, size, given)[0], given)


def _given(noise: float | None, points: Sequence[Sequence[float]], pts: np.ndarray, size: float) -> float:
    """The pen's stated jitter, 0 where it is not a positive number; where not stated (None), judged from the stroke:
    the lattice of its ``points`` as given, the jitter of ``pts`` (without repeats) and their diagonal ``size``
    (`units.stroke_noise`)."""
    if noise is None:
        with np.errstate(all="ignore"):
            measured = pen_noise.jitter(pts)
            return units.stroke_noise(pts, size, np.asarray(points, dtype=float)[:, :2], measured=measured,
                                      own_bends=measured <= SPARSE_BENDS * pen_noise.shape_bend(pts))
    return noise if math.isfinite(noise) and noise > 0 else 0.0


def _settled(pts: np.ndarray, keep: np.ndarray | None, size: float,
             given: float) -> tuple[np.ndarray, np.ndarray | None, float]:
    """``pts`` (with ``keep``, which of the given points they are, and their diagonal) without a finger's dwell where
    it landed or lifted (`landing.settled`: kept as one point)."""
    settled = landing.settled(pts, size, given)
    if settled.all():
        return pts, keep, size
    if keep is not None:
        keep[np.flatnonzero(keep)[~settled]] = False
    return pts[settled], keep, sg.bbox_diagonal(pts[settled])


def recognize_stroke(points: Sequence[Sequence[float]], times: Sequence[float] | None = None, *,
                     noise: float | None = PEN_NOISE, weights: Weights | None = None,
                     learned: bool | ranker.Asker = True) -> Recognition:
    """Recognise one stroke given as (x, y) points (extra columns such as t are ignored).

    ``noise`` is the pen's jitter in the points' units (pass it scaled with the coordinates: a canvas in
    fractions of its size has a noise of about 1 / its width in pixels), or None to judge it from the stroke in
    whatever units it is stored (`units.stroke_noise`: the lattice its coordinates are rounded to, else its jitter);
    a stroke that is visibly shakier is judged with its own, measured jitter (`pen_noise.jitter`). ``times`` (one a
    point, seconds), where given, tell the learned ranker how the pen slowed at corners. ``weights`` override the
    ranking's and ``learned=False`` leaves the rules' reading without the learned ranker (`ranker`; both for
    evaluation); ``learned`` may also be what is asked in the ranker's stead (`ranker.Asker`: its training). A stroke
    whose times show the pen lifted and drew the mark again is read by its last attempt (`pen_lifts`).
    """
    attempt = pen_lifts.last_attempt(points, times)
    if attempt is not None and times is not None:
        last = recognize_stroke(points[attempt], times[attempt], noise=noise, weights=weights, learned=learned)
        return replace(last, note=pen_lifts.told(times, attempt))
    with np.errstate(all="ignore"):  # huge coordinates overflow here; the checks below catch it
        pts, keep, size, reason = _clean(points)
    if pts is None:
        return Recognition(None, 0.0, None, (), reason)
    given = _given(noise, points, pts, size)
    pts, keep, size = _settled(pts, keep, size, given)
    if len(pts) == 2:
        return Recognition("line", 1.0, Line(_point(pts[0]), _point(pts[-1])))
    # judge the shape at unit size round the origin (no overflow, no underflow), answer in its own units
    with np.errstate(over="ignore", invalid="ignore"):
        origin = np.add.reduce(pts, axis=0) / len(pts)  # `pts.mean(axis=0)` to the bit
        scale = float(np.abs(pts - origin).max())
    if not math.isfinite(scale) or scale == 0.0:
        return Recognition(None, 0.0, None, (), "coordinates too large to recognise")
    measured = pen_noise.jitter(pts)
    # the pen may be worse than said, but a jitter that sparse points' own bends could make (`SPARSE_BENDS`) is
    # credited only up to an ordinary pen's (`SHAKY`) and does not get the stroke smoothed where it was sampled
    seen = not sparse_bends(pts, given, measured)
    noise = max(given, measured if seen else min(measured, SHAKY * given))
    shaky = measured > SHAKY * given and seen
    if size < MIN_SIZE * noise:
        return Recognition(None, 0.0, None, (), f"{TOO_SHORT}: {size:.3g} units across, within the pen's noise "
                                                f"({noise:.3g} units)")
    unit_noise = noise / scale
    unit = (pts - origin) / scale
    unit.flags.writeable = False
    views = StrokeViews(unit)  # the resampled copies the checks below share, each made once for this stroke
    with np.errstate(all="ignore"):  # degenerate shapes make NaN fits, which the ranking then drops
        rules = _classify(unit, unit_noise, weights or DEFAULT_WEIGHTS, shaky, size / scale,
                          (given if given > 0 else noise) / scale, _kept_times(times, keep, len(pts)), views)
        result = waves.as_curve(rules, unit, views)  # a wave's round bends are no zig-zag's teeth
        wavy = result is not rules
        # steps judged at their own scale; not on points so far apart that their jitter is the shape's own bends
        # (`sparse_bends`: a device's few events make any stroke straight runs joined at sharp turns)
        chain = None if wavy or not seen else stairs.chain_reading(result, unit, unit_noise, views)
        # a tick whose short arm the rules cut as a hook (under a tenth of the path, longer than a hook reaches)
        tick = (hooked_ticks.hooked_tick(unit, unit_noise, views)
                if chain is None and not wavy and result.kind in hooked_ticks.READ_AS else None)
        # a curve of the rules no steps or tick read: kept from the model where it is a wave (`waves.kept_curve`, asked
        # below only where the model would change the reading)
        may_be_wave = chain is None and tick is None and not wavy and rules.kind == "curve"
    if chain is not None:
        result = chain
    if tick is not None:
        result = tick
    if result.geometry is None:
        return result
    result = replace(result, geometry=scale_geometry(result.geometry, origin, scale))
    # a wave is not asked of the model (the people it was fitted on drew none), nor a chain of sharp corners (its
    # 64 points smooth small steps away), nor a tick whose short arm is a few percent of it (the model takes it for a
    # curve), nor a mark straight-armed as drawn, nor a square bracket whose corners were rounded off, nor a brace
    # drawn as straight runs, lopsided with a straight short half or square-cornered the rules read as a curve
    if (not learned or wavy or chain is not None or tick is not None
            or open_shapes.straight_armed_mark(result, pts, noise)
            or round_brackets.kept_bracket(result, unit, unit_noise, views)
            or dented_spines.kept_bracket(result, unit, unit_noise, views, (origin, scale))
            or angular_braces.kept_brace(result, unit, unit_noise, views)
            or lopsided_braces.kept_brace(result, unit, unit_noise, views)
            or square_braces.kept_brace(result, unit, unit_noise, views)):
        return result
    drawn = ranker.Drawn(pts, keep, origin, size, measured) if keep is not None else None
    with np.errstate(all="ignore"):  # the ranker keeps what is not one of its kinds
        reranked = (ranker.rerank(points, times, given if given > 0 else PEN_NOISE, result, ranker.shipped_model(),
                                  drawn, not seen) if learned is True
                    else learned(points, times, given if given > 0 else PEN_NOISE, result, drawn, not seen))
        if reranked != result and may_be_wave and waves.kept_curve(rules, unit, views):
            return result  # a wave (the people the model was fitted on drew none)
    return reranked


def _kept_times(times: Sequence[float] | None, keep: np.ndarray | None, n: int) -> np.ndarray | None:
    """The times of the points kept (``keep``: which of the given points they are; None where a long stroke was thinned,
    which leaves no time to a point), or None."""
    if times is None or keep is None or len(times) != len(keep):
        return None
    kept = np.asarray(times, dtype=float)[keep]
    return kept if len(kept) == n else None


def _point(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))


def recognize_strokes(strokes: Sequence[Sequence[Sequence[float]]], *, noise: float | None = PEN_NOISE,
                      times: Sequence[Sequence[float] | None] | None = None) -> Recognition:
    """One stroke, or two consecutive strokes that may be an X-symbol (thesis 3.2.1); ``times``, where given, holds
    each stroke's point times in seconds or None (`recognize_stroke`)."""
    at = list(times) if times is not None else [None] * len(strokes)
    if len(at) != len(strokes):
        raise ValueError(f"recognize_strokes: {len(strokes)} strokes but {len(at)} lists of times")
    if len(strokes) == 1:
        return recognize_stroke(strokes[0], at[0], noise=noise)
    if len(strokes) != 2:
        return Recognition(None, 0.0, None, (), f"expected one stroke or two (an X), got {len(strokes)}")
    first, second = (recognize_stroke(points, when, noise=noise) for points, when in zip(strokes, at, strict=True))
    if (first.kind == "line" and second.kind == "line" and isinstance(first.geometry, Line)
            and isinstance(second.geometry, Line)):
        x = x_symbol(first.geometry, second.geometry)
        if x is not None:
            return Recognition("x", x[1], x[0], (("line", 0.5),))
        return Recognition(None, 0.0, None, (("line", first.confidence),),
                           "two lines that do not make an X (they must cross near their middles, "
                           "roughly perpendicular)")
    return Recognition(None, 0.0, None, (), "only two crossing short lines make a two-stroke symbol (an X)")


MAX_JUDGED_POINTS = 600
"""A stroke is judged on at most this many points along its path (`_classify`)."""


def _classify(raw: np.ndarray, noise: float, weights: Weights, shaky: bool, diag: float,
              pen: float, times: np.ndarray | None = None, views: StrokeViews | None = None) -> Recognition:
    """``raw`` at unit size; ``diag`` its `stroke_geometry.bbox_diagonal`, ``noise`` in the same units (the stroke's
    measured jitter where worse than the pen's stated ``pen``); ``times`` one a point of ``raw`` (seconds) or None;
    ``views``: ``raw``'s `stroke_views.StrokeViews`, where made."""
    found = open_shapes.line(raw, noise, diag, pen)
    if found is not None:
        return found
    length = sg.path_length(raw)
    thickness = sg.thickness(raw)
    spacing = max(min(diag / 40, max(thickness, diag / 200) / 8), 2 * noise, length / MAX_JUDGED_POINTS)
    n = int(min(max(64, length / spacing), MAX_JUDGED_POINTS))
    # a shaky pen's points are smoothed where they were sampled first, then along the resampled path
    work = sg.smooth(sg.resample(sg.smooth(raw) if shaky else raw, n))
    th = sg.turning(work)
    if abs(float(np.add.reduce(th))) > COILED:  # a lead drawn out and back turns a half turn each way
        led = loop_ends.without_retraced_ends(work, diag)  # a first side or arc drawn twice over is drawn once
        if led is not work:
            work, th = led, sg.turning(led)
    # without its small loops, measured once where the coil test asks (`coils.COILED`) and used again below
    unlooped = remove_small_loops(work) if abs(float(np.add.reduce(th))) > COILED else None
    special = helix_or_scribble(work, n, diag, sg.path_length(work), th, unlooped)
    if special is not None:
        return special
    work = sg.resample(remove_small_loops(work) if unlooped is None else unlooped, n)  # loops at corners are flourishes
    sigma = max(noise, weights.relative_noise * diag)
    closed, loop, ellipse = closed_loops.closed_loop(raw, work, diag, sigma)
    # a round loop the pen landed on and ran on past its start as a long tail (`run_on_loops`) is that loop
    run_on = run_on_loops.AskedOnce(work, diag, sigma)  # of ``work`` as it is here, asked at most once
    ran_on = run_on() if not closed else None
    if ran_on is not None:
        closed, loop = True, ran_on
    corners_told = False  # a polygon left open whose rounded corners its turning tells (`shape_corners`)
    if not closed:
        hooked, unhooked = work, sg.remove_hooks(work)
        if closed_loops.hook_kept_apart(hooked, unhooked, diag, sigma):
            closed, loop, ellipse = closed_loops.closed_loop(unhooked, sg.resample(unhooked, n), diag, sigma)
        work = sg.resample(unhooked, n)
        how_left_open = closed_loops.polygon_left_open(work, diag, raw) if not closed else None
        if how_left_open is not None:
            closed, loop, corners_told = True, work, closed_loops.corners_told(how_left_open, work, raw)
        elif not closed:  # a box left open by part of a side (that part may be short enough to be cut as a hook)
            ways = (work, hooked) if len(unhooked) != len(hooked) else (work,)
            left_open = next((w for w in ways if open_boxes.box_left_open(w, diag)), None)
            if left_open is not None:
                closed, loop = True, left_open
    if not closed:
        return open_reading(raw, work, n, noise, sigma, weights, diag, views)
    return closed_reading(ClosedStroke(raw, work, n, loop, ellipse, diag, times, corners_told=corners_told,
                                       run_on=run_on), noise, sigma, weights, views)
