"""Speech recognition across synthesisers (issue 29): the rejection calibrated leaving each family out, per family.

Decodes the corpus `scripts/make_speech_corpus.py` made (tests/speechgen: espeak-ng, flite, festival, SVOX Pico;
commands, near-misses, other sentences, no speech; clean, noise at >= 20 dB, degraded conditions) once with every
rejection check off, keeping each utterance's confidences (`Decoded.ratio`, the worst content word's score,
`Decoded.margin`), then:

- for each family, chooses the three thresholds on the other families only (most commands right while wrong commands
  stay within ``--budget`` of commands and near-misses and >= 99 % of other speech and noise is rejected) and scores
  the family with them: a table per family, clean and noisy (>= 20 dB) apart, degraded conditions beside;
- the leave-one-family-out curve of right against wrong for each confidence alone and all together (the sum over
  held-out families at several budgets), which is how the confidence was chosen;
- the thresholds chosen on all families (the ones the recogniser ships) and decoding speed over the corpus.

    nice -n 10 .venv/bin/python benchmarks/bench_speech_corpus.py --redecode --shard 0/2 &   # decode on 2 cores
    nice -n 10 .venv/bin/python benchmarks/bench_speech_corpus.py --redecode --shard 1/2; wait
    .venv/bin/python benchmarks/bench_speech_corpus.py [--corpus DIR] [--write docs/BENCHMARKS.md]

Commands are compared by what they mean (kind, names, verb, prepositions), not by whether "the" was said.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import statistics
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

from speechgen import corpus  # noqa: E402

from physink_tui.input.speech.backends import make_recogniser  # noqa: E402
from physink_tui.input.speech.listener import Listener  # noqa: E402
from physink_tui.timeline.phrases import ARTICLES  # noqa: E402

WORDS = (-math.inf, -6.0, -5.0, -4.5, -4.0, -3.5, -3.0, -2.5, -2.0, -1.5)
RATIOS = (-math.inf, -4.0, -3.5, -3.0, -2.5, -2.0, -1.5, -1.0)
MARGINS = (-math.inf, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0)
REJECT = 0.99
"""Calibration keeps thresholds that reject at least this share of the other speech and noise."""
Thresholds = tuple[float, float, float]


def meaning(command: dict | None) -> tuple | None:
    """What a command means, "the" aside (`Command.as_json` without its text)."""
    return None if command is None else tuple(sorted((k, v) for k, v in command.items() if k != "text"))


def decode(folder: Path, cache: Path, shard: tuple[int, int] = (0, 1)) -> None:
    """One row per recording (of shard ``i`` of ``n``: every n-th from the i-th) into ``cache``: what it must give,
    what the recogniser heard and its confidences (checks off)."""
    recogniser = make_recogniser()
    recogniser.threshold = recogniser.min_ratio = recogniser.min_margin = -math.inf
    manifest = json.loads((folder / "manifest.json").read_text())
    listener = Listener(recogniser, manifest["labels"])
    with cache.open("w") as out:
        for n, (item, samples) in enumerate(corpus.load(folder, shard)):
            u = listener.hear(samples)
            d = u.decoded
            content = [w.score for w in (d.words if d else ()) if w.word not in ARTICLES] or \
                [w.score for w in (d.words if d else ())]
            row = {"id": item.id, "family": item.family, "kind": item.kind, "condition": item.condition,
                   "degraded": item.degraded, "expected": meaning(item.command), "text": item.text,
                   "heard": u.text, "got": meaning(u.command and u.command.as_json()),
                   "ratio": d.ratio if d and d.ratio is not None else -math.inf,
                   "word": min(content, default=-math.inf), "margin": d.margin if d else -math.inf,
                   "alternative": d.alternative if d else None,
                   "rtf": d.decode_seconds / d.seconds if d and d.seconds else None}
            out.write(json.dumps(row) + "\n")
            if n % 200 == 0:
                print(f"decoded {n}", file=sys.stderr, flush=True)


def load_rows(folder: Path) -> list[dict[str, Any]]:
    """The decoded rows of every shard, in the corpus's order."""
    rows = [json.loads(line) for cache in sorted(folder.glob("decoded-*.jsonl"))
            for line in cache.read_text().splitlines() if line]
    order = {entry["id"]: n for n, entry in enumerate(json.loads((folder / "manifest.json").read_text())["items"])}
    rows.sort(key=lambda r: order[r["id"]])
    for r in rows:
        r["expected"] = None if r["expected"] is None else tuple(map(tuple, r["expected"]))
        r["got"] = None if r["got"] is None else tuple(map(tuple, r["got"]))
    return rows


