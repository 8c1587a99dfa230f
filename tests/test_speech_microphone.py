"""Listening on a microphone without one: a fake input stream fed from a fixture on its own thread runs the real
listening thread, detector and recogniser; no PortAudio or no device is a `MicrophoneError`."""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from physink_tui.errors import MicrophoneError
from physink_tui.input.speech.audio import RATE, read_wav
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.listener import Listener, Utterance
from physink_tui.input.speech.microphone import BLOCK, MicrophoneListener, sounddevice_stream

SPEECH = Path(__file__).parent / "speech"


class FakeStream:
    """Delivers ``samples`` in sound-card blocks from a thread once started, like PortAudio's callback."""

    def __init__(self, samples: np.ndarray, deliver: Callable[[bytes], None]) -> None:
        self.samples, self.deliver = samples, deliver
        self.thread = threading.Thread(target=self._run)
        self.stopped = threading.Event()

    def start(self) -> None:
        self.thread.start()

    def _run(self) -> None:
        for i in range(0, len(self.samples), BLOCK):
            if self.stopped.is_set():
                return
            self.deliver(self.samples[i:i + BLOCK].astype("<i2").tobytes())

    def stop(self) -> None:
        self.thread.join()  # a recording is delivered whole before stopping
        self.stopped.set()

    def close(self) -> None:
        pass


def test_each_utterance_is_heard_with_the_time_it_began() -> None:
    rng = np.random.default_rng(3)
    gap = rng.normal(0, 8, RATE).astype(np.int16)
    label, phrase = read_wav(SPEECH / "cmd00_0.wav"), read_wav(SPEECH / "cmd09_0.wav")
    stream = np.concatenate([gap, label, gap, phrase])  # push-to-talk released right after the phrase
    heard: list[Utterance] = []
    listener = Listener(make_recogniser(), ["platform a"])
    mic = MicrophoneListener(listener, heard.append, clock=lambda: 100.0,
                             stream=lambda deliver: FakeStream(stream, deliver))
    mic.start()
    assert mic.listening
    mic.stop()
    assert not mic.listening
    assert [u.command.as_json() if u.command else u.rejected for u in heard] == [
        {"kind": "label", "label": "ball"},
        {"kind": "phrase", "text": "the ball falls", "subject": "ball", "verb": "falls", "preposition": None,
         "object": None}]
    first_word = 1.0 + 0.3  # the fixtures have 0.3 s of quiet before the speech
    assert heard[0].began == pytest.approx(100.0 + first_word, abs=0.15)
    second = 1.0 + len(label) / RATE + 1.0 + 0.3
    assert heard[1].began == pytest.approx(100.0 + second, abs=0.15)


def test_without_portaudio_listening_is_a_microphone_error(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "sounddevice", None)  # import fails as it does without the library
    mic = MicrophoneListener(Listener(make_recogniser()), lambda u: None)
    with pytest.raises(MicrophoneError, match=r"PortAudio cannot be loaded.*libportaudio2"):
        mic.start()
    assert not mic.listening
    mic.stop()  # harmless


def test_an_unknown_input_device_is_a_microphone_error() -> None:
    pytest.importorskip("sounddevice", reason="needs PortAudio (libportaudio2)")
    with pytest.raises(MicrophoneError, match="no microphone: cannot record from input device 'no such mic'"):
        sounddevice_stream("no such mic")(lambda block: None)
