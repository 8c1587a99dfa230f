"""Builds the pymunk objects mirroring a `Scene` (bodies, joints, springs, ropes); stepping and queries are world.py's.

Everything here runs when `world.World.from_scene` builds a world, or `live.LiveWorld` adds to one: it turns each
component into pymunk bodies, shapes and constraints and records which component owns what. Bodies and shapes are
added to the space here; constraints are not: `World` adds only those with at least one dynamic end (a constraint
between two static bodies makes Chipmunk divide by a zero mass and fills the space with NaNs), and re-decides when
it freezes or drags bodies.
How shapes get their materials' restitution and friction is `surfaces.py`'s.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import pymunk

from physink_tui.errors import SceneError
from physink_tui.scene.components import (
    BACKGROUND,
    Body,
    Component,
    Joint,
    Point,
    Rope,
    Scene,
    Spring,
)
from physink_tui.scene.physics.outlines import convex_pieces, distinct_points, need_area
from physink_tui.scene.physics.surfaces import ROPE_MATERIAL, Surfaces

POLYLINE_RADIUS = 2.0
"""Half-thickness of an open polyline body's segments, in canvas units (a ramp is a 4-unit strip)."""
ROPE_RADIUS = 1.5
"""Half-thickness of a rope link."""
ROPE_LINK_LENGTH = 15.0
"""Target length of one rope link; a rope gets between `ROPE_MIN_LINKS` and `ROPE_MAX_LINKS` links."""
ROPE_MIN_LINKS = 8
ROPE_MAX_LINKS = 40
SPRING_DAMPING_RATIO = 0.1
"""Fraction of critical damping given to springs: a little, so a plucked spring rings for a few periods."""
GROOVE_REACH = 10_000.0
"""How far a spring's groove runs from the fixed anchor (canvas units): the spring may shorten to zero length, never
invert, and stretch as far as any canvas needs."""
AXES = {"horizontal": (1.0, 0.0), "vertical": (0.0, 1.0)}
"""A spring's axis name -> the unit direction it may stretch along."""
SPRING_OVERLAP = 1.0
"""Canvas units by which a spring's two bodies may overlap where built and still collide with each other. Bodies
on a spring are two rigid bodies (thesis 3.2.3: a Hooke's-law force, and a prismatic joint that keeps it on one axis): a
trampoline struck hard stops on its base rather than sinking into it. Only bodies drawn into each other (a spring
anchored inside the body it holds) pass through each other, as a joint's bodies do, since colliding would push them
apart at the start."""



@dataclass(slots=True)
class Built:
    """The pymunk side of a scene and the two-way maps between component ids and pymunk objects.

    Attributes:
        space: the space, holding every body and shape (but no constraint yet).
        bodies: component id -> pymunk body, for every `Body` and for `BACKGROUND`.
        shapes: body or rope id -> its shapes (a body's in outline order, a rope's link by link).
        constraints: joint, spring or rope id -> its constraints, in creation order (empty for a weld to the
            background: the welded body is simply static).
        links: rope id -> its link bodies, start to end.
        owner: pymunk shape -> the id of the body or rope it belongs to.
        z: body id -> z-order (creation order: higher lies on top).
        rest_pose: pymunk body -> its pose when built (to carry anchors and rope points along in ``to_scene``).
        carriers: joint, spring or rope id -> for each of its scene points, the pymunk body that carries it.
        paths: rope id -> its link ends when built (`rope_path` of its points).
        welds: the pairs of pymunk bodies welded together (not counting welds to the background).
        surfaces: the materials' surface types, grips, bounces and frictions (`surfaces.Surfaces`).
    """

    space: pymunk.Space
    bodies: dict[str, pymunk.Body] = field(default_factory=dict)
    shapes: dict[str, tuple[pymunk.Shape, ...]] = field(default_factory=dict)
    constraints: dict[str, tuple[pymunk.Constraint, ...]] = field(default_factory=dict)
    links: dict[str, tuple[pymunk.Body, ...]] = field(default_factory=dict)
    owner: dict[pymunk.Shape, str] = field(default_factory=dict)
    z: dict[str, int] = field(default_factory=dict)
    rest_pose: dict[pymunk.Body, tuple[float, float, float]] = field(default_factory=dict)
    carriers: dict[str, tuple[pymunk.Body, ...]] = field(default_factory=dict)
    paths: dict[str, tuple[Point, ...]] = field(default_factory=dict)
    welds: list[tuple[pymunk.Body, pymunk.Body]] = field(default_factory=list)
    surfaces: Surfaces = field(default_factory=Surfaces)

