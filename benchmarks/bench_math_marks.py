"""Benchmark: radical signs and parentheses drawn by the pen models, read as the kinds people's labels say (a radical a
polyline, a parenthesis an arc or a curve).

Usage: .venv/bin/python benchmarks/bench_math_marks.py [--seeds tune|held|all] [--rules] [--family NAME]
       [--no-hooked-ticks] [--min-bends N]

Issue 25 (session 20): on the fifth held-back group (LaViola's mathematical symbols, read by the lead only) radicals and
parentheses lost readings in session 19, which added `recognition.hooked_ticks` and lowered `waves.MIN_BENDS` from 3 to
2. The marks (`tests/penmodels/math_marks`: radicals of straight sides, rounded ones, ones without their bar;
parentheses, plain and with an end hooked on or flicked back) are drawn by the pens of `bench_open_marks` (the careful
virtual pen, the hurried hand, the hurried hand through a coarse device and through a mouse), each read with its times
and without. ``--no-hooked-ticks`` and ``--min-bends 3`` read them as session 19's two changes had not been made (to
find which rule misreads what). Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`)
only measured.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
from penmodels.math_marks import EXPECTED, FAMILIES

from physink_tui.scene.recognition import hooked_ticks, waves


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> str | None:
    """The kind the recogniser reads the ``family``'s mark of ``seed`` drawn by ``pen`` (`bench_open_marks.PENS`) as."""
    return bench_open_marks.read(family, pen, seed, timed, learned, FAMILIES)


def main() -> None:
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--family", choices=tuple(FAMILIES), action="append", help="only these families")
    ap.add_argument("--no-hooked-ticks", action="store_true", help="without recognition.hooked_ticks")
    ap.add_argument("--min-bends", type=int, help="waves.MIN_BENDS (3 before session 19)")
    args = ap.parse_args()
    if args.no_hooked_ticks:
        hooked_ticks.hooked_tick = lambda unit, noise: None  # type: ignore[assignment]
    if args.min_bends is not None:
        waves.MIN_BENDS = args.min_bends
    groups = {"tune": [("tune 0-29", bench_open_marks.TUNING_SEEDS)],
              "held": [("held 1000-1029", bench_open_marks.HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print("| seeds | family | pen | read as expected | readings |\n|---|---|---|---:|---|")
    for name, seeds in groups[args.seeds]:
        total: Counter[str] = Counter()
        for family in args.family or FAMILIES:
            right_family = 0
            for pen in bench_open_marks.PENS:
                got = [read(family, pen, s, timed, not args.rules) for s in seeds for timed in (True, False)]
                right = sum(k in EXPECTED[family] for k in got)
                right_family += right
                total["right"] += right
                total["all"] += len(got)
                kinds = ", ".join(f"{k} {c}" for k, c in Counter(got).most_common())
                print(f"| {name} | {family} | {pen} | {right}/{len(got)} | {kinds} |", flush=True)
            print(f"| {name} | {family} | all | {right_family}/{len(seeds) * 2 * len(bench_open_marks.PENS)} | |")
        print(f"| {name} | all | all | {total['right']}/{total['all']} | |")


if __name__ == "__main__":
    main()
