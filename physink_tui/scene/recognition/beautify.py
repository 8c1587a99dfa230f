"""Beautified geometry for recognised strokes: clean circles, boxes, arcs, curves, springs, X-symbols.

Pure functions from a resampled stroke (numpy (n, 2) array) and its fits to the frozen primitives
of `primitives`; each returns None when the stroke does not have the shape's structure.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import fields, replace
from typing import Any

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Arc, Box, Circle, Curve, Ellipse, Geometry, Helix, Line, XSymbol
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_cubic

_UNSCALED = {"angle", "start_angle", "sweep", "turns"}


def _pt(v: np.ndarray) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


CIRCLE_RATIO = 0.8
"""Minor/major axis ratio above which a round shape is a circle."""


def round_geometry(ellipse: EllipseFit, circle_ratio: float = CIRCLE_RATIO) -> tuple[Circle | Ellipse, str]:
    centre, rx, ry, angle, _ = ellipse
    if ry / rx >= circle_ratio:
        return Circle(_pt(centre), (rx + ry) / 2), "circle"
    return Ellipse(_pt(centre), rx, ry, math.atan2(math.sin(angle), math.cos(angle))), "ellipse"


def box_geometry(vertices: np.ndarray, tolerance_deg: float = 24.0) -> Box | None:
    """A rectangle when the polygon has four sides meeting at roughly right angles."""
    if len(vertices) != 4:
        return None
    sides = [vertices[(i + 1) % 4] - vertices[i] for i in range(4)]
    lengths = [float(np.hypot(*s)) for s in sides]
    if min(lengths) == 0.0:
        return None
    longest = max(lengths)
    for i in range(4):
        a, b = sides[i], sides[(i + 1) % 4]
        cos = float(a @ b) / (lengths[i] * lengths[(i + 1) % 4])
        # a thin box's short ends are only a few points long: their direction is rough
        slack = tolerance_deg if min(lengths[i], lengths[(i + 1) % 4]) > 0.25 * longest else 2 * tolerance_deg
        if abs(math.degrees(math.acos(max(-1.0, min(1.0, cos)))) - 90.0) > slack:
            return None
    # the box's orientation: mean direction of the sides, folded onto a quarter turn
    angles = [math.atan2(s[1], s[0]) % (math.pi / 2) for s in sides]  # weighted by length: long sides aim truer
    mean = math.atan2(sum(n * math.sin(4 * a) for a, n in zip(angles, lengths, strict=True)),
                      sum(n * math.cos(4 * a) for a, n in zip(angles, lengths, strict=True))) / 4
    c, s = math.cos(mean), math.sin(mean)
    centre = vertices.mean(axis=0)
    rel = vertices - centre
    u, v = rel @ np.array([c, s]), rel @ np.array([-s, c])
    width = float(u.max() - u.min() + (np.abs(u).mean() * 2)) / 2
    height = float(v.max() - v.min() + (np.abs(v).mean() * 2)) / 2
    return Box(_pt(centre), width, height, mean)


def arc_geometry(work: np.ndarray, centre: np.ndarray, radius: float) -> Arc:
    angles = np.unwrap(np.arctan2(work[:, 1] - centre[1], work[:, 0] - centre[0]))
    return Arc(_pt(centre), radius, float(angles[0]), float(angles[-1] - angles[0]))


def curve_geometry(work: np.ndarray, corners: list[int], tolerance: float = 0.04) -> Curve:
    """Cubic Bézier segments between corners, split until each fits within ``tolerance`` of its chord."""
    ctrl: list[tuple[float, float]] = [_pt(work[0])]

    def add(a: int, b: int, depth: int) -> None:
        cubic, err = fit_cubic(work[a:b + 1])
        if err > tolerance and depth < 4 and b - a >= 8:
            mid = (a + b) // 2
            add(a, mid, depth + 1)
            add(mid, b, depth + 1)
            return
        ctrl.extend(_pt(p) for p in cubic[1:])

    for a, b in itertools.pairwise(corners):
        add(a, b, 0)
    return Curve(tuple(ctrl))


UNEVEN_PITCH = 0.3
"""A spring's loops follow each other evenly along its axis: where the pen runs back along it, half a turn into each
loop, those points' spacings along the axis vary by at most this share of their mean (their coefficient of variation;
with three loops or more, asked from either end). A line drawn with curls in it (a Quick, Draw! player's squiggle:
loops where the hand curled, a run of line between) turns as far as a spring, but its loops bunch and spread:
tutorboard seed260730 #4 and #41 vary by 0.61-0.74, seed90210 #379 and seed170731 #339 by 0.66-0.69 (the larger of the
two ends), an hcira star gone round twice by 1.39; the generated springs (`tests/strokegen` helix, 200 seeds: loop
size and pitch uneven by up to a tenth) by 0.21 at most, `tests/penmodels/squiggles`' coils by 0.16, people's coils
(quickdraw 5544426287923200, seed90210 #324, #350, #390) by 0.10-0.23 (session 33)."""
MIN_PITCHES = 2
"""A spring shows at least this many pitches (three loops where the pen runs back along its axis) so that their
evenness (`UNEVEN_PITCH`) can be asked: of two loops there is one pitch, nothing to tell a spring from two curls a
hand made in a line. People's two-loop "helices" were Quick, Draw! players' squiggles (tutorboard seed260730 #20: an m
with its dips curled; #32: a line with a small curl and a hump) and two of tutorboard's negatives (seed90210 #338,
#340); people's coils turn 3.1 turns or more. Every spring the project generates or models has three loops or more
(`tests/strokegen` helix 3-10, `tests/penmodels/squiggles`' coils 3-6, the hand-made springs 3 and 5), but a generated
spring whose end loops are part-loops may turn only 2.2-2.5 times once its hooks are cut, showing one pitch: 2 of 400
(`strokegen` helix seeds 0-199 any loops, 0-199 three loops) read as curves since (session 34)."""


def helix_geometry(work: np.ndarray, total_turn: float, abs_turn: float) -> Helix | None:
    """A spring: loops turning one way whose centres advance evenly along an axis (three or more, `MIN_PITCHES`)."""
    turns = abs(total_turn) / (2 * math.pi)
    if turns < 1.8 or abs(total_turn) < 0.7 * abs_turn:
        return None
    d = np.diff(work, axis=0)
    heading = np.unwrap(np.arctan2(d[:, 1], d[:, 0]))
    rel = np.abs(heading - heading[0])
    loop_ids = np.minimum((rel // (2 * math.pi)).astype(int), int(turns))
    centres, radii = [], []
    for k in range(int(turns) + 1):
        members = work[1:][loop_ids == k]
        if len(members) >= 5:
            c = members.mean(axis=0)
            centres.append(c)
            radii.append(float(np.hypot(*(members - c).T).mean()))
    if len(centres) < 2:
        return None
    radius = float(np.median(radii))
    axis = centres[-1] - centres[0]
    advance = float(np.hypot(*axis))
    if radius == 0.0 or advance < 0.8 * radius:
        return None  # loops on the same spot: a shape drawn several times round, not a spring
    unit = axis / advance
    off_axis = max(abs(float((c - centres[0]) @ np.array([-unit[1], unit[0]]))) for c in centres)
    if off_axis > 0.6 * radius + 0.15 * advance:
        return None  # the loops wander (flourishes round a box's corners), a spring's go straight
    # each loop where the pen runs back along the axis, half a turn into it: a spring's follow at its pitch
    backs = np.searchsorted(np.maximum.accumulate(rel), math.pi + 2 * math.pi * np.arange(int(turns + 0.5)))
    pitches = np.diff(work[1:][backs[backs < len(rel)]] @ unit)
    if len(pitches) < MIN_PITCHES:
        return None  # two curls in a line (a squiggle), not a spring: its evenness unseen (`MIN_PITCHES`)
    if float(np.std(pitches)) > UNEVEN_PITCH * float(np.mean(pitches)):
        return None  # loops bunched and spread where the hand curled (a curly line), a spring's follow evenly
    # the spring reaches as far along its axis as the stroke does (its end loops' centres fall short of them)
    reach = (work - centres[0]) @ unit
    start, end = centres[0] + float(reach[0]) * unit, centres[0] + float(reach[-1]) * unit
    return Helix(_pt(start), _pt(end), radius, turns)


def x_symbol(a: Line, b: Line) -> tuple[XSymbol, float] | None:
    """Two lines make an X when they cross, their midpoints are close and they are roughly
    perpendicular (thesis 3.2.1): ``(symbol, confidence)`` or None."""
    p, r = np.array(a.start), np.array(a.end) - np.array(a.start)
    q, s = np.array(b.start), np.array(b.end) - np.array(b.start)
    met = sg.line_meet(p, r, q, s)
    if met is None:
        return None  # parallel (or a line of no length); lines this near parallel fail the angle test below anyway
    centre, t, u = met
    if not (0.0 <= t <= 1.0 and 0.0 <= u <= 1.0):
        return None
    la, lb = float(np.hypot(*r)), float(np.hypot(*s))
    mid_gap = float(np.hypot(*((p + r / 2) - (q + s / 2))))
    if mid_gap > 0.4 * (la + lb) / 2:
        return None
    angle = math.degrees(math.acos(min(1.0, abs(float(r @ s)) / (la * lb))))
    if angle < 45.0:
        return None
    confidence = 0.5 + 0.5 * min(1.0, (angle - 45.0) / 40.0) * (1.0 - mid_gap / (0.4 * (la + lb) / 2))
    return XSymbol(_pt(centre), a, b), confidence


def scale_geometry(g: Geometry, origin: np.ndarray, scale: float) -> Geometry:
    """Map geometry found at unit size back to the stroke's units: points ``origin + scale * p``,
    lengths times ``scale``, angles and turn counts unchanged."""
    ox, oy = float(origin[0]), float(origin[1])
    changes: dict[str, Any] = {}
    for f in fields(g):
        v = getattr(g, f.name)
        if isinstance(v, Line):
            changes[f.name] = scale_geometry(v, origin, scale)
        elif isinstance(v, tuple) and v and isinstance(v[0], tuple):
            changes[f.name] = tuple((ox + scale * float(p[0]), oy + scale * float(p[1])) for p in v)
        elif isinstance(v, tuple):
            changes[f.name] = (ox + scale * float(v[0]), oy + scale * float(v[1]))
        elif f.name not in _UNSCALED:
            changes[f.name] = scale * float(v)
    return replace(g, **changes)


def shape_points(g: Geometry, per_piece: int = 12) -> list[tuple[float, float]]:
    """Points on the beautified shape itself (vertices, and points along its arcs, ellipses and curves; not
    an arc's centre or a curve's control points): what must stay near the stroke.

    >>> shape_points(Line((0.0, 0.0), (2.0, 1.0)))
    [(0.0, 0.0), (2.0, 1.0)]
    """
    if isinstance(g, Line):
        return [g.start, g.end]
    if isinstance(g, XSymbol):
        return [g.first.start, g.first.end, g.second.start, g.second.end]
    if isinstance(g, Box):
        return list(g.corners)
    if isinstance(g, Circle | Ellipse):
        rx, ry, angle = (g.radius, g.radius, 0.0) if isinstance(g, Circle) else (g.rx, g.ry, g.angle)
        c, s = math.cos(angle), math.sin(angle)
        out = []
        for k in range(4 * per_piece):
            a = 2 * math.pi * k / (4 * per_piece)
            u, v = rx * math.cos(a), ry * math.sin(a)
            out.append((g.center[0] + u * c - v * s, g.center[1] + u * s + v * c))
        return out
    if isinstance(g, Arc):
        return [(g.center[0] + g.radius * math.cos(g.start_angle + g.sweep * k / per_piece),
                 g.center[1] + g.radius * math.sin(g.start_angle + g.sweep * k / per_piece))
                for k in range(per_piece + 1)]
    if isinstance(g, Curve):
        ctrl, pts = _curve_points(g, per_piece)
        out = [(float(ctrl[0][0]), float(ctrl[0][1]))]
        out += map(tuple, pts.tolist())  # the same floats as float(x), float(y) a row
        return out
    if isinstance(g, Helix):
        return [g.start, g.end]
    return [(float(p[0]), float(p[1])) for p in g.points]  # Polyline, Polygon


def _curve_points(g: Curve, per_piece: int, pieces: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """A curve's control points as an array, and its `shape_points` after the first, as an array (rows of x, y); with
    ``pieces`` (indices), those pieces' points only (each point is worked out alone: the same floats)."""
    ctrl = np.asarray(g.control_points, dtype=float)
    ts = np.linspace(0.0, 1.0, per_piece + 1)[:, None]
    at = (np.arange(0, len(ctrl) - 3, 3) if pieces is None else 3 * pieces)[:, None, None]  # every piece at once
    p0, p1, p2, p3 = (ctrl[at + k, np.arange(2)] for k in range(4))
    pts = (1 - ts) ** 3 * p0 + 3 * ts * (1 - ts) ** 2 * p1 + 3 * ts * ts * (1 - ts) * p2 + ts ** 3 * p3
    return ctrl, pts[:, 1:].reshape(-1, 2)


def within(g: Geometry, lo: np.ndarray, hi: np.ndarray, per_piece: int = 12) -> bool:
    """Whether every one of ``g``'s `shape_points` is finite and within the box from ``lo`` to ``hi`` (x, y each):
    ``np.asarray(shape_points(g))`` tested against them, the same comparisons of the same floats, without making the
    array. A curve whose control points lie within the box less a hair is within it (each Bézier piece lies in its
    control points' hull; the hair, a billionth of the coordinates, is far more than the evaluation rounds by), a
    circle or an ellipse whose bounding box does: neither is then evaluated."""
    x0, y0, x1, y1 = float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])
    hair = 1e-9 * (1.0 + max(abs(x0), abs(y0), abs(x1), abs(y1)))
    if isinstance(g, Curve) and len(g.control_points) >= 4:
        lo_x, lo_y, hi_x, hi_y = x0 + hair, y0 + hair, x1 - hair, y1 - hair
        held = [lo_x <= float(x) <= hi_x and lo_y <= float(y) <= hi_y for x, y in g.control_points]
        out = [k for k in range((len(held) - 1) // 3) if not all(held[3 * k:3 * k + 4])]  # (NaN is held by none)
        if not out:
            return True
        ctrl, pts = _curve_points(g, per_piece, np.array(out))
        if out[0] == 0:  # the first point too, as `shape_points` gives it
            pts = np.concatenate([ctrl[:1], pts])
        return bool(np.isfinite(pts).all() and (pts >= lo).all() and (pts <= hi).all())
    if isinstance(g, Circle | Ellipse):
        rx, ry, angle = (g.radius, g.radius, 0.0) if isinstance(g, Circle) else (g.rx, g.ry, g.angle)
        c, s = math.cos(angle), math.sin(angle)
        reach_x, reach_y = math.hypot(rx * c, ry * s), math.hypot(rx * s, ry * c)  # the outline's extent either way
        cx, cy = float(g.center[0]), float(g.center[1])
        slack = 1e-9 * (1.0 + abs(cx) + abs(cy) + abs(rx) + abs(ry))
        if (x0 + hair <= cx - reach_x - slack and cx + reach_x + slack <= x1 - hair
                and y0 + hair <= cy - reach_y - slack and cy + reach_y + slack <= y1 - hair):
            return True
    return all(math.isfinite(x) and math.isfinite(y) and x0 <= x <= x1 and y0 <= y <= y1
               for x, y in ((float(p[0]), float(p[1])) for p in shape_points(g, per_piece)))
