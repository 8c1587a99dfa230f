"""SVG snapshots of the TUI's main states (pytest-textual-snapshot; review the pictures before updating them with
``--snapshot-update``): empty, the egg cracker sketched, its demonstration played back, the timeline as text, a
simulation's result in red and a search's progress line.

The states are built from journal entries handled before the live session starts, so each picture is the same
on every run (no tablet, no journal file named in the status bar).
"""

from __future__ import annotations

from pathlib import Path

from physink_tui.commands.demo import demo_journal
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.session.search_job import Progress
from physink_tui.tui.app import TuiOptions, make_app
from physink_tui.tui.screens.modals import TextScreen
from physink_tui.tui.widgets.search_bar import SearchBar
from tests.tui_helpers import SIZE, until_app, until_shown

NO_SETTINGS = Path("/nonexistent/physink/config.json")
"""The default settings, whatever the user's own are."""


def app_with(prior=(), header=None):
    return make_app(TuiOptions(header=header, prior=tuple(prior), tablet=False, journal=False, recover=False,
                               config_path=NO_SETTINGS))


def waiting_for(predicate, *keys, then=lambda app: True):
    """Wait until the screen shows a view satisfying ``predicate``, press ``keys``, wait until ``then(app)``."""
    async def run_before(pilot) -> None:
        await until_shown(pilot, predicate)
        if keys:
            await pilot.press(*keys)
            await until_app(pilot, lambda: then(pilot.app), "what the keys open")
            await pilot.pause()
    return run_before


def sketched():
    """The egg cracker drawn and labelled, before the demonstration."""
    header, entries = demo_journal()
    first_mode = next(i for i, e in enumerate(entries) if isinstance(e, CommandEntry) and e.name == "mode")
    return header, entries[:first_mode]


def demonstrated(at: float):
    """The egg cracker demonstrated, then shown in demo mode at timeline time ``at``."""
    header, entries = demo_journal()
    end = entries[-1].t
    return header, [*entries, CommandEntry(end + 0.1, "mode", ("demo",)), CommandEntry(end + 0.2, "seek", (at,))]


def test_empty(snap_compare) -> None:
    assert snap_compare(app_with(), terminal_size=SIZE, run_before=waiting_for(lambda v: True))


def test_egg_cracker_sketched(snap_compare) -> None:
    header, prior = sketched()
    assert snap_compare(app_with(prior, header), terminal_size=SIZE,
                        run_before=waiting_for(lambda v: len(v.scene.components) >= 8))


def test_demo_playback(snap_compare) -> None:
    header, prior = demonstrated(1.0)
    assert snap_compare(app_with(prior, header), terminal_size=SIZE,
                        run_before=waiting_for(lambda v: v.mode == "demo" and v.clock == 1.0))


def test_timeline_view(snap_compare) -> None:
    header, prior = demonstrated(1.0)
    assert snap_compare(app_with(prior, header), terminal_size=SIZE,
                        run_before=waiting_for(lambda v: v.mode == "demo" and v.clock == 1.0, "t",
                                               then=lambda app: isinstance(app.screen, TextScreen)))


def test_simulation_result(snap_compare) -> None:
    """Pinball simulated (found in its first rollout): the simulated paths drawn in red over the scene."""
    journal = read_journal(Path(__file__).parent / "journals" / "pinball.physink.jsonl")
    entries = [e for e in journal.entries if not (isinstance(e, CommandEntry) and e.name == "end")]
    prior = [*entries, CommandEntry(entries[-1].t + 0.1, "simulate", (0, 20))]
    assert snap_compare(app_with(prior, journal.header), terminal_size=SIZE,
                        run_before=waiting_for(lambda v: v.search is not None))


def test_searching(snap_compare) -> None:
    """The progress line of a search (a fixed progress: the search itself is not run)."""
    header, prior = sketched()

    async def run_before(pilot) -> None:
        await waiting_for(lambda v: len(v.scene.components) >= 8)(pilot)
        bar = pilot.app.main.query_one(SearchBar)
        bar.begin(200)
        bar.show(Progress(37, 200, 2.0, 135.25))
        await pilot.pause()
    assert snap_compare(app_with(prior, header), terminal_size=SIZE, run_before=run_before)
