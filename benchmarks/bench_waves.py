"""Benchmark: wavy open strokes (squiggles) read as curves and zig-zags as polylines, drawn by both pen models.

Usage: .venv/bin/python benchmarks/bench_waves.py [--seeds tune|held|all] [--rules]

The design sets hold zig-zags but no wavy line; the fourth held-back group's squiggles (quickdraw "squiggle": a short
wavy or curling line, a curve) fell in session 16. So the pen models draw them (issue 25, `recognition.waves`):

- a **wave**: a sine of 1-3.5 periods, its amplitude 0.06-0.25 of its length (0.06-0.875 of its wavelength: its
  steepness), 150-450 px long, turned; expected a curve;
- an **S** (session 19, the fourth group's squiggles): a sine of 0.8-1.2 periods starting near its middle line, two
  bends inside its ends, 0.1-0.3 of its length high; expected a curve;
- a **zig-zag**: 3-7 teeth of straight sides, 0.1-0.3 of its length high; expected a polyline;

each drawn by the careful virtual pen (windows-ink, through the points), the hurried hand (`tests/penmodels/hurried`:
a wave as a smooth path, a zig-zag's corners overshot, rounded or turned cleanly), the hurried hand through a device
sending an event every 15-30 ms (`bench_device_stress.coarse`) and, since session 20, through a mouse (whole-pixel
stair steps at 60-200 px across, bursts of events, repeated events: does a fast mouse round a zig-zag's teeth into a
wave's bends?), and read with the stroke's times and without.
Seeds 0-29 (`TUNING_SEEDS`) chose `waves`' thresholds with the design sets; 1000-1059 (`HELD_SEEDS`) were read once.
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

import numpy as np
from bench_device_stress import bursts, chain, coarse, duplicates, stairs
from penmodels.hurried import HurriedPen, touching
from penmodels.shapes import Curve
from penmodels.shapes import Path as PenPath

from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition.recognize import recognize_stroke

CANVAS = (1600, 1000)
TUNING_SEEDS = range(30)
HELD_SEEDS = range(1000, 1060)
Point = tuple[float, float]
EXPECTED = {"wave": "curve", "zigzag": "polyline", "s-curve": "curve"}


def _place(rng: random.Random) -> tuple[float, float, float]:
    """A random turn and a random place on the canvas."""
    return rng.uniform(0, 2 * math.pi), rng.uniform(500, 1100), rng.uniform(350, 650)


def _placed(curve: list[Point], place: tuple[float, float, float]) -> list[Point]:
    """``curve`` (centred on the origin) turned and moved to ``place`` (`_place`)."""
    angle, cx, cy = place
    c, s = math.cos(angle), math.sin(angle)
    return [(cx + x * c - y * s, cy + x * s + y * c) for x, y in curve]


def wave(seed: int) -> tuple[list[Point], float]:
    """The wave of ``seed`` (80 points along it) and its steepness (amplitude over wavelength)."""
    rng = random.Random(seed)
    length, periods = rng.uniform(150, 450), rng.uniform(1.0, 3.5)
    amplitude = rng.uniform(0.06, 0.25) * length
    place = _place(rng)
    phase = rng.choice([0.0, math.pi / 2])
    curve = [((k / 79 - 0.5) * length, amplitude * math.sin(2 * math.pi * periods * k / 79 + phase))
             for k in range(80)]
    return _placed(curve, place), amplitude * periods / length


def s_curve(seed: int) -> list[Point]:
    """The S of ``seed`` (80 points along it): a sine of 0.8-1.2 periods starting near its middle line, so that it
    bends twice inside its ends (a hump and a dip, as the Quick, Draw! players' squiggles often were), 0.1-0.3 of its
    length high, 150-450 px long, turned. Its seed is drawn apart from the waves' (``s-curve:seed``)."""
    rng = random.Random(f"s-curve:{seed}")
    length, periods = rng.uniform(150, 450), rng.uniform(0.8, 1.2)
    amplitude = rng.uniform(0.1, 0.3) * length
    place = _place(rng)
    phase = rng.uniform(-0.3, 0.3)
    return _placed([((k / 79 - 0.5) * length, amplitude * math.sin(2 * math.pi * periods * k / 79 + phase))
                    for k in range(80)], place)


def zigzag(seed: int) -> list[Point]:
    """The zig-zag of ``seed``: its corners."""
    rng = random.Random(seed)
    length, teeth = rng.uniform(150, 450), rng.randint(3, 7)
    height = rng.uniform(0.1, 0.3) * length
    place = _place(rng)
    return _placed([((k / teeth - 0.5) * length, height * (0.5 if k % 2 else -0.5)) for k in range(teeth + 1)], place)


def careful(points: list[Point], smooth: bool, seed: int) -> list[tuple[float, float, float]]:
    """The careful virtual pen through ``points``."""
    w, h = CANVAS
    samples = VirtualPen(REFERENCE_DEVICES["windows-ink"], seed=seed).samples(
        [Stroke(tuple((x / w, y / h) for x, y in points))])
    return [(p.state.x * w, p.state.y * h, p.t) for p in samples if p.phase == "touch"]


def hurried(points: list[Point], smooth: bool, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand along ``points``: a smooth path (`Curve`) or a chain of straight sides (`Path`)."""
    shape = Curve(tuple(points)) if smooth else PenPath(tuple(points))
    return touching(HurriedPen(random.Random(seed)).draw(shape, 0.0)[0])


def hurried_coarse(points: list[Point], smooth: bool, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand through a device sending an event every 15-30 ms."""
    drawn = np.array(hurried(points, smooth, seed))
    pts, when = coarse((drawn[:, :2], drawn[:, 2]), np.random.default_rng(seed))
    assert when is not None
    return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]


def hurried_mouse(points: list[Point], smooth: bool, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand through a mouse (`bench_open_marks`' "hurried-mouse": whole-pixel stair steps at 60-200 px
    across, events in bursts, repeated events)."""
    drawn = np.array(hurried(points, smooth, seed))
    pts, when = chain(stairs, bursts, duplicates)((drawn[:, :2], drawn[:, 2]), np.random.default_rng(seed))
    assert when is not None
    return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]


PENS: dict[str, Callable[[list[Point], bool, int], list[tuple[float, float, float]]]] = {
    "careful": careful, "hurried": hurried, "hurried-coarse": hurried_coarse, "hurried-mouse": hurried_mouse}


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> str | None:
    """The kind the recogniser reads the ``family``'s shape of ``seed`` drawn by ``pen`` as."""
    points = wave(seed)[0] if family == "wave" else s_curve(seed) if family == "s-curve" else zigzag(seed)
    drawn = PENS[pen](points, family != "zigzag", seed)
    return recognize_stroke([p[:2] for p in drawn], [p[2] for p in drawn] if timed else None, learned=learned).kind


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="all")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1059", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print("| seeds | family | pen | read as expected | readings |\n|---|---|---|---:|---|")
    for name, seeds in groups[args.seeds]:
        for family in EXPECTED:
            for pen in PENS:
                got = [read(family, pen, s, timed, not args.rules) for s in seeds for timed in (True, False)]
                right = sum(k == EXPECTED[family] for k in got)
                kinds = ", ".join(f"{k} {c}" for k, c in Counter(got).most_common())
                print(f"| {name} | {family} | {pen} | {right}/{len(got)} | {kinds} |")


if __name__ == "__main__":
    main()
