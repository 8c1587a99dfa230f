"""The session: the one state machine every driver (TUI, kiosk, `physink replay`, tests) feeds; single-threaded,
no clock of its own.

`handle(entry)` takes every input (journal entries), `advance(t)` the passage of time, `view()` gives an immutable
snapshot for views, `finish(t)` ends it. Time is always the input's: the session first advances to an entry's
``t``, so many small advances and one large one end the same, step for step. Pen input goes through the input side
(decoder, mapping, gesture engine) to the current mode (`modes`: sketch, adjust, demo), which owns its world;
the document (scene and timeline) changes only through the history, so undo, redo and clear mean the same in every
mode. ``simulate`` runs SIMULATE here (`simulation`), unless a driver already ran it for this document
(`simulation.Searched`); its result shows until the document changes. Nothing an
input can do raises out of `handle`: what cannot be done is told. With a journal attached, every entry is
journaled once handled (a command that makes no sense in the mode included: a replay tells the same), and the end
of the session too; an entry the journal cannot hold is refused before it acts, and not journaled.
"""

from __future__ import annotations

import traceback
from collections.abc import Iterable

from physink_tui.errors import JournalError, PhysinkError
from physink_tui.formats.journal.codec import encode_entry
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
from physink_tui.formats.project.codec import vocabulary_lines
from physink_tui.input.journal_replay import PEN_DEVICE, add_journal_device, pen_input_for
from physink_tui.input.pen.gestures import Gesture
from physink_tui.input.pen.pen_input import PenInput
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.sources import RawReport, SourceEnded
from physink_tui.scene.components import Scene
from physink_tui.scene.physics.live import LiveWorld
from physink_tui.session import labelling, simulation
from physink_tui.session.command_handling import Commands
from physink_tui.session.history import Document, History
from physink_tui.session.modes.base import Mode, ModeName
from physink_tui.session.modes.demo import DemoMode
from physink_tui.session.modes.sketch import SketchMode
from physink_tui.session.simulation import SearchResult, SessionInput
from physink_tui.session.speech_target import PenWatch
from physink_tui.session.view import Message, SessionView, snapshot
from physink_tui.sim.defaults import DEFAULT_BUDGET
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.phrases import DEFAULT_VOCABULARY, Vocabulary, parse_vocabulary


