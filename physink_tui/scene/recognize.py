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
    diag = sg.bbox_diagonal(raw)
    length = sg.path_length(raw)
    thickness = sg.thickness(raw)
    spacing = min(diag / 40, max(thickness, diag / 200) / 8)  # thin shapes need finer steps
    n = int(min(max(64, length / spacing), 480))
    work = sg.smooth(sg.resample(raw, n))
    coil = sg.resample(sg.remove_hooks(work), n)
    coil_turn = sg.turning(coil)
    if _turn_concentration(sg.turning(sg.resample(coil, 40))) < 0.5:  # smooth: a star winds twice too
        helix = helix_geometry(coil, float(coil_turn.sum()), float(np.abs(coil_turn).sum()))
        if helix is not None:
            return Recognition("helix", 0.9, helix, (("curve", 0.3),))
    work = sg.remove_hooks(sg.remove_small_loops(work))  # loops at corners are flourishes, not coils
    work = sg.resample(work, n)
    diag = sg.bbox_diagonal(work)
    length = sg.path_length(work)
    chord = float(np.hypot(*(work[-1] - work[0])))
    th = sg.turning(work)
    total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())

    # a line: close to its fit, no more ink than its chord
    _, _, line_err = fit_line(work)
    if line_err < LINE and length < 1.12 * chord:
        conf = 1.0 - line_err / LINE * 0.5
        return Recognition("line", conf, Line(tuple(work[0]), tuple(work[-1])), (("arc", 0.2),))

    reversals = int(np.count_nonzero(np.abs(th) > math.radians(150)))
    if length > 5 * diag and (reversals >= 4 or (abs_turn > 6 * math.pi and abs(total_turn) < 0.3 * abs_turn)):
        return Recognition(None, 0.0, None, (), "a scribble back and forth, not a shape")

    smooth = _turn_concentration(sg.turning(sg.resample(work, 40))) < 0.5
    if abs(total_turn) > 2.15 * math.pi and not smooth and _retraced(work, th, diag):
        work = _one_loop(work, th)  # a polygon gone round twice over the same sides: once is enough
        th = sg.turning(work)
        total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())
    if abs(total_turn) > 2.0 * math.pi and smooth:
        # a round shape drawn on past the start: judge the first time round only (a star, which
        # turns twice round at sharp corners, keeps its whole path)
        work = _one_loop(work, th)
        diag, length = sg.bbox_diagonal(work), sg.path_length(work)
        th = sg.turning(work)
        total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())
        loop = fit_ellipse(work)
        if loop is not None and loop[4] < ROUND_ERROR:  # once round, and round: a circle or ellipse
            geom, kind = round_geometry(loop, CIRCLE_RATIO)
            return Recognition(kind, max(0.5, 1.0 - loop[4] / ROUND_ERROR * 0.5), geom, (("curve", 0.3),))
    closure = _closure(work, diag)
    closed = closure < 0.22 and length > 1.75 * diag
    corners = sg.find_corners(work)
    if not closed:
        corners = _drop_end_stubs(work, corners, length)  # closed shapes may end on a short side
    else:
        trimmed = _trim_closed_hooks(work, corners, length)
        if trimmed is not None:
            work, corners = trimmed
            th = sg.turning(work)
            total_turn, abs_turn = float(th.sum()), float(np.abs(th).sum())
    straight = [sg.chord_deviation(work[a:b + 1]) < STRAIGHT for a, b in itertools.pairwise(corners)]
    concentration = _turn_concentration(sg.turning(sg.resample(work, 40)))
    if (not closed and closure < 0.42 and abs(total_turn) >= 1.25 * math.pi and len(straight) >= 3
            and all(straight) and _heading_home(work, corners)):
        closed = True  # straight sides turning round, the last one heading for the start: left open
    ellipse = fit_ellipse(work) if closed else None

    if closed:
        round_err = ellipse[4] if ellipse is not None else math.inf
        angular = (concentration > 0.55 and all(straight) and len(straight) >= 3
                   and float(np.mean(_corner_turns(th, corners))) >= 55.0)  # an octagon's 45 degrees is round
        if round_err < ROUND_ERROR and not angular:
            geom, kind = round_geometry(ellipse, CIRCLE_RATIO)
            conf = max(0.5, 1.0 - round_err / ROUND_ERROR * 0.5)
            return Recognition(kind, conf, geom, (("polygon", 0.3),))
        vertices = _polygon_vertices(work, corners)
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

    coarse = sg.turning(sg.resample(work, 40))
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


def _drop_end_stubs(work: np.ndarray, corners: list[int], length: float, fraction: float = 0.07) -> list[int]:
    """Forget corners that only cut a tiny first or last piece off the stroke (an unremoved hook)."""
    corners = list(corners)
    while len(corners) > 2 and sg.path_length(work[: corners[1] + 1]) < fraction * length:
        corners.pop(1)
    while len(corners) > 2 and sg.path_length(work[corners[-2]:]) < fraction * length:
        corners.pop(-2)
    return corners


