"""The pen's grip on a body being dragged: a kinematic control body at the pen and a pivot of limited force (pymunk's
mouse-joint recipe), optionally a gear holding the angle; `World.drag` moves the control and releases it.
"""

from __future__ import annotations

from dataclasses import dataclass

import pymunk

from physink_tui.scene.components import Point

DRAG_ACCELERATION = 20_000.0
"""The strongest pull of a drag, per unit of the dragged body's mass (canvas units/s², ~22 g)."""
DRAG_ANGULAR_ACCELERATION = 200.0
"""The strongest twist (rad/s², times the moment of inertia) with which a ``rotate=False`` drag holds the angle."""
DRAG_ERROR_BIAS = (1 - 0.15) ** 60
"""Fraction of the pen-to-grab-point distance left uncorrected after one second (pymunk's mouse-joint example)."""


@dataclass(slots=True)
class Drag:
    """A drag in progress: the body, the control body at the pen and the joints between them."""

    body_id: str
    body: pymunk.Body
    control: pymunk.Body
    parts: tuple[pymunk.Constraint, ...]
    fixed: bool  # static before the drag without being frozen: static again on release



def grab_body(space: pymunk.Space, body_id: str, body: pymunk.Body, grab: Point, *, rotate: bool,
              fixed: bool) -> Drag:
    """Grabs ``body`` at ``grab`` (canvas units): adds the control body to ``space`` and returns the drag, whose
    joints the world adds with its other constraints. With ``rotate=False`` a gear of limited torque keeps the
    body's angle."""
    control = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    control.position = grab
    pin = pymunk.PivotJoint(control, body, (0, 0), body.world_to_local(grab))
    pin.max_force = DRAG_ACCELERATION * body.mass
    pin.error_bias = DRAG_ERROR_BIAS
    parts: list[pymunk.Constraint] = [pin]
    if not rotate:
        hold = pymunk.GearJoint(control, body, body.angle, 1.0)
        hold.max_force = DRAG_ANGULAR_ACCELERATION * body.moment
        hold.error_bias = DRAG_ERROR_BIAS
        parts.append(hold)
    space.add(control)
    return Drag(body_id, body, control, tuple(parts), fixed)
