"""SIMULATE in the TUI: the search runs in a worker with a progress bar while pen input and keys go on; cancel
keeps the best so far; the result is drawn in red, journaled as ``simulate SEED BUDGET`` (a replay of the journal
finds the same), adopted into the project undoably and played back."""

from __future__ import annotations

import asyncio
import json
import threading
from functools import partial
from pathlib import Path

import pytest

from physink_tui import cli
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.timeline_json import timeline_object
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import evaluate_problem
from physink_tui.tui.screens import background
from physink_tui.tui.screens.background import SearchFinished, SearchProgressed
from physink_tui.tui.screens.modals import ConfirmModal
from physink_tui.tui.widgets.bars import NarrationBar
from physink_tui.tui.widgets.scene_view import SceneView
from physink_tui.tui.widgets.search_bar import SearchBar
from tests.tui_helpers import SIZE, click, tui_app, until, until_app

JOURNALS = Path(__file__).parent / "journals"


def recorded(name: str) -> tuple:
    journal = read_journal(JOURNALS / f"{name}.physink.jsonl")
    return journal.header, tuple(journal.entries)


def journaled(folder: Path) -> Session:
    """The session the app journaled into ``folder``/sessions, replayed."""
    (path,) = (folder / "sessions").glob("*.physink.jsonl")
    journal = read_journal(path)
    return Session.from_header(journal.header).run(journal.entries)


def simulate_args(folder: Path) -> list[tuple]:
    (path,) = (folder / "sessions").glob("*.physink.jsonl")
    return [e.args for e in read_journal(path).entries if getattr(e, "name", None) == "simulate"]


ENDLESS = 100_000
"""A budget no search here runs out before the test stops it (a search runs its whole budget, found or not): what
the keys meet is a search under way however fast the machine."""


def held_rollouts(monkeypatch) -> tuple[list[object], threading.Semaphore]:
    """Make the TUI's searches wait before each rollout until the test releases it: the candidates started so far
    and the semaphore to release them with (each wait gives up after 60 s, a hang guard)."""
    started: list[object] = []
    release = threading.Semaphore(0)

    def gated(problem, candidate):
        started.append(candidate)
        release.acquire(timeout=60)
        return evaluate_problem(problem, candidate)

    monkeypatch.setattr(background, "SearchJob", partial(background.SearchJob, evaluate=gated))
    return started, release


async def searching(pilot, app) -> SearchBar:
    """Once the demonstration is in, press Simulate (a search of `ENDLESS` rollouts) and wait for its first
    rollout; the search bar."""
    await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
    app.live.session.simulation_budget = ENDLESS
    await pilot.press("g")
    bar = app.main.query_one(SearchBar)
    await until_app(pilot, lambda: bar.progress is not None and bar.progress.rollouts >= 1)
    return bar


def test_simulate_shows_progress_then_the_result_in_red_and_the_journal_replays_to_it(tmp_path) -> None:
    header, entries = recorded("bouncing_above_b")
    messages: list = []

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE, message_hook=messages.append) as pilot:
            await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
            app.live.session.simulation_budget = 40
            await click(pilot, "#do-simulate")  # a search of well under a second: its progress is in the messages
            view = await until(pilot, lambda v: v.search is not None)
            assert view.search.found and view.search.budget == 40 and 1 <= view.search.rollouts < 40
            assert not app.main.query_one(SearchBar).display and app.main.background.job is None
            red = app.main.query_one(SceneView)._simulation_trails(view)
            assert red and all(trail.kind == "simulation" for trail in red)
            done = f"simulation done in {view.search.rollouts} rollouts"
            await until_app(pilot, lambda: app.main.query_one("#status").activity == done)
            assert view.messages[-1].text.startswith(f"simulation found in {view.search.rollouts} rollouts")
            shown = view.search
        return shown

    shown = asyncio.run(go())
    progress = [m.progress for m in messages if isinstance(m, SearchProgressed)]
    assert progress and progress[0].rollouts == 0 and all(p.budget == 40 for p in progress)
    assert [m.offer.result for m in messages if isinstance(m, SearchFinished)] == [shown]
    assert simulate_args(tmp_path) == [(0, 40)]
    assert journaled(tmp_path).view().search == shown


