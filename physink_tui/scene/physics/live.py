"""A physics world kept in step with a changing scene, by adding, moving and removing only what changed; no I/O.

Rebuilding a world for every stroke costs time in proportion to the whole sketch, so a session of n strokes pays
n^2. `LiveWorld.sync` instead compares the scene it mirrors with the new one component by component (scenes are
immutable, so an unchanged component is the same object) and mirrors the difference: new bodies, joints, springs
and ropes are added, erased ones removed, bodies that moved (adjusting, pushing clear) are moved, bodies welded to or
freed from the background become static or dynamic, and whatever holds on to a body that is rebuilt is rebuilt with
it. Undo and redo are differences like any other. It is the world a view shows while sketching; adjusting, pushing
clear and demonstrating build worlds of their own, so their results never depend on this world's history.
"""

from __future__ import annotations

import math
from itertools import islice, pairwise
from typing import Self

import pymunk

from physink_tui.scene.components import BACKGROUND, Body, Component, Joint, Rope, Scene
from physink_tui.scene.interpretation.body_shapes import THIN
from physink_tui.scene.physics.build import add
from physink_tui.scene.physics.world import DT, World

NEAR_MARGIN = 16.0
"""Canvas units added round a query's box: a body's shapes and its area as interpret sees it (`body_geometry`) may
differ by a few units (a polyline's collision radius against its strip, a circle against its polygon). A polyline's
strip grows with its length (`body_shapes.THIN`), so the margin grows with the widest strip in the world."""