def build(scene: Scene, space: pymunk.Space) -> Built:
    """Mirrors every component of ``scene`` into ``space``: bodies first (in z-order), then joints, springs, ropes.

    Raises:
        SceneError: a component with an unknown shape, kind or axis, degenerate geometry, or a reference to a body
            the scene does not have.
    """
    built = Built(space)
    background = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(background)
    built.bodies[BACKGROUND] = background
    built.rest_pose[background] = (0.0, 0.0, 0.0)
    fixed = scene.fixed_bodies()
    for body in scene.bodies():
        add(built, body, fixed=body.id in fixed)
    # Masses are known only once shapes are in the space, and springs need them for their damping.
    for component in scene.components.values():
        if not isinstance(component, Body):
            add(built, component, rope_index=len(built.links))
    return built


def add(built: Built, component: Component, *, fixed: bool = False, rope_index: int = 0) -> None:
    """Mirrors one component into ``built.space`` (a joint, spring or rope after the bodies it holds); ``fixed``
    makes a body static, ``rope_index`` picks a rope's collision group and category bit (see `_add_rope`)."""
    if isinstance(component, Body):
        _add_body(built, component, fixed=fixed)
    elif isinstance(component, Joint):
        _add_joint(built, component)
    elif isinstance(component, Spring):
        _add_spring(built, component)
    elif isinstance(component, Rope):
        _add_rope(built, component, index=rope_index)


def _add_body(built: Built, spec: Body, *, fixed: bool) -> None:
    body = pymunk.Body(body_type=pymunk.Body.STATIC if fixed else pymunk.Body.DYNAMIC)
    body.position = spec.position
    body.angle = spec.angle
    shapes = body_shapes(body, spec)
    for shape in shapes:
        shape.density = spec.material.density
        built.surfaces.dress(shape, spec.material.restitution, spec.material.friction)
        built.owner[shape] = spec.id
    built.space.add(body, *shapes)
    built.bodies[spec.id] = body
    built.shapes[spec.id] = tuple(shapes)
    built.z[spec.id] = len(built.z)
    # As pymunk reads it back (a centre of mass off the origin can change the last bit): unmoved means equal to this.
    built.rest_pose[body] = (body.position.x, body.position.y, body.angle)


def body_shapes(body: pymunk.Body, spec: Body) -> list[pymunk.Shape]:
    """The collision shapes of ``spec`` on ``body``, in body coordinates.

    Boxes and ellipses are one convex polygon each, circles a circle, closed freeform polygons a convex polygon or
    (when concave) the triangles of their constrained Delaunay triangulation (thesis 3.2.3 used poly2tri), open
    polylines a chain of thin segments.
    """
    if spec.shape == "circle":
        if not spec.radius > 0:
            raise SceneError(f"circle {spec.id!r} has radius {spec.radius!r}; expected a positive radius")
        return [pymunk.Circle(body, spec.radius)]
    if spec.shape in ("box", "ellipse"):
        need_area(spec)
        return [pymunk.Poly(body, spec.outline)]
    if spec.shape == "polygon":
        return [pymunk.Poly(body, triangle) for triangle in convex_pieces(spec)]
    if spec.shape == "polyline":
        return _polyline_segments(body, spec)
    raise SceneError(f"body {spec.id!r} has shape {spec.shape!r}; expected box, circle, ellipse, polygon or polyline")


