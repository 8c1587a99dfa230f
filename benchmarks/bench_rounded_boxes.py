"""Benchmark: rectangles and squares with all four corners rounded (radius 0.1-0.5 of the shorter side, aspect 1-4)
read as boxes, and circles and ellipses drawn as people draw them (wobbly, flattened, egg-shaped, overshot) read round,
by the project's pen models (`tests/penmodels/rounded_boxes.py`).

Usage: .venv/bin/python benchmarks/bench_rounded_boxes.py [--seeds A:B] [--held-back] [--families A,B] [--misread]

Each family draws its shape from its own seeded generator (`rounded_boxes.drawn`) and each pen draws it with the same
seed, as `bench_boxes` does: the careful virtual pen (windows-ink), the hurried hand (`penmodels.hurried`), the hurried
hand through a device sending an event every 15-30 ms and through a mouse (`bench_boxes.hurried_mouse`). Every stroke
is read with its times. A rounded box is right when it reads as a box, a round shape when it reads as a circle or an
ellipse. Seeds 0-29 are the tuning range; seeds 1000-1029 (``--held-back``) are never looked at while tuning and
reported apart. ``--misread`` lists each misread (family, pen, seed, kind). Deterministic: no clock, no unseeded
randomness.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_boxes import PENS
from bench_closed_shapes import add_seed_arguments, chosen_seeds
from penmodels.rounded_boxes import BOXES, FAMILIES, drawn

from physink_tui.scene.recognition.recognize import recognize_stroke

ROUND = ("circle", "ellipse")


def expected(family: str) -> tuple[str, ...]:
    """The kinds a person means by ``family``'s shape: a box, or round."""
    return ("box",) if family in BOXES else ROUND


def read(family: str, pen: str, seed: int) -> str | None:
    """The kind read from ``family``'s shape for ``seed`` drawn by ``pen``, with its times."""
    points = PENS[pen](drawn(family, seed), seed)
    return recognize_stroke([p[:2] for p in points], [p[2] for p in points]).kind


def run(families: list[str], seeds: range) -> dict[tuple[str, str], list[str | None]]:
    return {(f, p): [read(f, p, s) for s in seeds] for f in families for p in PENS}


def report(results: dict[tuple[str, str], list[str | None]], title: str) -> list[str]:
    lines = [f"#### {title}", "", "| family | " + " | ".join(PENS) + " | misread as |",
             "|---|" + "---:|" * len(PENS) + "---|"]
    pooled: Counter[str] = Counter()
    for family in dict.fromkeys(f for f, _ in results):
        cells, others = [], Counter[str]()
        kind = "box" if family in BOXES else "round"
        for pen in PENS:
            got = results[(family, pen)]
            right = sum(k in expected(family) for k in got)
            cells.append(f"{right}/{len(got)}")
            others.update(str(k) for k in got if k not in expected(family))
            pooled[f"{kind} {pen}"] += right
            pooled[f"{kind} {pen} n"] += len(got)
        lines.append(f"| {family} | " + " | ".join(cells) + " | "
                     + ", ".join(f"{k} {n}" for k, n in others.most_common()) + " |")
    lines.append("")
    for kind in ("box", "round"):
        if pooled[f"{kind} {next(iter(PENS))} n"]:
            total = sum(pooled[f"{kind} {p}"] for p in PENS)
            n = sum(pooled[f"{kind} {p} n"] for p in PENS)
            lines.append(f"- {kind}: " + ", ".join(f"{p} {pooled[f'{kind} {p}']}/{pooled[f'{kind} {p} n']}"
                                                   for p in PENS) + f"; all {total}/{n} = {100 * total / n:.1f} %")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_seed_arguments(parser)
    parser.add_argument("--families", help="a comma-separated subset of the families (default: all)")
    parser.add_argument("--misread", action="store_true", help="list every misread stroke")
    args = parser.parse_args()
    families = args.families.split(",") if args.families else list(FAMILIES)
    seeds, name = chosen_seeds(args)
    results = run(families, seeds)
    print("\n".join(report(results, name)))
    if args.misread:
        for (family, pen), got in results.items():
            for seed, kind in zip(seeds, got, strict=True):
                if kind not in expected(family):
                    print(f"{family} {pen} {seed} {kind}")


if __name__ == "__main__":
    main()
