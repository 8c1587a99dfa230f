"""Where speech accuracy is lost (issue 29): a plain pocketsphinx JSGF decoder against the shipped pipeline, one
difference at a time, on espeak-ng voice variants the fixtures do not use.

Ten espeak-ng variants (``en-us+<variant>``, the first ten of ``espeak-ng --voices=variant`` by name) say the
``label <name>`` commands for ``--labels ball,platform,knife,egg,paddle,frying pan,basket`` at espeak-ng's own speed
and pitch, clean: the speech (the synthesiser's silence trimmed) padded with 0.3 s of a quiet room's noise floor
(Gaussian, SD 8 on the 16-bit scale) and resampled from espeak-ng's 22,050 Hz to 16 kHz through the spectrum. Rows:

- the claim's setup: a plain pocketsphinx 5 `Decoder` (bundled en-us model) searching the grammar's JSGF (no phone
  loop), British variants added to the dictionary, the whole utterance at once, the front end reset each time;
- that setup with one thing changed: no British variants, digital silence as padding, resampling by linear
  interpolation (no anti-aliasing low-pass), live cepstral mean normalisation, no noise removal, no lattice best
  path, language weight 10, a VTLN frequency warp of 1.15;
- the pipeline's input (its voice-activity trim and its one-bit dither) into the plain decoder, from the quiet room
  and from digital silence;
- the pipeline (`Listener` with the pocketsphinx backend) with every rejection check off, and as shipped.

With ``--all-commands`` the first and the last two rows are also measured on all 44 commands of the corpus
(tests/speechgen/sentences.py). Under load, run it niced:

    nice -n 10 .venv/bin/python benchmarks/bench_speech_pipeline.py [--all-commands]
"""

from __future__ import annotations

import argparse
import math
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

from speechgen import sentences  # noqa: E402

from physink_tui.input.speech import pocketsphinx_backend as ps  # noqa: E402
from physink_tui.input.speech.audio import RATE, resample, to_int16  # noqa: E402
from physink_tui.input.speech.backends import make_recogniser  # noqa: E402
from physink_tui.input.speech.grammar import SpeechGrammar  # noqa: E402
from physink_tui.input.speech.letter_to_sound import pronounce  # noqa: E402
from physink_tui.input.speech.listener import Listener  # noqa: E402
from physink_tui.input.speech.vad import speech_bounds  # noqa: E402
from physink_tui.input.speech.wav_file import parse_wav  # noqa: E402

VARIANTS = ("adam", "Alex", "Alicia", "Andrea", "Andy", "anika", "anikaRobot", "Annie", "announcer", "antonio")
GRAMMAR = SpeechGrammar.build(sentences.LABELS)
PLAIN: dict[str, dict[str, object]] = {
    "plain JSGF decoder (the claim's setup)": {},
    "  no British variants": {"british": False},
    "  digital silence as padding": {"digital": True},
    "  linear-interpolation resampling (no low-pass)": {"linear": True},
    "  cmn live": {"cmn": "live"},
    "  remove_noise off": {"remove_noise": False},
    "  bestpath off": {"bestpath": False},
    "  lw 10": {"lw": 10.0},
    "  VTLN warp 1.15": {"warp_type": "inverse_linear", "warp_params": "1.15"},
}
_OURS = ("british", "digital", "linear")
_FRONT = ("cmn", "remove_noise")


def espeak(text: str, variant: str) -> tuple[np.ndarray, int]:
    """``text`` said by espeak-ng's en-us voice with ``variant``, as floats at its own rate, silence trimmed."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "out.wav"
        subprocess.run(["espeak-ng", "-v", f"en-us+{variant}", "-w", str(path), text], check=True)
        wav = parse_wav(path.read_bytes())
    x = np.frombuffer(wav.pcm, dtype="<i2").astype(np.float64)
    loud = np.flatnonzero(np.abs(x) > 200)
    return (x[loud[0]:loud[-1] + 1] if len(loud) else x), wav.rate


def recording(speech: np.ndarray, rate: int, seed: int, digital: bool = False, linear: bool = False) -> np.ndarray:
    """16 kHz int16: ``speech`` resampled, 0.3 s of padding either side, over a quiet room unless ``digital``."""
    if linear:
        n = round(len(speech) * RATE / rate)
        at16 = np.interp(np.arange(n) * rate / RATE, np.arange(len(speech)), speech)
    else:
        at16 = resample(speech, rate)
    edge = np.zeros(round(0.3 * RATE))
    audio = np.concatenate([edge, at16, edge])
    if not digital:
        audio = audio + np.random.default_rng(seed).normal(0.0, 8.0, len(audio))
    return to_int16(audio)


def plain_decoder(options: dict[str, object]) -> Callable[[np.ndarray], str]:
    """A pocketsphinx decoder on the grammar's plain JSGF (British variants unless ``british`` is False)."""
    import pocketsphinx

    config = {k: v for k, v in options.items() if k not in _OURS}
    decoder = pocketsphinx.Decoder(lm=None, loglevel="FATAL", samprate=RATE, **config)
    for word in GRAMMAR.words():
        known = [p for p in (decoder.lookup_word(word if n == 1 else f"{word}({n})") for n in range(1, 6)) if p]
        if not known:
            guess = pronounce(word)
            assert guess is not None
            decoder.add_word(word, guess, True)
            known = [guess]
        if options.get("british", True):
            extra = list(dict.fromkeys(v for v in (ps.british(p) for p in known) if v and v not in known))
            for n, phones in enumerate(extra, start=len(known) + 1):
                decoder.add_word(f"{word}({n})", phones, n == len(known) + len(extra))
    front = {k: v for k, v in config.items() if k in _FRONT}
    if front:  # the model's feat.params overrides these when given to the constructor (measured): set them after
        for key, value in front.items():
            decoder.config[key] = value
        decoder.reinit_feat()
    decoder.add_jsgf_string("physink", GRAMMAR.jsgf())
    decoder.activate_search("physink")

    def decode(samples: np.ndarray) -> str:
        decoder.reinit_feat()
        decoder.start_utt()
        decoder.process_raw(np.asarray(samples, dtype="<i2").tobytes(), full_utt=True)
        decoder.end_utt()
        hyp = decoder.hyp()
        return hyp.hypstr if hyp is not None else ""
    return decode


