"""The synthesiser families and their English voice settings, and synthesising one sentence in one of them; which
sentences are said, and the noise added, are `sentences`' and `conditions`'.

A family is one synthesiser: espeak-ng (every English voice it ships, each with every variant it ships), flite
(kal, kal16, awb, rms, slt), festival (the Debian festvox voices kal and ked diphones and the slt HTS voice) and SVOX
Pico (``py-nanotts``: en-US and en-GB), each at several speeds and pitches. `available` says which can run here.
"""

from __future__ import annotations

import functools
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from physink_tui.input.speech.audio import read_wav

FAMILIES = ("espeak-ng", "flite", "festival", "pico")
ESPEAK_VOICES = ("en-us", "en-gb", "en-gb-scotland", "en-gb-x-gbclan", "en-gb-x-gbcwmd", "en-gb-x-rp", "en-029",
                 "en-us-nyc")
FLITE_VOICES = ("kal", "kal16", "awb", "rms", "slt")
FESTIVAL_VOICES = ("kal_diphone", "ked_diphone", "cmu_us_slt_arctic_hts")
PICO_VOICES = ("en-US", "en-GB")
# (speed, pitch) settings per family, in each synthesiser's own units: espeak-ng words a minute and pitch 0-99;
# flite and festival a duration stretch and a mean F0 in Hz (None: the voice's own); Pico multipliers
SPEEDS = {"espeak-ng": (135, 160, 185), "flite": (0.85, 1.0, 1.2), "festival": (0.85, 1.0, 1.2),
          "pico": (0.8, 1.0, 1.25)}
PITCHES = {"espeak-ng": (35, 50, 65), "flite": (None, 100, 150), "festival": (None, 100, 140),
           "pico": (0.85, 1.0, 1.2)}


@dataclass(frozen=True, slots=True)
class Voice:
    """One voice setting of a family.

    Attributes:
        family: the synthesiser.
        voice: its voice name (espeak-ng: ``voice+variant``).
        speed: the speed in the synthesiser's units.
        pitch: the pitch in its units, or None for the voice's own.
    """

    family: str
    voice: str
    speed: float
    pitch: float | None

    def describe(self) -> str:
        pitch = "" if self.pitch is None else f", pitch {self.pitch:g}"
        return f"{self.family} {self.voice}, speed {self.speed:g}{pitch}"


@functools.cache
def espeak_variants() -> tuple[str, ...]:
    """Every voice variant espeak-ng ships (its ``--voices=variant`` list), by file name; "" is none."""
    out = subprocess.run(["espeak-ng", "--voices=variant"], capture_output=True, text=True, check=True).stdout
    names = [line.split()[4].removeprefix("!v/") for line in out.splitlines()[1:] if len(line.split()) >= 5]
    return ("", *sorted(names, key=str.lower))


def voice_settings(family: str) -> list[Voice]:
    """Every voice of ``family`` crossed with its speeds and pitches (espeak-ng: voices x variants, speeds and
    pitches by turns, so that every voice and every variant is there)."""
    speeds, pitches = SPEEDS[family], PITCHES[family]
    if family == "espeak-ng":  # by turns, so that any run of len(variants) settings has every variant and voice
        variants, out = espeak_variants(), []
        for a in range(len(ESPEAK_VOICES)):
            for r, variant in enumerate(variants):
                voice = ESPEAK_VOICES[(a + r) % len(ESPEAK_VOICES)] + (f"+{variant}" if variant else "")
                out.append(Voice(family, voice, speeds[(a + r) % 3], pitches[(a + 2 * r) % 3]))
        return out
    voices = {"flite": FLITE_VOICES, "festival": FESTIVAL_VOICES, "pico": PICO_VOICES}[family]
    return [Voice(family, v, s, p) for v in voices for s in speeds for p in pitches]


def available(family: str) -> bool:
    """Whether ``family`` can synthesise on this machine."""
    if family == "pico":
        try:
            import py_nanotts  # noqa: F401
        except ImportError:
            return False
        return True
    tool = {"espeak-ng": "espeak-ng", "flite": "flite", "festival": "text2wave"}[family]
    return shutil.which(tool) is not None


def synthesise(text: str, voice: Voice) -> np.ndarray:
    """``text`` said by ``voice``, as float samples at 16 kHz on the 16-bit scale."""
    if voice.family == "pico":
        from py_nanotts import NanoTTS

        pcm = NanoTTS().speak(text, voice=voice.voice, speed=voice.speed, pitch=voice.pitch)
        return np.frombuffer(pcm, dtype="<i2").astype(np.float64)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "out.wav"
        stdin = None
        if voice.family == "espeak-ng":
            command = ["espeak-ng", "-v", voice.voice, "-s", f"{voice.speed:g}", "-p", f"{voice.pitch:g}",
                       "-w", str(path), text]
        elif voice.family == "flite":
            command = ["flite", "-voice", voice.voice, "--setf", f"duration_stretch={voice.speed:g}"]
            if voice.pitch is not None:
                command += ["--setf", f"int_f0_target_mean={voice.pitch:g}"]
            command += ["-t", text, "-o", str(path)]
        else:
            command = ["text2wave", "-eval", f"(voice_{voice.voice})", "-eval",
                       f"(Parameter.set 'Duration_Stretch {voice.speed:g})"]
            if voice.pitch is not None and "diphone" in voice.voice:
                command += ["-eval", f"(set! int_lr_params '((target_f0_mean {voice.pitch:g}) (target_f0_std 20) "
                            "(model_f0_mean 170) (model_f0_std 34)))"]
            command += ["-o", str(path)]
            stdin = text
        subprocess.run(command, check=True, input=stdin, text=True, capture_output=True)
        return read_wav(path).astype(np.float64)
