"""Benchmark: an x swung round at its far side, a plain one-stroke x, a tick whose short arm is a few percent of the
stroke, and a pigtail whose arms cross as an x's do, drawn by the pen models, read as the kinds people's labels say
(x's and ticks polylines, pigtails curves).

Usage: .venv/bin/python benchmarks/bench_hurried_marks.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25 (session 19): one-stroke x's read as curves and ticks with short first arms read as curves on people's strokes
(`recognition.crossed_marks`, `recognition.hooked_ticks`). The marks (`tests/penmodels/hurried_marks`) are drawn by the
pens of `bench_open_marks` (the careful virtual pen, the hurried hand, the hurried hand through a coarse device and
through a mouse), each read with its times and without. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing;
1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from bench_open_marks import HELD_SEEDS, PENS, TUNING_SEEDS
from penmodels.hurried_marks import EXPECTED, FAMILIES

from physink_tui.scene.recognition.recognize import recognize_stroke


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> str | None:
    """The kind the recogniser reads the ``family``'s mark of ``seed`` drawn by ``pen`` as."""
    stroke = PENS[pen](FAMILIES[family](seed), seed)
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None, learned=learned).kind


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--family", choices=tuple(FAMILIES), action="append", help="only these families")
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print("| seeds | family | pen | read as expected | readings |\n|---|---|---|---:|---|")
    for name, seeds in groups[args.seeds]:
        for family in args.family or FAMILIES:
            for pen in PENS:
                got = [read(family, pen, s, timed, not args.rules) for s in seeds for timed in (True, False)]
                right = sum(k == EXPECTED[family] for k in got)
                kinds = ", ".join(f"{k} {c}" for k, c in Counter(got).most_common())
                print(f"| {name} | {family} | {pen} | {right}/{len(got)} | {kinds} |", flush=True)


if __name__ == "__main__":
    main()
