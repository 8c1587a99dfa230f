"""The session: consumes journal entries in time order, keeps the scene, mode, selection and undo
history, and journals what it consumed; the TUI, kiosk, CLI and tests all drive it the same way.

Time is the entries' ``t``, never a clock. Pen input goes through the input side (decoder, mapping,
gesture engine); each finished stroke is recognised and interpreted into the scene (sketch mode), and
the live physics world (`world`) follows the scene. A short, nearly straight stroke is held back until the next
stroke shows whether the two make an X. In demo mode the pen demonstrates behaviour (`demo`), playback commands
move timeline time, and phrases label its events; simulation arrives with a later issue (its command is accepted
and reported).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field, replace

import shapely

from physink_tui.errors import JournalError
from physink_tui.formats.journal.entries import (
    CommandEntry,
    DeviceEntry,
    HidEntry,
    JournalEntry,
    JournalHeader,
    PenEntry,
    SayEntry,
)
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.input.journal_replay import PEN_DEVICE, add_journal_device, pen_input_for
from physink_tui.input.pen.gestures import Dwell, Gesture, PenDown, PenMove, StrokeEnded, Tap
from physink_tui.input.pen.pen_input import PenInput
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.sources import RawReport
from physink_tui.scene.components import Body, Joint, Rope, Scene, Spring
from physink_tui.scene.interpretation.body_shapes import body_geometry
from physink_tui.scene.interpretation.interpret import Near, bodies_at, interpret
from physink_tui.scene.interpretation.x_pairing import pair_x, x_arm
from physink_tui.scene.physics.live import LiveWorld
from physink_tui.scene.physics.overlaps import overlapped, push_clear
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.recognize import recognize_stroke
from physink_tui.session import adjust, demo
from physink_tui.session.history import History
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.phrases import (
    DEFAULT_VOCABULARY,
    PhraseError,
    Vocabulary,
    label_event,
    parse_phrase,
    parse_vocabulary,
)

X_CANDIDATE = 0.08
"""A nearly straight stroke (`x_pairing.x_arm`) shorter than this share of the canvas diagonal may be half of an X:
it waits for the next stroke."""
PIN_SIZE = 0.012
"""A circle with a radius under this share of the canvas diagonal looks like a pin."""
VIEW_PIXELS = 1600.0
"""How many pixels across the canvas's longer side is taken to span on screen (the pen's noise is a pixel of it:
1 canvas unit on the thesis's 1600 x 1000 canvas)."""
X_WAIT = 1.5
"""Seconds a possible half-X waits for its second stroke to begin before it is taken on its own."""


@dataclass(frozen=True, slots=True)
class Message:
    """Something the user should be told, at input time ``t``."""

    t: float
    text: str


@dataclass
class _Pending:
    t: float
    points: list[tuple[float, float]]
    recognition: Recognition