def applied(row: dict[str, Any], th: Thresholds) -> tuple | None:
    """The command ``row`` gives with these (word, ratio, margin) thresholds, None when rejected."""
    word, ratio, margin = th
    ok = row["got"] is not None and row["word"] >= word and row["ratio"] >= ratio and row["margin"] >= margin
    return row["got"] if ok else None


def count(rows: list[dict[str, Any]], th: Thresholds) -> dict[str, int]:
    """Commands right, wrong commands applied (over commands and near-misses), other speech and noise rejected."""
    out = {"commands": 0, "right": 0, "said": 0, "wrong": 0, "other": 0, "rejected": 0, "near": 0, "near_right": 0}
    for r in rows:
        got = applied(r, th)
        if r["kind"] in ("command", "near-miss"):
            out["said"] += 1
            out["wrong"] += got is not None and got != r["expected"]
            if r["kind"] == "command":
                out["commands"] += 1
                out["right"] += got == r["expected"]
            else:
                out["near"] += 1
                out["near_right"] += got == r["expected"]
        else:
            out["other"] += 1
            out["rejected"] += got is None
    return out


def calibrate(rows: list[dict[str, Any]], budget: float, grid: list[Thresholds]) -> Thresholds:
    """The thresholds with the most commands right among those with wrong <= ``budget`` of commands and near-misses
    and >= `REJECT` of the rest rejected (else the fewest wrong); among equals the loosest."""
    def merit(th: Thresholds) -> tuple:
        c = count(rows, th)
        ok = c["wrong"] <= budget * c["said"] and c["rejected"] >= REJECT * c["other"]
        score = c["right"] if ok else -c["wrong"] - (c["other"] - c["rejected"])
        return ok, score, -c["wrong"], tuple(-t for t in th)
    return max(grid, key=merit)


def grids() -> dict[str, list[Thresholds]]:
    """The confidences compared: each alone, and all three together."""
    inf = -math.inf
    return {"word score": [(w, inf, inf) for w in WORDS], "utterance ratio": [(inf, r, inf) for r in RATIOS],
            "rival margin": [(inf, inf, m) for m in MARGINS],
            "all three": list(itertools.product(WORDS, RATIOS, MARGINS))}


def fmt(th: Thresholds) -> str:
    return ", ".join("-" if math.isinf(t) else f"{t:g}" for t in th)


def pct(a: int, b: int) -> str:
    return f"{a}/{b} ({a / b:.1%})" if b else "-"


