"""The PhysInk Textual app: starts the live session (recovering an unfinished one if asked), hands views to the
main screen, asks before losing work; the controls are the main screen's, the state the session's.

`make_app(options)` is the one factory the CLI (``physink tui``, ``physink demo``) and the tests share.
"""

from __future__ import annotations

import gc
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any, ClassVar

from rich.console import RenderableType
from textual.app import App
from textual.binding import Binding, BindingType
from textual.message import Message
from textual.screen import Screen
from textual.widgets import Input, TextArea

from physink_tui.errors import PhysinkError
from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.input.speech.microphone import StreamFactory
from physink_tui.session.view import SessionView
from physink_tui.tui import storage
from physink_tui.tui.config import Config, load_config, save_config
from physink_tui.tui.graphics import DEFAULT_CELL
from physink_tui.tui.live import LiveSession
from physink_tui.tui.pacing import FramePacer
from physink_tui.tui.screens.main import MainScreen
from physink_tui.tui.screens.modals import ConfirmModal, ErrorModal
from physink_tui.tui.widgets.bars import StatusBar

STYLESHEET = "physink.tcss"
"""The panel's styles: package data of ``physink_tui.tui`` (pyproject.toml's package-data lists it)."""


@dataclass
class TuiOptions:
    """How the TUI starts.

    Attributes:
        header, entries: a recorded session to replay into the live one (``--replay``, the demo), or None.
        prior: entries of ``header``'s session handled at once before the live session starts (tests, pictures).
        speed: replay speed (1: real time).
        simulate_after: once the replay is done, SIMULATE what it demonstrated (the demo's last step).
        project: a project file to open at the start (``physink tui PROJECT``), also the default for Save.
        device, serial: the tablet (``--device``, ``--serial``); ``tablet=False`` looks for none (tests).
        journal_dir: where the session journals (default: the XDG data folder); None with ``journal=False``.
        recover: offer to recover an unfinished session found there.
        theme: the scene's ``light`` or ``dark`` theme (default: the settings').
        config_path: the settings file (default: ``$XDG_CONFIG_HOME/physink/config.json``).
        max_fps: scene redraws a second at most.
        microphone: the sound input push-to-talk listens on (default: the microphone; tests give a recording).
        graphics, cell: how the scene is drawn (`physink_tui.tui.graphics`: ``halfblocks``, ``kitty`` or ``sixel``)
            and a cell's size in pixels (for the graphics protocols).
        clock: the live session's clock, seconds on a monotonic scale (tests pass one they can hold still while
            a Pilot draws, so a stroke's timing is the test's, not the loaded machine's).
    """

    header: JournalHeader | None = None
    entries: tuple[JournalEntry, ...] = ()
    prior: tuple[JournalEntry, ...] = ()
    speed: float = 1.0
    simulate_after: bool = False
    project: str | None = None
    device: str | None = None
    serial: str | None = None
    tablet: bool = True
    journal: bool = True
    journal_dir: Path | None = None
    recover: bool = True
    theme: str | None = None
    config_path: Path | None = None
    max_fps: float = 60.0
    microphone: StreamFactory | None = None
    graphics: str = "halfblocks"
    cell: tuple[int, int] = DEFAULT_CELL
    title: str = "PhysInk"
    notes: list[str] = field(default_factory=list)
    clock: Callable[[], float] = time.monotonic


class ViewUpdated(Message):
    """A new snapshot from the runner (only the latest one matters), posted at ``posted`` (`time.monotonic`)."""

    def __init__(self, view: SessionView) -> None:
        super().__init__()
        self.view = view
        self.posted = time.monotonic()

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, ViewUpdated)


class RunnerFailed(Message):
    """The session's worker stopped on a bug."""

    def __init__(self, error: BaseException) -> None:
        super().__init__()
        self.error = error


