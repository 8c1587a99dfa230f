"""Benchmark: triangles drawn with the habits of people we have not seen (`tests/penmodels/triangle_habits.py`: a gap
at the close, a start along the first side, a tail or a crossing past the close, ...) by the project's pen models, each
read as a polygon.
Usage: .venv/bin/python benchmarks/bench_triangles.py [--seeds A:B] [--held-back] [--rules] [--families A,B] [--misread]
The pens are `bench_boxes`' (the careful virtual pen, the hurried hand, and the hurried hand through a fast device and
through a mouse); every stroke is read with its times. A family is right when it reads as a polygon
(benchmarks/label_kinds.tsv: a triangle is a polygon). Seeds 0-29 are the tuning range; seeds 1000-1029
(``--held-back``) are never looked at while tuning and reported apart. Deterministic: no clock, no unseeded randomness.
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_boxes import PENS, read_drawn
from bench_closed_shapes import chosen_seeds, family_bench_parser
from penmodels.triangle_habits import FAMILIES, drawn

EXPECTED = "polygon"


def read(family: str, pen: str, seed: int, learned: bool = True) -> str | None:
    """The kind read from ``family``'s triangle for ``seed`` drawn by ``pen``, with its times."""
    return read_drawn(PENS[pen], drawn(family, seed), seed, learned)


def main() -> None:
    args = family_bench_parser(__doc__ or "").parse_args()
    families = args.families.split(",") if args.families else list(FAMILIES)
    seeds, name = chosen_seeds(args)
    print(f"#### {name}, {'rules' if args.rules else 'shipped recogniser'}", "",
          "| family | " + " | ".join(PENS) + f" | readings other than {EXPECTED} |",
          "|---|" + "---:|" * len(PENS) + "---|", sep="\n")
    pooled: Counter[str] = Counter()
    misread = []
    for family in families:
        cells, others = [], Counter[str]()
        for pen in PENS:
            got = [read(family, pen, seed, learned=not args.rules) for seed in seeds]
            right = sum(k == EXPECTED for k in got)
            cells.append(f"{right}/{len(got)}")
            others.update(str(k) for k in got if k != EXPECTED)
            pooled[pen] += right
            pooled["n"] += len(got)
            misread += [f"{family} {pen} {seed} {k}" for seed, k in zip(seeds, got, strict=True) if k != EXPECTED]
        print(f"| {family} | " + " | ".join(cells) + " | " + ", ".join(f"{k} {n}" for k, n in others.most_common())
              + " |")
    total = sum(pooled[p] for p in PENS)
    print("", "- " + ", ".join(f"{p} {pooled[p]}/{pooled['n'] // len(PENS)}" for p in PENS)
          + f"; all {total}/{pooled['n']} = {100 * total / pooled['n']:.1f} %", sep="\n")
    if args.misread:
        print("\n".join(misread))


if __name__ == "__main__":
    main()
