"""Sketch mode (thesis 3.2): finished strokes are recognised and interpreted into the scene, taps select, the
eraser removes, a dwell starts adjusting; a straight stroke that is short, or that crosses a body, waits to see
whether the next makes an X (a weld) or not (alone, a line through a body erases it: thesis 2.1).

The mode keeps the sketch's live world (`LiveWorld`, gravity-free, updated by difference) as the spatial index
of the scene; the session decides when gestures and time reach it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

from physink_tui.input.pen.gestures import Dwell, Gesture, PenDown, StrokeEnded, Tap
from physink_tui.scene.components import Body, Joint, Scene
from physink_tui.scene.interpretation.body_shapes import body_size
from physink_tui.scene.interpretation.interpret import Near, bodies_at, crossed_bodies, interpret
from physink_tui.scene.interpretation.x_pairing import pair_x, x_arm
from physink_tui.scene.physics.live import LiveWorld
from physink_tui.scene.physics.overlaps import clear_overlaps
from physink_tui.scene.physics.state import Pose
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.recognize import recognize_stroke
from physink_tui.session.modes.adjust import AdjustMode
from physink_tui.session.modes.base import Host, Mode, ModeName
from physink_tui.session.outcomes import erased, stroke_outcome
from physink_tui.timeline.events import Timeline

X_CANDIDATE = 0.08
"""A nearly straight stroke (`x_pairing.x_arm`) shorter than this share of the canvas diagonal may be half of an X:
it waits for the next stroke. One that crosses a body may be half of an X up to that body's own size."""
PIN_SIZE = 0.012
"""A circle with a radius under this share of the canvas diagonal looks like a pin."""
VIEW_PIXELS = 1600.0
"""How many pixels across the canvas's longer side is taken to span on screen (the pen's noise is a pixel of it:
1 canvas unit on the thesis's 1600 x 1000 canvas)."""
X_WAIT = 1.5
"""The X window: seconds from the end of a possible half-X to the start of the stroke that may complete it; when
none begins in it, the stroke is taken on its own (an erase, when it is a line through a body). Judged on the
inputs' times, so a replay decides the same."""

Points = list[tuple[float, float]]


@dataclass(frozen=True, slots=True)
class PendingStroke:
    """A possible half-X waiting for the next stroke: when it ended, its points (canvas units), what it is alone,
    how long (canvas units) an arm may be in an X it starts, and its points' times (the journal's, seconds)."""

    t: float
    points: tuple[tuple[float, float], ...]
    recognition: Recognition
    arm_limit: float = math.inf
    times: tuple[float, ...] | None = None