def body_area(spec: Body) -> float:
    """The area of a body's collision shapes (canvas units²): its mass at density 1.0. A polyline's thin segments
    count with their rounded thickness."""
    return float(sum(shape.area for shape in body_shapes(pymunk.Body(), spec)))


def _polyline_segments(body: pymunk.Body, spec: Body) -> list[pymunk.Shape]:
    points = distinct_points(spec)
    segments: list[pymunk.Shape] = []
    for i in range(len(points) - 1):
        segment = pymunk.Segment(body, points[i], points[i + 1], POLYLINE_RADIUS)
        # Neighbours let a ball roll over the joins between segments instead of catching on their corners.
        segment.set_neighbors(points[max(i - 1, 0)], points[min(i + 2, len(points) - 1)])
        segments.append(segment)
    return segments


def _body(built: Built, body_id: str, owner: str) -> pymunk.Body:
    body = built.bodies.get(body_id)
    if body is None:
        raise SceneError(f"{owner!r} refers to body {body_id!r}, which the scene does not have")
    return body


def _add_joint(built: Built, joint: Joint) -> None:
    a, b = _body(built, joint.a, joint.id), _body(built, joint.b, joint.id)
    if a is b:
        raise SceneError(f"joint {joint.id!r} joins body {joint.a!r} to itself")
    built.carriers[joint.id] = (b if joint.a == BACKGROUND else a,)  # the anchor moves with the body drawn in
    if joint.kind == "weld" and BACKGROUND in (joint.a, joint.b):
        built.constraints[joint.id] = ()  # the body is static: the weld is its body type, not a constraint
        return
    if joint.kind not in ("pivot", "weld"):
        raise SceneError(f"joint {joint.id!r} has kind {joint.kind!r}; expected pivot or weld")
    if a.body_type != pymunk.Body.DYNAMIC and b.body_type != pymunk.Body.DYNAMIC:
        built.constraints[joint.id] = ()  # both held still already (a pin in a welded body): nothing to constrain
        return
    pin = pymunk.PivotJoint(a, b, joint.anchor)
    parts: list[pymunk.Constraint] = [pin]
    if joint.kind == "weld":
        parts.append(pymunk.GearJoint(a, b, b.angle - a.angle, 1.0))
        built.welds.append((a, b))
    for part in parts:
        part.collide_bodies = False
    built.constraints[joint.id] = tuple(parts)


SPRING_UNITS = 1.0e4
"""Converts a spring constant in the thesis's units (N/m, Box2D) to this world's: taking 1 m = 100 canvas units
(gravity 900 units/s^2 = 9 m/s^2) and a mass of 1 per canvas unit^2, forces are 1e6 and lengths 1e2 times the SI
values, so stiffness is 1e4 times. The seed k = 20 then stretches a spring under a ball of radius 25 by about 9 units,
as it would in the thesis; `Spring.k` stays in the thesis's units everywhere else (projects, the parameter search)."""


