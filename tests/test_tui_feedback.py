"""The TUI tells the person what happened (issue 30): each message the session reports (what a stroke became, a
selection, an erase) in the status line and in the narration log; the help shows the drawing vocabulary with the
sizes the interpretation uses; a long event name is readable; Save says where it wrote (the XDG projects folder by
default); a picture of the moment shown is exported beside the videos; the clock never passes the duration."""

from __future__ import annotations

import asyncio
import math
from pathlib import Path

import pytest

from physink_tui.commands.demo import demo_journal
from physink_tui.formats.project.files import load_project
from physink_tui.render.images import decode_png
from physink_tui.scene.interpretation.interpret import JOINT_MAX_SIZE
from physink_tui.session.modes.sketch import X_CANDIDATE, X_WAIT
from physink_tui.session.view import SessionView
from physink_tui.tui.drawing_help import DRAWING, vocabulary
from physink_tui.tui.screens.modals import HelpScreen, PromptModal
from physink_tui.tui.widgets.bars import StatusBar
from physink_tui.tui.widgets.message_log import MessageLog, line
from physink_tui.tui.widgets.timeline_tree import TimelineTree
from tests.tui_helpers import SIZE, cell, cells_of, circle_points, drag, draw, screen_is, tap, tui_app, until, until_app

GUARD = 60.0


@pytest.fixture(scope="module")
def egg() -> tuple:
    header, entries = demo_journal()
    return header, tuple(entries)


def shows_messages(app, view: SessionView) -> bool:
    """The status line shows the view's latest message and the log every message, in order."""
    main = app.main
    status, log = main.query_one(StatusBar), main.query_one(MessageLog)
    latest = view.messages[-1].text if view.messages else None
    return (latest is None or latest in status._shown) and log.written == [line(m) for m in view.messages]


async def shown(pilot, view: SessionView) -> None:
    """Wait until the screen shows ``view``'s messages (the newest view is drawn soon after it is made)."""
    app = pilot.app
    await until_app(pilot, lambda: shows_messages(app, app.live.runner.latest_view()), "the view's messages")


