"""Keys on the main screen (issue 30): the playback keys (space, ←, →, home, end) work whichever widget has focus
while a text input keeps its keys; every press counts, even before the session has handled the one before; ctrl+c
quits as q does, asking when there is unsaved work, also in the middle of a drag, and twice quits."""

from __future__ import annotations

import asyncio
import math
import threading

import pytest
from textual.widgets import Button, Input, Tree

from physink_tui.commands.demo import demo_journal
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.tui.screens.modals import ConfirmModal, PromptModal
from physink_tui.tui.widgets.message_log import MessageLog
from physink_tui.tui.widgets.scene_view import SceneView
from physink_tui.tui.widgets.timeline_tree import TimelineTree
from tests.tui_helpers import SIZE, cells_of, circle_points, draw, screen_is, tui_app, until, until_app

GUARD = 60.0


@pytest.fixture(scope="module")
def egg() -> tuple:
    header, entries = demo_journal()
    return header, tuple(entries)


def seeks(folder) -> list[float]:
    (path,) = (folder / "sessions").glob("*.physink.jsonl")
    return [e.args[0] for e in read_journal(path).entries if isinstance(e, CommandEntry) and e.name == "seek"]


async def in_demo_mode(pilot) -> None:
    await until(pilot, lambda v: v.timeline is not None and bool(v.timeline.events), timeout=GUARD)
    await pilot.press("d")
    await until(pilot, lambda v: v.mode == "demo" and v.duration > 2, timeout=GUARD)


def test_the_playback_keys_work_whichever_widget_has_focus(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await in_demo_mode(pilot)
            tree = app.main.query_one(TimelineTree)
            await until_app(pilot, lambda: tree.last_line > 2, "the timeline tree")
            await pilot.click(TimelineTree, offset=(6, 1))  # an event chosen: the tree has focus
            assert app.focused is tree
            chosen = await until(pilot, lambda v: v.clock > 0)
            expanded = [tree.get_node_at_line(y).is_expanded for y in range(tree.last_line + 1)]
            await pilot.press("space")  # plays; does not fold the event's branch
            await until(pilot, lambda v: v.playing, timeout=GUARD)
            await pilot.press("space")
            paused = await until(pilot, lambda v: not v.playing, timeout=GUARD)
            assert [tree.get_node_at_line(y).is_expanded for y in range(tree.last_line + 1)] == expanded
            await pilot.press("home")
            await until(pilot, lambda v: v.clock == 0.0, timeout=GUARD)
            await pilot.press("right")
            await until(pilot, lambda v: math.isclose(v.clock, 0.5, abs_tol=1e-6), timeout=GUARD)
            await pilot.press("end")
            await until(pilot, lambda v: v.clock == v.duration, timeout=GUARD)
            await pilot.press("left")
            await until(pilot, lambda v: math.isclose(v.clock, v.duration - 0.5, abs_tol=1e-6), timeout=GUARD)
            assert chosen.clock > 0 and paused.clock > 0
            for widget in (app.main.query_one("#do-stop", Button), app.main.query_one(MessageLog),
                           app.main.query_one(SceneView)):
                widget.focus()
                await until_app(pilot, lambda w=widget: app.focused is w, "the focus")
                await pilot.press("home")  # a focused log would scroll to its top; a focused button...
                await until(pilot, lambda v: v.clock == 0.0, timeout=GUARD)
                await pilot.press("space")
                await until(pilot, lambda v: v.playing, timeout=GUARD)
                await pilot.press("space")  # ...would be pressed (Stop)
                await until(pilot, lambda v: not v.playing and v.clock > 0, timeout=GUARD)
    asyncio.run(go())


def test_a_text_input_keeps_space_and_the_arrows(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await in_demo_mode(pilot)
            await pilot.press("l")
            prompt = await screen_is(pilot, PromptModal)
            await pilot.press("a", "space", "b", "left", "left", "home", "x", "end", "c")
            field = prompt.query_one(Input)
            await until_app(pilot, lambda: field.value == "xa bc", f"the typed text (is {field.value!r})")
            view = app.live.runner.latest_view()
            assert not view.playing and view.clock == 0.0
    asyncio.run(go())


def test_every_press_of_an_arrow_counts_before_the_session_has_handled_the_last(tmp_path, egg) -> None:
    header, entries = egg
    gate = threading.Event()

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await in_demo_mode(pilot)
            session = app.live.session
            handle = session.handle

            def held(entry):  # the session busy: the seeks wait, as they do behind a frame on a slow machine
                if isinstance(entry, CommandEntry) and entry.name == "seek":
                    gate.wait(GUARD)
                handle(entry)

            session.handle = held
            await pilot.press("right", "right", "right", "right")
            gate.set()
            await until(pilot, lambda v: math.isclose(v.clock, 2.0, abs_tol=1e-6), timeout=GUARD)
            await pilot.press("left", "left", "left")
            await until(pilot, lambda v: math.isclose(v.clock, 0.5, abs_tol=1e-6), timeout=GUARD)
            await pilot.press("q")  # seeking changes no work: it quits at once, the journal ended
            await until_app(pilot, lambda: app.return_code is not None, "the app ending")
    asyncio.run(go())
    assert seeks(tmp_path) == [0.5, 1.0, 1.5, 2.0, 1.5, 1.0, 0.5]


def test_ctrl_c_quits_at_once_when_nothing_is_unsaved(tmp_path) -> None:
    async def go() -> int | None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await pilot.press("ctrl+c")
            await until_app(pilot, lambda: app.return_code is not None, "the app ending")
        return app.return_code
    assert asyncio.run(go()) == 0


def test_ctrl_c_asks_when_there_is_unsaved_work_and_twice_quits(tmp_path) -> None:
    async def go() -> int | None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, circle_points(0.5, 0.5, 120))], lambda v: len(v.scene.components) == 1)
            await pilot.press("ctrl+c")
            await screen_is(pilot, ConfirmModal)
            await pilot.press("n")  # stay
            await until_app(pilot, lambda: app.screen is app.main, "the main screen back")
            assert app.return_code is None
            await pilot.press("ctrl+c")
            await screen_is(pilot, ConfirmModal)
            await pilot.press("ctrl+c")  # twice: quit
            await until_app(pilot, lambda: app.return_code is not None, "the app ending")
        return app.return_code
    assert asyncio.run(go()) == 0


