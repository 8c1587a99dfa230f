"""The session's commands (``cmd`` journal entries): modes, playback, undo/redo/clear, labels, SIMULATE, load, save
and end, as methods the `Session` inherits; what a command means in a mode is the mode's, the document's changes go
through the session's history."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import replace

from physink_tui.errors import SceneError
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.json_checks import Place
from physink_tui.formats.project.codec import decode_project_object, project_vocabulary
from physink_tui.scene.components import Scene
from physink_tui.session import labelling, simulation
from physink_tui.session.history import Document
from physink_tui.session.modes.demo import DemoMode

PLAYBACK = ("play", "pause", "stop", "seek")


class SessionCommands:
    """Handling one command entry (mixed into `Session`, whose state these methods use)."""

    def _command(self, entry: CommandEntry) -> None:
        name, args, t = entry.name, entry.args, entry.t
        if name == "label":
            labelling.label(self, str(args[0]), str(args[1]))
        elif name in PLAYBACK:
            self._playback(name, args, t)
        elif name == "mode":
            self._switch(str(args[0]), t)
        elif name in ("undo", "redo", "clear"):
            with self._closed(t):
                self._edit(name)
        elif name == "simulate":
            with self._closed(t):
                self._simulate(int(args[0]), int(args[1]))
        elif name == "load":
            self._load(entry)
        elif name == "end":  # the driver finishes next; input after it would still be handled
            self._end()
        elif name == "save":  # the driver (the TUI) writes the file; a replay writes none
            self.sketch.flush(t)
        else:
            self.sketch.flush(t)
            self.tell(f"{name}: the session does not act on this command")

    def _switch(self, mode: str, t: float) -> None:
        """``mode sketch`` or ``mode demo``: what the current mode was doing is committed first."""
        if mode not in ("sketch", "demo"):
            self.tell(f"mode {mode}: the modes are sketch and demo")
            return
        if mode == "demo" and isinstance(self.current, DemoMode):
            return
        self.current.close(t)
        self.sketch.close(t)
        self.current = DemoMode(self, t) if mode == "demo" else self.sketch

    @contextmanager
    def _closed(self, t: float) -> Iterator[None]:
        """The body acts on the document with the modes closed at ``t`` (sketch takes a waiting half-X, adjust
        puts its body down, demo commits its take); a demonstration then starts again from the document."""
        self.current.close(t)
        self.sketch.close(t)
        demonstrating = isinstance(self.current, DemoMode)
        self.current = self.sketch
        try:
            yield
        finally:
            if demonstrating:
                self.current = DemoMode(self, t)

    def _edit(self, name: str) -> None:
        """Undo, redo and clear act on the document in every mode (`_closed`)."""
        if name == "undo" and self.history.undo() is None:
            self.tell("nothing to undo")
        elif name == "redo" and self.history.redo() is None:
            self.tell("nothing to redo")
        elif name == "clear":
            if self.scene.components or self.document.timeline is not None:
                self.commit(Document(replace(Scene(), next_id=self.scene.next_id)), "clear")
            self.selected = self.sketch.last_created = None
        self._forget_gone()

    def _simulate(self, seed: int, budget: int) -> None:
        """``simulate SEED BUDGET``: the search a driver ran for this document (`simulation.Searched`), else one
        run here and now (`simulation.attempt`); the result is shown until the document changes."""
        offered = self._offered
        if offered is not None and offered.fits(self.document, seed, budget):
            result, text = offered.result, simulation.summary(offered.result)
        else:
            result, text = simulation.attempt(self.document, self.canvas, seed, budget)
        if result is not None:
            self._searched = (self.document, result)
        self.tell(text)

    def _load(self, entry: CommandEntry) -> None:
        """``load PATH`` with the project embedded: it becomes the document (one undoable action) and its words
        join the vocabulary; a demonstration starts again from it."""
        where = f"load {entry.args[0] if entry.args else ''}".strip()
        if entry.project is None:
            self.tell(f"{where}: the project is not embedded in the input, so nothing was loaded")
            return
        project = decode_project_object(entry.project, Place(where, SceneError))
        with self._closed(entry.t):
            self.commit(Document(project.scene, project.timeline, project.demonstration), where)
            self.add_words(project_vocabulary(project))
            if tuple(project.canvas) != tuple(self.canvas):
                self.tell(f"{where}: the project was drawn on a {project.canvas[0]:g} x {project.canvas[1]:g} "
                          f"canvas, this session's is {self.canvas[0]:g} x {self.canvas[1]:g}; it is shown as drawn")
            self.tell(f"loaded {entry.args[0] if entry.args else 'a project'}: {len(project.scene.components)} "
                      "components" + (", a timeline" if project.timeline is not None else ""))

    def _end(self) -> None:
        self.current.close(self.t)
        self.sketch.close(self.t)
        self.current = self.sketch
        self.ended = True
        self._forget_stale_search()

    def _playback(self, name: str, args: tuple, t: float) -> None:
        demo = self.current
        if not isinstance(demo, DemoMode):
            self.sketch.flush(t)
            self.tell(f"{name}: playback works in demo mode (mode demo)")
        elif name == "seek":
            demo.seek(float(args[0]), t)
        else:
            {"play": demo.play, "pause": demo.pause, "stop": demo.stop}[name](t)
