"""Benchmark: many-cornered open polylines (staircases, square waves, zig-zags) read as polylines, by both pen models.

Usage: .venv/bin/python benchmarks/bench_stairs.py [--seeds tune|held|all] [--rules] [--families ...] [--steps 3 8]

Issue 25: a staircase of small steps drawn by a pen model read as a curve (session 17: 5-6 steps 26 of 26 times by
the careful pen). A person drawing a staircase, a ratchet's teeth, a comb or a crenellated wall means a polyline with
those corners (`recognition.stairs`). For each seed and each count of 3-8 steps (or teeth) the pen models draw:

- ``stairs``: equal steps (a floor tread, then a riser and a tread a step), each tread 18-55 px, risers 0.4-1.6 of it;
- ``uneven stairs``: the same with each tread and riser 0.5-1.5 of the step's;
- ``landings``: equal steps between two long landings (each 0.6-1.2 times the flight's run): the steps small against the
  stroke;
- ``square wave``: teeth (up, across, down, across: a crenellated wall, a comb), 20-55 px a period, a tooth 0.35-0.65
  of it wide and 0.4-1.4 of it high;
- ``zigzag``: teeth of two straight sides (up and down: a saw, a ratchet), 20-60 px a tooth, 0.3-1.2 of it high;

each shrunk to `MAX_DIAGONAL` where bigger and turned to a random angle, drawn by the careful virtual pen, the
hurried hand and the hurried hand through a coarse device (`bench_waves.PENS`), read with the stroke's times and
without. A reading is right when it is a polyline; its corners are "as drawn" when their count is within max(1, a
fifth) of the inner corners drawn.
Seeds 0-29 (`TUNING_SEEDS`) chose `recognition.stairs`' thresholds; 1000-1059 (`HELD_SEEDS`) were read once.
"""

from __future__ import annotations

import argparse
import math
import random
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_waves import PENS as WAVE_PENS
from bench_waves import _place, _placed

from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.recognize import recognize_stroke

PENS = {pen: WAVE_PENS[pen] for pen in ("careful", "hurried", "hurried-coarse")}
"""The pens of `bench_waves` this benchmark was measured with (not its mouse pen, added in session 20)."""

TUNING_SEEDS = range(30)
HELD_SEEDS = range(1000, 1060)
STEPS = range(3, 9)
MAX_DIAGONAL = 560.0
"""A shape wider than this across (the bigger, many-stepped ones) is shrunk to it: it stays on the canvas, turned."""
Point = tuple[float, float]


def _centred(points: list[Point]) -> list[Point]:
    """``points`` centred on the origin, shrunk where needed to `MAX_DIAGONAL` across."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    shrink = min(1.0, MAX_DIAGONAL / math.hypot(max(xs) - min(xs), max(ys) - min(ys)))
    return [((x - cx) * shrink, (y - cy) * shrink) for x, y in points]


def _flight(treads: list[float], risers: list[float]) -> list[Point]:
    """A staircase's corners: a tread, then a riser and a tread for each riser (``len(treads) == len(risers) + 1``)."""
    x, y = 0.0, 0.0
    points = [(x, y)]
    for k, tread in enumerate(treads):
        x += tread
        points.append((x, y))
        if k < len(risers):
            y -= risers[k]
            points.append((x, y))
    return points


def stairs(rng: random.Random, steps: int) -> list[Point]:
    run = rng.uniform(18, 55)
    rise = run * rng.uniform(0.4, 1.6)
    return _flight([run] * (steps + 1), [rise] * steps)


def uneven_stairs(rng: random.Random, steps: int) -> list[Point]:
    run = rng.uniform(18, 55)
    rise = run * rng.uniform(0.4, 1.6)
    return _flight([run * rng.uniform(0.5, 1.5) for _ in range(steps + 1)],
                   [rise * rng.uniform(0.5, 1.5) for _ in range(steps)])