def _lobes(work: np.ndarray, min_deg: float = 35.0) -> list[float]:
    """Net turning (degrees) of each run of same-direction turning on a coarse copy of the stroke,
    ignoring runs under ``min_deg``: a brace has five such lobes, a check mark one or two."""
    coarse = np.degrees(sg.turning(sg.resample(work, 40)))
    runs: list[float] = []
    for v in coarse.tolist():
        if runs and (v >= 0) == (runs[-1] >= 0):
            runs[-1] += v
        else:
            runs.append(v)
    lobes: list[float] = []
    for r in (r for r in runs if abs(r) >= min_deg):
        if lobes and (r >= 0) == (lobes[-1] >= 0):
            lobes[-1] += r
        else:
            lobes.append(r)
    return lobes


def _corner_turns(th: np.ndarray, corners: list[int], reach: int = 3) -> list[float]:
    """Net turning (degrees) right at each inner corner: a check mark's corner turns over 90 degrees,
    the top of a question mark's curl turns about 50 where the corner finder cut it."""
    n = len(th) + 2
    out = []
    for c in corners[1:-1]:
        lo, hi = max(c - reach, 1), min(c + reach, n - 2)
        out.append(abs(math.degrees(float(th[lo - 1:hi].sum()))))
    return out or [0.0]


def _bends(th: np.ndarray, corners: list[int], reach: int = 3) -> list[float]:
    """Net turning (degrees) along each segment, away from its corners."""
    n = len(th) + 2
    out = []
    for a, b in itertools.pairwise(corners):
        lo = a + reach if a > 0 else 0
        hi = b - reach if b < n - 1 else n - 2
        out.append(abs(math.degrees(float(th[lo:max(hi - 1, lo)].sum()))))
    return out


def _bent_polyline(work: np.ndarray, th: np.ndarray, corners: list[int]) -> bool:
    """A polyline drawn with bowed or curled sides (a check mark's arms): it turns at a really sharp
    corner, in at most three lobes none of which curls right round (a pigtail's loop), or mostly at
    sharp corners with nearly straight sides (an arrow whose head doubles back). A question mark's
    bend, where a corner finder may cut its curl, turns less than 90 degrees."""
    turns = _corner_turns(th, corners)
    lobes = _lobes(work)
    few_lobes = len(lobes) <= 3 and max((abs(v) for v in lobes), default=0.0) < 250.0
    if few_lobes and max(turns) >= VERY_SHARP_CORNER:
        return True
    if max(_bends(th, corners)) >= 120.0 or min(turns) < SHARP_CORNER or max(turns) < 90.0:
        return False
    share = _corner_share(th, corners)
    worst = max(sg.chord_deviation(work[a:b + 1]) for a, b in itertools.pairwise(corners))
    if share >= 0.7 and worst < 1.4 * STRAIGHT:
        return True
    return few_lobes and share >= CORNER_SHARE


def _corner_share(th: np.ndarray, corners: list[int], reach: int = 3) -> float:
    """Share of the turning done at the corners rather than along the segments between them.

    Net turning is summed per window, so hand jitter cancels: a check mark whose long arm bows
    still turns mostly at its corner; a brace or a question mark turns mostly along its curls.
    """
    n = len(th) + 2
    at_corners, along = 0.0, 0.0
    inner = corners[1:-1]
    bounds = [0]
    for c in inner:
        lo, hi = max(c - reach, 1), min(c + reach, n - 2)
        at_corners += abs(float(th[lo - 1:hi].sum()))
        bounds += [lo - 1, hi]
    bounds.append(n - 2)
    for a, b in zip(bounds[::2], bounds[1::2], strict=True):
        along += abs(float(th[a:b].sum()))
    total = at_corners + along
    return at_corners / total if total else 0.0


def _heading_home(work: np.ndarray, corners: list[int], max_deg: float = 50.0) -> bool:
    """Whether the last side points at the stroke's start (a polygon the pen lifted from too early)."""
    home = work[0] - work[-1]

    def angle(v: np.ndarray) -> float:
        norms = float(np.hypot(*v) * np.hypot(*home))
        return 0.0 if norms == 0.0 else math.degrees(math.acos(max(-1.0, min(1.0, float(v @ home) / norms))))

    # the last side aims at the start, or the pen stopped at a corner and the gap runs along the first side
    return angle(work[-1] - work[corners[-2]]) <= max_deg or angle(work[corners[1]] - work[0]) >= 180.0 - max_deg


