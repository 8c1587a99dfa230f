"""The main screen: scene, timeline tree, narration, buttons and status; turns keys, buttons, the mouse and the
tablet into journal entries for the live session; the blocking work (SIMULATE, export) is its `BackgroundWork`'s.

It keeps no state of the machine: what it shows comes from the latest `SessionView`, what it does goes to the
session as an entry, so the session's journal rebuilds everything. The project path, the recording status and
the workers' progress are all it holds.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar, Protocol, cast

from textual import events
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical
from textual.css.query import NoMatches
from textual.message import Message
from textual.screen import Screen
from textual.widgets import Input, Static, TextArea, Tree
from textual.worker import Worker, WorkerState

from physink_tui.formats.journal.entries import JournalEntry
from physink_tui.session.simulation import SessionInput
from physink_tui.session.view import SessionView
from physink_tui.timeline.narrate import timeline_text
from physink_tui.tui.config import Config
from physink_tui.tui.drawing_help import vocabulary_lines
from physink_tui.tui.graphics import DEFAULT_CELL
from physink_tui.tui.live import LiveSession
from physink_tui.tui.screens.background import BackgroundWork, SearchFinished, SearchProgressed
from physink_tui.tui.screens.modals import HelpScreen, PromptModal, TextScreen
from physink_tui.tui.screens.playback_keys import SEEK_STEP, PlaybackKeys
from physink_tui.tui.screens.project_files import ProjectFiles
from physink_tui.tui.screens.settings import SettingsScreen
from physink_tui.tui.screens.speech_keys import SpeechKeys, SpeechStatus
from physink_tui.tui.tablet import TabletWatch
from physink_tui.tui.widgets.bars import NarrationBar, StatusBar
from physink_tui.tui.widgets.controls import Controls
from physink_tui.tui.widgets.message_log import MessageLog
from physink_tui.tui.widgets.scene_view import PRESSURE, SceneView
from physink_tui.tui.widgets.search_bar import SearchBar
from physink_tui.tui.widgets.time_slider import TimeSlider
from physink_tui.tui.widgets.timeline_tree import TimelineTree

MIN_WIDTH, MIN_HEIGHT = 60, 16
"""The smallest terminal the panel is laid out in; below it a notice says so."""


@dataclass
class DeviceStatus(Message):
    """What the tablet watcher found (posted from its thread)."""

    text: str


class PanelApp(Protocol):
    """What the screen needs of its app (`app.PhysinkApp`, which imports this module) besides Textual's `App`."""

    config: Config

    def failed(self, error: BaseException, what: str) -> None: ...

    def mark_saved(self, view: SessionView) -> None: ...

    def adopt_settings(self, config: Config | None) -> None: ...


