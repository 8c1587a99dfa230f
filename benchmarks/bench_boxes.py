"""Benchmark: rectangles drawn with the habits of people we have not seen (`tests/penmodels/box_habits.py`: tails past
the close, retraced, turned, a wall askew, a corner swung wide, a gap at the close, ...) by the project's pen models,
each read as a box.

Usage: .venv/bin/python benchmarks/bench_boxes.py [--seeds A:B] [--held-back] [--rules] [--families A,B] [--misread]

Each family draws its box from its own seeded generator (`box_habits.drawn`) and each pen draws it with the same seed,
as `bench_closed_shapes` does: the careful virtual pen (windows-ink), the hurried hand (`penmodels.hurried`) and the
hurried hand through a device sending an event every 15-30 ms (a browser's sparse events) and through a mouse
(`hurried_mouse`: whole pixels, one axis a step, events in bursts). Every stroke is
read with its times. A family is right when it reads as a box (benchmarks/label_kinds.tsv: a rectangle is a box).
Seeds 0-29 are the tuning range; seeds 1000-1029 (``--held-back``) are never looked at while tuning and reported
apart. ``--misread`` lists each misread (family, pen, seed, kind). Deterministic: no clock, no unseeded randomness.
"""

from __future__ import annotations

import sys
from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np
from bench_closed_shapes import (
    careful,
    chosen_seeds,
    family_bench_parser,
    hurried,
    hurried_coarse,
)
from bench_device_stress import COMBINED
from penmodels.box_habits import FAMILIES, drawn
from penmodels.shapes import Shape

from physink_tui.scene.recognition.recognize import recognize_stroke


def hurried_mouse(s: Shape, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand through a mouse (`bench_device_stress.COMBINED` "mouse": 60-200 px across in whole pixels, one
    axis a step, events in bursts, some repeated)."""
    drawn_ = np.array(hurried(s, seed))
    pts, when = COMBINED["mouse: stairs, bursts, repeats"]((drawn_[:, :2], drawn_[:, 2]), np.random.default_rng(seed))
    assert when is not None
    return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]


PENS = {"careful": careful, "hurried": hurried, "hurried-coarse": hurried_coarse, "hurried-mouse": hurried_mouse}


def read(family: str, pen: str, seed: int, learned: bool = True) -> str | None:
    """The kind read from ``family``'s box for ``seed`` drawn by ``pen``, with its times."""
    return read_drawn(PENS[pen], drawn(family, seed), seed, learned)


def read_drawn(pen: Callable[[Shape, int], list[tuple[float, float, float]]], shape: Shape, seed: int,
               learned: bool = True) -> str | None:
    """The kind read from ``shape`` drawn by ``pen`` for ``seed``, with its times (every closed-shape family bench)."""
    points = pen(shape, seed)
    return recognize_stroke([p[:2] for p in points], [p[2] for p in points], learned=learned).kind


def a_box(family: str) -> str:
    """The kind every family of the box benches means."""
    return "box"


def report(results: dict[tuple[str, str], list[str | None]], title: str,
           pens: Mapping[str, object] = PENS, meant: Callable[[str], str] = a_box) -> list[str]:
    """The table of ``results``: a row per family, a column per pen of ``pens`` counting the readings of the kind the
    family means (``meant``), and the pooled figures."""
    lines = [f"#### {title}", "", "| family | " + " | ".join(pens) + " | other readings |",
             "|---|" + "---:|" * len(pens) + "---|"]
    pooled: Counter[str] = Counter()
    for family in dict.fromkeys(f for f, _ in results):
        cells, others = [], Counter[str]()
        for pen in pens:
            got = results[(family, pen)]
            right = sum(k == meant(family) for k in got)
            cells.append(f"{right}/{len(got)}")
            others.update(str(k) for k in got if k != meant(family))
            pooled[pen] += right
            pooled[f"{pen} n"] += len(got)
        lines.append(f"| {family} | " + " | ".join(cells) + " | "
                     + ", ".join(f"{k} {n}" for k, n in others.most_common()) + " |")
    total = sum(pooled[p] for p in pens)
    n = sum(pooled[f"{p} n"] for p in pens)
    lines += ["", "- " + ", ".join(f"{p} {pooled[p]}/{pooled[p + ' n']}" for p in pens)
              + f"; all {total}/{n} = {100 * total / n:.1f} %"]
    return lines


def misread(results: dict[tuple[str, str], list[str | None]], seeds: range,
            meant: Callable[[str], str] = a_box) -> list[str]:
    """One line per reading other than the kind the family means: family, pen, seed, the kind read."""
    return [f"{family} {pen} {seed} {kind}" for (family, pen), got in results.items()
            for seed, kind in zip(seeds, got, strict=True) if kind != meant(family)]


def family_main(doc: str, families: Sequence[str], pens: Mapping[str, object],
                read_one: Callable[[str, str, int, bool], str | None], meant: Callable[[str], str] = a_box) -> None:
    """A closed-shape family bench's command line: read ``families`` by ``pens`` on the chosen seeds (``read_one``:
    family, pen, seed, learned -> the kind read) and print the table, and with ``--misread`` every misreading."""
    args = family_bench_parser(doc).parse_args()
    chosen = args.families.split(",") if args.families else list(families)
    seeds, name = chosen_seeds(args)
    results = {(f, p): [read_one(f, p, s, not args.rules) for s in seeds] for f in chosen for p in pens}
    print("\n".join(report(results, f"{name}, {'rules' if args.rules else 'shipped recogniser'}", pens, meant)))
    if args.misread:
        print("\n".join(misread(results, seeds, meant)))


def main() -> None:
    family_main(__doc__ or "", list(FAMILIES), PENS, read)


if __name__ == "__main__":
    main()
