"""How a synthesised sentence is made into a recording: padded with a quiet room, noise at a given SNR, and the
degraded conditions (reverberation, telephone band, clipping, low SNR) reported beside the goals; plus recordings
with no speech in them. All seeded: the same seed gives the same samples."""

from __future__ import annotations

import numpy as np

from physink_tui.input.speech.audio import RATE

ROOM_SD = 8.0
"""The quiet room's noise floor (Gaussian, on the 16-bit scale): a microphone is never digital silence."""
NOISES = ("pink", "white", "babble")
DEGRADED = ("reverb", "telephone", "clipped", "snr15", "snr10")


def trimmed(samples: np.ndarray) -> np.ndarray:
    """The synthesised speech without the synthesiser's leading and trailing silence."""
    loud = np.flatnonzero(np.abs(samples) > 200)
    return samples[loud[0]:loud[-1] + 1] if len(loud) else samples


def in_room(speech: np.ndarray, rng: np.random.Generator, pad: float = 0.4) -> np.ndarray:
    """``speech`` with ``pad`` seconds before and after, all over the quiet room's floor."""
    edge = np.zeros(round(pad * RATE))
    audio = np.concatenate([edge, speech, edge])
    return audio + rng.normal(0.0, ROOM_SD, len(audio))


def noise(kind: str, n: int, rng: np.random.Generator, babble: np.ndarray | None = None) -> np.ndarray:
    """``n`` samples of unit-power noise: pink-ish, white, or ``babble`` (other speech, looped) when given."""
    if kind == "babble" and babble is not None and len(babble):
        out = np.resize(babble, n).astype(np.float64)
    else:
        out = rng.normal(0.0, 1.0, n)
        if kind != "white":
            out = np.convolve(out, np.ones(8) / 8, mode="same")
    return out / np.sqrt(np.mean(out ** 2) + 1e-12)


def with_noise(speech: np.ndarray, snr_db: float, kind: str, rng: np.random.Generator,
               babble: np.ndarray | None = None) -> np.ndarray:
    """``speech`` (in its room) with ``kind`` noise ``snr_db`` below the speech's power."""
    loud = np.abs(speech) > 200
    power = np.mean(speech[loud] ** 2) if np.any(loud) else 1e6
    return speech + noise(kind, len(speech), rng, babble) * np.sqrt(power / 10 ** (snr_db / 10))


def degrade(speech: np.ndarray, how: str, rng: np.random.Generator) -> np.ndarray:
    """``speech`` (in its room) under one of `DEGRADED`."""
    if how == "reverb":  # a small room: exponentially decaying noise as the impulse response, T60 about 0.4 s
        t = np.arange(round(0.4 * RATE)) / RATE
        ir = rng.normal(0.0, 1.0, len(t)) * np.exp(-6.9 * t / 0.4)
        ir[0] = 8.0
        wet = np.convolve(speech, ir)[:len(speech)]
        return wet * np.sqrt(np.mean(speech ** 2) / (np.mean(wet ** 2) + 1e-12))
    if how == "telephone":  # 300-3400 Hz
        spectrum = np.fft.rfft(speech)
        f = np.fft.rfftfreq(len(speech), 1 / RATE)
        spectrum[(f < 300) | (f > 3400)] = 0
        return np.fft.irfft(spectrum, len(speech))
    if how == "clipped":  # a gain too high: the loudest tenth clipped
        level = np.quantile(np.abs(speech[np.abs(speech) > 200]), 0.9) if np.any(np.abs(speech) > 200) else 1e4
        return np.clip(speech * 32000 / level, -32767, 32767)
    if how.startswith("snr"):
        return with_noise(speech, float(how[3:]), "pink", rng)
    raise ValueError(f"unknown condition {how!r}")


NON_SPEECH = ("silence", "quiet room", "white noise", "pink noise", "hum", "bursts", "clicks", "fan")


def non_speech(kind: str, rng: np.random.Generator, seconds: float = 2.0) -> np.ndarray:
    """``seconds`` of a recording with nothing said in it."""
    n = round(seconds * RATE)
    t = np.arange(n) / RATE
    level = float(rng.choice([300.0, 1000.0, 3000.0]))
    if kind == "silence":
        return np.zeros(n)
    if kind == "quiet room":
        return rng.normal(0.0, float(rng.choice([3.0, 8.0, 30.0])), n)
    if kind == "white noise":
        return rng.normal(0.0, level, n)
    if kind == "pink noise":
        return noise("pink", n, rng) * level
    if kind == "hum":
        base = float(rng.choice([50.0, 60.0, 100.0, 120.0]))
        return level * (np.sin(2 * np.pi * base * t) + 0.5 * np.sin(2 * np.pi * 3 * base * t)) + rng.normal(0, 30, n)
    if kind == "bursts":
        return rng.normal(0.0, 1.0, n) * (np.sin(2 * np.pi * float(rng.uniform(1, 4)) * t) > 0.6) * level * 2
    if kind == "clicks":
        out = rng.normal(0.0, 8.0, n)
        for at in rng.integers(0, n - 200, 12):
            out[at:at + 200] += rng.normal(0.0, level * 3, 200) * np.exp(-np.arange(200) / 30)
        return out
    if kind == "fan":
        out = noise("pink", n, rng) * level / 3
        return out + level / 2 * np.sin(2 * np.pi * float(rng.uniform(150, 400)) * t)
    raise ValueError(f"unknown non-speech {kind!r}")