def right(text: str, heard: str) -> bool:
    """Whether ``heard`` is the command ``text`` means ("the" aside)."""
    said, got = GRAMMAR.parse(text), GRAMMAR.parse(heard)
    if said is None or got is None:
        return False
    strip = lambda c: {k: v for k, v in c.as_json().items() if k != "text"}  # noqa: E731
    return strip(said) == strip(got)


def pipeline(checks: bool) -> Callable[[np.ndarray], str]:
    """The shipped `Listener`: the accepted command's text, "" when rejected."""
    recogniser = make_recogniser()
    if not checks:
        recogniser.threshold = recogniser.min_margin = -math.inf
        recogniser.min_confidence = 0.0
    listener = Listener(recogniser, sentences.LABELS)

    def hear(samples: np.ndarray) -> str:
        u = listener.hear(samples)
        return u.text if u.command is not None else ""
    return hear


def pipeline_input(samples: np.ndarray) -> np.ndarray:
    """What the pipeline decodes: the voice-activity trim, then the one-bit dither."""
    bounds = speech_bounds(samples)
    if bounds is not None:
        samples = samples[round(bounds[0] * RATE):round(bounds[1] * RATE)]
    return ps.dithered(samples)


def measure(texts: tuple[str, ...], rows: list[tuple[str, Callable[[np.ndarray], str], dict[str, object]]],
            say: Callable[[str], None]) -> None:
    said = {(v, t): espeak(t, v) for v in VARIANTS for t in texts}
    say(f"| setup ({len(texts)} sentences x {len(VARIANTS)} variants) | right | variants with all but one right |"
        "\n|---|---|---|")
    for name, decode, options in rows:
        per = {}
        for v in VARIANTS:
            per[v] = sum(right(t, decode(recording(*said[(v, t)], seed=i, digital=bool(options.get("digital")),
                                                   linear=bool(options.get("linear")))))
                         for i, t in enumerate(texts))
        total = sum(per.values())
        n = len(texts) * len(VARIANTS)
        good = sum(1 for c in per.values() if c >= len(texts) - 1)
        say(f"| {name} | {total}/{n} ({total / n:.0%}) | {good}/{len(VARIANTS)} |")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all-commands", action="store_true", help="also the 44 commands (three setups)")
    parser.add_argument("--rows", help="only the rows whose names contain one of these comma-separated words (on the "
                        "44 commands with --all-commands)")
    args = parser.parse_args(argv)
    if shutil.which("espeak-ng") is None:
        print("bench_speech_pipeline: espeak-ng is not installed (scripts/setup.sh installs it)", file=sys.stderr)
        return 1
    say = lambda line: print(line, flush=True)  # noqa: E731
    labels = tuple(f"label {name}" for name in sentences.LABELS)
    rows = [(name, plain_decoder(opts), opts) for name, opts in PLAIN.items()]
    base = rows[0][1]
    rows += [("  the pipeline's input (VAD trim, dither)", lambda s: base(pipeline_input(s)), {}),
             ("  digital silence, then the pipeline's input", lambda s: base(pipeline_input(s)), {"digital": True}),
             ("pipeline, every check off (phone-loop screen)", pipeline(False), {}),
             ("pipeline as shipped", pipeline(True), {})]
    if args.rows:
        rows = [r for r in rows if any(w in r[0] for w in args.rows.split(","))]
        measure(sentences.COMMANDS if args.all_commands else labels, rows, say)
        return 0
    measure(labels, rows, say)
    if args.all_commands:
        say("")
        measure(sentences.COMMANDS, [rows[0], rows[-2], rows[-1]], say)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
