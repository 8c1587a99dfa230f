"""Listening on the microphone (sounddevice, 16 kHz mono): audio to utterances on a thread of its own, each handed
to a callback with the time it began; push-to-talk keys, journaling and acting on commands are the caller's.

`MicrophoneListener.start()` opens the input and listens until `stop()`; the voice-activity detector cuts the
stream into utterances, and each goes through `Listener.hear` — the path `physink listen FILE.wav` takes. A TUI's
push-to-talk key calls `start()` and `stop()` (terminals send no key release, so one key toggles); `stop()` ends the
utterance under way and hears it. ``on_utterance`` runs on the listening thread: hand it on (``call_from_thread``,
``SessionRunner.say``). Without PortAudio or an input device, `start()` raises `MicrophoneError` and nothing else
is affected.
"""

from __future__ import annotations

import queue
import threading
import time
from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from physink_tui.errors import MicrophoneError
from physink_tui.input.speech.audio import RATE
from physink_tui.input.speech.listener import Listener, Utterance
from physink_tui.input.speech.vad import Segment, VadConfig, VoiceActivityDetector

BLOCK = RATE // 20
"""Samples per block the sound card hands over (50 ms)."""


class InputStream(Protocol):
    """What `MicrophoneListener` needs of a sound input (sounddevice's `RawInputStream`, or a test's fake)."""

    def start(self) -> None: ...

    def stop(self) -> None: ...

    def close(self) -> None: ...


StreamFactory = Callable[[Callable[[bytes], None]], InputStream]
"""Opens an input that calls its argument with each block of 16 kHz mono int16 bytes, from any thread."""


def sounddevice_stream(device: str | int | None = None) -> StreamFactory:
    """A `StreamFactory` on sounddevice's default (or named) input device.

    Opening raises `MicrophoneError`: PortAudio missing (the README's set-up installs it), no input device, or a
    device that does not record 16 kHz mono.
    """
    def open_stream(deliver: Callable[[bytes], None]) -> InputStream:
        try:
            import sounddevice
        except (ImportError, OSError) as exc:  # OSError: the PortAudio library itself is missing
            raise MicrophoneError(f"no microphone: PortAudio cannot be loaded ({exc}); install it with "
                                  "'apt-get install libportaudio2' (scripts/setup.sh does)") from None

        def callback(data: Any, frames: int, when: Any, status: Any) -> None:
            deliver(bytes(data))

        try:
            return sounddevice.RawInputStream(samplerate=RATE, blocksize=BLOCK, device=device, channels=1,
                                              dtype="int16", callback=callback)
        except Exception as exc:  # sounddevice.PortAudioError, ValueError for an unknown device name
            where = "the default input device" if device is None else f"input device {device!r}"
            raise MicrophoneError(f"no microphone: cannot record from {where} at 16 kHz mono ({exc})",
                                  None if device is None else str(device)) from None
    return open_stream


class MicrophoneListener:
    """Listens on an input stream and reports each utterance (see the module docstring).

    Args:
        listener: the recogniser and grammar (`Listener.set_words` may be called between utterances).
        on_utterance: called on the listening thread with each `Utterance`, accepted or rejected; its ``began``
            is on ``clock``'s scale.
        clock: seconds (``time.monotonic``; a session runner's ``now`` gives session time).
        stream: opens the input; `sounddevice_stream()` by default.
        vad: the voice-activity detector's tuning.
    """

    def __init__(self, listener: Listener, on_utterance: Callable[[Utterance], None],
                 clock: Callable[[], float] = time.monotonic, stream: StreamFactory | None = None,
                 vad: VadConfig | None = None) -> None:
        self.listener = listener
        self.on_utterance = on_utterance
        self.clock = clock
        self._open = stream or sounddevice_stream()
        self._vad_config = vad or listener.vad
        self._blocks: queue.Queue[bytes | None] = queue.Queue()
        self._stream: InputStream | None = None
        self._thread: threading.Thread | None = None
        self._lock = threading.Lock()

    @property
    def listening(self) -> bool:
        return self._stream is not None

    def start(self) -> None:
        """Open the input and listen (nothing if already listening). Raises `MicrophoneError` without one."""
        with self._lock:
            if self._stream is not None:
                return
            self._blocks = queue.Queue()
            stream = self._open(self._blocks.put)
            started = self.clock()
            self._thread = threading.Thread(target=self._listen, args=(self._blocks, started),
                                            name="physink-microphone", daemon=True)
            self._thread.start()
            stream.start()
            self._stream = stream

    def stop(self) -> None:
        """Stop listening: the utterance under way is ended and heard; returns once it has been reported."""
        with self._lock:
            stream, self._stream = self._stream, None
            thread, self._thread = self._thread, None
            if stream is not None:
                stream.stop()
                stream.close()
            self._blocks.put(None)
        if thread is not None:
            thread.join()

    def _listen(self, blocks: queue.Queue[bytes | None], started: float) -> None:
        detector = VoiceActivityDetector(self._vad_config)
        while (block := blocks.get()) is not None:
            for segment in detector.feed(np.frombuffer(block, dtype="<i2")):
                self._report(segment, started)
        last = detector.flush()
        if last is not None:
            self._report(last, started)

    def _report(self, segment: Segment, started: float) -> None:
        self.on_utterance(self.listener.hear(segment.samples, started + segment.start))
