"""The TUI keeps nothing the journal would not rebuild: its journal in the XDG data folder, recovery of an
unfinished session, Save and Load (a broken project keeps the work), the eraser, and the replayed demo."""

from __future__ import annotations

import asyncio
import json

from physink_tui.commands.demo import demo_journal
from physink_tui.formats.journal.entries import CommandEntry, PenEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.formats.project.files import load_project
from physink_tui.session.session import Session
from physink_tui.tui import storage
from physink_tui.tui.live import default_header
from physink_tui.tui.screens.modals import ConfirmModal, ErrorModal, PromptModal
from tests.tui_helpers import SIZE, box_points, cells_of, circle_points, click, drag, draw, tui_app, until, until_app


def run(coro) -> None:
    asyncio.run(coro)


def test_the_journal_rebuilds_what_the_tui_showed(tmp_path) -> None:
    app = tui_app(tmp_path)
    shown = {}

    async def go() -> None:
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, box_points(0.2, 0.5, 0.5, 0.8))], lambda v: len(v.scene.components) == 1)
            await draw(pilot, [cells_of(app, circle_points(0.7, 0.3, 100))], lambda v: len(v.scene.components) == 2)
            await pilot.press("l", *"ball", "enter")
            view = await until(pilot, lambda v: any(getattr(c, "label", None) == "ball"
                                                    for c in v.scene.components.values()))
            shown["scene"] = view.scene
            app.stop_live()
    run(go())
    journals = list((tmp_path / "sessions").glob("*.physink.jsonl"))
    assert len(journals) == 1
    journal = read_journal(journals[0])
    assert storage.finished(journal)
    assert any(isinstance(e, PenEntry) for e in journal.entries)
    replayed = Session.from_header(journal.header).run(journal.entries)
    assert replayed.scene == shown["scene"]


def test_an_unfinished_session_is_offered_for_recovery(tmp_path) -> None:
    folder = tmp_path / "sessions"
    folder.mkdir()
    old = folder / "20260101-000000-1.physink.jsonl"
    stroke = box_points(0.2, 0.3, 0.5, 0.6)
    with JournalWriter.create(old, default_header()) as writer:  # a crash: no end line
        writer.append(PenEntry(0.5, *stroke[0], 0.0, False, True, False, False, False))
        for i, (x, y) in enumerate(stroke):
            writer.append(PenEntry(0.51 + 0.01 * i, x, y, 0.6, True, True, False, False, False))
        writer.append(PenEntry(0.52 + 0.01 * len(stroke), *stroke[-1], 0.0, False, True, False, False, False))
    assert [p for p, _ in storage.unfinished_journals(folder)] == [old]

    async def go() -> None:
        app = tui_app(tmp_path, recover=True)
        async with app.run_test(size=SIZE) as pilot:
            await until_app(pilot, lambda: isinstance(app.screen, ConfirmModal), "the recovery question")
            await click(pilot, "#yes")
            view = await until(pilot, lambda v: len(v.scene.components) == 1)
            assert next(iter(view.scene.components.values())).shape == "box"
            assert view.t >= 0.6
    run(go())
    assert not old.exists() and old.with_name(old.name + storage.RECOVERED).exists()
    assert storage.unfinished_journals(folder) == []


def test_save_writes_the_project_and_load_reads_it_back(tmp_path) -> None:
    path = tmp_path / "machine.physink.json"

    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            drawn = await draw(pilot, [cells_of(app, box_points(0.2, 0.5, 0.5, 0.8))],
                               lambda v: len(v.scene.components) == 1)
            assert app.unsaved
            await pilot.press("ctrl+s")
            await until_app(pilot, lambda: isinstance(app.screen, PromptModal), "the save prompt")
            app.screen.query_one("Input").value = str(path)
            await pilot.press("enter")
            await until_app(pilot, lambda: not app.unsaved, "the project saved")
            assert path.exists()
            assert load_project(path).scene == drawn.scene
            await click(pilot, "#do-clear")
            await until(pilot, lambda v: not v.scene.components)
            await click(pilot, "#do-load")
            await until_app(pilot, lambda: isinstance(app.screen, PromptModal), "the load prompt")
            app.screen.query_one("Input").value = str(path)
            await pilot.press("enter")
            await until(pilot, lambda v: v.scene == drawn.scene)
            app.stop_live()
            journal = read_journal(app.live.journal_path)
            commands = [e for e in journal.entries if isinstance(e, CommandEntry)]
            assert [c.name for c in commands] == ["save", "clear", "load", "end"]
            assert commands[2].project == json.loads(path.read_text())
    run(go())


