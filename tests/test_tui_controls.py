"""Every control of the TUI, pressed through Pilot, does what it says to the session (checked in its views)."""

from __future__ import annotations

import asyncio
import math
import time
from pathlib import Path

import pytest
from textual.widgets import Tree

from physink_tui.commands.demo import demo_journal
from physink_tui.scene.components import Body
from physink_tui.tui.screens.main import MainScreen
from physink_tui.tui.screens.modals import ConfirmModal, ErrorModal, HelpScreen, PromptModal, TextScreen
from physink_tui.tui.widgets.controls import BUTTONS
from physink_tui.tui.widgets.scene_view import SceneView
from tests.tui_helpers import (
    HANG_GUARD,
    SIZE,
    box_points,
    cell,
    cells_of,
    circle_points,
    click,
    draw,
    tui_app,
    until,
    until_app,
)


@pytest.fixture(scope="module")
def egg() -> tuple:
    """The bundled egg cracker: drawn, labelled, demonstrated (its header and entries)."""
    header, entries = demo_journal()
    return header, tuple(entries)


def run(coro) -> None:
    asyncio.run(coro)


def test_every_button_names_an_action_of_the_screen() -> None:
    for action, _ in BUTTONS:
        assert callable(getattr(MainScreen, f"action_{action}")), action


def test_sketch_and_demo_switch_the_mode_by_button_and_key(tmp_path) -> None:
    async def go() -> None:
        async with tui_app(tmp_path).run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.mode == "sketch")
            await click(pilot, "#do-demo")
            await until(pilot, lambda v: v.mode == "demo")
            await click(pilot, "#do-sketch")
            await until(pilot, lambda v: v.mode == "sketch")
            await pilot.press("d")
            await until(pilot, lambda v: v.mode == "demo")
            await pilot.press("s")
            await until(pilot, lambda v: v.mode == "sketch")
    run(go())


def test_undo_redo_and_clear(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        async with tui_app(tmp_path, header=header, prior=entries).run_test(size=SIZE) as pilot:
            start = await until(pilot, lambda v: len(v.scene.components) > 5)
            await click(pilot, "#do-undo")
            undone = await until(pilot, lambda v: v.can_redo)
            assert (undone.scene, undone.timeline) != (start.scene, start.timeline)
            await click(pilot, "#do-redo")
            await until(pilot, lambda v: not v.can_redo and v.scene == start.scene)
            await click(pilot, "#do-clear")
            await until(pilot, lambda v: not v.scene.components and v.timeline is None)
            await pilot.press("u")
            await until(pilot, lambda v: v.scene == start.scene)
    run(go())


def test_play_pause_stop_and_the_arrow_keys_move_the_playback(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        async with tui_app(tmp_path, header=header, prior=entries).run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None)
            await click(pilot, "#do-demo")
            await until(pilot, lambda v: v.mode == "demo" and v.duration > 1)
            await click(pilot, "#do-play_pause")
            playing = await until(pilot, lambda v: v.playing and v.clock > 0.2)
            await click(pilot, "#do-play_pause")
            paused = await until(pilot, lambda v: not v.playing)
            assert paused.clock >= playing.clock
            await click(pilot, "#do-stop")
            await until(pilot, lambda v: not v.playing and v.clock == 0.0)
            await pilot.press("right")
            await until(pilot, lambda v: math.isclose(v.clock, 0.5, abs_tol=1e-6))
            await pilot.press("left")
            await until(pilot, lambda v: v.clock == 0.0)
    run(go())


def test_choosing_a_timeline_event_seeks_to_it(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None)
            tree = app.main.query_one(Tree)
            await until_app(pilot, lambda: any("Contact" in str(n.label) for n in _nodes(tree.root)),
                            "a contact in the timeline tree")
            node = next(n for n in _nodes(tree.root) if "Contact" in str(n.label))
            tree.move_cursor(node)
            tree.action_select_cursor()
            t, components = node.data
            view = await until(pilot, lambda v: v.mode == "demo" and math.isclose(v.clock, t, abs_tol=1e-5))
            assert view.clock > 0 and len(components) == 2
            scene = app.main.query_one(SceneView)  # the event's bodies are outlined
            await until_app(pilot, lambda: scene.highlight == frozenset(components), "the event's bodies outlined")
    run(go())


def _nodes(node):
    for child in node.children:
        yield child
        yield from _nodes(child)


def test_label_names_the_last_body_drawn(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, box_points(0.3, 0.4, 0.6, 0.7))], lambda v: len(v.scene.components) == 1)
            await click(pilot, "#do-label")
            await until_app(pilot, lambda: isinstance(app.screen, PromptModal), "the label prompt")
            await pilot.press(*"crate", "enter")
            view = await until(pilot, lambda v: any(getattr(c, "label", None) == "crate"
                                                    for c in v.scene.components.values()))
            assert [c.label for c in view.scene.components.values() if isinstance(c, Body)] == ["crate"]
    run(go())


def test_timeline_shows_the_narrated_timeline(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None)
            await click(pilot, "#do-timeline")
            await until_app(pilot, lambda: isinstance(app.screen, TextScreen), "the timeline screen")
            assert "Movement of ball CAUSES" in app.screen._text
            await pilot.press("escape")
            await until_app(pilot, lambda: isinstance(app.screen, MainScreen), "the main screen back")
    run(go())


