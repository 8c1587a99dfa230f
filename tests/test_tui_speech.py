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
from physink_tui.tui.screens.main import SpeechStatus
from physink_tui.tui.widgets.bars import StatusBar
from tests.test_speech_microphone import FakeStream
from tests.tui_helpers import SIZE, box_points, cells_of, drag_cells, tui_app, until, until_app

SPEECH = Path(__file__).parent / "speech"
FRAME = 0.05
"""Session seconds that let a view go out (more than a frame at the app's 60 a second)."""


def in_a_quiet_room(fixture: str, seed: int) -> np.ndarray:
    """A recorded command with half a second of room noise before and after it."""
    gap = np.random.default_rng(seed).normal(0, 8, RATE // 2).astype(np.int16)
    return np.concatenate([gap, read_wav(SPEECH / fixture), gap])


def said(messages: list) -> list[str]:
    """The speech statuses the app went through (its `SpeechStatus` messages, each once as it bubbles), in order."""
    once = {id(m): m for m in messages if isinstance(m, SpeechStatus)}  # the list holds them: ids are not reused
    return [m.text for m in once.values()]


def test_saying_label_ball_after_drawing_a_box_labels_it(tmp_path) -> None:
    recording = in_a_quiet_room("cmd00_0.wav", 5)  # "label ball"
    messages: list = []

    async def go() -> None:
        app = tui_app(tmp_path, microphone=lambda deliver: FakeStream(recording, deliver))
        async with app.run_test(size=SIZE, message_hook=messages.append) as pilot:
            await until(pilot, lambda v: True)
            # session time stands still from the drawing to the words: the box is the part drawn just before
            # them however long the recogniser takes to load (views wait: the statuses are messages)
            with app.options.clock.held():
                await drag_cells(pilot, cells_of(app, box_points(0.2, 0.4, 0.5, 0.6)))  # a box
                await pilot.press("v")  # listen: the recording plays
                await until_app(pilot, lambda: "speech: listening (press v again to stop)" in said(messages))
                await pilot.press("v")  # stop: what was said is heard
                await until_app(pilot, lambda: any(s.startswith("speech: off") for s in said(messages)))
            view = await until(pilot, lambda v: any(getattr(c, "label", None) == "ball"
                                                    for c in v.scene.components.values()))
            assert [c.label for c in view.scene.components.values() if isinstance(c, Body)] == ["ball"]
            assert said(messages) == ["speech: listening (press v again to stop)", 'speech: heard "label ball"',
                                      'speech: off (last heard "label ball")']
            await until_app(pilot, lambda: app.main.query_one(StatusBar).speech == said(messages)[-1])
    asyncio.run(go())


def test_holding_the_barrel_button_listens_until_it_is_released(tmp_path) -> None:
    recording = in_a_quiet_room("cmd02_0.wav", 6)  # "label basket"
    messages: list = []

    async def go() -> None:
        app = tui_app(tmp_path, microphone=lambda deliver: FakeStream(recording, deliver))
        async with app.run_test(size=SIZE, message_hook=messages.append) as pilot:
            await until(pilot, lambda v: True)
            assert app.live is not None

            def hover(button: bool) -> None:
                assert app.live is not None
                app.live.submit(PenEntry(0.0, 0.8, 0.2, 0.0, False, True, False, button, False))

            # as in the test above, session time stands still from the drawing to the words; the pen's button
            # reaches the screen in a view, which goes out once the clock is a frame on
            with app.options.clock.held() as clock:
                await drag_cells(pilot, cells_of(app, box_points(0.2, 0.4, 0.5, 0.6)))  # a box
                hover(False)
                hover(True)  # the barrel button held while hovering: listening, the recording plays
                clock.step(FRAME)
                await until_app(pilot, lambda: "speech: listening (release the pen button to stop)" in said(messages))
                hover(False)  # released: what was said is heard (if it was not already, at its pause)
                clock.step(FRAME)
                await until_app(pilot, lambda: any(s.startswith("speech: off") for s in said(messages)))
            view = await until(pilot, lambda v: any(getattr(c, "label", None) == "basket"
                                                    for c in v.scene.components.values()))
            assert [c.label for c in view.scene.components.values() if isinstance(c, Body)] == ["basket"]
            assert said(messages) == ["speech: listening (release the pen button to stop)",
                                      'speech: heard "label basket"', 'speech: off (last heard "label basket")']
            await until_app(pilot, lambda: app.main.query_one(StatusBar).speech == said(messages)[-1])
    asyncio.run(go())


def test_without_a_microphone_the_status_bar_says_why(tmp_path) -> None:
    messages: list = []

    async def go() -> None:
        app = tui_app(tmp_path)  # the real sounddevice input: this machine has none
        async with app.run_test(size=SIZE, message_hook=messages.append) as pilot:
            await until(pilot, lambda v: True)
            await pilot.press("v")
            await until_app(pilot, lambda: any(isinstance(m, SpeechStatus) for m in messages), "a speech status")
            speech = next(m.text for m in messages if isinstance(m, SpeechStatus))
            assert "microphone" in speech.lower() or "portaudio" in speech.lower(), speech
            assert app.live is not None and app.live.runner.error is None
    asyncio.run(go())