def test_loading_a_broken_project_shows_the_problem_and_keeps_the_work(tmp_path) -> None:
    broken = tmp_path / "broken.physink.json"
    broken.write_text('{"format": "physink-project", "version": 1, "canvas": [1600, 1000], "components": 5}')

    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            drawn = await draw(pilot, [cells_of(app, box_points(0.2, 0.5, 0.5, 0.8))],
                               lambda v: len(v.scene.components) == 1)
            app.main.open_project(str(broken))
            await until_app(pilot, lambda: isinstance(app.screen, ErrorModal), "the error")
            assert "broken.physink.json" in app.screen._message
            await pilot.press("enter")
            await until_app(pilot, lambda: app.screen is app.main, "the error closed")
            assert app.live.runner.latest_view().scene == drawn.scene
            app.main.open_project(str(tmp_path / "missing.physink.json"))
            await until_app(pilot, lambda: isinstance(app.screen, ErrorModal), "the error")
            assert "missing.physink.json" in app.screen._message
    run(go())


def test_the_right_button_erases(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, box_points(0.3, 0.4, 0.6, 0.7))], lambda v: len(v.scene.components) == 1)
            await drag(pilot, [(0.2 + 0.05 * k, 0.55) for k in range(11)], button=3)
            await until(pilot, lambda v: not v.scene.components)
    run(go())


def test_the_demo_is_replayed_into_the_live_session_and_leaves_the_user_in_control(tmp_path) -> None:
    header, entries = demo_journal()

    async def go() -> None:
        app = tui_app(tmp_path, header=header, entries=tuple(entries), speed=8.0)
        async with app.run_test(size=SIZE) as pilot:
            view = await until(pilot, lambda v: v.mode == "demo")
            assert len(view.scene.components) >= 7
            await until(pilot, lambda v: v.mode == "sketch" and v.timeline is not None)
            await until_app(pilot, lambda: app.main.query_one("#status").activity.startswith("replay done"),
                            "replay done in the status bar")
            await click(pilot, "#do-clear")
            await until(pilot, lambda v: not v.scene.components)
    run(go())


def test_physink_tui_project_opens_the_project(tmp_path) -> None:
    from physink_tui.formats.project.codec import Project
    from physink_tui.formats.project.files import save_project

    header, entries = demo_journal()
    session = Session.from_header(header).run(entries)
    path = tmp_path / "egg.physink.json"
    save_project(Project(session.scene, (), session.timeline, session.canvas), path)

    async def go() -> None:
        app = tui_app(tmp_path, project=str(path))
        async with app.run_test(size=SIZE) as pilot:
            view = await until(pilot, lambda v: v.scene == session.scene and v.timeline is not None)
            assert len(view.timeline.events) == len(session.timeline.events)
            assert app.main.project_path == str(path)
    run(go())


def test_a_journal_folder_that_cannot_be_made_is_said_and_the_session_runs_without(tmp_path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")

    async def go() -> None:
        app = tui_app(tmp_path, journal_dir=blocker / "sessions")
        async with app.run_test(size=SIZE) as pilot:
            await until_app(pilot, lambda: isinstance(app.screen, ErrorModal), "the error")
            assert "journal folder" in app.screen._message
            await pilot.press("enter")
            await click(pilot, "#do-demo")
            await until(pilot, lambda v: v.mode == "demo")
            assert app.live.journal_path is None
    run(go())