class MainScreen(Screen[None]):
    """The control panel."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("s", "sketch", "sketch mode"),
        Binding("d", "demo", "demo mode (record a demonstration)"),
        # the playback keys work whichever widget has focus (the tree, a button): priority bindings, which
        # `check_action` hands back to a text input
        Binding("space", "play_pause", "play / pause the demonstration", priority=True),
        Binding("p", "play_pause", "play / pause the demonstration"),
        Binding("full_stop", "stop", "stop (back to the start)"),
        Binding("left", "seek(-1)", f"seek back {SEEK_STEP:g} s (each press counts)", priority=True),
        Binding("right", "seek(1)", f"seek forward {SEEK_STEP:g} s (each press counts)", priority=True),
        Binding("home", "seek_to('start')", "go to the start of the demonstration", priority=True),
        Binding("end", "seek_to('end')", "go to the end of the demonstration", priority=True),
        Binding("u,ctrl+z", "undo", "undo"),
        Binding("r,ctrl+y", "redo", "redo"),
        Binding("c", "clear", "clear the sketch"),
        Binding("l", "label", "label the selected body (or the last drawn)"),
        Binding("ctrl+s", "save", "save the project (in $XDG_DATA_HOME/physink/projects/ unless told)"),
        Binding("ctrl+o", "load", "load a project"),
        Binding("t", "timeline", "the timeline as text"),
        Binding("g", "simulate", "simulate (search a physical simulation)"),
        Binding("a", "adopt", "adopt the simulation: its parameters and timeline become the project's (undoable)"),
        Binding("e", "export", "export the demonstration as a video"),
        Binding("i", "picture", "export a picture (PNG) of the moment shown"),
        Binding("escape", "cancel", "cancel the search (keeping the best so far) or the export"),
        Binding("f2", "settings", "settings: tablet mapping, tip thresholds, theme"),
        Binding("v", "listen", "push-to-talk: listen on the microphone / stop (\"label ball\", \"the ball falls\"); "
                "or hold the pen's barrel button while speaking"),
        Binding("question_mark,f1", "help", "this help: what to draw, and the keys"),
        Binding("q,ctrl+q,ctrl+c", "app.quit", "quit (asks when there is unsaved work; ctrl+c also while drawing, "
                "and twice quits)"),
    ]

    PLAYBACK = frozenset({"play_pause", "seek", "seek_to"})
    """Actions of priority keys that a focused text input keeps for itself."""

    def __init__(self, canvas: tuple[float, float], theme: str = "dark", graphics: str = "halfblocks",
                 cell: tuple[int, int] = DEFAULT_CELL) -> None:
        super().__init__()
        self.canvas = canvas
        self.theme_name = theme
        self.graphics, self.cell = graphics, cell
        self.live: LiveSession | None = None
        self.view: SessionView | None = None
        self.tablet: TabletWatch | None = None
        self._simulate_after = False  # SIMULATE once the replay is done
        self.scene_view: SceneView | None = None
        """The scene view, once composed (the app tells it when Textual painted over its Sixel picture)."""
        self.background = BackgroundWork(self, self)
        """SIMULATE and export, in worker threads."""
        self.files = ProjectFiles(self, self)
        """Save, Load and adopting a simulation."""
        self.playback = PlaybackKeys(self._latest, self.command)
        """Where the playback keys and the seek messages send the clock."""
        self.speech = SpeechKeys(self)
        """Push-to-talk: the key, the barrel button."""

    @property
    def panel_app(self) -> PanelApp:
        """The app, as `PanelApp` (Textual types ``self.app`` as any `App`)."""
        return cast(PanelApp, self.app)

    def compose(self) -> ComposeResult:
        with Vertical(id="panel"):
            with Horizontal(id="top"):
                self.scene_view = SceneView(self.canvas, self.theme_name, self.graphics, self.cell, id="scene")
                yield self.scene_view
                with Vertical(id="side"):
                    yield TimelineTree(id="timeline")
                    yield Static("", id="event-detail", markup=False)
                    yield MessageLog(id="log")
            yield TimeSlider(id="slider")
            yield NarrationBar(id="narration")
            yield SearchBar(id="search")
            yield Controls(id="controls")
            yield StatusBar(id="status")
        yield Static("", id="too-small")

    # -- wiring ------------------------------------------------------------------------------------------------

    def attach(self, live: LiveSession, journal: Path | None) -> None:
        self.live = live
        self.speech.attach(live, getattr(getattr(self.app, "options", None), "microphone", None))
        self.query_one(StatusBar).set(journal=f"journal {journal.name}" if journal else "not journaling")

    def watch_tablet(self, device: str | None, serial: str | None) -> None:
        if self.live is None:
            return
        self.tablet = TabletWatch(self.live.submit, lambda text: self.post_message(DeviceStatus(text)),
                                  spec=device, serial=serial, mapping=self.live.session.pen.mapping)
        self.live.on_stop(self.tablet.stop)
        self.tablet.start()

    def replay(self, entries: tuple[JournalEntry, ...], speed: float, *, simulate_after: bool = False) -> None:
        if self.live is None:
            return
        status = self.query_one(StatusBar)
        status.set(activity=f"replaying {len(entries)} inputs")
        self._simulate_after = simulate_after
        self.live.replay(entries, speed=speed,
                         on_done=lambda: self.post_message(DeviceStatus("")))

    def show(self, view: SessionView) -> None:
        self.background.drop_changed_search(view)
        self.view = view
        if not self.is_current:  # under a modal (help, settings, a prompt): drawn when it closes (on_screen_resume)
            return
        try:
            self._show(view)
        except NoMatches:  # a view arriving while the app closes (its widgets going one by one)
            return

    def on_screen_resume(self) -> None:
        if self.view is not None:
            self.show(self.view)
        self.query_one(SceneView).repaint_picture()  # a Sixel picture under the modal was painted over

    def _show(self, view: SessionView) -> None:
        self.query_one(SceneView).show(view)
        if self.query_one(TimelineTree).show(view):
            self.query_one("#event-detail", Static).update("")
        self.query_one(MessageLog).show(view)
        self.query_one(TimeSlider).show(view)
        self.query_one(NarrationBar).show(view, self.canvas)
        status = self.query_one(StatusBar)
        pen = next((f"pen {state} {p:.2f}" for state, p in view.pens.values() if state != "out of range"), None)
        status.set(pen=pen or "pen out of range")
        self.speech.follow(view)  # holding the barrel button: push-to-talk
        self.background.simulated(view, status)
        status.show(view)

    def on_device_status(self, message: DeviceStatus) -> None:
        if message.text:
            self.query_one(StatusBar).set(device=message.text)
        else:  # the replay ended
            self.query_one(StatusBar).set(activity="replay done: you are in control")
            if self._simulate_after:
                self._simulate_after = False
                self._simulate_once_handled()

    def _simulate_once_handled(self) -> None:
        """SIMULATE once the session has handled the replay's last entry (its view's time has reached the entry's
        stamp), however long that takes."""
        feed = self.live.feed if self.live is not None else None
        view = self.live.runner.latest_view() if self.live is not None else None
        if feed is None or feed.last_t is None or (view is not None and view.t >= feed.last_t):
            self._simulate_replayed()
        else:
            self.set_timer(0.05, self._simulate_once_handled)

    def _simulate_replayed(self) -> None:
        self.action_simulate()
        if self.background.job is not None:
            self.query_one(StatusBar).set(activity="replay done: you are in control; simulating (escape stops it)")

    def on_search_progressed(self, message: SearchProgressed) -> None:
        self.background.progressed(message)

    def on_search_finished(self, message: SearchFinished) -> None:
        self.background.finished(message)

    def on_search_bar_cancel(self, message: SearchBar.Cancel) -> None:
        self.background.cancel()

    def on_speech_status(self, message: SpeechStatus) -> None:
        self.query_one(StatusBar).set(speech=message.text)

    def action_listen(self) -> None:
        self.speech.toggle(self.view, self.query_one(StatusBar))

    def on_scene_view_pen(self, message: SceneView.Pen) -> None:
        if self.live is not None:
            self.live.mouse.push(message.x, message.y, p=PRESSURE if message.tip else 0.0, tip=message.tip,
                                 in_range=message.in_range, eraser=message.eraser)

    def on_tree_node_highlighted(self, event: Tree.NodeHighlighted) -> None:
        """The event under the tree's cursor, in full below the tree (a narrow tree cuts long names)."""
        if isinstance(event.control, TimelineTree):
            self.query_one("#event-detail", Static).update(str(event.node.label).strip())

    def on_timeline_tree_seek(self, message: TimelineTree.Seek) -> None:
        self.playback.seek(message.t)
        self.query_one(SceneView).emphasise(message.components)

    def on_time_slider_seek(self, message: TimeSlider.Seek) -> None:
        self.playback.seek(message.t)
        self.query_one(SceneView).emphasise(())

    def on_worker_state_changed(self, event: Worker.StateChanged) -> None:
        """A worker that died on a bug (SIMULATE, export: ``exit_on_error=False``) is said, never silent."""
        if event.state == WorkerState.ERROR and event.worker.error is not None:
            self.panel_app.failed(event.worker.error, event.worker.description or event.worker.name)

    async def on_controls_action(self, message: Controls.Action) -> None:
        await self.run_action(message.name)

    def on_resize(self, event: events.Resize) -> None:
        small = event.size.width < MIN_WIDTH or event.size.height < MIN_HEIGHT
        self.set_class(small, "too-small")
        if small:
            self.query_one("#too-small", Static).update(
                f"The terminal is {event.size.width}x{event.size.height}: PhysInk needs at least "
                f"{MIN_WIDTH}x{MIN_HEIGHT}. Make the window larger.")

    # -- commands ------------------------------------------------------------------------------------------------

    def action_sketch(self) -> None:
        self.command("mode", "sketch")

    def action_demo(self) -> None:
        self.command("mode", "demo")

    def action_play_pause(self) -> None:
        if self.view is not None and self.view.mode != "demo":
            self.command("mode", "demo")
        self.command("pause" if self.view is not None and self.view.playing else "play")

    def action_stop(self) -> None:
        self.command("stop")

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action in self.PLAYBACK and isinstance(self.focused, Input | TextArea):
            return False  # a text input keeps space and the arrows
        return True

    def _latest(self) -> SessionView | None:
        """The latest view, for a playback key: the runner's (the one drawn may be a frame behind)."""
        return (self.live.runner.latest_view() if self.live is not None else None) or self.view

    def action_seek(self, direction: int) -> None:
        self.playback.step(direction)

    def action_seek_to(self, where: str) -> None:
        self.playback.to_end(where)

    def lift_pen(self) -> None:
        """A drag under way on the scene ends (quitting)."""
        try:
            self.query_one(SceneView).lift()
        except NoMatches:
            pass

    def action_undo(self) -> None:
        self.command("undo")

    def action_redo(self) -> None:
        self.command("redo")

    def action_clear(self) -> None:
        self.command("clear")

    def action_label(self) -> None:
        view = self.view
        target = "selected" if view is not None and view.selected else "last"
        what = view.scene.called(view.selected) if view is not None and view.selected else "the last body drawn"

        def done(text: str | None) -> None:
            if text:
                self.command("label", target, text)
        self.app.push_screen(PromptModal(f"Label for {what}:", placeholder="ball"), done)

    def action_timeline(self) -> None:
        view = self.view
        text = "Nothing demonstrated yet: press d for demo mode and drag a body."
        if view is not None and view.timeline is not None and view.timeline.events:
            text = timeline_text(view.timeline, view.scene.names())
        self.app.push_screen(TextScreen("Timeline", text))

    def action_settings(self) -> None:
        config = self.panel_app.config
        self.app.push_screen(SettingsScreen(config, self.query_one(SceneView).canvas_cells),
                             self.panel_app.adopt_settings)

    def set_theme(self, theme: str) -> None:
        self.theme_name = theme
        self.query_one(SceneView).set_theme(theme)

    def action_adopt(self) -> None:
        self.files.adopt()

    def action_simulate(self) -> None:
        self.background.simulate()

    def action_export(self) -> None:
        self.background.export()

    def action_picture(self) -> None:
        self.background.picture()

    def action_cancel(self) -> None:
        self.background.cancel()

    def stop_workers(self) -> None:
        """Quitting: the search and the export stop, and nothing they did reaches the session."""
        self.background.stop()

    def command(self, name: str, *args: str | float, project: dict[str, Any] | None = None) -> SessionInput | None:
        """Send the command ``name`` to the live session; the input it became (None when no session is live)."""
        return self.live.command(name, *args, project=project) if self.live is not None else None

    def action_help(self) -> None:
        self.app.push_screen(HelpScreen(((b.key.replace("full_stop", ".").replace("question_mark", "?"),
                                          b.description) for b in self.BINDINGS if isinstance(b, Binding)),
                                        vocabulary_lines(self.canvas)))

    # -- files ---------------------------------------------------------------------------------------------------

    def action_save(self) -> None:
        self.files.ask_save()

    def action_load(self) -> None:
        self.files.ask_load()

    def open_project(self, path: str | None) -> None:
        """Load the project at ``path`` (the TUI's PROJECT argument, the Load dialog)."""
        self.files.load(path)

    @property
    def project_path(self) -> str | None:
        """The project file last saved or loaded."""
        return self.files.path

    def mark_saved(self, view: SessionView) -> None:
        self.panel_app.mark_saved(view)
