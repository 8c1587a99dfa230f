"""Benchmark: closed shapes whose ends run on past where they started (`tests/penmodels/run_on_closes`: a triangle,
box, diamond, pentagon, hexagon or ellipse whose pen lands before the first corner and runs on past it, the ends
crossing), drawn by the pen models, each read as the closed kind; and where, by the tail's length, it stops being.

Usage: .venv/bin/python benchmarks/bench_run_on_closes.py [--seeds tune|held|all] [--rules] [--family NAME]
       [--tails A:B] [--misread]

Issue 25, session 30: tutorboard seed90210's triangle #247 (fourth group) runs on past its first corner, its ends
crossing 0.17 and 0.33 of its size from them, and is read as a polyline. The shapes are drawn by the pens of
`bench_open_marks` (the careful virtual pen, the hurried hand, the hurried hand through a coarse device and through a
mouse), each read with its times and without.
Besides the table per family and pen, a table by the tail's share of the last side (in five bins of ``--tails``, the
same shapes with their tails scaled: straight or hooked, the pen landing near the corner or not) shows where the closed
reading stops. Seeds 0-29 (`TUNING_SEEDS`) were looked at while tuning; 1000-1029 (`HELD_SEEDS`) read once.
Session 31 (wt-tails) added ``triangle-long-tail`` (read closed) and ``x-run-past`` (an x or a delete mark whose start
lies at its crossing, read open), each with its own range of tails; they are counted per family, not by the tail.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from bench_open_marks import HELD_SEEDS, PENS, TUNING_SEEDS
from penmodels.run_on_closes import EXPECTED, FAMILIES, TAIL, TAILS, run_on

from physink_tui.scene.recognition.recognize import recognize_stroke

LEAD_SPLIT = 0.12
"""The second table counts the pen landing nearer the first corner than this share of the first side apart."""


def accepted(family: str) -> tuple[str, ...]:
    want = EXPECTED[family]
    return (want,) if isinstance(want, str) else want


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True,
         tails: tuple[float, float] | None = None) -> str | None:
    """The kind the ``family``'s shape of ``seed`` (its tail drawn from ``tails``, the family's own range where None)
    drawn by ``pen`` is read as (with its times where ``timed``)."""
    stroke = PENS[pen](run_on(family, seed, tails)[0], seed)
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None, learned=learned).kind


def main() -> None:
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--family", choices=tuple(FAMILIES), action="append", help="only these families")
    ap.add_argument("--misread", action="store_true", help="list every misreading (family, pen, seed, timed, kind)")
    ap.add_argument("--tails", default=None, help="the tails' shares of the last side, A:B (default: each "
                    "family's own, 0:0.5 but for the families of `run_on_closes.TAILS`)")
    args = ap.parse_args()
    given = tuple(float(v) for v in args.tails.split(":")) if args.tails else None
    assert given is None or len(given) == 2
    tails = given or TAIL  # the bins' range (a family of `TAILS` falls in the first or the last bin)
    bins = [tails[0] + (tails[1] - tails[0]) * (k + 1) / 5 for k in range(5)]
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    for name, seeds in groups[args.seeds]:
        print(f"#### {name}, {'rules' if args.rules else 'shipped recogniser'}\n")
        print("| family | " + " | ".join(PENS) + " | other readings |\n|---|" + "---:|" * len(PENS) + "---|")
        by_bin: Counter[tuple[str, int, bool, bool]] = Counter()
        misread, total = [], Counter[str]()
        for family in args.family or FAMILIES:
            cells, others = [], Counter[str]()
            for pen in PENS:
                right = 0
                for seed in seeds:
                    _, tail, hooked, lead = run_on(family, seed, given)
                    b = next((i for i, top in enumerate(bins) if tail <= top), 4)
                    for timed in (True, False):
                        kind = read(family, pen, seed, timed, not args.rules, given)
                        ok = kind in accepted(family)
                        right += ok
                        if given or family not in TAILS:  # the families of `TAILS` are counted by family only
                            by_bin[("n", b, hooked, lead >= LEAD_SPLIT)] += 1
                            by_bin[("ok", b, hooked, lead >= LEAD_SPLIT)] += ok
                        if not ok:
                            others[str(kind)] += 1
                            misread.append(f"{family} {pen} {seed} {'timed' if timed else 'untimed'} {kind} "
                                           f"tail {tail:.2f}{' hooked' if hooked else ''} lead {lead:.2f}")
                cells.append(f"{right}/{2 * len(seeds)}")
                total["right"] += right
                total["all"] += 2 * len(seeds)
            print(f"| {family} | " + " | ".join(cells) + " | "
                  + ", ".join(f"{k} {n}" for k, n in others.most_common()) + " |", flush=True)
        print(f"\n- all {total['right']}/{total['all']} = {100 * total['right'] / total['all']:.1f} %\n")
        print(f"| tail (of the last side) | straight, lead < {LEAD_SPLIT} | straight, lead >= {LEAD_SPLIT} "
              f"| hooked, lead < {LEAD_SPLIT} | hooked, lead >= {LEAD_SPLIT} |\n|---|---:|---:|---:|---:|")
        lo = tails[0]
        for b, top in enumerate(bins):
            cells = [f"{by_bin[('ok', b, h, far)]}/{by_bin[('n', b, h, far)]}" for h in (False, True)
                     for far in (False, True)]
            print(f"| {lo:.1f}-{top:.1f} | " + " | ".join(cells) + " |")
            lo = top
        if args.misread:
            print("", *misread, sep="\n")


if __name__ == "__main__":
    main()
