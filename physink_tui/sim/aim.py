"""Aiming at surfaces (issue 27): launch velocities that carry a start body onto points along the surface of its
first demonstrated contact, its ends and corners included; no stepping, no search.

A ball that must bounce off a platform's corner is a needle among launch velocities (a few throws in thousands)
but not among the points of the platform's outline: the corner is one of them. So the demonstrated first contact
is turned into *aim points*: points along each edge of the touched body that faces the demonstrated side (the
edge's ends included, `EDGE_SAMPLES` per edge) and, at each corner, the body's centre placed at `CORNER_FAN`
directions between the two edges' normals that still face that side. Each aim point is where the start body's
centre is when it touches (the surface point pushed out along the normal by the body's reach: a circle's radius,
else the half-diagonal of its bounds), and each is reached in `FLIGHT_FACTORS` times the slowest-launch flight
time by the ballistic launch through it (`seeding.ballistic`'s physics without its clamp). What lies between (a
platform in the way) is left to the rollouts, which score every candidate.

`Aim.point` and `Aim.normal` say where a candidate was aimed, so that a verdict can tell where its contact is.
Only a demonstration whose start event moves one body onto a fixed one gets aim points: with several start bodies
which is aimed where is not one choice but many, and a movable target's answer depends on its mass and friction,
which aiming does not touch (measured on the portfolio, seed 0: aiming at the lever, the cup and the golf ball
added 36 rollouts to the egg cracker, the cup dispenser and the golf ball helper and found none of them sooner).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from physink_tui.scene.components import Body, Point, Scene
from physink_tui.scene.physics.world import GRAVITY
from physink_tui.sim.clearance import CLEAR_FACTORS, clear_regions, clearance_grid, nearly_clear, obstacles
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.seeding import first_contact, start_movements
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.qualitative import side_along

EDGE_SAMPLES = 5
"""Points per edge facing the demonstrated side, its two ends included."""
CORNER_FAN = 4
"""Directions per corner, between (and excluding) the normals of the two edges meeting there."""
FLIGHT_FACTORS = (1.0, 1.5, 0.75, 2.2)
"""Flight times, as multiples of the slowest-launch flight time to the aim point, in the order tried."""
CIRCLE_SAMPLES = 16
"""Points round a round target."""
FACE_SAMPLES = 25
"""Places along each face (an edge, or a corner's fan) whose flights `clear_aimed` checks."""
LOW_FLIGHTS = sum(f < 1.0 for f in CLEAR_FACTORS)
"""`clearance.CLEAR_FACTORS` below the slowest-launch flight (factor 1): the low family of launches through a point
(flatter, faster); the rest are the high family (lobs). `clear_aimed` looks for clear flights in each."""
CLEARANCE = 1.0
"""Canvas units between the start body and the surface at its aim point (it arrives just touching)."""


@dataclass(frozen=True, slots=True)
class Aim:
    """One aim point: the surface point, its outward normal, the start body's centre there."""

    point: tuple[float, float]
    normal: tuple[float, float]
    centre: tuple[float, float]
    corner: bool
    edge: tuple[tuple[float, float], tuple[float, float]] | None = None
    """The edge the point lies on (None for a corner's fan direction)."""
    arc: tuple[float, float] | None = None
    """A corner's fan: how far the normal may turn (radians, clockwise positive) and still face the side."""
    reach: float = 0.0


@dataclass(frozen=True, slots=True)
class Aimed:
    """One aimed candidate: its parameters, the aim, the flight factor, the start body."""

    parameters: Parameters
    aim: Aim
    factor: float
    body: str
    origin: tuple[float, float]


ALONG_STEP = 0.25
"""`AimSpace`'s first coordinate: a unit moves the aim this share of its edge's length (or of its corner's fan)."""
FLIGHT_STEP = 0.35
"""`AimSpace`'s second coordinate: a unit multiplies the flight factor by e to this power."""


class AimSpace:
    """Two coordinates around one aimed candidate, for CMA-ES to correct it by rollouts: where along its edge (or
    round its corner) the start body arrives, and how long its flight takes; decoded into start velocities."""

    coords = ("along", "flight")

    def __init__(self, start: Parameters, aimed_: Aimed) -> None:
        self.start = start
        self.aimed = aimed_

    def decode(self, z: Sequence[float] | np.ndarray) -> Parameters:
        a = self.aimed.aim
        along, flight = float(z[0]), float(z[1])
        if a.edge is not None:
            (x0, y0), (x1, y1) = a.edge
            length = math.hypot(x1 - x0, y1 - y0) or 1.0
            u0 = math.hypot(a.point[0] - x0, a.point[1] - y0) / length
            u = min(max(u0 + ALONG_STEP * along, 0.0), 1.0)
            point = (x0 + u * (x1 - x0), y0 + u * (y1 - y0))
            normal = a.normal
        else:
            lo, hi = a.arc if a.arc is not None else (0.0, 0.0)
            theta = _angle(a.normal) + min(max(ALONG_STEP * along * (hi - lo), lo), hi)
            point, normal = a.point, (math.sin(theta), -math.cos(theta))
        centre = (point[0] + (a.reach + CLEARANCE) * normal[0], point[1] + (a.reach + CLEARANCE) * normal[1])
        d = (centre[0] - self.aimed.origin[0], centre[1] - self.aimed.origin[1])
        return self.start.with_velocities({self.aimed.body: launch(d, self.aimed.factor * math.exp(FLIGHT_STEP
                                                                                                  * flight))})


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _angle(n: tuple[float, float]) -> float:
    """A normal's angle from straight up, clockwise on screen (y down): up 0, right pi/2, left -pi/2."""
    return math.atan2(n[0], -n[1])


def first_target(scene: Scene, timeline: Timeline) -> tuple[Body, Body, str, tuple[float, float] | None] | None:
    """The start body, the fixed body of its first demonstrated contact, that body's side and the demonstrated
    contact point; None when the demonstration does not have one start body with such a first contact."""
    movements = start_movements(scene, timeline)
    if len(movements) != 1:
        return None
    movement, body = movements[0]
    contact = first_contact(timeline, movement)
    if contact is None or body.id not in contact.components or len(contact.components) != 2:
        return None
    target_id = next(c for c in contact.components if c != body.id)
    target = scene.components.get(target_id)
    side = dict(contact.sides).get(target_id)
    if not isinstance(target, Body) or side is None or not scene.is_fixed(target_id):
        return None
    return body, target, side, contact.point


def aim_points(scene: Scene, timeline: Timeline) -> tuple[str, tuple[Aim, ...]] | None:
    """The start body and its aim points on its first demonstrated contact, nearest the demonstrated contact
    point first; None when the demonstration does not have one start body with a first contact to aim at."""
    found = first_target(scene, timeline)
    if found is None:
        return None
    body, target, side, point = found
    reach = reach_of(body)
    aims = [Aim(p, n, (p[0] + (reach + CLEARANCE) * n[0], p[1] + (reach + CLEARANCE) * n[1]), corner, edge, arc,
                reach) for p, n, corner, edge, arc in _surface(target, side)]
    if not aims:
        return None
    shown = point or _centroid(aims)
    aims.sort(key=lambda a: (math.hypot(a.point[0] - shown[0], a.point[1] - shown[1]), a.normal))
    return body.id, tuple(aims)


def aimed(scene: Scene, timeline: Timeline, start: Parameters) -> list[Aimed]:
    """``start`` with its start body launched at aim points of its first demonstrated contact: first the clear
    flights (`clear_aimed`), then each aim point (`aim_points`) for each of `FLIGHT_FACTORS` (factors outermost),
    each with the aim it was given; empty when `aim_points` has none."""
    found = aim_points(scene, timeline)
    if found is None:
        return []
    body_id, aims = found
    body = scene.components[body_id]
    assert isinstance(body, Body)
    out = clear_aimed(scene, timeline, start)
    for factor in FLIGHT_FACTORS:
        for aim in aims:
            d = (aim.centre[0] - body.position[0], aim.centre[1] - body.position[1])
            out.append(Aimed(start.with_velocities({body_id: launch(d, factor)}), aim, factor, body_id,
                             body.position))
    return out


def clear_aimed(scene: Scene, timeline: Timeline, start: Parameters) -> list[Aimed]:
    """Launches at the first contact's surface whose flights are clear of the scene (`clearance`): each face (an
    edge facing the demonstrated side, or a corner's fan) sampled `FACE_SAMPLES` times against
    `clearance.CLEAR_FACTORS` flight times; of each connected clear region of (place, flight time), the launch
    furthest from everything. The largest region of each face first, faces nearest the demonstrated point first."""
    found = first_target(scene, timeline)
    if found is None:
        return []
    body, target, side, point = found
    reach = reach_of(body)
    target_faces = faces(target, side)
    if not target_faces:
        return []
    shown = point or (target.position[0], target.position[1])
    scene_obstacles = obstacles(scene, body.id)
    ranked: list[tuple[float, float, Aimed]] = []
    for face in target_faces:
        aims = [face_aim(face, k / (FACE_SAMPLES - 1), reach) for k in range(FACE_SAMPLES)]
        centres = np.array([a.centre for a in aims])
        grid = clearance_grid(body.position, centres, reach, target.id, scene_obstacles, inside=side == "inside")
        cells: list[tuple[float, tuple[int, int]]] = []
        for lo, hi in ((0, LOW_FLIGHTS), (LOW_FLIGHTS, len(CLEAR_FACTORS))):  # the low and the high family
            family = grid[:, lo:hi]
            regions = clear_regions(family)
            cells += [(float(rank), (row, lo + col)) for rank, (row, col) in enumerate(regions)]
            graze = nearly_clear(family, reach) if not regions else None
            if graze is not None:
                cells.append((0.5, (graze[0], lo + graze[1])))  # after every face's widest clear region
        for rank, (row, col) in cells:
            aim, factor = aims[row], CLEAR_FACTORS[col]
            d = (aim.centre[0] - body.position[0], aim.centre[1] - body.position[1])
            near = math.hypot(aim.point[0] - shown[0], aim.point[1] - shown[1])
            ranked.append((rank, near, Aimed(start.with_velocities({body.id: launch(d, factor)}), aim, factor,
                                             body.id, body.position)))
    ranked.sort(key=lambda r: (r[0], r[1]))
    return [a for _, _, a in ranked]


Face = tuple[Point, Point, tuple[float, float] | None]
"""An edge (its ends, None) or a corner's fan (the corner twice, the normal's angles it spans)."""


def faces(target: Body, side: str) -> list[Face]:
    """The target's edges facing ``side`` and its corners' fans (from `_surface`'s samples), each once."""
    out: list[Face] = []
    for p, n, corner, edge, arc in _surface(target, side):
        if edge is not None:
            face: Face = (edge[0], edge[1], None)
        elif corner and arc is not None:
            face = (p, p, (_angle(n) + arc[0], _angle(n) + arc[1]))
        else:
            continue
        if not any(f[0] == face[0] and f[1] == face[1] and (f[2] is None) == (face[2] is None) for f in out):
            out.append(face)
    return out


def face_aim(face: Face, u: float, reach: float) -> Aim:
    """The aim ``u`` (0-1) of the way along an edge, or round a corner's fan."""
    a, b, span = face
    if span is None:
        n = _unit((b[1] - a[1], -(b[0] - a[0])))
        point = (a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]))
        return Aim(point, n, _pushed(point, n, reach), u in (0.0, 1.0), (a, b), None, reach)
    theta = span[0] + u * (span[1] - span[0])
    n = (math.sin(theta), -math.cos(theta))
    return Aim(a, n, _pushed(a, n, reach), True, None, (span[0] - theta, span[1] - theta), reach)