def test_simulate_searches_then_adopt_and_undo(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None)
            app.live.session.simulation_budget = 2
            await click(pilot, "#do-simulate")
            view = await until(pilot, lambda v: v.search is not None, timeout=60)
            assert view.search.rollouts <= 2 and view.search.budget == 2
            assert "rollout" in view.messages[-1].text
            red = app.main.query_one(SceneView)._simulation_trails(view)  # the result's paths, drawn in red
            assert red and all(trail.kind == "simulation" for trail in red)
            done = f"simulation done in {view.search.rollouts} rollout" + ("" if view.search.rollouts == 1 else "s")
            await until_app(pilot, lambda: app.main.query_one("#status").activity == done, done)
            before = view
            await pilot.press("a")  # adopt: the parameters into the scene, the simulated timeline as the project's
            adopted = await until(pilot, lambda v: v.messages[-1].text.startswith("loaded simulation"))
            for body, p in before.search.parameters.bodies.items():  # the masses and frictions found
                material = adopted.scene.components[body].material
                assert material.friction == pytest.approx(p.friction, abs=1e-6)
            assert adopted.timeline is not None and adopted.can_undo
            assert [e.type for e in adopted.timeline.events] == [e.type for e in before.search.timeline.events]
            assert adopted.timeline != before.timeline
            await pilot.press("u")
            await until(pilot, lambda v: v.scene == before.scene and v.timeline == before.timeline)
    run(go())


def test_export_writes_a_video_of_the_demonstration(tmp_path, egg, monkeypatch) -> None:
    import av

    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None)
            await click(pilot, "#do-export")
            status = app.main.query_one("#status")
            await until_app(pilot, lambda: status.activity.startswith("exported") or isinstance(app.screen, ErrorModal),
                            "the export")
            assert status.activity.startswith("exported"), getattr(app.screen, "_message", status.activity)
    run(go())
    videos = list((tmp_path / "data" / "physink" / "exports").glob("*.mp4"))
    assert len(videos) == 1
    with av.open(str(videos[0])) as video:
        frames = sum(1 for _ in video.decode(video=0))
    assert frames > 30


def test_help_lists_every_key_binding(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("question_mark")
            await until_app(pilot, lambda: isinstance(app.screen, HelpScreen), "the help screen")
            text = str(app.screen.query_one("#help-text").render())
            for binding in MainScreen.BINDINGS:
                assert binding.description in text
            await pilot.press("escape")
            await until_app(pilot, lambda: isinstance(app.screen, MainScreen), "the main screen back")
    run(go())


def test_a_terminal_too_small_shows_a_notice(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.resize_terminal(50, 12)
            await until_app(pilot, lambda: app.main.has_class("too-small"), "the too-small notice")
            assert "needs at least" in str(app.main.query_one("#too-small").render())
            await pilot.resize_terminal(*SIZE)
            await until_app(pilot, lambda: not app.main.has_class("too-small"), "the notice gone")
    run(go())


def test_quitting_with_unsaved_work_asks(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, box_points(0.3, 0.4, 0.6, 0.7))], lambda v: len(v.scene.components) == 1)
            await pilot.press("q")
            await until_app(pilot, lambda: isinstance(app.screen, ConfirmModal), "the question")
            await pilot.press("n")
            await until_app(pilot, lambda: isinstance(app.screen, MainScreen), "the main screen back")
            assert not app.live.stopped
            await pilot.press("q")
            await until_app(pilot, lambda: isinstance(app.screen, ConfirmModal), "the question again")
            await pilot.press("y")
            await until_app(pilot, lambda: app.live.stopped, "the session stopped")
    run(go())


def test_clicking_the_time_slider_seeks(tmp_path, egg) -> None:
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            view = await until(pilot, lambda v: v.timeline is not None and v.duration > 1)
            slider = app.main.query_one("#slider")
            width = slider._bar_width()
            await pilot.click("#slider", offset=((width - 1) // 2, 0))
            want = round(((width - 1) // 2) / (width - 1) * view.duration, 6)
            await until(pilot, lambda v: v.mode == "demo" and math.isclose(v.clock, want, abs_tol=1e-5))
    run(go())


def test_the_status_bar_says_recording_while_the_pen_demonstrates(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, circle_points(0.5, 0.5, 100))], lambda v: len(v.scene.components) == 1)
            await pilot.press("d")
            await until(pilot, lambda v: v.mode == "demo")
            status = app.main.query_one("#status")
            await pilot.mouse_down(SceneView, offset=cell(app, 0.5, 0.5))
            await until(pilot, lambda v: any(s == "touching" for s, _ in v.pens.values()))
            await until_app(pilot, lambda: "● recording" in str(status.render()), "recording in the status bar")
            assert "0.60" in str(status.render())
            await pilot.hover(SceneView, offset=cell(app, 0.6, 0.5))
            await pilot.mouse_up(SceneView, offset=cell(app, 0.6, 0.5))
            await until(pilot, lambda v: v.timeline is not None and v.timeline.events)
    run(go())


def test_escape_cancels_an_export(tmp_path, egg, monkeypatch) -> None:
    """The worker stops at the next frame once cancelled (a stand-in for the encoder that goes on until it is
    stopped: the real one writes this timeline in well under a second; the hang guard ends it if never)."""
    from physink_tui.render.export import Export

    def endless_video(self, path, progress=None) -> None:
        frames = int(HANG_GUARD / 0.02)
        for i in range(frames):
            time.sleep(0.02)
            progress(i + 1, frames)
        Path(path).write_bytes(b"not reached")

    monkeypatch.setattr(Export, "video", endless_video)
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    header, entries = egg

    async def go() -> None:
        app = tui_app(tmp_path, header=header, prior=entries)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None)
            status = app.main.query_one("#status")
            await pilot.press("e")
            await until_app(pilot, lambda: status.activity.startswith("exporting"), "the export under way")
            await pilot.press("escape")
            await until_app(pilot, lambda: not status.activity.startswith("exporting"), "the export's end")
            assert status.activity == "export cancelled"
    run(go())
    assert not list((tmp_path / "data" / "physink" / "exports").glob("*.mp4"))
