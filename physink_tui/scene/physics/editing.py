"""Editing a world: every body frozen but one, and one body dragged by the pen: `Editing`, which `World` owns and
calls for `freeze_all_except`, `unfreeze`, `drag` and `release`; the space's constraints stay the world's to sync.
"""

from __future__ import annotations

from collections.abc import Callable

import pymunk

from physink_tui.scene.components import BACKGROUND, Point
from physink_tui.scene.physics.build import Built
from physink_tui.scene.physics.dragging import Drag, grab_body
from physink_tui.scene.physics.sleeping import tied_groups


class Editing:
    """The frozen bodies (with the velocities `unfreeze` gives back) and the drag under way of one world.

    Args:
        space: the world's space.
        built: the world's pymunk objects by component id.
        body: a body by id (raising `SceneError` for an unknown one).
        dynamic_bodies: the dynamic bodies and rope links now, bottom first.
        sync_constraints: puts in the space exactly the constraints (the drag's among them) with a dynamic end.
        unlink: takes a constraint out of the space for good.
    """

    def __init__(self, space: pymunk.Space, built: Built, body: Callable[[str], pymunk.Body],
                 dynamic_bodies: Callable[[], list[pymunk.Body]], sync_constraints: Callable[[], None],
                 unlink: Callable[[pymunk.Constraint], None]) -> None:
        self._space = space
        self._built = built
        self._body = body
        self._dynamic_bodies = dynamic_bodies
        self._sync_constraints = sync_constraints
        self._unlink = unlink
        self._frozen: dict[pymunk.Body, tuple[tuple[float, float], float]] = {}
        self._drag: Drag | None = None

    @property
    def drag_parts(self) -> tuple[pymunk.Constraint, ...]:
        """The joints of the drag under way (none without one)."""
        return self._drag.parts if self._drag is not None else ()

    def freeze_all_except(self, body_id: str) -> None:
        """`World.freeze_all_except`."""
        self.unfreeze()
        keep = self._weld_group(body_id)
        for rope_id, links in self._built.links.items():
            if {b for part in self._built.constraints[rope_id] for b in (part.a, part.b)} & keep:
                keep.update(links)
        for body in self._dynamic_bodies():
            if body in keep:
                continue
            self._frozen[body] = ((body.velocity.x, body.velocity.y), body.angular_velocity)
            body.body_type = pymunk.Body.STATIC
            self._space.reindex_shapes_for_body(body)
        self._sync_constraints()

    def unfreeze(self) -> None:
        """`World.unfreeze`."""
        for body, (velocity, spin) in self._frozen.items():
            if self._drag is not None and body is self._drag.body:
                continue  # already dynamic, and moving with the pen
            body.body_type = pymunk.Body.DYNAMIC
            body.velocity = velocity
            body.angular_velocity = spin
        self._frozen.clear()
        self._sync_constraints()

    def drag(self, body_id: str, target_point: Point, grab_point: Point | None, *, rotate: bool) -> None:
        """`World.drag`."""
        body = self._body(body_id)
        if self._drag is not None and self._drag.body is not body:
            self.release()
        if self._drag is None:
            fixed = body.body_type != pymunk.Body.DYNAMIC and body not in self._frozen
            if body.body_type != pymunk.Body.DYNAMIC:  # fixed, or frozen (frozen again on release, until `unfreeze`)
                body.body_type = pymunk.Body.DYNAMIC
                body.velocity, body.angular_velocity = (0.0, 0.0), 0.0
            grab = body.position if grab_point is None else grab_point
            self._drag = grab_body(self._space, body_id, body, grab, rotate=rotate, fixed=fixed)
            self._sync_constraints()
        self._drag.control.position = target_point

    def release(self) -> None:
        """`World.release`."""
        drag, self._drag = self._drag, None
        if drag is None:
            return
        for part in drag.parts:
            self._unlink(part)
        self._space.remove(drag.control)
        if drag.fixed or drag.body in self._frozen:
            drag.body.body_type = pymunk.Body.STATIC
            self._space.reindex_shapes_for_body(drag.body)
        self._sync_constraints()

    def _weld_group(self, body_id: str) -> set[pymunk.Body]:
        """``body_id``'s body and every body welded to it, directly or through others (not the background)."""
        start, background = self._body(body_id), self._built.bodies[BACKGROUND]
        bodies = [b for b in self._built.bodies.values() if b is not background]
        return next(set(group) for group in tied_groups(bodies, self._built.welds) if start in group)