def _pushed(p: Point, n: Point, reach: float) -> tuple[float, float]:
    return (p[0] + (reach + CLEARANCE) * n[0], p[1] + (reach + CLEARANCE) * n[1])


def reach_of(body: Body) -> float:
    """How far a body's surface lies from its centre at most: a circle's radius, else its bounds' half-diagonal."""
    return body.radius if body.shape == "circle" else _half_diagonal(body)


def launch(d: tuple[float, float], factor: float, gravity: tuple[float, float] = GRAVITY) -> tuple[float, float]:
    """The launch velocity carrying a body by ``d`` in ``factor`` times the slowest-launch flight time.

    >>> vx, vy = launch((300.0, 0.0), 1.0, (0.0, 900.0))
    >>> round(vx), round(vy)
    (367, -367)
    """
    g = math.hypot(*gravity)
    distance = math.hypot(*d)
    if distance == 0 or g == 0:
        return (0.0, 0.0)
    t = factor * math.sqrt(2 * distance / g)
    return (round(d[0] / t - gravity[0] * t / 2, 6), round(d[1] / t - gravity[1] * t / 2, 6))


Surface = tuple[Point, Point, bool, tuple[Point, Point] | None, tuple[float, float] | None]
"""A point of a target's surface: the point, its outward normal, at a corner, the edge it lies on, a corner's fan."""