def test_each_message_of_the_session_is_in_the_status_line_and_the_narration_log(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            drawn = await draw(pilot, [cells_of(app, circle_points(0.5, 0.5, 120))],
                               lambda v: len(v.scene.components) == 1)
            await shown(pilot, drawn)
            (ball,) = drawn.scene.components
            assert any(m.kind == "outcome" for m in drawn.messages)  # what the stroke became, as the session says
            told = len(drawn.messages)
            await tap(pilot, cell(app, 0.5, 0.5))  # a tap selects: the session says so
            tapped = await until(pilot, lambda v: v.selected == ball and len(v.messages) > told, timeout=GUARD)
            await shown(pilot, tapped)
            assert ball in tapped.messages[-1].text
            await drag(pilot, [(0.35 + 0.3 * k / 12, 0.5) for k in range(13)], button=3)  # erased with the right button
            erased = await until(pilot, lambda v: not v.scene.components, timeout=GUARD)
            await shown(pilot, erased)
            assert [m.kind for m in erased.messages[len(tapped.messages):]].count("outcome") == 1  # the erase, said
            log = app.main.query_one(MessageLog)
            assert len(log.written) == len(erased.messages) >= 1 and log.lines  # drawn in the log
    asyncio.run(go())


def test_the_help_shows_each_gesture_drawn_with_the_sizes_the_interpretation_uses(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await pilot.press("question_mark")
            help_screen = await screen_is(pilot, HelpScreen)
            text = str(help_screen.query_one("#help-text").render())
            words = " ".join("".join(ch for ch in text if not 0x2800 <= ord(ch) <= 0x28FF).split())
            gestures = {g.name: g for g in vocabulary(app.main.canvas)}
            for gesture in gestures.values():
                assert " ".join(f"{gesture.name}: {gesture.meaning}".split()) in words
                for row in gesture.drawing:  # the little drawing, in braille dots, beside it
                    assert f"  {row}  " in text or f"  {row}\n" in text
            x = gestures["X in a body"].meaning  # the sizes are the interpretation's own
            arm = X_CANDIDATE * math.hypot(*app.main.canvas)
            assert f"{X_CANDIDATE:.0%} of the canvas diagonal ({arm:.0f} units)" in x and f"{X_WAIT:g} s" in x
            assert f"{JOINT_MAX_SIZE:.0%}" in gestures["small circle in a body"].meaning
            assert "ctrl+c" in words and "home" in words
    asyncio.run(go())


def test_the_drawings_are_of_the_gestures() -> None:
    """Each drawing has ink in it, and the pin's circle sits inside its body's outline."""
    gestures = {g.name: g for g in vocabulary((1600.0, 1000.0))}
    for gesture in gestures.values():
        assert len(gesture.drawing) == DRAWING[1] and all(len(row) == DRAWING[0] for row in gesture.drawing)
        assert sum(ch != "\u2800" for row in gesture.drawing for ch in row) >= 6, gesture.name
    pin = gestures["small circle in a body"].drawing
    assert pin[0][0] != "\u2800" and pin[1][DRAWING[0] // 2] != "\u2800"


def test_the_chosen_events_full_name_is_shown_below_the_tree(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None and len(v.timeline.events) > 3, timeout=GUARD)
            tree = app.main.query_one(TimelineTree)
            await until_app(pilot, lambda: tree.last_line > 2, "the timeline tree")
            cut = [tree.get_node_at_line(y) for y in range(tree.last_line + 1)
                   if str(tree.get_node_at_line(y).label).strip() not in tree.render_line(y).text]
            assert cut  # deep in the tree a long name is cut ("Contact between lever an")
            name = str(cut[-1].label).strip()
            tree.focus()
            tree.move_cursor(cut[-1])
            detail = app.main.query_one("#event-detail")
            await until_app(pilot, lambda: str(detail.render()) == name, "the event's full name")
            assert detail.size.height * detail.size.width >= len(name)  # wrapped, all of it on screen
    asyncio.run(go())


def test_save_offers_the_xdg_projects_folder_and_says_where_it_wrote(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    monkeypatch.chdir(tmp_path)
    projects = tmp_path / "data" / "physink" / "projects"

    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, circle_points(0.5, 0.5, 120))], lambda v: len(v.scene.components) == 1)
            await pilot.press("ctrl+s")
            prompt = await screen_is(pilot, PromptModal)
            offered = Path(prompt.query_one("#prompt-input").value)
            assert offered.parent == projects and offered.name.endswith(".physink.json")
            await pilot.press("enter")
            status = app.main.query_one(StatusBar)
            await until_app(pilot, lambda: status.activity == f"saved {offered}", "where the project went")
            assert len(load_project(offered).scene.components) == 1
            await pilot.press("ctrl+s")  # a bare name goes in the projects folder too
            prompt = await screen_is(pilot, PromptModal)
            assert prompt.query_one("#prompt-input").value == str(offered)  # the last place saved
            prompt.query_one("#prompt-input").value = "egg"
            await pilot.press("enter")
            await until_app(pilot, lambda: status.activity == f"saved {projects / 'egg.physink.json'}", "saved")
    asyncio.run(go())
    assert sorted(p.name for p in tmp_path.glob("*.json")) == []  # nothing where the program was started


def test_a_picture_of_the_moment_shown_is_exported_beside_the_videos(tmp_path, monkeypatch, egg) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None, timeout=GUARD)
            await pilot.press("d")
            await until(pilot, lambda v: v.mode == "demo" and v.duration > 1)
            await pilot.press("right", "right")
            await until(pilot, lambda v: math.isclose(v.clock, 1.0, abs_tol=1e-6))
            await pilot.click("#do-picture")
            status = app.main.query_one(StatusBar)
            await until_app(pilot, lambda: status.activity.startswith("picture saved to "), "the picture saved")
            return Path(status.activity.removeprefix("picture saved to "))
    path = asyncio.run(go())
    assert path.parent == tmp_path / "data" / "physink" / "exports" and path.suffix == ".png"
    pixels = decode_png(path.read_bytes())
    assert pixels.shape == (800, 1280, 4)
    assert len({tuple(p) for p in pixels[::16, ::16, :3].reshape(-1, 3)}) > 5  # the scene, not a blank page


def test_the_clock_never_shows_more_than_the_duration(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None, timeout=GUARD)
            await pilot.press("d")
            await until(pilot, lambda v: v.mode == "demo" and v.duration > 1)
            await pilot.press("space")  # played to the end: the session's clock stops at the first step past it
            await until(pilot, lambda v: v.playing)
            end = await until(pilot, lambda v: not v.playing and v.clock >= v.duration - 1e-6, timeout=GUARD)
            status, slider = app.main.query_one(StatusBar), app.main.query_one("#slider")
            await until_app(pilot, lambda: app.main.view is not None and app.main.view.revision >= end.revision,
                            "the last view drawn")  # the status bar and the slider show it
            assert slider.clock == min(end.clock, end.duration) == end.duration  # never past it (it was 3.41/3.40)
            assert f"{end.duration:5.2f}/{end.duration:.2f} s" in status._shown
            assert f"{end.duration:5.2f} / {end.duration:.2f} s" in str(slider.render())
    asyncio.run(go())
