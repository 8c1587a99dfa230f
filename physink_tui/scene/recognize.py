"""Recognises one stroke (or an X of two) as a primitive with a beautified geometry; no I/O, no clock.

In PaleoSketch's manner (Paulson & Hammond 2008) every primitive gets its own geometric test on a
cleaned, resampled stroke, and the passing ones are ranked: line before polyline, round shapes and
boxes before freeform polygons, arcs before free curves. Thresholds are ratios (distance over
size, angles), never absolute distances, so the answer is the same at any scale and rotation.

>>> import math
>>> circle = [(10 * math.cos(a / 20), 10 * math.sin(a / 20)) for a in range(126)]
>>> recognize_stroke(circle).kind
'circle'
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from physink_tui.scene import stroke_features as sf
from physink_tui.scene import stroke_geometry as sg
from physink_tui.scene.beautify import (
    arc_geometry,
    box_geometry,
    curve_geometry,
    helix_geometry,
    round_geometry,
    scale_geometry,
    x_symbol,
)
from physink_tui.scene.primitives import Line, Polygon, Polyline, Recognition
from physink_tui.scene.shape_fits import fit_circle, fit_ellipse, fit_line

TOO_SHORT = "too short to recognise"
MAX_COORDINATE = 1e150  # beyond this, fitting squares coordinates past what a float holds
STRAIGHT = 0.12  # a segment is straight when it strays from its chord by less than this fraction
LINE = 0.045  # a whole stroke is a line when it strays from its fit by less than this fraction
ROUND_ERROR = 0.09  # normalised radial error below which a closed stroke is an ellipse
VERY_SHARP_CORNER = 100.0  # degrees: a corner this sharp makes a polyline whatever its sides do
SHARP_CORNER = 62.0  # degrees a bowed polyline's corners must each turn
CORNER_SHARE = 0.45  # an open stroke turning at least this share at its corners is a polyline
NEARLY_ROUND = 1.25  # an open smooth stroke turning more than this many pi radians is a round shape left open
CIRCLE_RATIO = 0.8  # minor/major axis ratio above which an ellipse is a circle


def _clean(points: Sequence[Sequence[float]]) -> tuple[np.ndarray | None, str | None]:
    try:
        pts = np.asarray(points, dtype=float)
    except (TypeError, ValueError):
        return None, "points must be pairs of numbers"
    if pts.ndim != 2 or pts.shape[0] == 0 or pts.shape[1] < 2:
        return None, f"{TOO_SHORT}: no points" if pts.size == 0 else "points must be pairs of numbers"
    pts = pts[:, :2]
    bad = ~np.isfinite(pts).all(axis=1)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        return None, f"coordinates must be finite numbers; point {i} is ({float(pts[i, 0])!r}, {float(pts[i, 1])!r})"
    if float(np.abs(pts).max()) > MAX_COORDINATE:
        return None, f"coordinates too large to recognise (beyond {MAX_COORDINATE:g})"
    if len(pts) > sg.MAX_WORKING_POINTS:
        pts = sg.resample(sg.drop_duplicates(pts), sg.MAX_WORKING_POINTS)
    pts = sg.drop_duplicates(pts)
    if len(pts) < 2:
        return None, f"{TOO_SHORT}: a single point"
    if sg.bbox_diagonal(pts) == 0.0:
        return None, f"{TOO_SHORT}: no extent"
    return pts, None


def recognize_stroke(points: Sequence[Sequence[float]], times: Sequence[float] | None = None) -> Recognition:
    """Recognise one stroke given as (x, y) points (extra columns such as t are ignored).

    ``times`` are accepted for symmetry with pen input; the tests are geometric.
    """
    with np.errstate(all="ignore"):  # huge coordinates overflow here; the checks below catch it
        pts, reason = _clean(points)
    if pts is None:
        return Recognition(None, 0.0, None, (), reason)
    if len(pts) == 2:
        return Recognition("line", 1.0, Line(_point(pts[0]), _point(pts[-1])))
    # judge the shape at unit size round the origin (no overflow, no underflow), answer in its own units
    with np.errstate(over="ignore", invalid="ignore"):
        origin = pts.mean(axis=0)
        scale = float(np.abs(pts - origin).max())
    if not math.isfinite(scale) or scale == 0.0:
        return Recognition(None, 0.0, None, (), "coordinates too large to recognise")
    with np.errstate(all="ignore"):  # degenerate shapes make NaN fits, which the tests then reject
        result = _classify((pts - origin) / scale)
    if result.geometry is None:
        return result
    return replace(result, geometry=scale_geometry(result.geometry, origin, scale))


def _line(raw: np.ndarray) -> Recognition | None:
    """A line, judged at the coarse scale of the whole stroke (jitter at the pen's own scale would make a
    short, slow line look long and wavy): close to its fit, no more ink than its chord, hooks ignored."""
    coarse = sg.smooth(sg.resample(raw, 48))
    coarse = sg.resample(sg.remove_hooks(coarse), 48)
    _, _, err = fit_line(coarse)
    length = sg.path_length(coarse)
    chord = float(np.hypot(*(coarse[-1] - coarse[0])))
    if (err < LINE and length < 1.12 * chord) or (err < 0.5 * LINE and length < 1.3 * chord):
        return Recognition("line", 1.0 - err / LINE * 0.5, Line(_point(coarse[0]), _point(coarse[-1])),
                           (("arc", 0.2),))
    return None


def _point(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))


def recognize_strokes(strokes: Sequence[Sequence[Sequence[float]]]) -> Recognition:
    """One stroke, or two consecutive strokes that may be an X-symbol (thesis 3.2.1)."""
    if len(strokes) == 1:
        return recognize_stroke(strokes[0])
    if len(strokes) != 2:
        return Recognition(None, 0.0, None, (), f"expected one stroke or two (an X), got {len(strokes)}")
    first, second = recognize_stroke(strokes[0]), recognize_stroke(strokes[1])
    if first.kind == "line" and second.kind == "line":
        x = x_symbol(first.geometry, second.geometry)
        if x is not None:
            return Recognition("x", x[1], x[0], (("line", 0.5),))
        return Recognition(None, 0.0, None, (("line", first.confidence),),
                           "two lines that do not make an X (they must cross near their middles, "
                           "roughly perpendicular)")
    return Recognition(None, 0.0, None, (), "only two crossing short lines make a two-stroke symbol (an X)")


def _classify(raw: np.ndarray) -> Recognition:
    line = _line(raw)
    if line is not None:
        return line
    diag = sg.bbox_diagonal(raw)
    length = sg.path_length(raw)
    thickness = sg.thickness(raw)
    spacing = min(diag / 40, max(thickness, diag / 200) / 8)  # thin shapes need finer steps
    n = int(min(max(64, length / spacing), 320))
    work = sg.smooth(sg.resample(raw, n))
    if abs(float(sg.turning(work).sum())) > 3.5 * math.pi:  # enough turning for two loops or more
        coil = sg.resample(sg.remove_hooks(work), n)
        coil_turn = sg.turning(coil)
        if sf.turn_concentration(sg.turning(sg.resample(coil, 40))) < 0.5:  # smooth: a star winds twice too
            helix = helix_geometry(coil, float(coil_turn.sum()), float(np.abs(coil_turn).sum()))
            if helix is not None:
                return Recognition("helix", 0.9, helix, (("curve", 0.3),))
    work = sg.remove_hooks(sg.remove_small_loops(work))  # loops at corners are flourishes, not coils
    work = sg.resample(work, n)
    diag = sg.bbox_diagonal(work)
    length = sg.path_length(work)
    th = sg.turning(work)
    total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())

    reversals = int(np.count_nonzero(np.abs(th) > math.radians(150)))
    if length > 5 * diag and (reversals >= 4 or (abs_turn > 6 * math.pi and abs(total_turn) < 0.3 * abs_turn)):
        return Recognition(None, 0.0, None, (), "a scribble back and forth, not a shape")

    smooth = sf.turn_concentration(sg.turning(sg.resample(work, 40))) < 0.5
    if abs(total_turn) > 2.15 * math.pi and not smooth and sf.retraced(work, th, diag):
        work = sf.one_loop(work, th)  # a polygon gone round twice over the same sides: once is enough
        th = sg.turning(work)
        total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())
    if abs(total_turn) > 2.0 * math.pi and smooth:
        # a round shape drawn on past the start: judge the first time round only (a star, which
        # turns twice round at sharp corners, keeps its whole path)
        work = sf.one_loop(work, th)
        diag, length = sg.bbox_diagonal(work), sg.path_length(work)
        th = sg.turning(work)
        total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())
        loop = fit_ellipse(work)
        if loop is not None and loop[4] < ROUND_ERROR:  # once round, and round: a circle or ellipse
            geom, kind = round_geometry(loop, CIRCLE_RATIO)
            return Recognition(kind, max(0.5, 1.0 - loop[4] / ROUND_ERROR * 0.5), geom, (("curve", 0.3),))
    closure = sf.closure(work, diag)
    closed = closure < 0.22 and length > 1.75 * diag
    corners = sg.find_corners(work)
    if not closed:
        corners = sf.drop_end_stubs(work, corners, length)  # closed shapes may end on a short side
    else:
        trimmed = sf.trim_closed_hooks(work, corners, length)
        if trimmed is not None:
            work, corners = trimmed
            th = sg.turning(work)
            total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())
    # short runs (a thin box's ends) are too short to judge: smoothing rounds their ends
    straight = [sg.chord_deviation(work[a:b + 1]) < STRAIGHT or sg.path_length(work[a:b + 1]) < 0.06 * length
                for a, b in itertools.pairwise(corners)]
    coarse = sg.turning(sg.resample(work, 40))
    concentration = sf.turn_concentration(coarse)
    if (not closed and closure < 0.42 and abs(total_turn) >= 1.25 * math.pi and len(straight) >= 3
            and all(straight) and sf.heading_home(work, corners)):
        closed = True  # straight sides turning round, the last one heading for the start: left open
    ellipse = fit_ellipse(work) if closed else None

    if closed:
        round_err = ellipse[4] if ellipse is not None else math.inf
        angular = (concentration > 0.55 and all(straight) and len(straight) >= 3
                   and float(np.mean(sf.corner_turns(th, corners))) >= 55.0)  # an octagon's 45 degrees is round
        if round_err < ROUND_ERROR and not angular:
            geom, kind = round_geometry(ellipse, CIRCLE_RATIO)
            conf = max(0.5, 1.0 - round_err / ROUND_ERROR * 0.5)
            return Recognition(kind, conf, geom, (("polygon", 0.3),))
        vertices = sf.polygon_vertices(work, corners)
        if len(vertices) >= 3:
            box = box_geometry(vertices)
            if box is not None:
                return Recognition("box", 0.9, box, (("polygon", 0.6),))
            if angular or all(straight):
                return Recognition("polygon", 0.85, Polygon(tuple(map(tuple, vertices))), (("ellipse", 0.2),))
        if round_err < 2 * ROUND_ERROR:
            geom, kind = round_geometry(ellipse, CIRCLE_RATIO)
            return Recognition(kind, 0.5, geom, (("polygon", 0.4),))
        if len(vertices) >= 3:
            return Recognition("polygon", 0.6, Polygon(tuple(map(tuple, vertices))), (("curve", 0.3),))

    if abs(total_turn) >= NEARLY_ROUND * math.pi and abs(float(coarse.sum())) > 0.75 * float(np.abs(coarse).sum()):
        # most of a turn, smoothly: a round shape left open (people often stop short of the start)
        open_ellipse = fit_ellipse(work)
        if open_ellipse is not None and open_ellipse[4] < 0.6 * ROUND_ERROR:
            geom, kind = round_geometry(open_ellipse, CIRCLE_RATIO)
            return Recognition(kind, 0.7, geom, (("arc", 0.5),))

    if len(straight) >= 2 and (all(straight) or _bent_polyline(work, th, corners)):
        pts = tuple(tuple(work[c]) for c in corners)
        return Recognition("polyline", 0.85, Polyline(pts), (("curve", 0.3),))

    if len(corners) <= 3 or concentration < 0.5:
        centre, radius, circle_err = fit_circle(work)
        one_way = abs(float(coarse.sum())) > 0.8 * float(np.abs(coarse).sum())  # no S-bends
        if circle_err < 0.06 and 0.35 < abs(total_turn) < 1.8 * math.pi and one_way:
            return Recognition("arc", 1.0 - circle_err * 5, arc_geometry(work, centre, radius),
                               (("curve", 0.5),))
    return Recognition("curve", 0.7, curve_geometry(work, corners), (("polyline", 0.3),))


def _bent_polyline(work: np.ndarray, th: np.ndarray, corners: list[int]) -> bool:
    """A polyline drawn with bowed or curled sides (a check mark's arms): it turns at a really sharp
    corner, in at most three lobes none of which curls right round (a pigtail's loop), or mostly at
    sharp corners with nearly straight sides (an arrow whose head doubles back). A question mark's
    bend, where a corner finder may cut its curl, turns less than 90 degrees."""
    turns = sf.corner_turns(th, corners)
    lobes = sf.lobes(work)
    few_lobes = len(lobes) <= 3 and max((abs(v) for v in lobes), default=0.0) < 250.0
    if few_lobes and max(turns) >= VERY_SHARP_CORNER:
        return True
    if max(sf.bends(th, corners)) >= 120.0 or min(turns) < SHARP_CORNER or max(turns) < 90.0:
        return False
    share = sf.corner_share(th, corners)
    worst = max(sg.chord_deviation(work[a:b + 1]) for a, b in itertools.pairwise(corners))
    if share >= 0.7 and worst < 1.4 * STRAIGHT:
        return True
    return few_lobes and share >= CORNER_SHARE
