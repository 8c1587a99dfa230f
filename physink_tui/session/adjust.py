"""Adjusting structure for the session (thesis 3.2.4): dwell on a body, drag it with the others frozen,
put it down flush; the session decides when, this module how."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from physink_tui.input.pen.gestures import Dwell, PenMove
from physink_tui.scene.interpretation.body_shapes import body_size
from physink_tui.scene.interpretation.interpret import bodies_at
from physink_tui.scene.physics.world import World

if TYPE_CHECKING:
    from physink_tui.session.session import Session

ADJUST_CENTRE = 0.25
"""A body grabbed within this share of its size from its centre moves without turning."""
MAX_ADJUST_STEPS = 60
"""At most this many physics steps per pen sample (a pause in the input does not freeze the session)."""
CATCH_UP_STEPS = 60
SETTLE_STEPS = 30


@dataclass
class Adjust:
    body_id: str
    world: World
    t: float
    offset: tuple[float, float]



def start_adjust(session: Session, dwell: Dwell) -> None:
    """Dwelling on a body grabs it: the world runs without gravity, every other body frozen."""
    session._flush_pending()
    point = session._to_canvas(dwell.x, dwell.y)
    found = bodies_at(session.scene, point)
    if not found:
        return
    body = found[0]
    world = World.from_scene(session.scene, gravity=(0.0, 0.0))
    world.freeze_all_except(body.id)
    # grabbed near its centre the body slides; grabbed near an edge it turns about the pen as well
    near_centre = math.dist(point, body.position) < ADJUST_CENTRE * body_size(body)
    if near_centre:  # hold the centre, which keeps its offset from the pen
        offset = (point[0] - body.position[0], point[1] - body.position[1])
        world.drag(body.id, body.position, body.position, rotate=False)
    else:
        offset = (0.0, 0.0)
        world.drag(body.id, point, point, rotate=True)
    session._adjust = Adjust(body.id, world, dwell.t, offset)
    session.tell(f"moving {session._name(body.id)}")

def move_adjust(session: Session, move: PenMove) -> None:
    adjust = session._adjust
    x, y = session._to_canvas(move.x, move.y)
    adjust.world.drag(adjust.body_id, (x - adjust.offset[0], y - adjust.offset[1]))
    advance_adjust(session, move.t)

def advance_adjust(session: Session, t: float) -> None:
    adjust = session._adjust
    steps = min(int((t - adjust.t) / adjust.world.dt), MAX_ADJUST_STEPS)
    if steps > 0:
        adjust.world.step(steps)
        adjust.t += steps * adjust.world.dt

def end_adjust(session: Session, t: float) -> None:
    adjust, session._adjust = session._adjust, None
    if adjust is None:
        return
    world = adjust.world
    world.step(CATCH_UP_STEPS)  # the body catches up with where the pen lifted (unless something blocks it)
    world.release()
    world.set_velocity(adjust.body_id, (0.0, 0.0), 0.0)  # put down where the pen left it, not thrown
    world.step(SETTLE_STEPS)  # overlaps resolve; bodies end flush (thesis figure 2-6)
    moved = world.to_scene(session.scene)
    if moved != session.scene:
        session.history.push(moved, f"adjust {adjust.body_id}")