def landings(rng: random.Random, steps: int) -> list[Point]:
    run = rng.uniform(18, 55)
    rise = run * rng.uniform(0.4, 1.6)
    flight = run * steps
    return _flight([flight * rng.uniform(0.6, 1.2)] + [run] * (steps - 1) + [flight * rng.uniform(0.6, 1.2)],
                   [rise] * steps)


def square_wave(rng: random.Random, teeth: int) -> list[Point]:
    period = rng.uniform(20, 55)
    width, height = period * rng.uniform(0.35, 0.65), period * rng.uniform(0.4, 1.4)
    gap = period - width
    points, x = [(0.0, 0.0), (gap, 0.0)], gap
    for _ in range(teeth):
        points += [(x, -height), (x + width, -height), (x + width, 0.0), (x + width + gap, 0.0)]
        x += width + gap
    return points


def zigzag(rng: random.Random, teeth: int) -> list[Point]:
    tooth = rng.uniform(20, 60)
    height = tooth * rng.uniform(0.3, 1.2)
    return [(k * tooth / 2, -height if k % 2 else 0.0) for k in range(2 * teeth + 1)]


FAMILIES: dict[str, Callable[[random.Random, int], list[Point]]] = {
    "stairs": stairs, "uneven stairs": uneven_stairs, "landings": landings, "square wave": square_wave,
    "zigzag": zigzag}


def shape(family: str, steps: int, seed: int) -> list[Point]:
    """The corners of ``family``'s shape of ``steps`` steps (or teeth) for ``seed``, placed on the canvas."""
    rng = random.Random(f"{family}/{steps}/{seed}")
    corners = _centred(FAMILIES[family](rng, steps))
    return _placed(corners, _place(rng))


def reading(family: str, steps: int, pen: str, seed: int, timed: bool, learned: bool = True) -> Recognition:
    """The recogniser's reading of ``family``'s shape drawn by ``pen``."""
    drawn = PENS[pen](shape(family, steps, seed), False, seed)
    return recognize_stroke([p[:2] for p in drawn], [p[2] for p in drawn] if timed else None, learned=learned)


def corners_as_drawn(found: Recognition, drawn: int) -> bool:
    """Whether ``found`` is a polyline with about ``drawn`` inner corners (within max(1, a fifth of them))."""
    if found.kind != "polyline" or not isinstance(found.geometry, Polyline):
        return False
    return abs(len(found.geometry.points) - 2 - drawn) <= max(1, drawn // 5)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--families", nargs="*", default=list(FAMILIES), choices=list(FAMILIES))
    ap.add_argument("--pens", nargs="*", default=list(PENS), choices=list(PENS))
    ap.add_argument("--steps", nargs=2, type=int, default=(STEPS.start, STEPS.stop - 1))
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1059", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print("| seeds | family | steps | pen | polylines | corners as drawn | readings |")
    print("|---|---|---:|---|---:|---:|---|")
    for name, seeds in groups[args.seeds]:
        totals: Counter[tuple[str, str]] = Counter()
        for family in args.families:
            for steps in range(args.steps[0], args.steps[1] + 1):
                for pen in args.pens:
                    drawn = len(shape(family, steps, 0)) - 2
                    got = [reading(family, steps, pen, s, timed, not args.rules) for s in seeds for timed in (1, 0)]
                    right = sum(r.kind == "polyline" for r in got)
                    as_drawn = sum(corners_as_drawn(r, drawn) for r in got)
                    totals[(family, pen)] += right
                    totals[(family, "n")] += len(got)
                    kinds = ", ".join(f"{k} {c}" for k, c in Counter(r.kind for r in got).most_common())
                    print(f"| {name} | {family} | {steps} | {pen} | {right}/{len(got)} | {as_drawn} | {kinds} |",
                          flush=True)
        for family in args.families:
            cells = ", ".join(f"{pen} {totals[(family, pen)]}" for pen in args.pens)
            print(f"| {name} | {family} | all | | {cells} of {totals[(family, 'n')] // len(args.pens)} each | | |")


if __name__ == "__main__":
    main()