def test_keys_work_while_it_searches_and_cancel_keeps_the_best_so_far(tmp_path, monkeypatch) -> None:
    """Keys reach the session while a search runs, and escape stops it keeping the best so far. The rollouts are
    held by the test, so the search is still under way when the keys arrive however fast the machine (the cup
    dispenser's search may otherwise find its answer first)."""
    header, entries = recorded("cup_dispenser")
    started, release = held_rollouts(monkeypatch)

    async def go():
        app = tui_app(tmp_path, header=header, prior=tuple(entries))
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
            app.live.session.simulation_budget = ENDLESS
            await pilot.press("g")
            bar = app.main.query_one(SearchBar)
            await until_app(pilot, lambda: len(started) == 1)
            release.release()  # the first rollout ends; the second starts and is held
            await until_app(pilot, lambda: len(started) == 2 and bar.progress is not None
                            and bar.progress.rollouts >= 1)
            await pilot.press("d")  # the session takes keys while the search runs
            await until(pilot, lambda v: v.mode == "demo")
            assert app.main.background.job is not None and bar.display
            await pilot.press("g")  # a second search is refused while one runs
            await pilot.press("escape")
            release.release(ENDLESS)  # the held rollout ends; the stopped search starts no other
            view = await until(pilot, lambda v: v.search is not None)
            kept = view.search
            assert kept.budget == kept.rollouts and 1 <= kept.rollouts <= len(started) < ENDLESS
            assert view.mode == "demo"
            stopped = f"simulation stopped: the best of {kept.rollouts} rollout{'' if kept.rollouts == 1 else 's'} kept"
            await until_app(pilot, lambda: app.main.query_one("#status").activity == stopped)
        return kept

    kept = asyncio.run(go())
    assert simulate_args(tmp_path) == [(0, kept.rollouts)]
    assert journaled(tmp_path).view().search == kept


def test_a_search_of_a_machine_changed_meanwhile_is_discarded(tmp_path) -> None:
    header, entries = recorded("cup_dispenser")

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=tuple(entries))
        async with app.run_test(size=SIZE) as pilot:
            await searching(pilot, app)
            await pilot.press("c")  # clear: the machine searched is gone
            await until(pilot, lambda v: not v.scene.components)
            await pilot.press("escape")
            await until_app(pilot, lambda: app.main.background.job is None)
            await until_app(pilot, lambda: app.main.query_one("#status").activity.startswith(
                "simulation discarded: the machine changed"))
            assert app.live.runner.latest_view().search is None

    asyncio.run(go())
    assert simulate_args(tmp_path) == []


def test_an_adopted_simulation_is_undoable_and_plays_back(tmp_path) -> None:
    header, entries = recorded("pinball")

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            before = await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
            await pilot.press("g")
            found = await until(pilot, lambda v: v.search is not None)
            assert found.search.found
            await pilot.press("a")
            adopted = await until(pilot, lambda v: v.messages[-1].text.startswith("loaded simulation"))
            for body, p in found.search.parameters.bodies.items():  # the masses and frictions found
                material = adopted.scene.components[body].material
                assert material.friction == pytest.approx(p.friction, abs=1e-6)
            assert [e.type for e in adopted.timeline.events] == [e.type for e in found.search.timeline.events]
            assert adopted.timeline != before.timeline and adopted.can_undo
            await pilot.press("space")  # play the adopted simulation back
            await until(pilot, lambda v: v.mode == "demo" and v.playing and v.clock > 0.2)
            await pilot.press("u")
            await until(pilot, lambda v: v.scene == before.scene and v.timeline == before.timeline)

    asyncio.run(go())


def test_a_replay_can_end_with_simulate_as_the_demo_does(tmp_path) -> None:
    header, entries = recorded("pinball")

    async def go() -> None:
        app = tui_app(tmp_path, header=header, entries=entries, speed=20.0, simulate_after=True)
        async with app.run_test(size=SIZE) as pilot:
            view = await until(pilot, lambda v: v.search is not None)
            assert view.search.found and view.timeline is not None
            status = app.main.query_one("#status")  # the status bar follows the view it was handed next
            await until_app(pilot, lambda: status.activity.startswith("simulation done in"))
    asyncio.run(go())


def test_quitting_during_a_search_stops_it_and_journals_no_simulate(tmp_path) -> None:
    header, entries = recorded("cup_dispenser")
    jobs = []

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=tuple(entries))
        async with app.run_test(size=SIZE) as pilot:
            await searching(pilot, app)
            jobs.append(app.main.background.job)
            await pilot.press("q")
            await until_app(pilot, lambda: isinstance(app.screen, ConfirmModal) or app.live.stopped, "the quit")
            if isinstance(app.screen, ConfirmModal):  # unsaved work: quit all the same
                await click(pilot, "#yes")
            await until_app(pilot, lambda: jobs[0].stopped, "the search stopped")

    asyncio.run(go())
    (job,) = jobs  # the search stopped after its rollout under way, not at the end of its budget; the app closed
    assert job.stopped and job.rollouts < job.budget, (job.rollouts, job.budget)
    assert simulate_args(tmp_path) == []