def _trim_closed_hooks(work: np.ndarray, corners: list[int], length: float,
                       ) -> tuple[np.ndarray, list[int]] | None:
    """Cut a hook off either end of a closed stroke: a first or last piece shorter than 6 % of the
    path that is not straight (a straight short piece is a side and stays)."""
    start, end = 0, len(work) - 1
    if len(corners) > 3:
        a, b = corners[0], corners[1]
        if sg.path_length(work[a:b + 1]) < 0.06 * length and sg.chord_deviation(work[a:b + 1]) >= 0.2:
            start = b
        a, b = corners[-2], corners[-1]
        if sg.path_length(work[a:b + 1]) < 0.06 * length and sg.chord_deviation(work[a:b + 1]) >= 0.2:
            end = a
    if (start, end) == (0, len(work) - 1):
        return None
    kept = [c - start for c in corners if start <= c <= end]
    return work[start:end + 1], kept


def _closure(work: np.ndarray, diag: float) -> float:
    """How nearly the stroke returns to its start, over its size: the gap between its ends, or, for a
    stroke drawn past its start (or started before it), twice the closest approach of one end to
    the other end's first fifth (a shape closes through its ends, not through its middle)."""
    n = len(work)
    gap = float(np.hypot(*(work[-1] - work[0])))
    tail = work[int(n * 0.8):]
    head = work[: max(2, int(n * 0.2))]
    d1 = float(np.hypot(*(tail - work[0]).T).min())
    d2 = float(np.hypot(*(head - work[-1]).T).min())
    return min(gap, 2 * d1, 2 * d2) / diag


def _retraced(work: np.ndarray, th: np.ndarray, diag: float) -> bool:
    """Whether what comes after the first time round runs back over it (a shape drawn twice),
    rather than on new ground (a star turns twice round on different sides)."""
    end = int(np.searchsorted(np.abs(np.cumsum(th)), 2 * math.pi)) + 2
    first, rest = work[:end], work[end:]
    if len(rest) < 4 or len(first) < 4:
        return False
    d = np.hypot(rest[:, None, 0] - first[None, :, 0], rest[:, None, 1] - first[None, :, 1]).min(axis=1)
    return float(np.quantile(d, 0.9)) < 0.06 * diag


def _one_loop(work: np.ndarray, th: np.ndarray) -> np.ndarray:
    """The stroke once round: up to where it comes closest to its start while its turning is
    between 1.5 and 2.5 pi (robust to where exactly a corner completes the turn), resampled."""
    cum = np.abs(np.concatenate([[0.0, 0.0], np.cumsum(th)]))  # turning done on reaching each point
    window = np.flatnonzero((cum >= 1.5 * math.pi) & (cum <= 2.5 * math.pi))
    if not len(window):
        return work
    gaps = np.hypot(*(work[window] - work[0]).T)
    end = int(window[int(np.argmin(gaps))]) + 1
    return sg.resample(work[: max(end, 8)], len(work))


def _turn_concentration(th: np.ndarray) -> float:
    """Share of all turning done in the sharpest fifth of the stroke (boxes ~0.9, circles ~0.3)."""
    a = np.abs(th)
    total = float(a.sum())
    if total == 0.0:
        return 0.0
    k = max(1, len(a) // 5)
    return float(np.sort(a)[-k:].sum()) / total


def _polygon_vertices(work: np.ndarray, corners: list[int]) -> np.ndarray:
    """The closed polygon's vertices: where its sides' fitted lines meet.

    Sides are the runs between corners, with the runs on either side of the pen's start joined when
    they continue each other (a shape started mid-side) and slivers under 4 % of the perimeter
    dropped (half a rounded corner on either side of the start), so neither where the pen started
    nor how round the corners are moves a vertex.
    """
    runs = [work[a:b + 1] for a, b in itertools.pairwise(corners)]
    if len(runs) >= 3:
        first, last = runs[0], runs[-1]
        d1, d2 = first[-1] - first[0], last[-1] - last[0]
        norms = float(np.hypot(*d1) * np.hypot(*d2))
        if norms and float(d1 @ d2) / norms > math.cos(math.radians(35)):
            runs = [np.concatenate([last, first[1:]]), *runs[1:-1]]
    perimeter = sum(sg.path_length(r) for r in runs)
    runs = [r for r in runs if sg.path_length(r) >= 0.04 * perimeter] or runs
    if len(runs) < 3:
        return np.array([r[0] for r in runs])
    lines = []
    for r in runs:
        k = len(r)
        core = r[int(k * 0.15): max(int(k * 0.85), int(k * 0.15) + 2)]
        point, direction, _ = fit_line(core if len(core) >= 2 else r)
        lines.append((point, direction))
    verts = []
    for (p1, d1), (p2, d2) in zip(lines[-1:] + lines[:-1], lines, strict=True):
        denom = d1[0] * d2[1] - d1[1] * d2[0]
        if abs(denom) < 1e-9:
            verts.append((p1 + p2) / 2)
            continue
        t = ((p2 - p1)[0] * d2[1] - (p2 - p1)[1] * d2[0]) / denom
        verts.append(p1 + t * d1)
    return np.array(verts)