@dataclass
class Session:
    """One session's state. Build with `Session.from_header`; feed with `handle`; end with `finish`.

    Attributes:
        canvas: (width, height) in canvas units; pen positions are fractions of it.
        history: the scene and its undo/redo stacks.
        mode: ``sketch`` or ``demo``.
        selected: the component the last tap chose, or None.
        last_created: the component the last stroke made, or None (``label last``).
        messages: what the user has been told, in order.
    """

    canvas: tuple[float, float]
    pen: PenInput
    history: History = field(default_factory=lambda: History(Scene()))
    mode: str = "sketch"
    selected: str | None = None
    last_created: str | None = None
    messages: list[Message] = field(default_factory=list)
    t: float = 0.0
    _pending: _Pending | None = None
    _drawing: bool = False
    _adjust: adjust.Adjust | None = None
    _unsettled: tuple[str, ...] = ()
    journal: JournalWriter | None = None
    timeline: Timeline | None = None
    vocabulary: Vocabulary = DEFAULT_VOCABULARY
    _demo: demo.Demo | None = None
    _world: LiveWorld | None = None

    @classmethod
    def from_header(cls, header: JournalHeader) -> Session:
        """A session for the journal with this header (its canvas, input mapping and vocabulary).

        Raises:
            PhraseError: the header's vocabulary has a bad line (named).
        """
        session = cls((header.canvas_width, header.canvas_height), pen_input_for(header))
        if header.vocabulary:
            words = parse_vocabulary(header.vocabulary, "journal header vocabulary")
            session.vocabulary = DEFAULT_VOCABULARY.extended(words)
        return session

    @property
    def scene(self) -> Scene:
        return self.history.current

    @property
    def world(self) -> LiveWorld:
        """The sketch as a physics world without gravity, brought in step with the scene (what a view shows): only
        what changed since the last call is added, moved or removed."""
        if self._world is None:
            self._world = LiveWorld.from_scene(self.scene)
        else:
            self._world.sync(self.scene)
        return self._world

    def _near(self, scene: Scene) -> Near:
        """The live world's spatial index, brought in step with ``scene`` (the current one or one on its way)."""
        if self._world is None:
            self._world = LiveWorld.from_scene(scene)
        else:
            self._world.sync(scene)
        return self._world.bodies_in

    # -- input ---------------------------------------------------------------------------------

    def handle(self, entry: JournalEntry) -> None:
        """Consume one input; entries must come in time order (the journal guarantees it)."""
        self.t = entry.t
        if self.journal is not None:
            try:
                self.journal.append(entry)  # journalled first: what the session consumed is what a replay feeds it
                self.journal.flush()
            except JournalError as exc:  # a full disk stops the journal, never the session
                self.journal = None
                self.messages.append(Message(entry.t, str(exc)))
        if self._demo is not None:
            demo.advance_demo(self, entry.t)
        if self._pending is not None and not self._drawing and entry.t - self._pending.t > X_WAIT:
            self._flush_pending()
        if isinstance(entry, HidEntry):
            self._gestures(self.pen.handle(RawReport(entry.t, entry.data, entry.dev)))
        elif isinstance(entry, PenEntry):
            sample = PenSample(entry.t, entry.x, entry.y, entry.p, entry.tip, entry.range, entry.eraser,
                               entry.b1, entry.b2, None, None, 0)
            self._gestures(self.pen.feed_canvas_sample(PEN_DEVICE, sample))
        elif isinstance(entry, CommandEntry):
            self._command(entry)
        elif isinstance(entry, SayEntry):
            self._say(entry)
        elif isinstance(entry, DeviceEntry):  # a tablet plugged in during the session
            for device in entry.devices:
                add_journal_device(self.pen, device, f"journal at t={entry.t:g}")

    def run(self, entries: Iterable[JournalEntry]) -> Session:
        for entry in entries:
            self.handle(entry)
        self.finish()
        return self

    def finish(self) -> None:
        """The input ended: settle a held-back half-X, end a demonstration, close the journal if one is kept."""
        self._flush_pending()
        if self._demo is not None:
            demo.end_demo(self)
        if self.journal is not None:
            self.journal.close()

    def tell(self, text: str) -> None:
        self.messages.append(Message(self.t, text))

    # -- pen -------------------------------------------------------------------------------------

    def _gestures(self, gestures: list[Gesture]) -> None:
        if self.mode == "demo":
            for g in gestures:
                demo.demo_gesture(self, g)
            return
        for g in gestures:
            if isinstance(g, PenDown | StrokeEnded | Tap):
                self._drawing = isinstance(g, PenDown)  # a second stroke begun in time may still finish an X
            if isinstance(g, StrokeEnded):
                self._stroke(g)
            elif isinstance(g, Tap):
                self._tap(g)
            elif isinstance(g, Dwell) and self.mode == "sketch":
                adjust.start_adjust(self, g)
            elif isinstance(g, PenMove) and g.touching and self._adjust is not None:
                adjust.move_adjust(self, g)

    def _to_canvas(self, x: float, y: float) -> tuple[float, float]:
        return (x * self.canvas[0], y * self.canvas[1])

    def _tap(self, tap: Tap) -> None:
        found = bodies_at(self.scene, self._to_canvas(tap.x, tap.y), near=self._near(self.scene))
        self.selected = found[0].id if found else None
        if self.selected:
            self.tell(f"selected {self._name(self.selected)}")

    def _stroke(self, ended: StrokeEnded) -> None:
        if self.mode != "sketch":
            return
        stroke = ended.stroke
        if stroke.dwell_t is not None:
            adjust.end_adjust(self, ended.t)  # a drag after a dwell adjusts; it draws nothing
            return
        points = [self._to_canvas(p.x, p.y) for p in stroke.points]
        if stroke.eraser:
            self._flush_pending()
            self._eraser(points)
            return
        if self._pending is not None:
            pending, self._pending = self._pending, None
            pair = pair_x(pending.points, points, self._x_arm_limit(), self._pen_noise())
            if pair is not None:
                self._apply(pair, [pending.points, points], "X-symbol")
                return
            self._apply(pending.recognition, [pending.points], pending.recognition.kind or "stroke")
        recognition = recognize_stroke(points, noise=self._pen_noise())
        if x_arm(points, self._x_arm_limit()) is not None:  # whatever the recogniser named it: a bowed or hooked
            self._pending = _Pending(ended.t, points, recognition)  # half-X is seldom a clean line
            return
        self._apply(recognition, [points], recognition.kind or "stroke")

    def _pen_noise(self) -> float:
        """The pen's jitter in canvas units: a pixel of a view `VIEW_PIXELS` wide showing the whole canvas."""
        return max(self.canvas) / VIEW_PIXELS

    def _settle(self) -> None:
        """Push the bodies still waiting clear of what they overlap (as part of the action that made them)."""
        waiting, self._unsettled = self._unsettled, ()
        waiting = tuple(b for b in waiting if b in self.scene.components)
        if waiting:
            self.history.amend(self._clear_overlaps(self.scene, waiting))

    def _clear_overlaps(self, scene: Scene, created: tuple[str, ...]) -> Scene:
        """A new body drawn into others (not joined to it) is pushed clear by the physics, the others held still."""
        for body_id in created:
            if scene.is_fixed(body_id):
                continue
            hit = overlapped(scene, body_id, self._near(scene))
            if not hit:
                continue
            pushed = push_clear(scene, body_id, hit)
            names = ", ".join(self._name(h, scene) for h in hit)
            if not body_geometry(pushed.components[body_id]).intersects(shapely.box(0, 0, *self.canvas)):
                self.tell(f"{self._name(body_id, scene)} overlaps {names}; pushing it clear would put it off the "
                          f"canvas, so it stays where it was drawn")
                continue
            scene = pushed
            self.tell(f"{self._name(body_id, scene)} overlapped {names}; the physics pushed it clear")
        return scene

    def _x_arm_limit(self) -> float:
        return X_CANDIDATE * math.hypot(*self.canvas)

    def _flush_pending(self) -> None:
        if self._pending is not None:
            pending, self._pending = self._pending, None
            self._apply(pending.recognition, [pending.points], pending.recognition.kind or "stroke")
        self._settle()

    def _apply(self, recognition: Recognition, strokes: list[list[tuple[float, float]]], what: str) -> None:
        result = interpret(self.scene, recognition, strokes, self._near(self.scene))
        if result.message:
            self.tell(result.message)
        if result.scene != self.scene:
            self.history.push(result.scene, f"{result.action}: {what}")
            if result.created:
                self.last_created = result.created[-1]
            if self.selected in result.removed:
                self.selected = None
        # a body drawn into others waits one stroke: a pin or an X drawn next may join it where it is
        joined = {end for c in (self.scene.components.get(i) for i in result.created)
                  if isinstance(c, Joint) for end in (c.a, c.b)}
        self._unsettled = tuple(b for b in self._unsettled if b not in joined)
        self._settle()
        if result.action == "body":
            self._unsettled = result.created
            small = [c for c in (self.scene.components.get(i) for i in result.created)
                     if isinstance(c, Body) and c.shape == "circle" and c.radius < PIN_SIZE * math.hypot(*self.canvas)]
            if small:
                self.tell(f"the small circle {small[0].id} is outside every body, so it became a body; "
                          "a pin is drawn inside the body it holds")

    def _eraser(self, points: list[tuple[float, float]]) -> None:
        """An eraser stroke removes the topmost body it passes over (and what holds on to it)."""
        near = self._near(self.scene)
        for point in points:
            found = bodies_at(self.scene, point, near=near)
            if found:
                gone = (found[0].id, *self.scene.attached_to(found[0].id))
                self.history.push(self.scene.remove(*gone), f"erase: {found[0].id}")
                return

    # -- commands and speech ---------------------------------------------------------------------

    def _command(self, entry: CommandEntry) -> None:
        name, args = entry.name, entry.args
        if name != "label":
            self._flush_pending()
        if name == "mode":
            mode = str(args[0])
            if mode == "demo" and self.mode != "demo":
                demo.start_demo(self)
            elif mode == "sketch" and self.mode == "demo":
                demo.end_demo(self)
            self.mode = mode
        elif name == "undo":
            if self.history.undo() is None:
                self.tell("nothing to undo")
        elif name == "redo":
            if self.history.redo() is None:
                self.tell("nothing to redo")
        elif name == "clear":
            if self.scene.components:
                self.history.push(replace(Scene(), next_id=self.scene.next_id), "clear")
            self.selected = self.last_created = None
        elif name == "label":
            self._label(str(args[0]), str(args[1]))
        elif name in ("play", "pause", "stop", "seek"):
            self._playback(name, args)
        else:
            self.tell(f"{name}: not available yet (simulation and saving come with later issues)")

    def _playback(self, name: str, args: tuple) -> None:
        if self._demo is None:
            self.tell(f"{name}: playback works in demo mode (mode demo)")
        elif name == "seek":
            demo.seek(self, float(args[0]))
        else:
            {"play": demo.play, "pause": demo.pause, "stop": demo.stop}[name](self)

    def _say(self, entry: SayEntry) -> None:
        words = entry.text.strip().split()
        if len(words) >= 2 and words[0].lower() == "label":
            self._label("selected" if self.selected else "last", " ".join(words[1:]))
        elif entry.text.strip() and self.mode == "demo" and self._demo is not None:
            self._narrate(entry.text)
        elif entry.text.strip():
            self.tell(f"heard {entry.text!r}; only 'label <name>' is understood while sketching")

    def _narrate(self, text: str) -> None:
        """A phrase (``the egg lands in the frying pan``) labels the nearest event involving what it names."""
        names = self.scene.labels()
        recorder = self._demo.recorder
        try:
            phrase = parse_phrase(text, names, self.vocabulary)
            timeline, event_id = label_event(recorder.snapshot(), phrase, self._demo.clock)
        except PhraseError as exc:
            self.tell(str(exc))
            return
        recorder.timeline = timeline
        self.tell(f"{event_id} is now narrated {phrase.text!r}")

    def _label(self, target: str, text: str) -> None:
        component_id = {"last": self.last_created, "selected": self.selected}.get(target, target)
        if component_id is None:
            self.tell(f"label {text!r}: nothing is {target} — tap a body first, or draw one")
            return
        component = self.scene.components.get(component_id)
        if component is None:
            known = ", ".join(self.scene.components) or "none"
            self.tell(f"label {text!r}: there is no component {component_id!r} (components: {known})")
            return
        if not isinstance(component, Body | Rope | Spring):
            self.tell(f"label {text!r}: joints take no labels")
            return
        self.history.push(self.scene.update(replace(component, label=text)), f"label {component_id} {text}")

    def _name(self, component_id: str, scene: Scene | None = None) -> str:
        c = (scene or self.scene).components.get(component_id)
        label = getattr(c, "label", None)
        return f"{label} ({component_id})" if label else component_id

