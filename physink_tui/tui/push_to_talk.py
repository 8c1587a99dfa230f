"""Push-to-talk for the TUI: a key toggles listening on the microphone (terminals send no key release), and holding
the pen's barrel button listens while it is held; what is heard and accepted goes to the session as a ``say`` entry
stamped with the time the utterance began. Recognising is `input.speech`'s, acting on the words the session's.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable, Mapping

from physink_tui.errors import PhysinkError
from physink_tui.input.pen.state import PenState
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.listener import Listener, Utterance
from physink_tui.input.speech.microphone import MicrophoneListener, StreamFactory
from physink_tui.input.speech.recogniser import Recogniser
from physink_tui.session.runner import SessionRunner

BUTTON_STATES = frozenset({PenState.HOVERING_BUTTON.value, PenState.TOUCHING_BUTTON.value})
"""The pen states (`SessionView.pens`) in which a barrel button is held."""


def barrel_held(pens: Mapping[str, tuple[str, float]]) -> bool:
    """Whether some pen has a barrel button held, from a view's ``pens`` (device → (state, pressure)).

    >>> barrel_held({"usb0": ("hovering with a button pressed", 0.0)}), barrel_held({"usb0": ("hovering", 0.0)})
    (True, False)
    """
    return any(state in BUTTON_STATES for state, _ in pens.values())


class PushToTalk:
    """Listening for one live session.

    Args:
        runner: the live session's runner (`say` stamps utterances on its clock).
        status: called with a short line for the status bar (from any thread).
        stream: the sound input (default: the microphone through sounddevice; tests give a recording).
        recogniser: makes the recogniser on the first use (loading pocketsphinx's model takes a moment).
    """

    def __init__(self, runner: SessionRunner, status: Callable[[str], object], stream: StreamFactory | None = None,
                 recogniser: Callable[[], Recogniser] = make_recogniser) -> None:
        self.runner = runner
        self.status = status
        self._stream = stream
        self._make_recogniser = recogniser
        self._microphone: MicrophoneListener | None = None
        self._lock = threading.Lock()  # the key and the button each start a worker: one toggles at a time
        self._telling = threading.Lock()  # "listening" is told before anything heard on the listening thread
        self._by_button = False
        self.button_pressed = False
        """Whether the pen's barrel button is held, as last seen (set by the UI thread; `follow_button` acts on it,
        so workers that run out of order still end in the latest state)."""
        self.last_heard = ""

    @property
    def listening(self) -> bool:
        return self._microphone is not None and self._microphone.listening

    def toggle(self, labels: Iterable[str]) -> None:
        """Start listening (the grammar on ``labels``), or stop and hear the utterance under way. Blocks while the
        recogniser loads or the last utterance is decoded: call it from a worker thread."""
        with self._lock:
            self._by_button = False
            self._toggle(labels, "press v again to stop")

    def follow_button(self, labels: Iterable[str]) -> None:
        """Follow the pen's barrel button (`button_pressed`): pressed starts listening, released stops what the
        press started (and hears it). Blocks like `toggle`: call it from a worker thread."""
        with self._lock:
            pressed = self.button_pressed
            if pressed and not self.listening:
                self._toggle(labels, "release the pen button to stop")
                self._by_button = self.listening
            elif not pressed and self._by_button:
                self._by_button = False
                if self.listening:
                    self._toggle(labels, "")

    def _toggle(self, labels: Iterable[str], how_to_stop: str) -> None:
        if self.listening:
            assert self._microphone is not None
            self._microphone.stop()  # hears the utterance under way first
            self.status(f'speech: off (last heard "{self.last_heard}")' if self.last_heard else "speech: off")
            return
        with self._telling:  # what the listening thread hears waits until "listening" has been told
            try:
                if self._microphone is None:
                    listener = Listener(self._make_recogniser())
                    self._microphone = MicrophoneListener(listener, self._heard, clock=self.runner.now,
                                                          stream=self._stream)
                self._microphone.listener.set_words(labels)
                self._microphone.start()
            except PhysinkError as exc:  # no PortAudio, no microphone, no model
                self.status(f"speech: {exc}")
                return
            self.status(f"speech: listening ({how_to_stop})")

    def stop(self) -> None:
        """Stop listening, if listening (the session is ending)."""
        if self.listening:
            assert self._microphone is not None
            self._microphone.stop()

    def _heard(self, utterance: Utterance) -> None:
        with self._telling:
            self._tell_heard(utterance)

    def _tell_heard(self, utterance: Utterance) -> None:
        if utterance.command is None:
            self.status(f"speech: not understood ({utterance.rejected})")
            return
        self.runner.say(utterance.text, utterance.began)
        self.last_heard = utterance.text
        self.status(f'speech: heard "{utterance.text}"')
