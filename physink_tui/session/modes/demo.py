"""Demo mode (thesis 3.3): the gravity-free world the pen pushes, stepped on the fixed dt to the input's time, the
recorder it feeds, and playback (play, pause, stop, seek) with concurrent movement.

Timeline time (`DemoMode.clock`) runs while the pen holds a body, while anything recorded still moves, and while
the recording plays; otherwise it stands still. Grabbing a body at timeline time t re-demonstrates it from t
(the assisted edit) while every other recorded body plays back in step, kinematically: it pushes what it meets and
follows its recording whatever hits it. What has been demonstrated since the last commit is a take: it becomes one
undoable action of the document when the mode closes (mode change, undo, redo, clear, the end) or playback moves
timeline time (seek, play, stop).
"""

from __future__ import annotations

from collections.abc import Mapping

from physink_tui.input.pen.gestures import Gesture, PenDown, PenMove, StrokeEnded, Tap
from physink_tui.scene.components import Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.scene.physics.stepping import demo_world, step_and_observe, steps_until
from physink_tui.session.history import Document
from physink_tui.session.modes.base import Host, Mode, ModeName
from physink_tui.timeline.demo_setup import recorder_for
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.observation import Observation
from physink_tui.timeline.phrase_events import label_event
from physink_tui.timeline.phrases import PhraseError, Vocabulary, parse_phrase
from physink_tui.timeline.tape import Tape

TIME_EPSILON = 1e-6
"""Timeline times are kept to the microsecond: a recorded time within this of the clock is now, not later."""