def test_a_verdict_leaves_the_narration_once_the_machine_it_was_about_changed(tmp_path) -> None:
    from physink_tui.tui.widgets.bars import NarrationBar, StatusBar

    header, entries = recorded("pinball")

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            view = await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
            app.live.session.simulation_budget = 40
            await pilot.press("g")
            found = await until(pilot, lambda v: v.search is not None, timeout=60)
            narration, status = app.main.query_one(NarrationBar), app.main.query_one(StatusBar)
            verdict = found.messages[-1].text
            assert verdict.startswith("simulation found")
            await until_app(pilot, lambda: narration.text == verdict and verdict in status._shown)
            await pilot.press("u")  # the demonstration undone: the verdict is about a machine that is gone
            edited = await until(pilot, lambda v: v.search is None and v.timeline != view.timeline, timeout=60)
            await until_app(pilot, lambda: narration.text != verdict and verdict not in status._shown)
            assert verdict in [m.text for m in edited.messages]  # still in the narration log: it was said
            await pilot.press("r")
            await until(pilot, lambda v: v.timeline == view.timeline)

    asyncio.run(go())


def test_an_edit_stops_the_search_before_its_next_rollout(tmp_path, monkeypatch) -> None:
    """Clearing the machine while a search runs: the rollout under way ends, no other starts, nothing reaches the
    session, and the status says why."""
    header, entries = recorded("cup_dispenser")
    started, release = held_rollouts(monkeypatch)

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=tuple(entries))
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
            await pilot.press("g")
            await until_app(pilot, lambda: len(started) == 1)
            release.release()  # the first rollout ends; the second starts and is held
            await until_app(pilot, lambda: len(started) == 2)
            job = app.main.background.job
            await pilot.press("c")  # the machine cleared: the search stops before its next rollout
            await until_app(pilot, lambda: job.stopped)
            status = app.main.query_one("#status")
            assert status.activity.startswith("simulation discarded: the machine changed")
            for _ in range(Session.simulation_budget):
                release.release()
            await until_app(pilot, lambda: app.main.background.job is None)
            assert len(started) == 2  # no rollout started after the edit
            assert status.activity.startswith("simulation discarded: the machine changed")
            assert app.live.runner.latest_view().search is None

    asyncio.run(go())
    assert simulate_args(tmp_path) == []


def test_equiv_up_to_demonstrated_of_the_adopted_project_agrees_with_what_the_tui_said(tmp_path, capsys) -> None:
    header, entries = recorded("pinball")

    async def go():
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            before = await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
            await pilot.press("g")
            found = await until(pilot, lambda v: v.search is not None and any(
                m.text.startswith("simulation found in") for m in v.messages), timeout=60)
            bar = app.main.query_one(NarrationBar)  # the narration says it in the same words
            await until_app(pilot, lambda: "equivalent up to the last demonstrated event" in bar.text)
            await pilot.press("a")
            adopted = await until(pilot, lambda v: v.messages[-1].text.startswith("loaded simulation"))
        return before, found, adopted

    before, found, adopted = asyncio.run(go())
    told = next(m.text for m in found.messages if m.text.startswith("simulation found in"))
    assert "(equivalent up to the last demonstrated event: qualitative distance 0," in told
    names = before.scene.names()
    as_written = [timeline_object(t, names) for t in (adopted.demonstration, before.timeline,  # to 6 decimals
                                                      adopted.timeline, found.search.timeline)]
    assert as_written[0] == as_written[1] and as_written[2] == as_written[3]  # the demonstration kept beside it
    (journal,) = (tmp_path / "sessions").glob("*.physink.jsonl")
    assert cli.main(["replay", str(journal), "--out", str(tmp_path / "replayed")]) == 0  # the project it leaves
    capsys.readouterr()
    assert cli.main(["equiv", str(tmp_path / "replayed" / "project.json"), "--up-to-demonstrated", "--json"]) == 0
    said = json.loads(capsys.readouterr().out)
    assert said["equivalent"] is found.search.found is True
    assert said["qualitative_distance"] == found.search.qualitative_distance == 0
    assert said["quantitative_distance"] == pytest.approx(found.search.quantitative_distance, abs=1e-3)
    assert said["afterwards"] == found.search.afterwards
    if found.search.afterwards:
        assert told.endswith(f"; {found.search.afterwards}")
