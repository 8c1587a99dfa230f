"""Demo mode for the session (thesis 3.3): the gravity-free world the pen pushes, stepped to the input times, the
recorder it feeds, and playback (play, pause, stop, seek) with concurrent movement; the session decides when,
this module how.

Timeline time (`Demo.clock`) runs while the pen holds a body, while anything recorded still moves, and while
the recording plays; otherwise it stands still. Grabbing a body at timeline time t re-demonstrates it from t
(the assisted edit) while every other recorded body plays back in step, kinematically: it pushes what it meets and
follows its recording whatever hits it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from physink_tui.input.pen.gestures import Gesture, PenDown, PenMove, StrokeEnded, Tap
from physink_tui.scene.physics.world import World
from physink_tui.timeline.demo_setup import recorder_for
from physink_tui.timeline.recorder import ContactSeen, Observation, Recorder
from physink_tui.timeline.tape import Tape

if TYPE_CHECKING:
    from physink_tui.session.session import Session

DEMO_DAMPING = 0.1
"""Share of its velocity a free body keeps after one second in demo mode."""
MAX_DEMO_STEPS = 240
"""At most this many demo steps per input (2 s) outside playback: a long pause in the input does not run the world
for ever."""


@dataclass
class Demo:
    world: World
    recorder: Recorder
    t: float  # input time the world has been stepped to
    clock: float = 0.0  # timeline time: seconds since the demonstration's start
    grabbed: str | None = None
    playing: bool = False
    tape: Tape | None = None  # what plays back while bodies are demonstrated or the recording plays
    live: set[str] = field(default_factory=set)  # bodies demonstrated since the last seek: never played back
    following: set[str] = field(default_factory=set)  # bodies moving along the tape now

    @property
    def duration(self) -> float:
        return max((ev.t1 for ev in self.recorder.timeline.events), default=0.0)


def start_demo(session: Session) -> None:
    """Demo mode: the world runs without gravity; the pen grabs movable bodies; the recorder listens.

    A timeline already recorded is continued from its start (the world as drawn, timeline time 0).
    """
    if not session.scene.bodies():
        session.tell("demo mode with nothing drawn: draw the machine first")
    world = World.from_scene(session.scene, gravity=(0.0, 0.0))
    world.space.damping = DEMO_DAMPING  # a released body comes to rest (DESIGN.md), as on a table top
    world.limit_speeds()
    recorder = recorder_for(session.scene, session.canvas, world.dt, session.timeline)
    session._demo = Demo(world, recorder, session.t)


def end_demo(session: Session) -> None:
    demo, session._demo = session._demo, None
    if demo is not None:
        demo.world.release()
        timeline = demo.recorder.finish()
        session.timeline = timeline if timeline.events else session.timeline


def demo_gesture(session: Session, g: Gesture) -> None:
    demo = session._demo
    if demo is None:
        return
    if isinstance(g, PenDown):
        point = session._to_canvas(g.x, g.y)
        under = demo.world.bodies_at(point)  # where the bodies are now, not where they were drawn
        found = [b for b in under if b in demo.recorder.movable]
        if not found:
            if under:
                session.tell(f"{session._name(under[0])} is fixed: it cannot be moved in the demonstration")
            return
        grab(session, found[0], point)
    elif isinstance(g, PenMove) and g.touching and demo.grabbed is not None:
        demo.world.drag(demo.grabbed, session._to_canvas(g.x, g.y))
    elif isinstance(g, StrokeEnded | Tap) and demo.grabbed is not None:
        demo.world.release()
        demo.grabbed = None


def grab(session: Session, body_id: str, point: tuple[float, float]) -> None:
    """The pen takes ``body_id`` at timeline time ``clock``: what it did from then on is demonstrated again."""
    demo = session._demo
    recorder = demo.recorder
    group = recorder.group_bodies(body_id)
    later = any(ev.t1 > demo.clock + 1e-9 and set(group) & set(ev.components)
                for ev in recorder.timeline.events if ev.type != "start")
    if later:
        recorder.redemonstrate(body_id, demo.clock)
        if demo.clock < demo.duration:
            session.tell(f"re-demonstrating {session._name(body_id)} from {demo.clock:.2f} s: "
                         "what its old movement caused is deleted")
    demo.playing = False
    demo.live.update(group)
    for body in group:
        demo.world.let_go(body)
        demo.following.discard(body)
    demo.tape = Tape(recorder.snapshot(), exclude=demo.live)
    demo.grabbed = body_id
    demo.world.drag(body_id, point, point)


def seek(session: Session, t: float) -> None:
    """The world shows the recorded state at timeline time ``t``; playback pauses."""
    demo = session._demo
    duration = demo.duration
    if not 0 <= t <= duration + 1e-9:
        session.tell(f"seek {t:g}: the timeline runs from 0 to {duration:.2f} s; stayed at {demo.clock:.2f} s")
        return
    demo.recorder.pause()
    demo.world.release()
    demo.grabbed = None
    demo.playing = False
    demo.live.clear()
    demo.tape = Tape(demo.recorder.timeline)
    demo.clock = t
    _place_all(session, demo.tape, t)


def play(session: Session) -> None:
    """The recording plays from the current timeline time (from the start once it has played to the end)."""
    demo = session._demo
    if demo.duration <= 0:
        session.tell("play: nothing has been demonstrated yet")
        return
    seek(session, 0.0 if demo.clock >= demo.duration - 1e-9 else demo.clock)
    demo.playing = True


def pause(session: Session) -> None:
    session._demo.playing = False


def stop(session: Session) -> None:
    seek(session, 0.0)


def _place_all(session: Session, tape: Tape, t: float) -> None:
    demo = session._demo
    for body in session.scene.bodies():
        if body.id not in demo.recorder.movable:
            continue
        demo.world.let_go(body.id)
        demo.following.discard(body.id)
        if body.id in tape.bodies:
            demo.world.place(body.id, tape.pose(body.id, t), tape.velocity(body.id, t, demo.world.dt))
        else:
            demo.world.place(body.id, (*body.position, body.angle))


def advance_demo(session: Session, t: float) -> None:
    """Step the demo world up to input time ``t`` while timeline time runs (see the module docstring)."""
    demo = session._demo
    world = demo.world
    dt = world.dt
    steps = int((t - demo.t) / dt + 1e-9)
    if not demo.playing:  # playback ends with the recording; a demonstration left running is cut short
        steps = min(steps, MAX_DEMO_STEPS)
    bodies = [b.id for b in session.scene.bodies()]
    for _ in range(max(steps, 0)):
        if demo.grabbed is None and not demo.recorder.moving and not demo.playing:
            break
        clock = round(demo.clock + dt, 9)
        playing = _follow_tape(demo, clock, dt)
        world.step(1)
        demo.t += dt
        demo.clock = clock
        poses = {}
        for body_id in bodies:
            x, y, angle = world.pose(body_id)
            vx, vy, w = world.velocity(body_id)
            poses[body_id] = (x, y, angle, vx, vy, w)
        contacts = [ContactSeen(c.a_id, c.b_id, c.point, c.normal) for c in world.take_contacts()
                    if c.a_id in poses and c.b_id in poses]
        touching = frozenset(p for p in world.touching() if all(c in poses for c in p))
        if demo.live or not demo.playing:
            demo.recorder.observe(Observation(round(clock, 6), poses, contacts, demo.grabbed, touching, playing))
        if demo.playing and clock >= demo.tape.duration:
            demo.playing = False
    if steps >= MAX_DEMO_STEPS or (demo.grabbed is None and not demo.recorder.moving and not demo.playing):
        demo.t = t  # timeline time stands still while nothing moves


def _follow_tape(demo: Demo, clock: float, dt: float) -> frozenset[str]:
    """Bodies with recorded motion at ``clock`` follow it; those whose recording ended move freely again."""
    tape = demo.tape
    if tape is None:
        return frozenset()
    now = set()
    for body in tape.bodies:
        if body in demo.live or body not in demo.recorder.movable:
            continue
        if tape.covers(body, clock):
            demo.world.follow(body, tape.pose(body, clock - dt), tape.velocity(body, clock - dt, dt))
            now.add(body)
        elif body in demo.following:  # its recording ends here: it stays where it was left
            demo.world.let_go(body)
            demo.world.place(body, tape.pose(body, clock))
    demo.following = now
    return frozenset(now)