def _add_spring(built: Built, spring: Spring) -> None:
    """A Hooke's-law spring plus a prismatic joint (groove + gear) that lets its free end move along one axis only.

    The groove lies on the fixed end (``a`` unless only ``b`` is static) and runs through the free anchor, from the
    fixed anchor's level outwards, so the spring can shorten to nothing but not turn inside out; the spring's fixed
    anchor is moved onto that line so its pull is exactly axial.
    """
    if spring.axis not in AXES:
        raise SceneError(f"spring {spring.id!r} has axis {spring.axis!r}; expected horizontal or vertical")
    if not spring.k > 0 or not spring.rest_length >= 0:
        raise SceneError(f"spring {spring.id!r} has k={spring.k!r}, rest length {spring.rest_length!r}; "
                         "expected k > 0 and a rest length >= 0")
    a, b = _body(built, spring.a, spring.id), _body(built, spring.b, spring.id)
    if a is b:
        raise SceneError(f"spring {spring.id!r} joins body {spring.a!r} to itself")
    built.carriers[spring.id] = (a, b)
    if a.body_type != pymunk.Body.DYNAMIC and b.body_type != pymunk.Body.DYNAMIC:
        built.constraints[spring.id] = ()  # both ends held still (a fixed body to the background): nothing to do
        return
    fixed, free, fixed_at, free_at = a, b, spring.anchor_a, spring.anchor_b
    if a.body_type == pymunk.Body.DYNAMIC and b.body_type != pymunk.Body.DYNAMIC:
        fixed, free, fixed_at, free_at = b, a, spring.anchor_b, spring.anchor_a
    ux, uy = AXES[spring.axis]
    along = (free_at[0] - fixed_at[0]) * ux + (free_at[1] - fixed_at[1]) * uy
    sign = 1.0 if along >= 0 else -1.0
    # The fixed anchor, slid across the axis onto the line through the free anchor.
    base = (free_at[0] - along * ux, free_at[1] - along * uy)
    far = (base[0] + sign * GROOVE_REACH * ux, base[1] + sign * GROOVE_REACH * uy)
    # The groove holds the free body's centre of mass on a parallel line (with rotation locked that is the same
    # constraint): Chipmunk's groove solver only converges for a slider at the centre of mass.
    cog = free.local_to_world(free.center_of_gravity)
    ox, oy = cog[0] - free_at[0], cog[1] - free_at[1]
    stiffness = spring.k * SPRING_UNITS
    damping = SPRING_DAMPING_RATIO * 2.0 * math.sqrt(stiffness * _reduced_mass(fixed, free))
    parts = (
        pymunk.DampedSpring(fixed, free, fixed.world_to_local(base), free.world_to_local(free_at), spring.rest_length,
                            stiffness, damping),
        pymunk.GrooveJoint(fixed, free, fixed.world_to_local((base[0] + ox, base[1] + oy)),
                           fixed.world_to_local((far[0] + ox, far[1] + oy)), free.center_of_gravity),
        pymunk.GearJoint(fixed, free, free.angle - fixed.angle, 1.0),
    )
    apart = _apart(built.space, built.shapes.get(spring.a, ()), built.shapes.get(spring.b, ()))
    for part in parts:
        part.collide_bodies = apart
    built.constraints[spring.id] = parts


def _apart(space: pymunk.Space, shapes_a: tuple[pymunk.Shape, ...], shapes_b: tuple[pymunk.Shape, ...]) -> bool:
    """Whether no shape of one body overlaps one of the other's by more than `SPRING_OVERLAP` where built."""
    others = set(shapes_b)
    for shape in shapes_a:
        shape.cache_bb()
        for hit in space.shape_query(shape):
            if hit.shape in others and any(p.distance < -SPRING_OVERLAP for p in hit.contact_point_set.points):
                return False
    return True


def _reduced_mass(a: pymunk.Body, b: pymunk.Body) -> float:
    masses = [body.mass for body in (a, b) if body.body_type == pymunk.Body.DYNAMIC]
    if not masses:
        return 0.0
    return masses[0] if len(masses) == 1 else masses[0] * masses[1] / (masses[0] + masses[1])


def rope_path(points: tuple[Point, ...]) -> tuple[Point, ...]:
    """A rope's link ends: its points as they are when they already make 8 to 40 links, else resampled evenly.

    Resampling picks about `ROPE_LINK_LENGTH` per link. Keeping a path that already has a valid link count makes
    ``World.to_scene`` (which writes link ends back) a fixed point.

    >>> len(rope_path(((0.0, 0.0), (300.0, 0.0)))) - 1
    20
    """
    if ROPE_MIN_LINKS + 1 <= len(points) <= ROPE_MAX_LINKS + 1:
        return points
    lengths = [math.dist(points[i], points[i + 1]) for i in range(len(points) - 1)]
    total = sum(lengths)
    n = min(max(round(total / ROPE_LINK_LENGTH), ROPE_MIN_LINKS), ROPE_MAX_LINKS)
    out: list[Point] = [points[0]]
    i, walked = 0, 0.0
    for k in range(1, n):
        goal = total * k / n
        while i < len(lengths) - 1 and walked + lengths[i] < goal:
            walked += lengths[i]
            i += 1
        f = (goal - walked) / lengths[i] if lengths[i] > 0 else 0.0
        (x0, y0), (x1, y1) = points[i], points[i + 1]
        out.append((x0 + (x1 - x0) * f, y0 + (y1 - y0) * f))
    out.append(points[-1])
    return tuple(out)


