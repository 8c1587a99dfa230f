"""WAV reading (any common rate, width, channels to 16 kHz mono) and the voice-activity detector."""

from __future__ import annotations

import wave
from pathlib import Path

import numpy as np
import pytest

from physink_tui.errors import SpeechError
from physink_tui.input.speech.audio import RATE, read_wav, resample
from physink_tui.input.speech.vad import VoiceActivityDetector, speech_bounds

SPEECH = Path(__file__).parent / "speech"


def _write(path: Path, samples: np.ndarray, rate: int, width: int, channels: int) -> None:
    """``samples`` (float, int16 scale) as PCM of ``width`` bytes, the same in every channel."""
    x = np.repeat(samples[:, None], channels, axis=1).ravel()
    if width == 1:
        data = (np.clip(x / 256 + 128, 0, 255)).astype(np.uint8).tobytes()
    elif width == 2:
        data = x.astype("<i2").tobytes()
    elif width == 3:
        v = (x * 256).astype(np.int32)
        data = np.stack([v & 255, (v >> 8) & 255, (v >> 16) & 255], axis=1).astype(np.uint8).tobytes()
    else:
        data = (x * 65536).astype("<i4").tobytes()
    with wave.open(str(path), "wb") as w:
        w.setnchannels(channels)
        w.setsampwidth(width)
        w.setframerate(rate)
        w.writeframes(data)


def _dominant_hz(samples: np.ndarray) -> float:
    spectrum = np.abs(np.fft.rfft(samples))
    return float(np.argmax(spectrum) * RATE / len(samples))


@pytest.mark.parametrize(("rate", "width", "channels"), [
    (8000, 1, 1), (11025, 2, 2), (22050, 2, 1), (44100, 3, 2), (48000, 4, 1), (16000, 2, 1), (96000, 2, 6),
])
def test_any_common_wav_becomes_16khz_mono_int16(tmp_path: Path, rate: int, width: int, channels: int) -> None:
    t = np.arange(rate) / rate
    tone = 8000 * np.sin(2 * np.pi * 440 * t)
    path = tmp_path / "tone.wav"
    _write(path, tone, rate, width, channels)
    samples = read_wav(path)
    assert samples.dtype == np.int16
    assert len(samples) == RATE
    assert _dominant_hz(samples) == pytest.approx(440, abs=2)
    assert np.max(np.abs(samples)) == pytest.approx(8000, rel=0.05)


def test_resampling_drops_what_16khz_cannot_hold_instead_of_folding_it() -> None:
    rate = 44100
    t = np.arange(rate) / rate
    above = 10000 * np.sin(2 * np.pi * 12000 * t)  # above 8 kHz: would alias to 4 kHz
    out = resample(above, rate)
    assert np.max(np.abs(out)) < 50


@pytest.mark.parametrize(("content", "fragment"), [
    (b"", "empty file"),
    (b"junk that is no wav", "not a PCM WAV file"),
    (b"RIFF\x24\x00\x00\x00WAVEfmt ", "not a PCM WAV file"),
])
def test_a_broken_wav_is_one_error_naming_the_file(tmp_path: Path, content: bytes, fragment: str) -> None:
    path = tmp_path / "broken.wav"
    path.write_bytes(content)
    with pytest.raises(SpeechError, match=fragment) as info:
        read_wav(path)
    assert str(info.value).startswith(f"{path}: ")
    assert info.value.path == str(path)


def test_a_missing_wav_names_the_file(tmp_path: Path) -> None:
    with pytest.raises(SpeechError, match="cannot read"):
        read_wav(tmp_path / "none.wav")


def test_speech_bounds_find_the_utterance_and_nothing_in_silence_or_steady_noise() -> None:
    said = read_wav(SPEECH / "cmd00_0.wav")
    rng = np.random.default_rng(1)
    room = rng.normal(0, 8, RATE).astype(np.int16)
    padded = np.concatenate([room, said, room])
    start, end = speech_bounds(padded)
    assert 0.8 < start < 1.3 and 1.0 + len(said) / RATE - 0.6 < end < 1.0 + len(said) / RATE + 0.3
    assert speech_bounds(read_wav(SPEECH / "silence.wav")) is None
    assert speech_bounds(read_wav(SPEECH / "white_noise.wav")) is None


def test_the_streaming_detector_gives_each_utterance_with_its_start_time() -> None:
    said = read_wav(SPEECH / "cmd04_0.wav")
    gap = np.random.default_rng(2).normal(0, 8, 2 * RATE).astype(np.int16)
    stream = np.concatenate([gap, said, gap, said, gap])
    detector = VoiceActivityDetector()
    found = []
    for chunk in np.array_split(stream, 97):  # odd chunk sizes, as a sound card gives
        found.extend(detector.feed(chunk))
    assert detector.flush() is None
    assert len(found) == 2
    second_start = (2 * RATE + len(said) + 2 * RATE) / RATE
    assert found[0].start == pytest.approx(2.0 + 0.3 - 0.25, abs=0.15)
    assert found[1].start == pytest.approx(second_start + 0.3 - 0.25, abs=0.15)
    assert not detector.in_speech