def _surface(target: Body, side: str) -> list[Surface]:
    """(surface point, outward normal, at a corner, edge, fan) facing ``side`` of the target (``inside``: its
    hollow); edge is the edge a point lies on, fan a corner direction's range of normal angles."""
    px, py = target.position
    out: list[Surface] = []
    if target.shape == "circle":
        for k in range(CIRCLE_SAMPLES):
            angle = 2 * math.pi * k / CIRCLE_SAMPLES
            n = (math.cos(angle), math.sin(angle))
            if side in ("inside", side_along(*n)):
                out.append(((px + target.radius * n[0], py + target.radius * n[1]), n, False, None, None))
        return out
    c, s = math.cos(target.angle), math.sin(target.angle)
    pts = [(px + x * c - y * s, py + x * s + y * c) for x, y in target.outline]
    closed = target.shape != "polyline"
    if closed and len(pts) >= 3 and _area(pts) < 0:
        pts.reverse()  # counter-clockwise on screen (y down): outward normals are (dy, -dx)
    edges = list(zip(pts, pts[1:] + pts[:1], strict=True)) if closed else list(itertools.pairwise(pts))
    normals = []
    hollow = _hollow(pts)
    for a, b in edges:
        n = _unit((b[1] - a[1], -(b[0] - a[0])))
        if not closed and side == "inside" and n[0] * (hollow[0] - (a[0] + b[0]) / 2) + n[1] * (
                hollow[1] - (a[1] + b[1]) / 2) < 0:
            n = (-n[0], -n[1])  # an open outline (a cup) is touched inside on the faces towards its hollow
        normals.append(n)
        if n != (0.0, 0.0) and (side_along(*n) == side or side == "inside"):
            for k in range(EDGE_SAMPLES):
                u = k / (EDGE_SAMPLES - 1)
                out.append(((a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])), n, k in (0, EDGE_SAMPLES - 1),
                            (a, b), None))
    if closed:
        for i, corner in enumerate(pts):
            n0, n1 = normals[i - 1], normals[i]
            fan = [_unit((n0[0] * (1 - k / 32) + n1[0] * k / 32, n0[1] * (1 - k / 32) + n1[1] * k / 32))
                   for k in range(33)]
            facing = [f for f in fan if f != (0.0, 0.0) and side_along(*f) == side]
            for k in range(1, CORNER_FAN + 1):
                u = k / (CORNER_FAN + 1)
                n = _unit((n0[0] * (1 - u) + n1[0] * u, n0[1] * (1 - u) + n1[1] * u))
                if n != (0.0, 0.0) and side_along(*n) == side:
                    turns = [_wrap(_angle(f) - _angle(n)) for f in facing]
                    out.append((corner, n, True, None, (min(turns), max(turns))))
    return out


def _hollow(pts: list[tuple[float, float]]) -> tuple[float, float]:
    """A point in an open outline's hollow: halfway from the mean of its vertices to the middle of its ends."""
    cx = sum(p[0] for p in pts) / len(pts)
    cy = sum(p[1] for p in pts) / len(pts)
    return ((cx + (pts[0][0] + pts[-1][0]) / 2) / 2, (cy + (pts[0][1] + pts[-1][1]) / 2) / 2)


def _area(pts: list[tuple[float, float]]) -> float:
    return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1], strict=True)) / 2


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    n = math.hypot(*v)
    return (0.0, 0.0) if n < 1e-12 else (v[0] / n, v[1] / n)


def _half_diagonal(body: Body) -> float:
    xs = [x for x, _ in body.outline] or [0.0]
    ys = [y for _, y in body.outline] or [0.0]
    return math.hypot(max(xs) - min(xs), max(ys) - min(ys)) / 2


def _centroid(aims: list[Aim]) -> tuple[float, float]:
    return (sum(a.point[0] for a in aims) / len(aims), sum(a.point[1] for a in aims) / len(aims))