def test_ctrl_c_in_the_middle_of_a_drag_ends_the_stroke_and_asks(tmp_path) -> None:
    async def go() -> int | None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            cells = cells_of(app, circle_points(0.5, 0.5, 120))
            await pilot.mouse_down(SceneView, offset=cells[0])
            for c in cells[1:12]:
                await pilot.hover(SceneView, offset=c)
            await until(pilot, lambda v: any(state == "touching" for state, _ in v.pens.values()) and bool(v.ink),
                        timeout=GUARD)
            await pilot.press("ctrl+c")
            await screen_is(pilot, ConfirmModal)  # a stroke was being drawn: that is unsaved work
            lifted = await until(pilot, lambda v: not v.ink and all(state != "touching" for state, _ in
                                                                    v.pens.values()), timeout=GUARD)
            assert lifted.pens
            await pilot.press("y")
            await until_app(pilot, lambda: app.return_code is not None, "the app ending")
        return app.return_code
    assert asyncio.run(go()) == 0


def test_the_tree_keeps_its_own_keys_for_moving_in_it(tmp_path, egg) -> None:
    """Up and down still move the tree's cursor (only the playback keys are the screen's)."""
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await in_demo_mode(pilot)
            tree = app.main.query_one(Tree)
            await until_app(pilot, lambda: tree.last_line > 2, "the timeline tree")
            tree.focus()
            await until_app(pilot, lambda: app.focused is tree, "the focus")
            start = tree.cursor_line
            await pilot.press("down", "down")
            await until_app(pilot, lambda: tree.cursor_line == start + 2, "the tree's cursor moving")
    asyncio.run(go())
