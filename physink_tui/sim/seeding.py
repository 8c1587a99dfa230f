"""Seeds the free parameters of a simulation from the scene and the demonstrated timeline (thesis 3.4.3); no
stepping, no search (adjusting the seeds is the search's business).

- Every movable body: mass = area x density 1.0, friction 1.0 or 0.0 by shape class (`MATERIALS`, thesis 3.2.3).
- Every spring: k = 20, natural length = the sketched length (`Spring.rest_length`).
- Every body the start event moves (the first body of a movement the start event causes): an initial velocity
  "with the direction and magnitude required to reach its initial destination", found through the timeline's
  causes. Choices the thesis leaves open, made here:
  * the destination is where the body was when its first contact happened: the last frame of the start-caused
    movement when that movement (directly) causes a contact, else the contact's point, else the movement's last
    frame (a start movement that hits nothing);
  * the velocity is the ballistic one under `GRAVITY` that reaches the destination in the demonstrated time (the
    contact's time less the movement's start), that time clamped to [`MIN_FLIGHT`, `MAX_FLIGHT`] times the time of
    the slowest-launch flight sqrt(2 |d| / g): a hurried or slow pen neither shoots nor lobs the body; the flight
    ignores what lies between (a ramp under a ball), which the search corrects;
  * a body on a spring slides along the spring's axis only (a groove carries gravity): its velocity is the
    displacement along the axis over the demonstrated time;
  * a start-moved body with no destination (no frames) gets no velocity (0, 0).
"""

from __future__ import annotations

import math

from physink_tui.scene.components import MATERIALS, Body, Point, Scene, Spring, material_class
from physink_tui.scene.physics.build import body_area
from physink_tui.scene.physics.world import GRAVITY
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters
from physink_tui.timeline.events import Event, Timeline

DENSITY = 1.0
"""The seed density (thesis 3.4.3: 1.0 kg/m², here per canvas unit²)."""
SPRING_K = 20.0
"""The seed spring constant (thesis 3.4.3)."""
FRICTION = {name: material.friction for name, material in MATERIALS.items()}
"""The seed friction per shape class: 1.0 (boxes, round bodies) or 0.0 (freeform), thesis 3.2.3."""
MIN_FLIGHT = 0.5
MAX_FLIGHT = 2.0
"""Bounds on the seeded flight time, as multiples of the slowest-launch flight time."""
MIN_TIME = 1 / 60
"""Seconds: the shortest demonstrated time used (a contact in the movement's first frame)."""
AXES = {"horizontal": (1.0, 0.0), "vertical": (0.0, 1.0)}
FLIGHT_FACTORS = (0.35, 0.5, 0.7, 1.4, 2.0)
"""Flight times tried around the seeded one (`seed_family`), as factors of it."""


def seed(scene: Scene, timeline: Timeline, canvas: tuple[float, float]) -> Parameters:
    """The thesis's seed parameters for ``scene`` demonstrated as ``timeline`` on a canvas of ``canvas`` units.

    ``canvas`` is not needed by the rules above; it is taken so that seeds may later depend on the canvas's size
    (e.g. a default speed for a start movement demonstrated without frames).
    """
    del canvas
    bodies = {b.id: BodyParameters(body_area(b) * DENSITY, FRICTION[material_class(b.shape)])
              for b in scene.bodies() if not scene.is_fixed(b.id)}
    springs = {c.id: SpringParameters(SPRING_K, c.rest_length)
               for c in scene.components.values() if isinstance(c, Spring)}
    velocities = {}
    for movement, body in start_movements(scene, timeline):
        velocities[body.id] = initial_velocity(scene, timeline, movement, body)
    return Parameters(bodies, springs, velocities)


