"""The session's commands (``cmd`` journal entries): modes, playback, undo/redo/clear, labels, SIMULATE, load, save
and end, handled by `Commands` for the session that owns it (seen through `CommandHost`); what a command means in a
mode is the mode's, the document's changes go through the session's history."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import replace
from typing import Protocol

from physink_tui.errors import SceneError
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.json_checks import Place
from physink_tui.formats.project.codec import decode_project_object, project_vocabulary
from physink_tui.formats.project.sanity import check_project
from physink_tui.scene.components import Scene
from physink_tui.session import labelling, simulation
from physink_tui.session.history import Document, History
from physink_tui.session.labelling import LabelHost
from physink_tui.session.modes.base import Mode, ModeName
from physink_tui.session.modes.demo import DemoMode
from physink_tui.session.modes.sketch import SketchMode
from physink_tui.session.simulation import SearchResult
from physink_tui.timeline.phrases import Vocabulary

PLAYBACK = ("play", "pause", "stop", "seek")


class CommandHost(LabelHost, Protocol):
    """The session as its commands see it: the document's history, the modes, and what it is told."""

    t: float
    history: History
    sketch: SketchMode
    current: Mode
    """The mode the session is in (``sketch`` or another)."""
    ended: bool

    def amend(self, document: Document) -> None: ...

    def select(self, component_id: str | None) -> None: ...

    def add_words(self, words: Vocabulary) -> None: ...

    def forget_gone(self) -> None:
        """A selection or last stroke whose component is gone (undone, cleared) is forgotten."""

    def found(self, result: SearchResult) -> None:
        """SIMULATE gave ``result`` for the document now (shown until the document changes)."""


class Commands:
    """Handles the command entries of one session, ``host``."""

    def __init__(self, host: CommandHost) -> None:
        self.host = host

    def handle(self, entry: CommandEntry, offered: simulation.Searched | None = None) -> None:
        """Act on ``entry``; ``offered``: the search a driver ran for it (a ``simulate``), if any."""
        name, args, t = entry.name, entry.args, entry.t
        host = self.host
        if name == "label":
            labelling.label(host, str(args[0]), str(args[1]))
        elif name in PLAYBACK:
            self._playback(name, args, t)
        elif name == "mode":
            self._switch(str(args[0]), t)
        elif name in ("undo", "redo", "clear"):
            with self._closed(t):
                self._edit(name)
        elif name == "simulate":
            with self._closed(t):
                self._simulate(int(args[0]), int(args[1]), offered)
        elif name == "load":
            self._load(entry)
        elif name == "end":  # the driver finishes next; input after it would still be handled
            self.end()
        elif name == "save":  # the driver (the TUI) writes the file; a replay writes none
            host.sketch.flush(t)
        else:
            host.sketch.flush(t)
            host.tell(f"{name}: the session does not act on this command")

    def end(self) -> None:
        """The session ends: what the modes were doing is committed, and it is back to sketching."""
        host = self.host
        host.current.close(host.t)
        host.sketch.close(host.t)
        host.current = host.sketch
        host.ended = True

    def _switch(self, mode: str, t: float) -> None:
        """``mode sketch`` or ``mode demo``: what the current mode was doing is committed first."""
        host = self.host
        if mode not in (ModeName.SKETCH, ModeName.DEMO):
            host.tell(f"mode {mode}: the modes are sketch and demo")
            return
        if mode == ModeName.DEMO and isinstance(host.current, DemoMode):
            return
        host.current.close(t)
        host.sketch.close(t)
        host.current = DemoMode(host, t) if mode == ModeName.DEMO else host.sketch

    @contextmanager
    def _closed(self, t: float) -> Iterator[None]:
        """The body acts on the document with the modes closed at ``t`` (sketch takes a waiting half-X, adjust
        puts its body down, demo commits its take); a demonstration then starts again from the document."""
        host = self.host
        host.current.close(t)
        host.sketch.close(t)
        demonstrating = isinstance(host.current, DemoMode)
        host.current = host.sketch
        try:
            yield
        finally:
            if demonstrating:
                host.current = DemoMode(host, t)

    def _edit(self, name: str) -> None:
        """Undo, redo and clear act on the document in every mode (`_closed`)."""
        host = self.host
        if name == "undo" and host.history.undo() is None:
            host.tell("nothing to undo")
        elif name == "redo" and host.history.redo() is None:
            host.tell("nothing to redo")
        elif name == "clear":
            if host.scene.components or host.document.timeline is not None:
                host.commit(Document(replace(Scene(), next_id=host.scene.next_id)), "clear")
            host.selected = host.sketch.last_created = None
        host.forget_gone()

    def _simulate(self, seed: int, budget: int, offered: simulation.Searched | None) -> None:
        """``simulate SEED BUDGET``: the search a driver ran for this document (`simulation.Searched`), else one
        run here and now (`simulation.attempt`); the result is shown until the document changes."""
        host = self.host
        result: SearchResult | None
        if offered is not None and offered.fits(host.document, seed, budget):
            result, text = offered.result, simulation.summary(offered.result)
        else:
            result, text = simulation.attempt(host.document, host.canvas, seed, budget)
        if result is not None:
            host.found(result)
        host.tell(text)

    def _load(self, entry: CommandEntry) -> None:
        """``load PATH`` with the project embedded: it becomes the document (one undoable action) and its words
        join the vocabulary; a demonstration starts again from it."""
        host = self.host
        where = f"load {entry.args[0] if entry.args else ''}".strip()
        if entry.project is None:
            host.tell(f"{where}: the project is not embedded in the input, so nothing was loaded")
            return
        project = check_project(decode_project_object(entry.project, Place(where, SceneError)),
                                Place(where, SceneError))
        with self._closed(entry.t):
            host.commit(Document(project.scene, project.timeline, project.demonstration), where)
            host.add_words(project_vocabulary(project))
            if tuple(project.canvas) != tuple(host.canvas):
                host.tell(f"{where}: the project was drawn on a {project.canvas[0]:g} x {project.canvas[1]:g} "
                          f"canvas, this session's is {host.canvas[0]:g} x {host.canvas[1]:g}; it is shown as drawn")
            host.tell(f"loaded {entry.args[0] if entry.args else 'a project'}: {len(project.scene.components)} "
                      "components" + (", a timeline" if project.timeline is not None else ""))

    def _playback(self, name: str, args: tuple[str | float, ...], t: float) -> None:
        demo = self.host.current
        if not isinstance(demo, DemoMode):
            self.host.sketch.flush(t)
            self.host.tell(f"{name}: playback works in demo mode (mode demo)")
        elif name == "seek":
            demo.seek(float(args[0]), t)
        else:
            {"play": demo.play, "pause": demo.pause, "stop": demo.stop}[name](t)
