"""Reads WAV recordings into 16 kHz mono 16-bit samples (numpy), resampling as needed; recognising them is left to
others.

>>> import numpy as np
>>> resample(np.ones(441, dtype=np.float64), 44100).shape
(160,)
"""

from __future__ import annotations

import wave
from pathlib import Path

import numpy as np

from physink_tui.errors import SpeechError
from physink_tui.input.speech.wav_file import WavProblem, parse_wav

RATE = 16000
"""Samples a second of everything the recognisers hear."""
_WIDTHS = {1: "8-bit", 2: "16-bit", 3: "24-bit", 4: "32-bit"}


def read_wav(path: str | Path, data: bytes | None = None) -> np.ndarray:
    """The recording as 16 kHz mono int16 samples.

    Any rate, 8/16/24/32-bit PCM (plain or WAVE_FORMAT_EXTENSIBLE), any number of channels (averaged) is taken.
    ``data`` gives the file's bytes when they were read already (a pipe).

    Raises:
        SpeechError: the file cannot be read, is not a PCM WAV file, holds a header and no samples, or is cut off
            (naming it and what is wrong; `wav_file.parse_wav`).
    """
    name = str(path)
    try:
        raw = Path(path).read_bytes() if data is None else data
    except OSError as exc:
        raise SpeechError(f"{name}: cannot read: {exc.strerror or exc}", name) from None
    if not raw:
        raise SpeechError(f"{name}: empty file; expected a WAV recording", name)
    try:
        wav = parse_wav(raw)
    except WavProblem as exc:
        hint = "; expected a WAV like 'ffmpeg -i IN -ac 1 -ar 16000 OUT.wav' writes" if str(exc).startswith(
            "not a PCM") else ""
        raise SpeechError(f"{name}: {exc}{hint}", name) from None
    channels, width, rate, pcm = wav.channels, wav.width, wav.rate, wav.pcm
    if rate < 4000:
        raise SpeechError(f"{name}: unsupported WAV: {channels} channel(s), {width * 8}-bit, {rate} Hz; expected "
                          "8, 16, 24 or 32-bit PCM at 4000 Hz or more", name)
    samples = _to_float(pcm, width)
    usable = len(samples) - len(samples) % channels
    mono = samples[:usable].reshape(-1, channels).mean(axis=1)
    return to_int16(resample(mono, rate))


def _to_float(pcm: bytes, width: int) -> np.ndarray:
    """PCM bytes as floats on the 16-bit scale (8-bit WAV is unsigned, the others signed little-endian)."""
    if width == 1:
        return (np.frombuffer(pcm, dtype=np.uint8).astype(np.float64) - 128.0) * 256.0
    if width == 2:
        return np.frombuffer(pcm, dtype="<i2").astype(np.float64)
    if width == 4:
        return np.frombuffer(pcm, dtype="<i4").astype(np.float64) / 65536.0
    usable = len(pcm) - len(pcm) % 3
    b = np.frombuffer(pcm[:usable], dtype=np.uint8).reshape(-1, 3).astype(np.int32)
    value = b[:, 0] | (b[:, 1] << 8) | (b[:, 2] << 16)
    value = np.where(value >= 1 << 23, value - (1 << 24), value)
    return value.astype(np.float64) / 256.0


def resample(samples: np.ndarray, rate: int, target: int = RATE) -> np.ndarray:
    """``samples`` at ``rate`` resampled to ``target`` Hz through the spectrum (an ideal low-pass, no aliasing)."""
    if rate == target or len(samples) == 0:
        return np.asarray(samples, dtype=np.float64)
    n = len(samples)
    m = max(1, round(n * target / rate))
    spectrum = np.fft.rfft(samples)
    out = np.zeros(m // 2 + 1, dtype=complex)
    keep = min(len(spectrum), len(out))
    out[:keep] = spectrum[:keep]
    return np.fft.irfft(out, m) * (m / n)


def to_int16(samples: np.ndarray) -> np.ndarray:
    """Float samples on the 16-bit scale, rounded and clipped to int16."""
    return np.clip(np.rint(samples), -32768, 32767).astype(np.int16)


def write_wav(path: str | Path, samples: np.ndarray, rate: int = RATE) -> None:
    """Write int16 mono ``samples`` as a WAV file (fixtures, recordings kept for a bug report)."""
    with wave.open(str(path), "wb") as wav:
        wav.setnchannels(1)
        wav.setsampwidth(2)
        wav.setframerate(rate)
        wav.writeframes(np.asarray(samples, dtype="<i2").tobytes())