def _add_rope(built: Built, rope: Rope, *, index: int) -> None:
    """A chain of thin links joined by pivots, its ends pinned to the bodies named (or free), plus a length limit.

    Collision filtering: the links of one rope share a group (they never collide with each other) and a category
    bit (rope ``index`` mod 32) that the shapes of the bodies holding its ends leave out of their masks, so a rope
    passes freely through what it is tied to while still hitting everything else.
    """
    if len(rope.points) < 2:
        raise SceneError(f"rope {rope.id!r} has {len(rope.points)} points; expected at least 2")
    path = rope_path(rope.points)
    if not sum(math.dist(path[i], path[i + 1]) for i in range(len(path) - 1)) > 0:
        raise SceneError(f"rope {rope.id!r} has zero length: {rope.points!r}")
    links: list[pymunk.Body] = []
    shapes: list[pymunk.Shape] = []
    parts: list[pymunk.Constraint] = []
    bit = 1 << (index % 32)
    no_self = pymunk.ShapeFilter(group=index + 1, categories=bit)
    for (x0, y0), (x1, y1) in itertools.pairwise(path):
        half = math.dist((x0, y0), (x1, y1)) / 2
        link = pymunk.Body()
        link.position = ((x0 + x1) / 2, (y0 + y1) / 2)
        link.angle = math.atan2(y1 - y0, x1 - x0)
        segment = pymunk.Segment(link, (-half, 0), (half, 0), ROPE_RADIUS)
        segment.density = ROPE_MATERIAL.density
        built.surfaces.dress(segment, ROPE_MATERIAL.restitution, ROPE_MATERIAL.friction)
        segment.filter = no_self
        built.owner[segment] = rope.id
        built.rest_pose[link] = (link.position.x, link.position.y, link.angle)
        built.space.add(link, segment)
        if links:
            parts.append(pymunk.PivotJoint(links[-1], link, (x0, y0)))
        links.append(link)
        shapes.append(segment)
    for end, at, link in ((rope.start_body, path[0], links[0]), (rope.end_body, path[-1], links[-1])):
        if end is not None:
            parts.append(pymunk.PivotJoint(_body(built, end, rope.id), link, at))
            for shape in built.shapes.get(end, ()):
                f = shape.filter
                shape.filter = pymunk.ShapeFilter(f.group, f.categories, f.mask & ~bit)
    for part in parts:
        part.collide_bodies = False
    if rope.start_body is not None and rope.end_body is not None and rope.start_body != rope.end_body:
        # Box2D's rope joint: the ends never get further apart than the rope is long, however heavy what they hold
        # (an iterative solver cannot keep a chain of light links taut under a body a thousand times heavier).
        a, b = built.bodies[rope.start_body], built.bodies[rope.end_body]
        length = sum(math.dist(p, q) for p, q in itertools.pairwise(path))
        if pymunk.Body.DYNAMIC in (a.body_type, b.body_type):  # (between two fixed bodies it has nothing to do)
            parts.append(pymunk.SlideJoint(a, b, a.world_to_local(path[0]), b.world_to_local(path[-1]), 0.0, length))
    built.links[rope.id] = tuple(links)
    built.shapes[rope.id] = tuple(shapes)
    built.constraints[rope.id] = tuple(parts)
    built.carriers[rope.id] = (*links, links[-1])
    built.paths[rope.id] = path