class Session:
    """One session's state (see the module docstring). Build with `from_header`; feed with `handle` and
    `advance`; look with `view`; end with `finish`.

    Attributes:
        canvas: (width, height) in canvas units; pen positions are fractions of it.
        pen: the input side (decoders, mapping, gesture engines).
        history: the document (scene and timeline) and its undo/redo stacks.
        selected: the component the last tap chose, or None.
        messages: what the user has been told, in order.
        errors: internal errors met while handling inputs (a bug each; the session carried on).
        journal: where handled entries are journaled, or None.
        t: the input time reached.
    """

    raise_internal_errors = False
    """Tests set this: an internal error is raised (after journaling) instead of only reported."""
    simulation_budget = DEFAULT_BUDGET
    """The budget of a ``simulate`` given none (journaled with it, so replays never read it; tests lower it)."""

    def __init__(self, canvas: tuple[float, float], pen: PenInput, document: Document | None = None) -> None:
        self.canvas = canvas
        self.pen = pen
        self.history = History(document or Document())
        self.words = Vocabulary()  # the user's own verbs and prepositions (the project keeps them)
        self.selected: str | None = None
        self.messages: list[Message] = []
        self.errors: list[str] = []
        self.journal: JournalWriter | None = None
        self.t = 0.0
        self.revision = 0
        self.ended = False
        self.sketch = SketchMode(self)
        self.current: Mode = self.sketch
        self._searched: tuple[Document, SearchResult] | None = None  # the last SIMULATE and its document
        self.watch = PenWatch()  # drawing, hovering and what strokes made: whom a spoken label names
        self._commands = Commands(self)

    @classmethod
    def from_header(cls, header: JournalHeader, document: Document | None = None) -> Session:
        """A session for the journal with this header (its canvas, input mapping and vocabulary).

        Raises:
            PhraseError: the header's vocabulary has a bad line (named).
        """
        session = cls((header.canvas_width, header.canvas_height), pen_input_for(header), document)
        if header.vocabulary:
            words = parse_vocabulary(header.vocabulary, "journal header vocabulary")
            session.add_words(words)
        return session

    # -- what a view and a driver read -----------------------------------------------------------------------

    @property
    def document(self) -> Document:
        return self.history.current

    @property
    def scene(self) -> Scene:
        return self.history.current.scene

    @property
    def timeline(self) -> Timeline | None:
        """The timeline as it stands now (while demonstrating, what has been recorded so far)."""
        return self.current.timeline()

    @property
    def demonstration(self) -> Timeline | None:
        """When the timeline is an adopted simulation, the demonstrated timeline it was found for; else None."""
        return self.document.demonstration

    @property
    def vocabulary(self) -> Vocabulary:
        """The words phrases may use: the default ones and the user's."""
        return DEFAULT_VOCABULARY.extended(self.words)

    def add_words(self, words: Vocabulary) -> None:
        """The user's vocabulary grows by ``words`` (a vocabulary file)."""
        self.words = self.words.extended(words)

    def vocabulary_lines(self) -> tuple[str, ...]:
        """The user's words as a project keeps them."""
        return vocabulary_lines(self.words)

    @property
    def mode(self) -> ModeName:
        """The mode the session is in."""
        return self.current.name

    @property
    def last_created(self) -> str | None:
        """The component the last stroke made (``label last``)."""
        return self.sketch.last_created

    @property
    def stroke_pending(self) -> bool:
        """A stroke has ended but the sketch has not yet decided what it makes (an X's first half)."""
        return self.sketch.pending is not None

    @property
    def world(self) -> LiveWorld:
        """The sketch as a gravity-free physics world, in step with the scene (see `SketchMode.world`)."""
        return self.sketch.world

    def view(self) -> SessionView:
        """An immutable snapshot of everything a view shows."""
        pens = {device: (dev.engine.state.value, dev.engine.ink[-1].p if dev.engine.ink else 0.0)
                for device, dev in self.pen.devices.items()}
        return snapshot(self.revision, self.t, self.current, self.scene, self.canvas, self.pen.ink(),
                        self.sketch.pending, self.selected, self.history, self.messages,
                        self._searched[1] if self._searched else None, pens)

    # -- input ---------------------------------------------------------------------------------------------

    def handle(self, entry: SessionInput) -> None:
        """Consume one input: time first advances to its ``t``; then it is acted on (or refused, with a message);
        then it is journaled. An entry the journal cannot hold (a value out of range, time going backwards) is
        refused before it is acted on, so a replay of the journal sees what the session saw. Nothing an input can
        do raises out of here."""
        offered = None
        if isinstance(entry, simulation.Searched):  # a driver ran this simulate's search (journaled as the command)
            offered, entry = entry, entry.entry()
        if isinstance(entry, CommandEntry):
            entry = simulation.with_defaults(entry, self.simulation_budget)  # journaled with both numbers
        refusal = self._refusal(entry)
        if refusal is not None:
            self.tell(f"input refused: {refusal}")
            return
        errors = len(self.errors)
        try:
            self.advance(entry.t)
            self._act(entry, offered)
        except PhysinkError as exc:  # input the session cannot use (an unknown device, a bad descriptor)
            self.tell(str(exc))
        except Exception as exc:  # a bug: recorded and told; the session and its journal carry on
            self.errors.append("".join(traceback.format_exception(exc)))
            self.tell(f"internal error handling the input at {entry.t:g} s: {exc!r} (reported; carrying on)")
        self._forget_stale_search()
        self.revision += 1
        self._journal(entry)
        if len(self.errors) > errors and self.raise_internal_errors:
            raise AssertionError(f"internal error in the session:\n{self.errors[-1]}")

    def advance(self, t: float) -> None:
        """Time passes to input time ``t`` (no earlier than before): a dwell may complete, a waiting half-X may be
        taken on its own, and the current mode's world steps on its fixed dt."""
        if t <= self.t:
            return
        changed = False
        for g in self.pen.tick(t):
            before = self.sketch.last_created
            changed |= self.current.advance(g.t)
            self._note_created(before, g.t)
            self._gesture(g)
            changed = True
        before = self.sketch.last_created
        changed |= self.current.advance(t)
        self._note_created(before, t)
        self.t = t
        self._forget_stale_search()
        if changed:
            self.revision += 1

    def run(self, entries: Iterable[JournalEntry]) -> Session:
        for entry in entries:
            self.handle(entry)
        self.finish()
        return self

    def finish(self, t: float | None = None) -> None:
        """The session ends at ``t`` (default: the time reached): time advances to it, what the mode was doing is
        committed to the document, and a journal gets ``end`` at ``t`` and is closed."""
        if t is not None:
            self.advance(t)
        if not self.ended:
            self._commands.end()
            self._forget_stale_search()
            if self.journal is not None:
                self._journal(CommandEntry(self.t, "end", ()))
        if self.journal is not None:
            self.journal.close()
            self.journal = None

    def tell(self, text: str, t: float | None = None, kind: str = "note") -> None:
        self.messages.append(Message(self.t if t is None else t, text, kind))

    # -- what modes may do (`modes.base.Host`) ----------------------------------------------------------------

    def commit(self, document: Document, description: str) -> None:
        self.history.push(document, description)
        self.forget_gone()

    def amend(self, document: Document) -> None:
        self.history.amend(document)
        self.forget_gone()

    def select(self, component_id: str | None) -> None:
        self.selected = component_id
        if component_id is not None:
            self.tell(f"selected {self.scene.called(component_id)}")

    # -- what commands may do (`command_handling.CommandHost`) ------------------------------------------------

    def forget_gone(self) -> None:
        """A selection or last stroke whose component is gone (erased, undone) is forgotten."""
        components = self.scene.components
        if self.selected not in components:
            self.selected = None
        if self.sketch.last_created not in components:
            self.sketch.last_created = None

    def found(self, result: SearchResult) -> None:
        """SIMULATE gave ``result`` for the document now: shown until the document changes."""
        self._searched = (self.document, result)

    # -- acting on entries ---------------------------------------------------------------------------------

    def _act(self, entry: JournalEntry, offered: simulation.Searched | None) -> None:
        if isinstance(entry, HidEntry):
            self._gestures(self.pen.handle(RawReport(entry.t, entry.data, entry.dev)))
        elif isinstance(entry, PenEntry):
            sample = PenSample(entry.t, entry.x, entry.y, entry.p, entry.tip, entry.range, entry.eraser,
                               entry.b1, entry.b2, None, None, 0)
            self._gestures(self.pen.feed_canvas_sample(PEN_DEVICE, sample))
        elif isinstance(entry, CommandEntry):
            self._commands.handle(entry, offered)
        elif isinstance(entry, SayEntry):
            self._say(entry)
        elif isinstance(entry, DeviceEntry):  # a tablet plugged in during the session, or plugged back in
            for device in entry.devices:
                if device.id in self.pen.devices:  # reconnected: the gesture it was making ends here
                    self._gestures(self.pen.handle(SourceEnded(entry.t, device.id, None)))
                add_journal_device(self.pen, device, f"journal at t={entry.t:g}")

    def _gestures(self, gestures: list[Gesture]) -> None:
        for g in gestures:
            self._gesture(g)

    def _gesture(self, g: Gesture) -> None:
        before = self.sketch.last_created
        self.watch.gesture(g)
        following = self.current.gesture(g)
        if following is not None:
            self.current = following
        if self.current.finished:
            self.current = self.sketch
        self._note_created(before, g.t)
        waiting = None if self.watch.drawing or self.sketch.pending is not None else self.watch.take_waiting()
        if waiting is not None:  # the stroke said to be labelled ended without making anything
            self.tell(f"label {waiting.text!r}: the stroke being drawn made no component to label")

    def _note_created(self, before: str | None, t: float) -> None:
        """A stroke made a component (now or when a half-X waited out): a label said while drawing it applies."""
        made = self.sketch.last_created
        if made is None or made == before:
            return
        self.watch.made(made, t)
        waiting = self.watch.take_waiting()
        if waiting is not None:
            labelling.label(self, made, waiting.text)

    def _forget_stale_search(self) -> None:
        """A SIMULATE result whose document changed (an edit, or a take being recorded) is forgotten."""
        if self._searched is not None and (self._searched[0] is not self.document or (
                isinstance(self.current, DemoMode) and self.current.has_take)):
            self._searched = None

    def _say(self, entry: SayEntry) -> None:
        words = entry.text.strip().split()
        if len(words) >= 2 and words[0].lower() == "label":
            labelling.spoken_label(self, " ".join(words[1:]), entry.t)
        elif entry.text.strip() and isinstance(self.current, DemoMode):
            self.current.narrate(entry.text, self.vocabulary, entry.t)
        elif entry.text.strip():
            self.tell(f"heard {entry.text!r}; only 'label <name>' is understood while sketching")

    def _refusal(self, entry: JournalEntry) -> str | None:
        """Why ``entry`` cannot be taken (what a journal could not hold, or time going backwards), or None."""
        if entry.t < self.t:
            return f"input at {entry.t:g} s after the session reached {self.t:g} s (inputs come in time order)"
        try:
            if self.journal is not None:
                self.journal.check(entry)
            else:
                encode_entry(entry, devices=self.pen.devices)
        except (JournalError, TypeError) as exc:
            return str(exc)
        return None

    def _journal(self, entry: JournalEntry) -> None:
        if self.journal is None:
            return
        try:
            self.journal.append(entry)
            self.journal.flush()
        except JournalError as exc:  # a full disk stops the journal, never the session
            self.journal = None
            self.tell(str(exc), entry.t)
