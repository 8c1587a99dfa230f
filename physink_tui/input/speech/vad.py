"""Energy-based voice-activity detection over 16 kHz samples, streaming or whole; what the speech says is not its job.

The detector tracks the noise floor (the quietest recent frames) and calls a 10 ms frame voiced when its energy
stands `threshold_db` above that floor and above an absolute minimum. An utterance starts after `start_frames`
voiced frames in a row (kept with `pad` seconds before them) and ends after `end_seconds` of unvoiced frames. The
kiosk reuses it for its own recordings.

>>> import numpy as np
>>> rng = np.random.default_rng(0)
>>> quiet = rng.normal(0, 30, 16000)
>>> loud = np.sin(np.arange(8000) * 0.2) * 8000
>>> bounds = speech_bounds(np.concatenate([quiet, loud, quiet]))
>>> [round(b, 2) for b in bounds]
[0.75, 1.75]
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from physink_tui.input.speech.audio import RATE

FRAME = RATE // 100
"""Samples in one 10 ms frame."""


@dataclass(frozen=True, slots=True)
class VadConfig:
    """Tuning of the detector.

    Attributes:
        threshold_db: how far above the noise floor a voiced frame's energy is, in dB.
        min_db: the least energy of a voiced frame, dB relative to 1 (int16 scale): 20 dB is an amplitude of 10.
        start_frames: voiced 10 ms frames in a row that start an utterance.
        end_seconds: unvoiced seconds that end an utterance.
        pad: seconds of audio kept before an utterance's start and after its end.
        floor_seconds: how far back the noise floor looks (its quietest frame within this window).
        min_seconds: utterances shorter than this (a click, a cough) are dropped.
    """

    threshold_db: float = 12.0
    min_db: float = 40.0
    start_frames: int = 8
    end_seconds: float = 0.5
    pad: float = 0.25
    floor_seconds: float = 3.0
    min_seconds: float = 0.25


def frame_db(samples: np.ndarray) -> np.ndarray:
    """Energy of each whole 10 ms frame in dB (mean square on the int16 scale)."""
    n = len(samples) // FRAME
    frames = np.asarray(samples[: n * FRAME], dtype=np.float64).reshape(n, FRAME)
    return 10.0 * np.log10(np.mean(frames * frames, axis=1) + 1.0)


@dataclass(frozen=True, slots=True)
class Segment:
    """One utterance the detector found.

    Attributes:
        start: seconds from the stream's start to the utterance's first sample (padding included).
        samples: int16 samples at 16 kHz, padding included.
    """

    start: float
    samples: np.ndarray

    @property
    def end(self) -> float:
        return self.start + len(self.samples) / RATE


class VoiceActivityDetector:
    """Splits a stream of 16 kHz samples into utterances (`feed`, `flush`); keeps no more audio than it must."""

    def __init__(self, config: VadConfig | None = None) -> None:
        self.config = c = config or VadConfig()
        self._floor: deque[float] = deque(maxlen=max(1, round(c.floor_seconds * 100)))
        self._pending = np.zeros(0, dtype=np.int16)  # samples not yet a whole frame
        self._frames = 0  # whole frames seen
        self._before: deque[np.ndarray] = deque(maxlen=max(1, round(c.pad * 100)) + c.start_frames)
        self._voiced_run = 0
        self._silent_run = 0
        self._current: list[np.ndarray] | None = None
        self._current_start = 0  # frame index where the current utterance's audio starts

    @property
    def in_speech(self) -> bool:
        """Whether an utterance is under way."""
        return self._current is not None

    def feed(self, samples: np.ndarray) -> Iterator[Segment]:
        """Take more samples; yield the utterances they finish."""
        c = self.config
        data = np.concatenate([self._pending, np.asarray(samples, dtype=np.int16)])
        whole = len(data) // FRAME * FRAME
        self._pending = data[whole:]
        frames = data[:whole].reshape(-1, FRAME)
        for frame, db in zip(frames, frame_db(data[:whole]), strict=True):
            floor = min(self._floor) if self._floor else db
            voiced = db >= max(c.min_db, floor + c.threshold_db)
            if not voiced or self._current is None:
                self._floor.append(db)
            self._frames += 1
            if self._current is None:
                self._before.append(frame)
                self._voiced_run = self._voiced_run + 1 if voiced else 0
                if self._voiced_run >= c.start_frames:
                    self._current = list(self._before)
                    self._current_start = self._frames - len(self._before)
                    self._before.clear()
                    self._silent_run = 0
                continue
            self._current.append(frame)
            self._silent_run = 0 if voiced else self._silent_run + 1
            if self._silent_run >= round(c.end_seconds * 100):
                keep = len(self._current) - self._silent_run + round(c.pad * 100)
                found = self._finish(keep)
                if found is not None:
                    yield found

    def flush(self) -> Segment | None:
        """The utterance under way, ended here (push-to-talk released, a file's end), or None."""
        if self._current is None:
            return None
        keep = len(self._current) - self._silent_run + round(self.config.pad * 100)
        return self._finish(keep)

    def _finish(self, keep: int) -> Segment | None:
        frames, self._current = self._current or [], None
        self._voiced_run = 0
        frames = frames[:keep]
        voiced_frames = len(frames) - round(self.config.pad * 100) * 2
        if not frames or voiced_frames < self.config.min_seconds * 100:
            return None
        return Segment(self._current_start / 100, np.concatenate(frames))


def speech_bounds(samples: np.ndarray, config: VadConfig | None = None) -> tuple[float, float] | None:
    """(start, end) in seconds of the longest utterance in a whole recording, padding included; None for silence."""
    detector = VoiceActivityDetector(config)
    found = list(detector.feed(np.asarray(samples)))
    last = detector.flush()
    if last is not None:
        found.append(last)
    if not found:
        return None
    best = max(found, key=lambda s: len(s.samples))
    return best.start, best.end
