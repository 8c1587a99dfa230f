"""Demo mode for the session (thesis 3.3.1): the gravity-free world the pen pushes, stepped to the input
times, and the recorder it feeds; the session decides when, this module how."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from physink_tui.input.gestures import Gesture, PenDown, PenMove, StrokeEnded, Tap
from physink_tui.scene.interpret import bodies_at
from physink_tui.scene.world import World
from physink_tui.timeline.recorder import Recorder

if TYPE_CHECKING:
    from physink_tui.session.session import Session

DEMO_DAMPING = 0.1
"""Share of its velocity a free body keeps after one second in demo mode."""
MAX_DEMO_STEPS = 240
"""At most this many demo steps per input (2 s): a long pause in the input does not run the world for ever."""


@dataclass
class Demo:
    world: World
    recorder: Recorder
    t: float  # input time the world has been stepped to
    start: float  # input time demo mode began
    clock: float = 0.0  # timeline clock (advances only while something moves)
    grabbed: str | None = None

    def __post_init__(self) -> None:
        self.clock = self.start



def start_demo(session: Session) -> None:
    """Demo mode: the world runs without gravity; the pen grabs movable bodies; the recorder listens."""
    movable = frozenset(b.id for b in session.scene.bodies() if not session.scene.is_fixed(b.id))
    if not session.scene.bodies():
        session.tell("demo mode with nothing drawn: draw the machine first")
    world = World.from_scene(session.scene, gravity=(0.0, 0.0))
    world.space.damping = DEMO_DAMPING  # a released body comes to rest (DESIGN.md), as on a table top
    session._demo = Demo(world, Recorder(movable), session.t, session.t)

def end_demo(session: Session) -> None:
    demo, session._demo = session._demo, None
    if demo is not None:
        demo.world.release()
        session.timeline = demo.recorder.finish()

def demo_gesture(session: Session, g: Gesture) -> None:
    demo = session._demo
    if demo is None:
        return
    if isinstance(g, PenDown):
        point = session._to_canvas(g.x, g.y)
        found = [b for b in bodies_at(session.scene, point) if b.id in demo.recorder.movable]
        if not found:
            fixed = bodies_at(session.scene, point)
            if fixed:
                session.tell(f"{session._name(fixed[0].id)} is fixed: it cannot be moved in the demonstration")
            return
        body_id = found[0].id
        demo.grabbed = body_id
        demo.world.drag(body_id, point, point)
    elif isinstance(g, PenMove) and g.touching and demo.grabbed is not None:
        x, y = session._to_canvas(g.x, g.y)
        demo.world.drag(demo.grabbed, (x, y))
    elif isinstance(g, StrokeEnded | Tap) and demo.grabbed is not None:
        demo.world.release()
        demo.grabbed = None

def advance_demo(session: Session, t: float) -> None:
    """Step the demo world up to input time ``t``; timeline time runs while the pen holds a body or bodies
    move, and stands still otherwise."""
    demo = session._demo
    dt = demo.world.dt
    steps = min(int((t - demo.t) / dt), MAX_DEMO_STEPS)
    if demo.grabbed is None and not demo.recorder.moving:
        demo.t = t  # nothing moves: timeline time stands still
        return
    bodies = [b.id for b in session.scene.bodies()]
    for _ in range(max(steps, 0)):
        demo.world.step(1)
        demo.t += dt
        demo.clock += dt
        poses = {}
        for body_id in bodies:
            x, y, angle = demo.world.pose(body_id)
            vx, vy, _ = demo.world.velocity(body_id)
            poses[body_id] = (x, y, angle, vx, vy)
        contacts = [(c.a_id, c.b_id, c.point) for c in demo.world.take_contacts()
                    if c.a_id in poses and c.b_id in poses]
        demo.recorder.observe(round(demo.clock - demo.start, 6), poses, contacts, demo.grabbed)
    if steps >= MAX_DEMO_STEPS:
        demo.t = t