class PhysinkApp(App[None]):
    """The control panel. The live session starts on mount (after the recovery question, if any)."""

    CSS = resources.files(__package__).joinpath(STYLESHEET).read_text("utf-8")
    """The styles, read as package data (a path beside this file is not there in every installation)."""
    TITLE = "PhysInk"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = [
        # ctrl+c quits as q does, on every screen and in the middle of a drag (Textual's own binding only says how
        # to quit); a focused text input keeps it for copying (`check_action`)
        Binding("ctrl+c", "quit", "quit", show=False, priority=True),
    ]

    def __init__(self, options: TuiOptions | None = None) -> None:
        super().__init__()
        self.options = options or TuiOptions()
        self.config = Config()
        """The settings (`physink_tui.tui.config`), read on mount."""
        self.live: LiveSession | None = None
        self.main: MainScreen | None = None
        self.saved_document: tuple[object, object] | None = None
        """The (scene, timeline) last saved or opened: work differs from it when unsaved."""
        self.pacer = FramePacer()
        """When views are drawn (all of them while the UI keeps up)."""
        self._waiting: SessionView | None = None  # a view passed over, drawn by `_catch_up`
        self._asking_to_quit = False  # the unsaved-work question is up: quitting again quits
        self.failure: BaseException | None = None
        """A bug that stopped part of the app (the session's worker, a background job): quitting then exits 1."""

    # -- start -----------------------------------------------------------------------------------------------

    async def on_mount(self) -> None:
        problem = None
        try:
            self.config = load_config(self.options.config_path)
        except PhysinkError as exc:
            problem = str(exc)
        header = self.options.header or self.config.header()
        self.main = MainScreen((header.canvas_width, header.canvas_height), self.options.theme or self.config.theme,
                               self.options.graphics, self.options.cell)
        await self.push_screen(self.main)
        if problem is not None:
            self.push_screen(ErrorModal("Settings not read (the defaults are used)", problem))
        found = []
        if self.options.journal and self.options.recover and self.options.header is None:
            found = storage.unfinished_journals(self.options.journal_dir or storage.sessions_dir())
        if found:
            path, journal = found[0]
            dropped = "" if journal.dropped is None else f"\nIts journal is damaged: {journal.dropped}.\n"
            question = (f"A session did not finish: {path.name} ({len(journal.entries)} inputs).\n{dropped}"
                        "Recover it (replay it here and carry on)?")

            def answered(yes: bool | None) -> None:
                storage.mark_recovered(path)
                if yes:
                    self._start(journal.header, journal.entries)
                else:
                    self._start(None, ())

            self.push_screen(ConfirmModal(question, "Recover", "Start afresh"), answered)
        else:
            self._start(None, ())

    def _start(self, recovered_header: JournalHeader | None, prior: tuple[JournalEntry, ...]) -> None:
        options = self.options
        header = recovered_header or options.header or self.config.header()
        path = None
        if options.journal:
            try:
                path = storage.new_journal_path(options.journal_dir)
            except OSError as exc:
                self.push_screen(ErrorModal("Not journaling", f"cannot make the journal folder: {exc}"))
        try:
            live = LiveSession(header, journal_path=path, prior=prior or options.prior, max_fps=options.max_fps,
                               on_error=lambda exc: self.post_message(RunnerFailed(exc)), clock=options.clock)
        except PhysinkError as exc:
            self.push_screen(ErrorModal("Cannot start the session", str(exc)))
            live = LiveSession(header, journal_path=None, max_fps=options.max_fps, clock=options.clock)
        self.live = live
        last = [-1]

        def publish(view: SessionView) -> None:  # on the runner's thread: only views that changed go on
            if view.revision != last[0]:
                last[0] = view.revision
                self.post_message(ViewUpdated(view))

        live.runner.subscribe(publish)
        live.start()
        # What exists now (modules, widgets, a replayed journal) lives as long as the app: collected once and
        # frozen, later full collections skip it, which took their pauses (every thread stops) from about 100 ms
        # to about 20 ms while a tablet streams (docs/BENCHMARKS.md).
        gc.collect()
        gc.freeze()
        if self.main is None:  # never: on_mount made it
            return
        self.main.attach(live, path)
        if options.tablet:
            self.main.watch_tablet(options.device, options.serial)
        else:
            self.main.query_one("#status", StatusBar).set(device="no tablet (mouse only)")
        if options.project:
            self.main.open_project(options.project)
        if options.entries:
            self.main.replay(options.entries, options.speed, simulate_after=options.simulate_after)
        for note in options.notes:  # e.g. why the scene is in half-blocks: long enough to be read
            self.notify(note, timeout=30)

    def _display(self, screen: Screen[Any], renderable: RenderableType | None) -> None:
        """Textual's one place that writes a screen update to the terminal, followed here by the scene view's Sixel
        picture when the update wrote cells over it (Textual has no public hook after painting; the scene view
        already writes its escapes through the same driver)."""
        super()._display(screen, renderable)
        main = self.main
        if main is None or main.scene_view is None or renderable is None:
            return
        from textual._compositor import ChopsUpdate, LayoutUpdate

        if isinstance(renderable, LayoutUpdate):
            region = renderable.region
            main.scene_view.painted((region.x, region.y, region.width, region.height))
        elif isinstance(renderable, ChopsUpdate):
            main.scene_view.painted(None, renderable.spans)

    # -- views -----------------------------------------------------------------------------------------------

    def on_view_updated(self, message: ViewUpdated) -> None:
        if self.saved_document is None:
            self.saved_document = (message.view.scene, message.view.timeline)
        if self.main is None:
            return
        now = time.monotonic()
        if self.pacer.draw_now(message.posted, now):
            self._waiting = None
            self.main.show(message.view)
            return
        if self._waiting is None:  # behind: drawn when the pacer's interval is up, unless a newer view is first
            self.set_timer(self.pacer.catch_up_in(now), self._catch_up)
        self._waiting = message.view

    def _catch_up(self) -> None:
        view, self._waiting = self._waiting, None
        if view is not None and self.main is not None:
            self.pacer.drew(time.monotonic())
            self.main.show(view)

    def on_runner_failed(self, message: RunnerFailed) -> None:
        self.failed(message.error, "the session stopped")

    def failed(self, error: BaseException, what: str) -> None:
        """A bug stopped ``what``: said in a dialog; the app exits with status 1 when the user quits."""
        self.failure = self.failure or error
        self.push_screen(ErrorModal("Internal error", f"{what}: {error!r}\nQuitting exits with status 1."))

    @property
    def unsaved(self) -> bool:
        """Whether the document differs from the one last saved or opened, or a stroke is being drawn."""
        view = self.live.runner.latest_view() if self.live is not None else None
        if view is None or self.saved_document is None:
            return False
        scene, timeline = self.saved_document
        return view.scene is not scene or view.timeline is not timeline or bool(view.ink or view.pending)

    def mark_saved(self, view: SessionView) -> None:
        self.saved_document = (view.scene, view.timeline)

    def adopt_settings(self, config: Config | None) -> None:
        """Save ``config`` (from the settings screen) and apply its theme; None changes nothing."""
        if config is None:
            return
        try:
            path = save_config(config, self.options.config_path)
        except PhysinkError as exc:
            self.push_screen(ErrorModal("Settings not saved", str(exc)))
            return
        self.config = config
        if self.main is not None:
            self.main.set_theme(config.theme)
        self.notify(f"settings saved to {path}; the mapping and tip thresholds apply from the next session")

    # -- the end ---------------------------------------------------------------------------------------------

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action == "quit" and isinstance(self.focused, Input | TextArea):
            return False  # ctrl+c in a text input copies, as Textual has it
        return True

    async def action_quit(self) -> None:
        if self.main is not None:
            self.main.lift_pen()  # quitting in the middle of a drag: the stroke ends where the mouse is
        if self._asking_to_quit:  # asked to quit again while the question is up (ctrl+c twice): quit
            self._quit_now()
        elif self.unsaved:
            def answered(yes: bool | None) -> None:
                self._asking_to_quit = False
                if yes:
                    self._quit_now()
            self._asking_to_quit = True
            self.push_screen(ConfirmModal("There is unsaved work (save it with ctrl+s).\nQuit anyway? The "
                                          "session's journal keeps everything.", "Quit", "Stay"), answered)
        else:
            self._quit_now()

    def _quit_now(self) -> None:
        self.stop_live()
        self.exit(return_code=1 if self.failure is not None else 0)

    def stop_live(self) -> None:
        """Stop the sources and the runner (the journal gets its end); an empty journal is removed."""
        live = self.live
        if live is None or live.stopped:
            return
        if self.main is not None:
            self.main.stop_workers()
        try:
            live.stop()
        except Exception as exc:  # the runner's bug, already shown
            self.log.error(f"session stopped with {exc!r}")
        if live.journal_path is not None:
            storage.remove_if_empty(live.journal_path)

    def on_unmount(self) -> None:
        self.stop_live()


def make_app(options: TuiOptions | None = None) -> PhysinkApp:
    """The app for ``options`` (the CLI and the tests build it the same way)."""
    return PhysinkApp(options)