def start_movements(scene: Scene, timeline: Timeline) -> list[tuple[Event, Body]]:
    """The movements the start event causes, each with the body it moves (its first component), first first; a
    body moved by the start twice counts once (its first movement)."""
    starts = {ev.id for ev in timeline.events if ev.type == "start"}
    out: list[tuple[Event, Body]] = []
    seen: set[str] = set()
    for ev in sorted(timeline.events, key=lambda e: e.t0):
        if ev.type != "movement" or not starts & set(ev.causes) or not ev.components:
            continue
        body = scene.components.get(ev.components[0])
        if isinstance(body, Body) and not scene.is_fixed(body.id) and body.id not in seen:
            seen.add(body.id)
            out.append((ev, body))
    return out


def first_contact(timeline: Timeline, movement: Event) -> Event | None:
    """The earliest contact that ``movement`` causes, or None."""
    contacts = [timeline.event(c) for c in timeline.children(movement.id)]
    contacts = [c for c in contacts if c.type == "contact"]
    return min(contacts, key=lambda c: c.t0, default=None)


def destination(timeline: Timeline, movement: Event) -> tuple[Point, float] | None:
    """Where the moving body should be, and when (seconds after the movement began); None without frames."""
    contact = first_contact(timeline, movement)
    if movement.trajectory:
        last = movement.trajectory[-1]
        t = (contact.t0 if contact is not None else last.t) - movement.t0
        return (last.x, last.y), t
    if contact is not None and contact.point is not None:
        return contact.point, contact.t0 - movement.t0
    return None


def initial_velocity(scene: Scene, timeline: Timeline, movement: Event, body: Body,
                     time_factor: float = 1.0) -> tuple[float, float]:
    """The seed velocity of ``body``, moved by the start in ``movement`` (see the module docstring); with a
    ``time_factor``, the velocity that reaches the same destination in that many times the seeded flight time."""
    goal = destination(timeline, movement)
    if goal is None:
        return (0.0, 0.0)
    (x, y), t = goal
    dx, dy = x - body.position[0], y - body.position[1]
    axis = _spring_axis(scene, body.id)
    if axis is not None:
        along = dx * axis[0] + dy * axis[1]
        t = max(t, MIN_TIME) * time_factor
        return (along * axis[0] / t, along * axis[1] / t)
    return ballistic((dx, dy), t, time_factor=time_factor)


def seed_family(scene: Scene, timeline: Timeline, canvas: tuple[float, float],
                factors: tuple[float, ...] = FLIGHT_FACTORS) -> list[Parameters]:
    """The seed with every start body reaching its destination in ``factor`` times its seeded flight time, one
    candidate per factor (the same factor for every start body, so bodies demonstrated meeting still meet).

    The demonstrated time is the pen's pace, not the physics': a faster launch meets the same first contact
    with more speed (the basketball's balls must still be rising when they collide to bounce back into their
    baskets), a slower one as a lob.
    """
    base = seed(scene, timeline, canvas)
    out = []
    for factor in factors:
        velocities = {body.id: initial_velocity(scene, timeline, movement, body, factor)
                      for movement, body in start_movements(scene, timeline)}
        out.append(base.with_velocities(velocities))
    return out


def ballistic(d: Point, t: float, gravity: Point = GRAVITY, *, time_factor: float = 1.0) -> Point:
    """The launch velocity that carries a body by ``d`` in about ``t`` seconds under ``gravity`` (``t`` clamped as
    the module docstring says, then multiplied by ``time_factor``).

    >>> vx, vy = ballistic((300.0, 0.0), 1.0)
    >>> round(vx), round(vy)  # sideways and up, falling back to its level after about a second
    (300, -450)
    """
    g = math.hypot(*gravity)
    distance = math.hypot(*d)
    if distance == 0:
        return (0.0, 0.0)
    slowest = math.sqrt(2 * distance / g) if g > 0 else max(t, MIN_TIME)
    t = min(max(t, MIN_FLIGHT * slowest, MIN_TIME), MAX_FLIGHT * slowest) * time_factor
    return (d[0] / t - gravity[0] * t / 2, d[1] / t - gravity[1] * t / 2)


def _spring_axis(scene: Scene, body_id: str) -> tuple[float, float] | None:
    for c in scene.components.values():
        if isinstance(c, Spring) and body_id in (c.a, c.b):
            return AXES.get(c.axis)
    return None
