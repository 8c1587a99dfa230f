"""The physics world: one pymunk space mirroring a Scene, stepped on a fixed dt, queried and dragged by component id.

`World` owns the space, the fixed time step and the two-way maps between component ids and pymunk objects (built by
build.py). It answers which body lies under a point, where a body is and how fast it moves; it freezes bodies
and drags one through a soft constraint for editing and demonstrating; it records where contacts begin and writes
poses back into a Scene. Deciding what strokes become (interpret), what contacts mean (timeline) and when to step
(session) is left to others.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import Self

import pymunk

from physink_tui.errors import SceneError
from physink_tui.scene.components import Point, Scene
from physink_tui.scene.physics.build import Built, build
from physink_tui.scene.physics.contacts import ContactListener, ContactRecord, set_friction, touching_record
from physink_tui.scene.physics.editing import Editing
from physink_tui.scene.physics.sleeping import sleep_groups
from physink_tui.scene.physics.speed import limit_speed
from physink_tui.scene.physics.state import REST, Motion, Pose, Velocity, WorldState
from physink_tui.scene.physics.write_back import scene_from

GRAVITY: Point = (0.0, 900.0)
"""Gravity in canvas units per second squared, pointing down the canvas (+y).

A sketch is about 1000 units across and a pen-drawn ball 20-60 units wide. At 900 units/s² (about 9.2 m/s² if a
unit is a centimetre, so a canvas is a ten-metre Rube Goldberg room) a body falls the whole canvas height in
sqrt(2 * 1000 / 900) ~ 1.5 s: slow enough to follow on screen, fast enough to feel like falling. Its speed then is
about 1340 units/s, i.e. 11 units per 1/120 s step, less than the half-thickness of any body the recogniser makes,
so nothing tunnels through a platform.
"""
DT = 1 / 120
"""The fixed time step in seconds (two steps per 60 Hz frame)."""
ITERATIONS = 20
"""Solver iterations per step (pymunk's default is 10): ropes carrying heavy bodies stretch visibly with fewer."""
class World:
    """A pymunk space mirroring a `Scene`, addressed by component id.

    Bodies welded to the background (`Scene.is_fixed`) are pymunk STATIC bodies rather than dynamic bodies held by
    a weld constraint: they cannot drift or sag, cost the solver nothing, and stay put when other bodies land on
    them. A drag may still move one (it is made dynamic for the drag and static again on release).

    Contacts take the larger restitution and the mean friction of the two shapes (DESIGN.md; pymunk would multiply
    them); restitution acts only when a contact begins faster than `BOUNCE_THRESHOLD`. The world owns the space's
    collision handlers: shapes carry no elasticity and a surface type as their collision type (see build.py), so no
    other handler may replace them.

    >>> from physink_tui.scene.components import MATERIALS, Body
    >>> ball = Body("b1", "circle", (), 20.0, (100.0, 100.0), 0.0, MATERIALS["round"])
    >>> world = World.from_scene(Scene().add(ball))
    >>> world.step(120)
    >>> round(world.pose("b1")[1])  # one second of free fall: 100 + 900 / 2, less the step pymunk lags by
    546
    """

    def __init__(self, scene: Scene, *, gravity: Point = GRAVITY, dt: float = DT) -> None:
        """The world of ``scene`` (`from_scene` says the same by name); a subclass adds its own state after this.

        Raises:
            SceneError: a component the world cannot build (see `build.build`), or a non-positive ``dt``.
        """
        if not dt > 0:
            raise SceneError(f"time step {dt!r} is not positive")
        space = pymunk.Space()
        space.gravity = gravity
        space.iterations = ITERATIONS
        built = build(scene, space)
        self._built = built
        self._space = space
        self._dt = dt
        self._steps = 0
        self._listener = ContactListener(built.owner, built.surfaces.bounces)
        self._frictions = 0  # how many of `Surfaces.frictions` have their pre-solve callback
        self._live: set[pymunk.Constraint] = set()
        self._editing = Editing(space, built, self._get, self._dynamic_bodies, self._sync_constraints, self._unlink)
        """The frozen bodies and the drag under way (`freeze_all_except`, `drag`)."""
        self._by_z = sorted(built.z, key=built.z.__getitem__)
        self.substeps = 1
        """Sub-steps per step: a simulation without demo mode's speed limit divides a step whose fastest body would
        cross more than a thin body's width (sim/rollout.py); contacts begun in any sub-step count for the step."""
        self._space.on_collision(begin=self._listener.begin, separate=self._listener.separate)
        self._handle_frictions()
        self._sync_constraints()

    @classmethod
    def from_scene(cls, scene: Scene, *, gravity: Point = GRAVITY, dt: float = DT) -> Self:
        """Builds the world for ``scene``.

        Raises:
            SceneError: a component the world cannot build (see `build.build`), or a non-positive ``dt``.
        """
        return cls(scene, gravity=gravity, dt=dt)

    # -- what the world holds -------------------------------------------------------------------------------------

    @property
    def dt(self) -> float:
        return self._dt

    @property
    def steps(self) -> int:
        """Steps taken since the world was built."""
        return self._steps

    @property
    def gravity(self) -> Point:
        g = self._space.gravity
        return (g.x, g.y)

    @gravity.setter
    def gravity(self, value: Point) -> None:
        self._space.gravity = value

    def body_ids(self) -> tuple[str, ...]:
        """The bodies' ids, bottom first (creation order)."""
        return tuple(self._by_z)

    @property
    def damping(self) -> float:
        """Share of its velocity a free body keeps after one second (1.0: none lost)."""
        return float(self._space.damping)

    @damping.setter
    def damping(self, value: float) -> None:
        self._space.damping = value

    @property
    def pymunk_parts(self) -> Built:
        """The pymunk objects behind the world, by component id: for tests and benchmarks that look at what pymunk
        holds. The program asks the world its questions instead; only `scene.physics` imports pymunk (import-linter).
        """
        return self._built

    # -- queries --------------------------------------------------------------------------------------------------

    def bodies_at(self, point: Point) -> list[str]:
        """Ids of the bodies whose shape contains ``point``, topmost (last created) first; ropes are not bodies."""
        z = self._built.z
        hits = {self._built.owner.get(hit.shape) for hit in self._space.point_query(point, 0.0, pymunk.ShapeFilter())}
        return sorted((h for h in hits if h in z), key=z.__getitem__, reverse=True)

    def body_at(self, point: Point) -> str | None:
        """The topmost body containing ``point``, or None."""
        hits = self.bodies_at(point)
        return hits[0] if hits else None

    def pose(self, body_id: str) -> Pose:
        """Where a body's origin (`Body.position`) is and its rotation in radians."""
        body = self._get(body_id)
        return Pose(body.position.x, body.position.y, body.angle)

    def velocity(self, body_id: str) -> Velocity:
        """How fast a body's origin moves (canvas units per second) and turns (radians per second)."""
        return _motion(self._get(body_id)).velocity

    def motion(self, body_id: str) -> Motion:
        """A body's pose and velocity together."""
        return _motion(self._get(body_id))

    def motions(self, body_ids: Iterable[str], known: Mapping[str, Motion] | None = None) -> dict[str, Motion]:
        """`motion` of each of ``body_ids``, or its motion in ``known`` when given there (bodies that cannot move)."""
        get = self._get
        given = known or {}
        out: dict[str, Motion] = {}
        for body_id in body_ids:
            m = given.get(body_id)
            out[body_id] = _motion(get(body_id)) if m is None else m
        return out

    def is_asleep(self, body_id: str) -> bool:
        """Whether a body sleeps (`hold_until_touched`): gravity does not move it until something wakes it."""
        return bool(self._get(body_id).is_sleeping)

    def mass(self, body_id: str) -> float:
        """A body's mass as built (the parameters applied)."""
        return float(self._get(body_id).mass)

    def half_size(self, body_id: str) -> float:
        """Half the smaller side of the smallest bounding box of a body's shapes (canvas units): how far the body
        reaches from its middle at its thinnest; infinite for a body without shapes (the background)."""
        shapes = self._built.shapes.get(body_id, ())
        return min((min(s.bb.right - s.bb.left, s.bb.top - s.bb.bottom) / 2 for s in shapes), default=math.inf)

    def contact_between(self, a_id: str, b_id: str, step: int) -> ContactRecord | None:
        """The contact joining bodies ``a_id`` and ``b_id`` now, as a record of one begun in ``step``
        (`contacts.touching_record`); None when they do not touch."""
        return touching_record(step, self._get(a_id), self._get(b_id), a_id, b_id)

    def state(self) -> WorldState:
        """The world now as a frozen value: every body's and rope link's motion, the steps taken and the gravity."""
        links = {rope: tuple(_motion(link) for link in bodies) for rope, bodies in self._built.links.items()}
        return WorldState(self._steps, {cid: self.motion(cid) for cid in self._by_z}, self.gravity, links)

    @classmethod
    def from_state(cls, scene: Scene, state: WorldState, *, dt: float = DT, warm: int = 0) -> World:
        """A world of ``scene`` with its bodies where ``state`` has them, moving as they moved, and its step count:
        a search forks any number of worlds from one state. Contact caches and drags are not part of a state: with
        ``warm`` > 0, that many steps, each undone, give resting bodies' contacts the impulses that hold them (kept
        while asleep: `hold_until_touched`), as in the world the state was taken from; their contacts are not told."""
        world = cls.from_scene(scene, gravity=state.gravity, dt=dt)
        world._restore(state)
        for _ in range(warm):
            world._space.step(dt)
            world._restore(state)
        world._listener.take()
        return world

    def _restore(self, state: WorldState) -> None:
        for cid, motion in state.bodies.items():
            if cid in self._built.bodies:
                self.place(cid, motion.pose, motion.velocity)
        for rope, motions in state.links.items():
            for link, m in zip(self._built.links.get(rope, ()), motions, strict=False):
                _put(self._space, link, m.pose, m.velocity)
        self._steps = state.step
        self._listener.step = state.step

    def set_velocity(self, body_id: str, velocity: Point, angular_velocity: float = 0.0) -> None:
        """Gives a dynamic body a velocity (of its centre of mass) and an angular velocity."""
        body = self._get(body_id)
        body.velocity = velocity
        body.angular_velocity = angular_velocity

    def is_dynamic(self, body_id: str) -> bool:
        return self._get(body_id).body_type == pymunk.Body.DYNAMIC

    # -- time -----------------------------------------------------------------------------------------------------

    def step(self, n: int = 1) -> None:
        """Advances exactly ``n`` steps of ``dt``, each in `substeps` equal sub-steps."""
        if len(self._built.surfaces.frictions) != self._frictions:
            self._handle_frictions()  # a component added since (`live.LiveWorld`) brought a new material
        parts = self.substeps
        for _ in range(n):
            self._steps += 1
            self._listener.next_step()
            if parts == 1:
                self._space.step(self._dt)
            else:
                for _ in range(parts):
                    self._space.step(self._dt / parts)

    def take_contacts(self) -> list[ContactRecord]:
        """The contacts begun since the last call, in the order they began."""
        return self._listener.take()

    def touching(self) -> frozenset[frozenset[str]]:
        """The pairs of components (bodies and ropes) touching now."""
        return self._listener.touching()

    # -- demonstrating and playing back ---------------------------------------------------------------------------

    def follow(self, body_id: str, pose: Pose, velocity: Velocity) -> None:
        """Moves a body along a recording: kinematic (it pushes what it meets and nothing pushes it), placed at
        ``pose`` (x, y, angle) and moving with ``velocity`` (vx, vy, angular) until the next call or `let_go`."""
        body = self._get(body_id)
        if body.body_type == pymunk.Body.DYNAMIC:
            body.body_type = pymunk.Body.KINEMATIC
            self._sync_constraints()
        self.place(body_id, pose, velocity)

    def let_go(self, body_id: str) -> None:
        """A body that followed a recording is moved by the physics again, with the velocity it had."""
        body = self._get(body_id)
        if body.body_type == pymunk.Body.KINEMATIC:
            velocity, spin = body.velocity, body.angular_velocity
            body.body_type = pymunk.Body.DYNAMIC
            body.velocity, body.angular_velocity = velocity, spin
            self._sync_constraints()

    def place(self, body_id: str, pose: Pose, velocity: Velocity = REST) -> None:
        """Puts a body that is not fixed at ``pose`` (x, y, angle) with ``velocity`` (vx, vy, angular)."""
        body = self._get(body_id)
        if body.body_type != pymunk.Body.STATIC:  # fixed bodies stay where they are
            _put(self._space, body, pose, velocity)

    def limit_speeds(self) -> None:
        """No tunnelling: every body that can move (not the rope links) gets `speed.limit_speed`."""
        for cid in self._by_z:
            if self._built.bodies[cid].body_type == pymunk.Body.DYNAMIC:
                limit_speed(self._built.bodies[cid], self._dt)

    def hold_until_touched(self, awake: set[str] | frozenset[str],
                           together: Iterable[frozenset[str]] = ()) -> None:
        """Every dynamic body except ``awake`` and what joints, ropes and springs tie to them sleeps where it is:
        gravity does not move it until an awake body touches it, and then it wakes within the same step with
        everything tied to it (a lever, its rope and the knife on the rope sleep as one group), so the blow that
        woke it is solved as between two moving bodies (Chipmunk's sleeping). A simulation holds this way what
        its drawing does not hold by itself. ``together`` names pairs of bodies (touching ones, say) that sleep in
        one group too: a cup on a platform and the peg that holds the platform wake as one, so the peg's spring
        pushes it on when the platform drops away. A group keeps its contacts asleep: in a world forked ``warm``
        (`from_state`) none begins again as it wakes, and a spring pressing a body against another does not jolt
        it for a step before the contact pushes back (`sleeping.sleep_groups`)."""
        keep = {self._get(body_id) for body_id in awake}
        pairs = [tuple(self._get(b) for b in sorted(pair)) for pair in together if len(pair) == 2]
        sleep_groups(self._space, self._dynamic_bodies(), keep, pairs)

    # -- editing --------------------------------------------------------------------------------------------------

    def freeze_all_except(self, body_id: str) -> None:
        """Makes every dynamic body static except ``body_id``, what is welded to it, and ropes attached to those.

        Velocities are kept and given back by `unfreeze`. Calling it again first unfreezes.
        """
        self._editing.freeze_all_except(body_id)

    def unfreeze(self) -> None:
        """Undoes `freeze_all_except`: the frozen bodies move again with the velocities they had."""
        self._editing.unfreeze()

    def drag(self, body_id: str, target_point: Point, grab_point: Point | None = None, *,
             rotate: bool = True) -> None:
        """Pulls ``body_id`` so that the point grabbed moves towards ``target_point`` (a mouse joint).

        The first call for a body grabs it at ``grab_point`` (canvas units; default its origin); later calls for the
        same body only move the target. A kinematic control body at the target holds the grabbed point through a
        pivot joint of limited force, so the body follows the pen but is stopped by what it hits. With
        ``rotate=False`` a gear of limited torque also keeps its angle. A static (fixed) body is made dynamic for
        the drag and static again by `release` (`editing.Editing`).
        """
        self._editing.drag(body_id, target_point, grab_point, rotate=rotate)

    def release(self) -> None:
        """Ends the drag; a fixed or frozen body becomes static again where it now is."""
        self._editing.release()

    # -- back to the scene ----------------------------------------------------------------------------------------

    def to_scene(self, scene: Scene) -> Scene:
        """``scene`` with its bodies where the world has them now, and what they carry moved along
        (`write_back.scene_from`)."""
        return scene_from(self._built, scene)

    # -- internals ------------------------------------------------------------------------------------------------

    def _get(self, body_id: str) -> pymunk.Body:
        body = self._built.bodies.get(body_id)
        if body is None:
            raise SceneError(f"no body {body_id!r} in the world")
        return body

    def _dynamic_bodies(self) -> list[pymunk.Body]:
        built = self._built
        bodies = [built.bodies[i] for i in self._by_z] + [link for links in built.links.values() for link in links]
        return [b for b in bodies if b.body_type == pymunk.Body.DYNAMIC]

    def _unlink(self, part: pymunk.Constraint) -> None:
        """A constraint out of the space for good (a released drag's joints)."""
        self._space.remove(part)
        self._live.discard(part)

    def _handle_frictions(self) -> None:
        """Registers `contacts.set_friction` for the pairs of surfaces not registered yet (pairs are only added)."""
        for (a, b), friction in list(self._built.surfaces.frictions.items())[self._frictions:]:
            self._space.on_collision(a, b, pre_solve=set_friction, data=friction)
        self._frictions = len(self._built.surfaces.frictions)

    def _sync_constraints(self) -> None:
        """Puts in the space exactly the constraints with at least one dynamic body (static-static ones give NaNs)."""
        parts = [p for ps in self._built.constraints.values() for p in ps]
        parts.extend(self._editing.drag_parts)
        dynamic = pymunk.Body.DYNAMIC
        for part in parts:
            live = part.a.body_type == dynamic or part.b.body_type == dynamic
            if live and part not in self._live:
                self._space.add(part)
                self._live.add(part)
            elif not live and part in self._live:
                self._space.remove(part)
                self._live.discard(part)


def _motion(body: pymunk.Body) -> Motion:
    """A body's motion, its velocity taken at its origin (`Body.position`), each coordinate read once (a rope link's
    origin is its centre of gravity: its velocity there is pymunk's ``velocity``, bit for bit)."""
    p = body.position
    v = body.velocity_at_world_point(p)
    return Motion(p.x, p.y, body.angle, v.x, v.y, body.angular_velocity)


def _put(space: pymunk.Space, body: pymunk.Body, pose: Pose, velocity: Velocity) -> None:
    body.position, body.angle = pose[:2], pose[2]
    body.velocity, body.angular_velocity = velocity[:2], velocity[2]
    space.reindex_shapes_for_body(body)