def report(rows: list[dict[str, Any]], budget: float, say: Callable[[str], None]) -> None:
    goal = [r for r in rows if not r["degraded"]]
    families = sorted({r["family"] for r in rows})
    all3 = grids()["all three"]
    say(f"Corpus: {len(rows)} recordings ({len(goal)} in the goals' conditions), families: {', '.join(families)}. "
        f"Calibration budget: wrong <= {budget:.1%} of commands and near-misses, >= {REJECT:.0%} of other speech and "
        "noise rejected, on the other families.\n")
    for fam in families:
        th = calibrate([r for r in goal if r["family"] != fam], budget, all3)
        mine = [r for r in rows if r["family"] == fam]
        say(f"#### {fam} (thresholds calibrated without it: word {fmt(th[:1])}, ratio {fmt(th[1:2])}, "
            f"margin {fmt(th[2:])})\n")
        say("| condition | commands right | wrong applied / (commands + near-misses) | near-misses right "
            "| other sentences rejected | no speech rejected |\n|---|---|---|---|---|---|")
        parts = [("clean", [r for r in mine if r["condition"] == "clean"]),
                 ("noise >= 20 dB", [r for r in mine if not r["degraded"] and r["condition"] != "clean"
                                     and r["kind"] != "non-speech"]),
                 ("goals' conditions, all", [r for r in mine if not r["degraded"]])]
        parts += [(f"degraded: {how}", [r for r in mine if r["condition"] == how])
                  for how in sorted({r["condition"] for r in mine if r["degraded"]})]
        for name, part in parts:
            c = count(part, th)
            oog = count([r for r in part if r["kind"] == "out-of-grammar"], th)
            none = count([r for r in part if r["kind"] == "non-speech"], th)
            say(f"| {name} | {pct(c['right'], c['commands'])} | {pct(c['wrong'], c['said'])} | "
                f"{pct(c['near_right'], c['near'])} | {pct(oog['rejected'], oog['other'])} | "
                f"{pct(none['rejected'], none['other'])} |")
        say("")
    say("Leave-one-family-out curve (each family scored with thresholds chosen on the others at that budget; summed "
        "over the families, goals' conditions):\n")
    say("| confidence | budget | commands right | wrong applied | other speech and noise rejected |\n"
        "|---|---|---|---|---|")
    for name, grid in grids().items():
        for b in (0.0, 0.0025, 0.005, 0.01, 0.02, 0.05, 1.0):
            tot = {"right": 0, "commands": 0, "wrong": 0, "said": 0, "rejected": 0, "other": 0}
            for fam in families:
                th = calibrate([r for r in goal if r["family"] != fam], b, grid)
                c = count([r for r in goal if r["family"] == fam], th)
                for k in tot:
                    tot[k] += c[k]
            say(f"| {name} | {b:.2%} | {pct(tot['right'], tot['commands'])} | {pct(tot['wrong'], tot['said'])} | "
                f"{pct(tot['rejected'], tot['other'])} |")
    th = calibrate(goal, budget, all3)
    c = count(goal, th)
    say(f"\nCalibrated on all families (what the recogniser ships): word {fmt(th[:1])}, ratio {fmt(th[1:2])}, margin "
        f"{fmt(th[2:])}: commands right {pct(c['right'], c['commands'])}, wrong {pct(c['wrong'], c['said'])}, "
        f"rejected {pct(c['rejected'], c['other'])}.")
    ceiling = [r for r in goal if r["kind"] == "command"]
    heard = {fam: [r["got"] == r["expected"] for r in ceiling if r["family"] == fam] for fam in families}
    say("Before any rejection the sentence heard is the one said for " + ", ".join(
        f"{fam} {pct(sum(ok), len(ok))}" for fam, ok in heard.items()) + " (the acoustic model's ceiling here).")
    rtf = [r["rtf"] for r in rows if r["rtf"] is not None]
    say(f"Decoding time over speech length (every check on, rivals searched for every command): median "
        f"{statistics.median(rtf):.3f}x, worst {max(rtf):.3f}x over {len(rtf)} recordings.\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=corpus.DEFAULT_DIR)
    parser.add_argument("--redecode", action="store_true", help="decode again even when decoded rows are cached")
    parser.add_argument("--shard", default="0/1", help="decode only shard I/N (run N at once on N cores), no report")
    parser.add_argument("--budget", type=float, default=0.005, help="wrong commands allowed while calibrating")
    parser.add_argument("--write", type=Path, help="replace the marked section of this Markdown file")
    args = parser.parse_args(argv)
    i, n = map(int, args.shard.split("/"))
    cache = args.corpus / f"decoded-{i}of{n}.jsonl"
    if args.redecode or not list(args.corpus.glob("decoded-*.jsonl")):
        decode(args.corpus, cache, (i, n))
        if n > 1:
            return 0
    rows = load_rows(args.corpus)
    lines: list[str] = []
    report(rows, args.budget, lines.append)
    text = "\n".join(lines)
    print(text)
    if args.write:
        doc = args.write.read_text()
        start, end = "<!-- bench_speech_corpus -->", "<!-- /bench_speech_corpus -->"
        if start in doc:
            doc = doc[:doc.index(start)] + start + "\n" + text + "\n" + doc[doc.index(end):]
            args.write.write_text(doc)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
