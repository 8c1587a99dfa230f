"""Push-to-talk in the TUI: `v` listens, `v` again stops, and so does holding the pen's barrel button; a recording
fed as the microphone (the real listening thread, voice detector and recogniser) labels the body just drawn; without
a microphone the status bar says why."""

from __future__ import annotations

import asyncio
from pathlib import Path

import numpy as np

from physink_tui.formats.journal.entries import PenEntry
from physink_tui.input.speech.audio import RATE, read_wav
from physink_tui.scene.components import Body
from physink_tui.tui.widgets.bars import StatusBar
from tests.test_speech_microphone import FakeStream
from tests.tui_helpers import SIZE, box_points, cells_of, draw, tui_app, until

SPEECH = Path(__file__).parent / "speech"


def in_a_quiet_room(fixture: str, seed: int) -> np.ndarray:
    """A recorded command with half a second of room noise before and after it."""
    gap = np.random.default_rng(seed).normal(0, 8, RATE // 2).astype(np.int16)
    return np.concatenate([gap, read_wav(SPEECH / fixture), gap])


def test_saying_label_ball_after_drawing_a_box_labels_it(tmp_path) -> None:
    recording = in_a_quiet_room("cmd00_0.wav", 5)  # "label ball"

    async def go() -> None:
        app = tui_app(tmp_path, microphone=lambda deliver: FakeStream(recording, deliver))
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, box_points(0.2, 0.4, 0.5, 0.6))], lambda v: len(v.scene.components) == 1)
            await pilot.press("v")  # listen: the recording plays
            await pilot.pause(0.5)
            await pilot.press("v")  # stop: what was said is heard
            view = await until(pilot, lambda v: any(getattr(c, "label", None) == "ball"
                                                    for c in v.scene.components.values()), timeout=30.0)
            assert [c.label for c in view.scene.components.values() if isinstance(c, Body)] == ["ball"]
            for _ in range(50):  # the worker that stopped listening says so last
                await pilot.pause(0.1)
                if "off" in app.main.query_one(StatusBar).speech:
                    break
            assert app.main.query_one(StatusBar).speech == 'speech: off (last heard "label ball")'
    asyncio.run(go())


def test_holding_the_barrel_button_listens_until_it_is_released(tmp_path) -> None:
    recording = in_a_quiet_room("cmd02_0.wav", 6)  # "label basket"

    async def go() -> None:
        app = tui_app(tmp_path, microphone=lambda deliver: FakeStream(recording, deliver))
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await draw(pilot, [cells_of(app, box_points(0.2, 0.4, 0.5, 0.6))], lambda v: len(v.scene.components) == 1)
            assert app.live is not None

            def hover(button: bool) -> None:
                assert app.live is not None
                app.live.submit(PenEntry(0.0, 0.8, 0.2, 0.0, False, True, False, button, False))

            hover(False)
            hover(True)  # the barrel button held while hovering: listening, the recording plays
            await until(pilot, lambda v: any(state == "hovering with a button pressed" for state, _ in v.pens.values()))
            for _ in range(50):
                await pilot.pause(0.1)
                if "listening" in app.main.query_one(StatusBar).speech:
                    break
            assert app.main.query_one(StatusBar).speech == "speech: listening (release the pen button to stop)"
            await pilot.pause(0.5)
            hover(False)  # released: what was said is heard
            view = await until(pilot, lambda v: any(getattr(c, "label", None) == "basket"
                                                    for c in v.scene.components.values()), timeout=30.0)
            assert [c.label for c in view.scene.components.values() if isinstance(c, Body)] == ["basket"]
            for _ in range(50):
                await pilot.pause(0.1)
                if "off" in app.main.query_one(StatusBar).speech:
                    break
            assert app.main.query_one(StatusBar).speech == 'speech: off (last heard "label basket")'
    asyncio.run(go())


def test_without_a_microphone_the_status_bar_says_why(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)  # the real sounddevice input: this machine has none
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await pilot.press("v")
            for _ in range(200):
                await pilot.pause(0.1)
                speech = app.main.query_one(StatusBar).speech
                if speech.startswith("speech: ") and "starting" not in speech:
                    break
            assert "microphone" in speech.lower() or "portaudio" in speech.lower(), speech
            assert app.live is not None and app.live.runner.error is None
    asyncio.run(go())
