"""The main screen's blocking work, each in a Textual worker thread: SIMULATE (a `SearchJob` on a snapshot of the
document, its progress in the `SearchBar`, cancel keeping the best so far, the result handed to the session as a
`Searched` entry; an edit meanwhile stops it before its next rollout and drops it) and the exports (a video of the
demonstration, a PNG of the moment shown): `BackgroundWork`, a helper the screen (`MainScreen`) owns, which sees the
screen through `Host` (its session, view, canvas and theme) and through Textual's `Screen` (workers, messages,
widgets).

A search never runs on the session's thread, so pen input and keys are handled while it runs; what it found
reaches the session as one ``simulate SEED BUDGET`` entry that a replay of the journal searches again to the same
result (`physink_tui.session.search_job`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Protocol

from textual.message import Message
from textual.screen import Screen

from physink_tui.errors import PhysinkError
from physink_tui.scene.components import Scene
from physink_tui.session import simulation
from physink_tui.session.search_job import Progress, SearchJob
from physink_tui.session.simulation import Searched, SessionInput
from physink_tui.session.view import SessionView
from physink_tui.sim.defaults import DEFAULT_SEED
from physink_tui.timeline.events import Timeline
from physink_tui.tui import storage
from physink_tui.tui.live import LiveSession
from physink_tui.tui.screens.modals import ErrorModal
from physink_tui.tui.widgets.bars import StatusBar
from physink_tui.tui.widgets.search_bar import SearchBar

DISCARDED = "simulation discarded: the machine changed while it searched (g searches again)"


class _Cancelled(Exception):
    """The export worker was cancelled (escape, quitting)."""


@dataclass
class SearchProgressed(Message, bubble=False):
    """A search's progress (posted from its worker after every rollout; only the latest one matters; for the screen
    alone, as `SearchFinished`)."""

    progress: Progress

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, SearchProgressed)


@dataclass
class SearchFinished(Message, bubble=False):
    """A search ended: what it offers the session (None when stopped before a rollout), or why it could not run."""

    job: SearchJob
    offer: Searched | None
    error: str | None = None


class Host(Protocol):
    """The screen as its background work sees it: the live session, the view shown and the canvas."""

    @property
    def live(self) -> LiveSession | None: ...

    @property
    def view(self) -> SessionView | None: ...

    @property
    def canvas(self) -> tuple[float, float]: ...

    @property
    def theme_name(self) -> str: ...


class BackgroundWork:
    """SIMULATE and export for a screen: ``screen`` runs the workers and receives their messages (it hands
    `SearchProgressed`, `SearchFinished` and `SearchBar.Cancel` to `progressed`, `finished` and `cancel`);
    ``host`` (the same screen) gives the session, the view and the canvas."""

    def __init__(self, screen: Screen[None], host: Host) -> None:
        self._screen = screen
        self._host = host
        self.job: SearchJob | None = None
        """The search running, or None."""
        self._simulating: SessionInput | None = None  # the simulate entry submitted, until the session handled it
        self._discarded: SearchJob | None = None  # a search stopped because the machine changed
        self._same: tuple[object, object] | None = None  # a (scene, timeline) found equal to the one searched
        self._simulated = ""  # what the status bar says once it has

    # -- SIMULATE ------------------------------------------------------------------------------------------------

    def simulate(self) -> None:
        """Search the document shown in a worker; with nothing to search, the session says what is missing."""
        screen, live = self._screen, self._host.live
        if live is None:
            return
        if self.job is not None:
            screen.notify("a search is running: escape (or Cancel) stops it, keeping the best so far",
                          severity="warning")
            return
        view = live.runner.latest_view() or self._host.view
        if view is None or view.timeline is None or simulation.missing(view.scene, view.timeline) is not None:
            live.command("simulate")  # the session tells what to do first (and journals the attempt)
            return
        budget = live.session.simulation_budget
        self._same = None
        self.job = SearchJob(view.scene, view.timeline, live.canvas, DEFAULT_SEED, budget,
                             on_progress=lambda progress: screen.post_message(SearchProgressed(progress)))
        screen.query_one(SearchBar).begin(budget)
        screen.query_one(StatusBar).set(activity="simulating (escape cancels)")
        screen.run_worker(partial(self._search, self.job), thread=True, exclusive=True, exit_on_error=False,
                          group="simulate", description="simulate")

    def _search(self, job: SearchJob) -> None:
        try:
            offer = job.run()
        except PhysinkError as exc:
            self._screen.post_message(SearchFinished(job, None, str(exc)))
            return
        self._screen.post_message(SearchFinished(job, offer))

    def progressed(self, message: SearchProgressed) -> None:
        if self.job is not None:
            self._screen.query_one(SearchBar).show(message.progress)

    def finished(self, message: SearchFinished) -> None:
        job, screen = message.job, self._screen
        if job is not self.job:
            return
        self.job = None
        screen.query_one(SearchBar).end()
        status = screen.query_one(StatusBar)
        live = self._host.live
        if live is None or live.stopped:
            return
        if message.error is not None:
            status.set(activity="")
            screen.app.push_screen(ErrorModal("Cannot simulate", message.error))
            return
        offer = message.offer
        latest = live.runner.latest_view()
        if job is self._discarded or (offer is not None and (latest is None
                                                             or not offer.searched(latest.scene, latest.timeline))):
            status.set(activity=DISCARDED)
            return
        if offer is None:
            status.set(activity="simulation cancelled before its first rollout")
            return
        self._simulating = live.submit(offer)
        rollouts = f"{offer.result.rollouts} rollout{'' if offer.result.rollouts == 1 else 's'}"
        self._simulated = (f"simulation stopped: the best of {rollouts} kept" if job.stopped else
                           f"simulation done in {rollouts}")
        status.set(activity="simulation: handing the result to the session")

    def drop_changed_search(self, view: SessionView) -> None:
        """Called with each view: once the machine differs from the one being searched, the search stops before its
        next rollout (the one under way ends) and what it found is dropped."""
        job = self.job
        if job is None or job.stopped:
            return
        if self._same is not None and view.scene is self._same[0] and view.timeline is self._same[1]:
            return  # judged equal before: views come up to 60 a second, and comparing timelines is not free
        if _searched(view, job.scene, job.timeline):
            self._same = (view.scene, view.timeline)
            return
        job.stop()
        self._discarded = job
        self._screen.query_one(StatusBar).set(activity=DISCARDED)

    def simulated(self, view: SessionView, status: StatusBar) -> None:
        """Called with each view: once the session handled the result, the status bar says so."""
        if self._simulating is not None and view.t >= self._simulating.t:
            self._simulating = None
            status.set(activity=self._simulated if view.search is not None else "")

    # -- export --------------------------------------------------------------------------------------------------

    def export(self) -> None:
        view, screen = self._host.view, self._screen
        if view is None or view.timeline is None or not view.timeline.events:
            screen.notify("nothing demonstrated to export yet", severity="warning")
            return
        screen.run_worker(partial(self._export, view, storage.exports_dir(), screen.query_one(StatusBar)),
                          thread=True, exclusive=True, exit_on_error=False, group="export",
                          description="export video")

    def _export(self, view: SessionView, folder: Path, status: StatusBar) -> None:
        from textual.worker import get_current_worker

        from physink_tui.render.export import Export, Look

        worker, app = get_current_worker(), self._screen.app
        folder.mkdir(parents=True, exist_ok=True)
        path = storage.new_journal_path(folder).with_suffix("").with_suffix(".mp4")

        def progress(done: int, total: int) -> None:
            if worker.is_cancelled:
                raise _Cancelled
            app.call_from_thread(status.set, activity=f"exporting {done}/{total} frames")

        try:
            Export(view.scene, view.timeline, self._host.canvas, Look(width=960, height=600)).video(path, progress)
        except _Cancelled:
            app.call_from_thread(status.set, activity="export cancelled")
            return
        except PhysinkError as exc:
            app.call_from_thread(app.push_screen, ErrorModal("Cannot export", str(exc)))
            return
        app.call_from_thread(status.set, activity=f"exported {path}")

    def picture(self) -> None:
        """A PNG of the moment the scene view shows (any mode), beside the videos in the exports folder."""
        host, screen = self._host, self._screen
        view = (host.live.runner.latest_view() if host.live is not None else None) or host.view
        if view is None:
            return
        screen.run_worker(partial(self._picture, view, storage.exports_dir(), host.theme_name,
                                  screen.query_one(StatusBar)),
                          thread=True, exit_on_error=False, group="picture", description="export picture")

    def _picture(self, view: SessionView, folder: Path, theme: str, status: StatusBar) -> None:
        from physink_tui.tui.picture import PICTURE_SIZE, write_picture

        app = self._screen.app
        try:
            folder.mkdir(parents=True, exist_ok=True)
            path = storage.new_journal_path(folder).with_suffix("").with_suffix(".png")
            write_picture(path, view, self._host.canvas, theme, PICTURE_SIZE)
        except OSError as exc:
            app.call_from_thread(app.push_screen, ErrorModal("Cannot export", f"{folder}: {exc}"))
            return
        except PhysinkError as exc:
            app.call_from_thread(app.push_screen, ErrorModal("Cannot export", str(exc)))
            return
        app.call_from_thread(status.set, activity=f"picture saved to {path}")

    # -- both ----------------------------------------------------------------------------------------------------

    def cancel(self) -> None:
        """Escape: stop the search (its best so far goes to the session) and the export."""
        if self.job is not None and not self.job.stopped:
            self.job.stop()
            self._screen.query_one(StatusBar).set(activity="stopping the search after the rollout under way…")
        self._screen.workers.cancel_group(self._screen, "export")

    def stop(self) -> None:
        """Quitting: the search and the export stop, and nothing they did reaches the session."""
        job, self.job = self.job, None  # its end is then ignored
        if job is not None:
            job.stop()
        self._screen.workers.cancel_group(self._screen, "export")


def _searched(view: SessionView, scene: Scene, timeline: Timeline) -> bool:
    """Whether ``view`` shows this scene and timeline (the same objects, or equal ones)."""
    return ((view.scene is scene or view.scene == scene)
            and (view.timeline is timeline or view.timeline == timeline))
