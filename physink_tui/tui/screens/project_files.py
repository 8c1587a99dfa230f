"""The main screen's project files: Save (to `storage.projects_dir()` by default, saying where), Load (a project
file checked as every command checks it, embedded in a journaled ``load``) and adopting a SIMULATE result (one
journaled ``load`` of the scene with the found parameters, the simulated timeline and the demonstration kept):
`ProjectFiles`, a helper the screen owns, which sees it through `Host` and through Textual's `Screen` (dialogs,
notifications, the status bar). It leaves the session to the screen: everything it does goes in as a command.
"""

from __future__ import annotations

import json
import os
from typing import Any, Protocol

from textual.screen import Screen

from physink_tui.errors import PhysinkError
from physink_tui.formats.project.codec import Project, encode_project
from physink_tui.formats.project.files import load_project, save_project
from physink_tui.session.simulation import SessionInput
from physink_tui.session.view import SessionView
from physink_tui.sim.parameters import apply
from physink_tui.tui import storage
from physink_tui.tui.live import LiveSession
from physink_tui.tui.screens.modals import ErrorModal, PromptModal
from physink_tui.tui.widgets.bars import StatusBar


class Host(Protocol):
    """The screen as its project files see it: the live session, the view shown and the commands it sends."""

    @property
    def live(self) -> LiveSession | None: ...

    @property
    def view(self) -> SessionView | None: ...

    def command(self, name: str, *args: str | float, project: dict[str, Any] | None = None
                ) -> SessionInput | None: ...

    def mark_saved(self, view: SessionView) -> None: ...


class ProjectFiles:
    """Save, Load and adopt for ``screen`` (its dialogs and status bar); ``host`` (the same screen) gives the session,
    the view and sends the commands."""

    def __init__(self, screen: Screen[None], host: Host) -> None:
        self._screen = screen
        self._host = host
        self.path: str | None = None
        """The project file last saved or loaded (the dialogs' default)."""

    def ask_save(self) -> None:
        default = self.path or str(storage.new_project_path())
        self._screen.app.push_screen(PromptModal(
            f"Save the project as (a name alone goes in {storage.projects_dir()}):", default), self.save)

    def save(self, path: str | None) -> None:
        live = self._host.live
        view = self._host.view if live is None else live.runner.latest_view()
        if not path or view is None or live is None:
            return
        target = storage.project_target(path)
        project = Project(view.scene, live.vocabulary_lines(), view.timeline, live.canvas, view.demonstration)
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
            save_project(project, target)
        except OSError as exc:
            self._fail("Cannot save", f"cannot make the folder {target.parent}: {exc.strerror or exc}")
            return
        except PhysinkError as exc:
            self._fail("Cannot save", str(exc))
            return
        self.path = str(target)
        self._host.command("save", str(target))
        self._host.mark_saved(view)
        self._screen.query_one(StatusBar).set(activity=f"saved {target}")
        self._screen.notify(f"saved the project to {target}")

    def ask_load(self) -> None:
        self._screen.app.push_screen(PromptModal("Load the project:", self.path or ""), self.load)

    def load(self, path: str | None) -> None:
        """The project at ``path``, read and checked once (`load_project`: as export and simulate read it), into the
        session as a ``load`` command with the project embedded (so a replay rebuilds it)."""
        if not path:
            return
        try:
            project = load_project(path)
        except PhysinkError as exc:
            self._fail("Cannot load", str(exc))
            return
        self.path = path
        self._host.command("load", os.path.abspath(path), project=json.loads(encode_project(project, where=path)))

    def adopt(self) -> None:
        """The SIMULATE result's parameters applied to the scene, its simulated timeline as the project's and the
        demonstration it was found for kept beside it (for comparing them again): one journaled ``load`` with the
        project embedded, so it is undoable and a replay rebuilds it."""
        view, live = self._host.view, self._host.live
        if view is None or view.search is None or live is None:
            self._screen.notify("nothing to adopt: simulate first (g)", severity="warning")
            return
        search = view.search
        try:
            scene = apply(view.scene, search.parameters)
            text = encode_project(Project(scene, live.vocabulary_lines(), search.timeline, live.canvas,
                                          view.timeline))
        except PhysinkError as exc:
            self._fail("Cannot adopt the simulation", str(exc))
            return
        self._host.command("load", "simulation", project=json.loads(text))
        if not search.found:
            self._screen.notify("adopted the best simulation found, which is not equivalent to the demonstration up "
                                "to its last event (undo with u)", severity="warning")

    def _fail(self, title: str, text: str) -> None:
        self._screen.app.push_screen(ErrorModal(title, text))
