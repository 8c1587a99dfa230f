"""Speed limits for the bodies of a physics world, so that nothing tunnels through a thin body when it is pushed
at absurd speed (demo mode); which world gets them is the world's business."""

from __future__ import annotations

from collections.abc import Callable

import pymunk

SPEED_LIMIT = 0.5
"""Share of its own half-size a body may travel in one step (see `limit_speed`)."""
MIN_SPEED_LIMIT = 1200.0
"""Canvas units per second any body may reach whatever its size (thin bars would otherwise barely move)."""

VelocityFunc = Callable[[pymunk.Body, tuple[float, float], float, float], None]


def _capped(limit: float) -> VelocityFunc:
    def velocity_func(body: pymunk.Body, gravity: tuple[float, float], damping: float, dt: float) -> None:
        pymunk.Body.update_velocity(body, gravity, damping, dt)
        speed = body.velocity.length
        if speed > limit:
            body.velocity = body.velocity * (limit / speed)
    return velocity_func


def limit_speed(body: pymunk.Body, dt: float, share: float = SPEED_LIMIT) -> None:
    """Caps ``body``'s speed at ``share`` of its half-size (its narrowest shape's) per step of ``dt``, and at
    least `MIN_SPEED_LIMIT`: a body at most half its size deeper into another after a step is pushed back out
    on the side it came from."""
    half = min((min(s.bb.right - s.bb.left, s.bb.top - s.bb.bottom) / 2 for s in body.shapes), default=0.0)
    body.velocity_func = _capped(max(share * half / dt, MIN_SPEED_LIMIT))