class DemoMode:
    """A demonstration of the document's scene, continuing its timeline (see the module docstring)."""

    name = ModeName.DEMO
    finished = False

    def __init__(self, host: Host, t: float) -> None:
        self.host = host
        document = host.document
        self.document = document  # what this demonstration started from
        self._scene = document.scene
        self.world = demo_world(self._scene)
        self.recorder = recorder_for(self._scene, host.canvas, self.world.dt, document.timeline)
        self.bodies = tuple(b.id for b in self._scene.bodies())
        self.origin = t  # input time of step 0 of the current run of timeline time
        self.steps = 0
        self.clock = 0.0  # timeline time: seconds since the demonstration's start
        self.grabbed: str | None = None
        self.playing = False
        self.tape: Tape | None = None  # what plays back while bodies are demonstrated or the recording plays
        self.live: set[str] = set()  # bodies demonstrated since the last seek: never played back
        self.following: set[str] = set()  # bodies moving along the tape now
        self._committed = document.timeline
        if not self._scene.bodies():
            host.tell("demo mode with nothing drawn: draw the machine first", t)

    # -- the mode interface ------------------------------------------------------------------------------------

    @property
    def duration(self) -> float:
        """The timeline's length, movements being recorded included (always from an up-to-date snapshot, so it
        never depends on whether a view looked in between)."""
        return max((ev.t1 for ev in self.recorder.snapshot().events), default=0.0)

    def gesture(self, g: Gesture) -> Mode | None:
        world = self.world
        if isinstance(g, PenDown):
            point = self._to_canvas(g.x, g.y)
            under = world.bodies_at(point)  # where the bodies are now, not where they were drawn
            found = [b for b in under if b in self.recorder.movable]
            if found:
                self._grab(found[0], point, g.t)
            elif under:
                self.host.tell(f"{self._scene.called(under[0])} is fixed: it cannot be moved in the demonstration",
                               g.t)
        elif isinstance(g, PenMove) and g.touching and self.grabbed is not None:
            world.drag(self.grabbed, self._to_canvas(g.x, g.y))
        elif isinstance(g, StrokeEnded | Tap) and self.grabbed is not None:
            world.release()
            self.grabbed = None
        return None

    def advance(self, t: float) -> bool:
        """Step the world up to input time ``t`` while timeline time runs; when nothing runs, timeline time stands
        still and the next run starts from ``t``. Steps are counted from the run's start, so advancing in many
        small pieces or one large one takes exactly the same steps."""
        dt = self.world.dt
        target = steps_until(t, self.origin, dt)
        stepped = False
        while self.steps < target and self._running():
            self._step(dt)
            self.steps += 1
            stepped = True
        if not self._running():
            self.origin, self.steps = t, 0
        return stepped

    def close(self, t: float) -> None:
        """The take so far becomes part of the document (one undoable action)."""
        self.world.release()
        self.grabbed = None
        self.playing = False
        self.recorder.pause()
        self._commit()

    def poses(self) -> Mapping[str, Pose]:
        return {b: self.world.pose(b) for b in self.bodies}

    @property
    def has_take(self) -> bool:
        """Whether anything was recorded since the last commit (undo would take it back)."""
        return bool(self.recorder.timeline.events) and self.recorder.timeline is not self._committed

    def timeline(self) -> Timeline | None:
        snapshot = self.recorder.snapshot()
        return snapshot if snapshot.events else self.document.timeline

    def scene(self) -> Scene:
        return self._scene

    # -- playback -------------------------------------------------------------------------------------------

    def seek(self, t: float, now: float) -> None:
        """The world shows the recorded state at timeline time ``t``; playback pauses."""
        duration = self.duration
        if not 0 <= t <= duration + TIME_EPSILON:
            self.host.tell(f"seek {t:g}: the timeline runs from 0 to {duration:.2f} s; stayed at {self.clock:.2f} s",
                           now)
            return
        self.recorder.pause()
        self._commit()
        self.world.release()
        self.grabbed = None
        self.playing = False
        self.live.clear()
        self.tape = Tape(self.recorder.timeline)
        self.clock = t
        self._place_all(self.tape, t)

    def play(self, now: float) -> None:
        """The recording plays from the current timeline time (from the start once it has played to the end)."""
        if self.duration <= 0:
            self.host.tell("play: nothing has been demonstrated yet", now)
            return
        self.seek(0.0 if self.clock >= self.duration - TIME_EPSILON else self.clock, now)
        self.playing = True

    def pause(self, now: float) -> None:
        self.playing = False

    def stop(self, now: float) -> None:
        self.seek(0.0, now)

    def narrate(self, text: str, vocabulary: Vocabulary, now: float) -> None:
        """A phrase (``the egg lands in the frying pan``) labels the nearest event involving what it names."""
        try:
            phrase = parse_phrase(text, self.host.document.scene.labels(), vocabulary)
            timeline, event_id = label_event(self.recorder.snapshot(), phrase, self.clock)
        except PhraseError as exc:
            self.host.tell(str(exc), now)
            return
        self.recorder.relabel(timeline)
        self.host.tell(f"{event_id} is now narrated {phrase.text!r}", now)

    # -- internals ------------------------------------------------------------------------------------------

    def _to_canvas(self, x: float, y: float) -> tuple[float, float]:
        return (x * self.host.canvas[0], y * self.host.canvas[1])

    def _running(self) -> bool:
        return self.grabbed is not None or self.recorder.moving or self.playing

    def _commit(self) -> None:
        """What was recorded since the last commit becomes one undoable action (the document keeps the scene it
        has now: labels given during the demonstration stay)."""
        timeline = self.recorder.snapshot()
        if not timeline.events or timeline is self._committed:
            return
        self._committed = timeline
        self.host.commit(Document(self.host.document.scene, timeline), "demonstrate")

    def _grab(self, body_id: str, point: tuple[float, float], t: float) -> None:
        """The pen takes ``body_id`` at timeline time `clock`: what it did from then on is demonstrated again."""
        recorder = self.recorder
        group = recorder.group_bodies(body_id)
        later = any(ev.t1 > self.clock + TIME_EPSILON and set(group) & set(ev.components)
                    for ev in recorder.snapshot().events if ev.type != "start")
        if later:
            recorder.redemonstrate(body_id, self.clock)
            if self.clock < self.duration:
                self.host.tell(f"re-demonstrating {self._scene.called(body_id)} from {self.clock:.2f} s: "
                               "what its old movement caused is deleted", t)
        self.playing = False
        self.live.update(group)
        for body in group:
            self.world.let_go(body)
            self.following.discard(body)
        self.tape = Tape(recorder.snapshot(), exclude=self.live)
        self.grabbed = body_id
        self.world.drag(body_id, point, point)

    def _step(self, dt: float) -> None:
        clock = round(self.clock + dt, 9)
        playing = self._follow_tape(clock, dt)
        frame = step_and_observe(self.world, self.bodies)
        self.clock = clock
        if self.live or not self.playing:
            self.recorder.observe(Observation(round(clock, 6), frame.motions, frame.contacts, self.grabbed,
                                              frame.touching, playing))
        if self.playing and self.tape is not None and clock >= self.tape.duration:
            self.playing = False

    def _place_all(self, tape: Tape, t: float) -> None:
        for body in self._scene.bodies():
            if body.id not in self.recorder.movable:
                continue
            self.world.let_go(body.id)
            self.following.discard(body.id)
            if body.id in tape.bodies:
                self.world.place(body.id, tape.pose(body.id, t), tape.velocity(body.id, t, self.world.dt))
            else:
                self.world.place(body.id, Pose(*body.position, body.angle))

    def _follow_tape(self, clock: float, dt: float) -> frozenset[str]:
        """Bodies with recorded motion at ``clock`` follow it; those whose recording ended move freely again."""
        tape = self.tape
        if tape is None:
            return frozenset()
        now = set()
        for body in tape.bodies:
            if body in self.live or body not in self.recorder.movable:
                continue
            if tape.covers(body, clock):
                self.world.follow(body, tape.pose(body, clock - dt), tape.velocity(body, clock - dt, dt))
                now.add(body)
            elif body in self.following:  # its recording ends here: it stays where it was left
                self.world.let_go(body)
                self.world.place(body, tape.pose(body, clock))
        self.following = now
        return frozenset(now)