class SketchMode:
    """Strokes, taps, the eraser and dwells while sketching."""

    name = ModeName.SKETCH
    finished = False

    def __init__(self, host: Host) -> None:
        self.host = host
        self.canvas = host.canvas
        self.pending: PendingStroke | None = None
        self.last_created: str | None = None
        self._drawing = False
        self._unsettled: tuple[str, ...] = ()
        self._world: LiveWorld | None = None

    # -- the mode interface ------------------------------------------------------------------------------------

    def gesture(self, g: Gesture) -> Mode | None:
        if isinstance(g, PenDown | StrokeEnded | Tap):
            self._drawing = isinstance(g, PenDown)  # a second stroke begun in time may still finish an X
        if isinstance(g, StrokeEnded):
            self._stroke(g)
        elif isinstance(g, Tap):
            found = bodies_at(self._scene, self._to_canvas(g.x, g.y), near=self.near(self._scene))
            self.host.select(found[0].id if found else None)
        elif isinstance(g, Dwell):
            self.flush(g.t)
            return AdjustMode.start(self.host, self._to_canvas(g.x, g.y), g.t)
        return None

    def advance(self, t: float) -> bool:
        """A possible half-X whose second stroke did not begin in `X_WAIT` is taken on its own."""
        pending = self.pending
        if pending is not None and not self._drawing and t - pending.t > X_WAIT:
            self.flush(pending.t + X_WAIT)
            return True
        return False

    def close(self, t: float) -> None:
        self.flush(t)

    def poses(self) -> Mapping[str, Pose]:
        return {b.id: Pose(*b.position, b.angle) for b in self._scene.bodies()}

    def timeline(self) -> Timeline | None:
        return self.host.document.timeline

    def scene(self) -> Scene:
        return self._scene

    # -- the sketch's world ------------------------------------------------------------------------------------

    @property
    def world(self) -> LiveWorld:
        """The sketch as a physics world without gravity, brought in step with the scene: only what changed since
        the last call is added, moved or removed."""
        self.near(self._scene)
        assert self._world is not None
        return self._world

    def near(self, scene: Scene) -> Near:
        """The live world's spatial index, brought in step with ``scene`` (the current one or one on its way)."""
        if self._world is None:
            self._world = LiveWorld.from_scene(scene)
        else:
            self._world.sync(scene)
        return self._world.bodies_in

    def flush(self, t: float) -> None:
        """Take a waiting half-X on its own, and push what waits to be settled clear of what it overlaps."""
        if self.pending is not None:
            pending, self.pending = self.pending, None
            self._apply(pending.recognition, [list(pending.points)], pending.recognition.kind or "stroke", t)
        self._settle(t)

    # -- strokes ---------------------------------------------------------------------------------------------

    @property
    def _scene(self) -> Scene:
        return self.host.document.scene

    def _to_canvas(self, x: float, y: float) -> tuple[float, float]:
        return (x * self.canvas[0], y * self.canvas[1])

    def _stroke(self, ended: StrokeEnded) -> None:
        stroke, t = ended.stroke, ended.t
        if stroke.dwell_t is not None:
            return  # a drag after a dwell adjusted; it draws nothing
        points = [self._to_canvas(p.x, p.y) for p in stroke.points]
        times = tuple(p.t for p in stroke.points)
        if stroke.eraser:
            self.flush(t)
            self._erase(points, t)
            return
        if self.pending is not None:
            pending, self.pending = self.pending, None
            pair = pair_x(list(pending.points), points, pending.arm_limit, self._pen_noise(), (pending.times, times))
            if pair is not None:
                self._apply(pair, [list(pending.points), points], "X-symbol", t)
                return
            self._apply(pending.recognition, [list(pending.points)], pending.recognition.kind or "stroke", t)
        recognition = recognize_stroke(points, times, noise=self._pen_noise())
        limit = self._x_arm_limit(points)
        if limit > 0.0:  # whatever the recogniser named it: a bowed or hooked half-X is seldom a clean line
            self.pending = PendingStroke(t, tuple(points), recognition, limit, times)
            return
        self._apply(recognition, [points], recognition.kind or "stroke", t)

    def _pen_noise(self) -> float:
        """The pen's jitter in canvas units: a pixel of a view `VIEW_PIXELS` wide showing the whole canvas."""
        return max(self.canvas) / VIEW_PIXELS

    def _x_arm_limit(self, points: Points) -> float:
        """How long an arm of an X this stroke may start can be, or 0 when it cannot start one: a straight stroke
        up to `X_CANDIDATE` of the diagonal, or up to the size of the largest body its straight axis crosses."""
        short = X_CANDIDATE * math.hypot(*self.canvas)
        arm = x_arm(points)
        if arm is None:
            return 0.0
        length = math.dist(arm.start, arm.end)
        if length <= short:
            return short
        crossed = crossed_bodies(self._scene, arm, self.near(self._scene))
        largest = max((body_size(b) for b in crossed), default=0.0)
        return max(short, largest) if length <= largest else 0.0

    def _settle(self, t: float) -> None:
        """Push the bodies still waiting clear of what they overlap (as part of the action that made them)."""
        waiting, self._unsettled = self._unsettled, ()
        waiting = tuple(b for b in waiting if b in self._scene.components)
        if not waiting:
            return
        scene, notes = clear_overlaps(self._scene, waiting, self.near, self.canvas)
        for note in notes:
            self.host.tell(note, t)
        if scene != self._scene:
            self.host.amend(replace(self.host.document, scene=scene))

    def _apply(self, recognition: Recognition, strokes: list[Points], what: str, t: float) -> None:
        before = self._scene
        result = interpret(before, recognition, strokes, self.near(before))
        outcome = stroke_outcome(recognition.kind, result, before)
        if outcome:
            self.host.tell(outcome, t, "outcome")
        if recognition.note:
            self.host.tell(recognition.note, t)
        if result.message:
            self.host.tell(result.message, t)
        if result.scene != before:
            self.host.commit(replace(self.host.document, scene=result.scene), f"{result.action}: {what}")
            if result.created:
                self.last_created = result.created[-1]
        # a body drawn into others waits one stroke: a pin or an X drawn next may join it where it is
        scene = self._scene
        joined = {end for c in (scene.components.get(i) for i in result.created)
                  if isinstance(c, Joint) for end in (c.a, c.b)}
        self._unsettled = tuple(b for b in self._unsettled if b not in joined)
        self._settle(t)
        if result.action == "body":
            self._unsettled = result.created
            small = [c for c in (scene.components.get(i) for i in result.created)
                     if isinstance(c, Body) and c.shape == "circle" and c.radius < PIN_SIZE * math.hypot(*self.canvas)]
            if small:
                self.host.tell(f"the small circle {small[0].id} is outside every body, so it became a body; "
                               "a pin is drawn inside the body it holds", t)

    def _erase(self, points: Points, t: float) -> None:
        """An eraser stroke removes the topmost body it passes over (and what holds on to it)."""
        scene = self._scene
        near = self.near(scene)
        for point in points:
            found = bodies_at(scene, point, near=near)
            if found:
                gone = (found[0].id, *scene.attached_to(found[0].id))
                self.host.commit(replace(self.host.document, scene=scene.remove(*gone)), f"erase: {found[0].id}")
                self.host.tell(erased(scene, gone), t, "outcome")
                return
