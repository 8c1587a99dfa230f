"""Benchmark: polygons of 3-8 sides whose corners a hand rounded (`tests/penmodels/rounded_polygons`) read by the pen
models as the outline drawn, with as many sides.

Usage: .venv/bin/python benchmarks/bench_rounded_polygons.py [--seeds tune|held|all] [--rules] [--family NAME]
[--misread]

Issue 25, session 32: the fourth group's octagons with rounded corners read as ellipses, a box with one rounded corner
as a pentagon. Each outline (every corner rounded over 0.08-0.35 of a side, or one corner over 0.2-0.45 among sharp
ones) is drawn by the pens of `bench_open_marks` (the careful virtual pen, the hurried hand, the hurried hand through a
coarse device and through a mouse), each read with its times and without. A reading is right when it is the kind
expected (a box for four sides, a polygon otherwise) and a polygon has the outline's number of vertices; the table
gives both and the readings. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`)
were read once, at the end.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from bench_open_marks import HELD_SEEDS, PENS, TUNING_SEEDS
from penmodels.rounded_polygons import EXPECTED, FAMILIES, SIDES

from physink_tui.scene.recognition.primitives import Polygon
from physink_tui.scene.recognition.recognize import recognize_stroke


def reading(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> str:
    """The kind read from ``family``'s outline of ``seed`` drawn by ``pen``, a polygon's with its number of vertices
    (``polygon5``)."""
    stroke = PENS[pen](FAMILIES[family](seed), seed)
    got = recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None, learned=learned)
    if isinstance(got.geometry, Polygon):
        return f"{got.kind}{len(got.geometry.points)}"
    return str(got.kind)


def right(family: str, got: str) -> bool:
    """Whether ``got`` (`reading`) is ``family``'s outline as drawn: its kind, and a polygon's sides."""
    return got == (f"polygon{SIDES[family]}" if EXPECTED[family] == "polygon" else EXPECTED[family])


def main() -> None:
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--family", choices=tuple(FAMILIES), action="append", help="only these families")
    ap.add_argument("--misread", action="store_true", help="list every misread (family, pen, seed, timed, reading)")
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    misread = []
    print("| seeds | family | pen | as drawn | readings |\n|---|---|---|---:|---|")
    for name, seeds in groups[args.seeds]:
        total = Counter[str]()
        for family in args.family or FAMILIES:
            for pen in PENS:
                got = [(s, t, reading(family, pen, s, t, not args.rules)) for s in seeds for t in (True, False)]
                ok = sum(right(family, g) for _, _, g in got)
                misread += [(family, pen, s, t, g) for s, t, g in got if not right(family, g)]
                total["right"] += ok
                total["all"] += len(got)
                total[f"{pen} right"] += ok
                total[f"{pen} all"] += len(got)
                kinds = ", ".join(f"{k} {c}" for k, c in Counter(g for _, _, g in got).most_common())
                print(f"| {name} | {family} | {pen} | {ok}/{len(got)} | {kinds} |", flush=True)
        for pen in PENS:
            print(f"| {name} | all | {pen} | {total[f'{pen} right']}/{total[f'{pen} all']} | |")
        print(f"| {name} | all | all | {total['right']}/{total['all']} | |")
    if args.misread:
        for m in misread:
            print(*m)


if __name__ == "__main__":
    main()
