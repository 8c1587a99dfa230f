"""The kiosk's ears (``physink kiosk --speech``): the microphone listened to all the time, the voice-activity detector
cutting it into utterances, each handed to the kiosk with the time it began; recognising is `input.speech`'s, which
session hears it the kiosk's (`Kiosk.hear`), acting on the words the session's.

A kiosk has no key to hold while talking, so listening never stops: silence and noise are cut away by the detector,
and what does not parse as a command of the grammar is rejected and changes nothing. Without PortAudio, a microphone
or the recogniser's model the kiosk records as before, and one log line says why it does not listen.
"""

from __future__ import annotations

from collections.abc import Callable

from physink_tui.errors import PhysinkError
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.listener import Listener, Utterance
from physink_tui.input.speech.microphone import MicrophoneListener, StreamFactory, sounddevice_stream
from physink_tui.input.speech.recogniser import Recogniser


class KioskSpeech:
    """Continuous listening for a kiosk.

    Args:
        hear: called on the listening thread with every utterance (`Kiosk.hear`).
        clock: the kiosk's clock (seconds): an utterance's ``began`` is on its scale.
        log: where the one line about listening (or not) goes.
        stream: the sound input; the default microphone through sounddevice by default.
        recogniser: makes the recogniser (pocketsphinx's by default, vosk's with a model folder).
    """

    def __init__(self, hear: Callable[[Utterance], None], clock: Callable[[], float], log: Callable[[str], None],
                 stream: StreamFactory | None = None,
                 recogniser: Callable[[], Recogniser] = make_recogniser) -> None:
        self._hear = hear
        self._clock = clock
        self._log = log
        self._stream = stream
        self._make_recogniser = recogniser
        self._microphone: MicrophoneListener | None = None

    def start(self) -> bool:
        """Load the recogniser and open the microphone; False (and a log line) when either cannot be had."""
        try:
            listener = Listener(self._make_recogniser())
            microphone = MicrophoneListener(listener, self._hear, clock=self._clock,
                                            stream=self._stream or sounddevice_stream())
            microphone.start()
        except PhysinkError as exc:  # no PortAudio, no input device, no model
            self._log(f"kiosk: not listening: {exc}")
            return False
        self._microphone = microphone
        self._log("kiosk: listening for spoken labels and events")
        return True

    def stop(self) -> None:
        """Stop listening; the utterance under way is heard first."""
        microphone, self._microphone = self._microphone, None
        if microphone is not None:
            microphone.stop()