class LiveWorld(World):
    """A `World` that follows a scene through `sync`; build it with `LiveWorld.from_scene`.

    It is not stepped while it follows (a stepped world's bodies leave the poses of the scene), and it does not
    freeze or drag: those belong to the worlds that adjusting and demonstrating build.

    >>> from physink_tui.scene.components import MATERIALS
    >>> ball = Body("b1", "circle", (), 20.0, (100.0, 100.0), 0.0, MATERIALS["round"])
    >>> world = LiveWorld.from_scene(Scene(), gravity=(0.0, 0.0))
    >>> world.sync(Scene().add(ball)); world.body_ids()
    ('b1',)
    >>> world.sync(Scene()); world.body_ids()
    ()
    """

    def __init__(self, scene: Scene, *, gravity: tuple[float, float] = (0.0, 0.0), dt: float = DT) -> None:
        """The world of ``scene``, ready to follow it (no gravity unless given: a sketch stands still)."""
        super().__init__(scene, gravity=gravity, dt=dt)
        self._scene = scene
        self._fixed = scene.fixed_bodies()
        links = self._built.links
        self._next_rope = len(links)
        self._rope_bits = {rid: 1 << (i % 32) for i, rid in enumerate(links)}
        self._strips = {b.id: _strip(b) for b in scene.bodies() if b.shape == "polyline"}
        """polyline id -> half-width of its strip as `body_geometry` draws it"""

    @classmethod
    def from_scene(cls, scene: Scene, *, gravity: tuple[float, float] = (0.0, 0.0), dt: float = DT) -> Self:
        """The world of ``scene``, ready to follow it (no gravity unless given: a sketch stands still)."""
        return cls(scene, gravity=gravity, dt=dt)

    @property
    def scene(self) -> Scene:
        """The scene this world mirrors now."""
        return self._scene

    def bodies_in(self, bounds: tuple[float, float, float, float]) -> list[str]:
        """Ids of the bodies whose shapes' boxes come within `NEAR_MARGIN` of ``bounds`` (x0, y0, x1, y1), topmost
        first: the world's spatial index answering for the scene it mirrors (see `interpret.Near`)."""
        x0, y0, x1, y1 = bounds
        m = NEAR_MARGIN + max(self._strips.values(), default=0.0)
        z = self._built.z
        owners = {self._built.owner.get(s) for s in self._space.bb_query(pymunk.BB(x0 - m, y0 - m, x1 + m, y1 + m),
                                                                          pymunk.ShapeFilter())}
        return sorted((o for o in owners if o in z), key=z.__getitem__, reverse=True)

    def sync(self, scene: Scene) -> None:
        """Mirrors ``scene`` by changing only what differs from the scene mirrored so far.

        Raises:
            SceneError: a new component the world cannot build (see `build.build`).
        """
        old = self._scene
        if scene is old:
            return
        before, after = old.components, scene.components
        fixed = scene.fixed_bodies()
        moved: dict[str, Body] = {}
        rebuild: set[str] = set()
        for cid, c in before.items():
            new = after.get(cid)
            if new is c:
                continue
            if isinstance(c, Body) and isinstance(new, Body) and _same_solid(c, new):
                if (new.position, new.angle) != (c.position, c.angle):
                    moved[cid] = new
            else:
                rebuild.add(cid)
        # what holds on to a body rebuilt, or to one that becomes fixed or free, is built again around it
        touched = {cid for cid in rebuild if isinstance(before[cid], Body)} | (fixed ^ self._fixed)
        if touched:
            rebuild.update(cid for cid, c in before.items() if not isinstance(c, Body) and _ends(c) & touched)
        for cid in sorted(rebuild, key=lambda i: isinstance(before[i], Body)):  # holders first, then bodies
            self._remove(cid, before[cid])
        for cid, body in moved.items():
            self._move(cid, body)
        for cid in fixed ^ self._fixed:
            if cid in self._built.bodies and cid not in rebuild:
                self._set_fixed(cid, cid in fixed)
        new_ids = [cid for cid in after if cid not in before or cid in rebuild]
        for cid in new_ids:
            if isinstance(after[cid], Body):
                self._add(after[cid], fixed=cid in fixed)
        for cid in new_ids:
            if not isinstance(after[cid], Body):
                self._add(after[cid])
        self._order_bodies(after, [cid for cid in new_ids if isinstance(after[cid], Body)],
                           any(isinstance(before[cid], Body) for cid in rebuild))
        self._scene, self._fixed = scene, fixed
        self._sync_constraints()

    def _order_bodies(self, after: dict[str, Component], added: list[str], removed: bool) -> None:
        """Z-order follows the scene's order: bodies drawn last lie on top (a body brought back by undo or redo
        goes back to its place)."""
        on_top = list(islice((cid for cid in reversed(after) if isinstance(after[cid], Body)), len(added)))[::-1]
        if not removed and on_top == added:
            self._by_z.extend(added)  # the usual stroke: one body more, on top (its z is the next one already)
        elif added or removed:
            self._by_z = [cid for cid, c in after.items() if isinstance(c, Body)]
            self._built.z.clear()
            self._built.z.update((cid, z) for z, cid in enumerate(self._by_z))

    # -- one component at a time ----------------------------------------------------------------------------------

    def _add(self, c: Component, *, fixed: bool = False) -> None:
        if isinstance(c, Rope):
            self._rope_bits[c.id] = 1 << (self._next_rope % 32)
            add(self._built, c, rope_index=self._next_rope)
            self._next_rope += 1
        else:
            add(self._built, c, fixed=fixed)
            if isinstance(c, Body) and c.shape == "polyline":
                self._strips[c.id] = _strip(c)

    def _remove(self, cid: str, c: Component) -> None:
        built, space = self._built, self._space
        self._strips.pop(cid, None)
        parts = built.constraints.pop(cid, ())
        for part in parts:
            if part in self._live:
                space.remove(part)
                self._live.discard(part)
        if parts and (parts[0].a, parts[0].b) in built.welds and isinstance(c, Joint) and c.kind == "weld":
            built.welds.remove((parts[0].a, parts[0].b))
        built.carriers.pop(cid, None)
        shapes = built.shapes.pop(cid, ())
        for shape in shapes:
            built.owner.pop(shape, None)
        bodies = list(built.links.pop(cid, ()))
        if isinstance(c, Body):
            bodies.append(built.bodies.pop(cid))
            built.z.pop(cid)
        for body in bodies:
            built.rest_pose.pop(body, None)
        space.remove(*shapes, *bodies)
        if isinstance(c, Rope):
            built.paths.pop(cid, None)
            bit = self._rope_bits.pop(cid)
            for end in _ends(c):  # the bodies it was tied to collide with ropes of its bit again
                for shape in built.shapes.get(end, ()):
                    f = shape.filter
                    shape.filter = pymunk.ShapeFilter(f.group, f.categories, f.mask | bit)

    def _move(self, cid: str, spec: Body) -> None:
        body = self._built.bodies[cid]
        body.position, body.angle = spec.position, spec.angle
        self._space.reindex_shapes_for_body(body)
        self._built.rest_pose[body] = (body.position.x, body.position.y, body.angle)

    def _set_fixed(self, cid: str, fixed: bool) -> None:
        body = self._built.bodies[cid]
        body.body_type = pymunk.Body.STATIC if fixed else pymunk.Body.DYNAMIC
        if not fixed:
            body.velocity, body.angular_velocity = (0.0, 0.0), 0.0
        self._space.reindex_shapes_for_body(body)


def _strip(body: Body) -> float:
    """Half the width of a polyline body's strip (`body_shapes.body_geometry`)."""
    return THIN * sum(math.dist(p, q) for p, q in pairwise(body.outline))


def _same_solid(a: Body, b: Body) -> bool:
    """Whether two versions of a body differ at most in pose and label (so moving it is enough)."""
    return (a.shape, a.outline, a.radius, a.material) == (b.shape, b.outline, b.radius, b.material)


def _ends(c: Component) -> set[str]:
    """The bodies a joint, spring or rope holds on to (not the background)."""
    ends: set[str | None]
    if isinstance(c, Rope):
        ends = {c.start_body, c.end_body}
    elif isinstance(c, Body):
        return set()
    else:
        ends = {c.a, c.b}
    return {e for e in ends if e is not None and e != BACKGROUND}
