"""Benchmark: straight lines as people draw them (hooked, slightly bowed, shaky, short) read as lines, and arcs drawn on
purpose read as arcs, by four pen models.

Usage: .venv/bin/python benchmarks/bench_lines.py [--seeds tune|held|all] [--rules] [--by length]

A line is the commonest part of a machine sketch (a rod, a ground, a ramp). The families (issue 25,
`recognition.lines`):

- **straight**: a line 15-800 px long (log-uniform) at any angle, as the pen model draws it;
- **hooked**: the same with a hook where the pen lands, where it lifts, or both: 2-8 px (a person's hook is the pen's
  landing or flick, as long on a short line as on a long one; at most a third of the line), turned back 100-160 deg;
- **bowed**: the same bowed to one side, its sag 0-4 % of its length (a hurried or swung hand), hooks as the pen's;
- **short-hooked**: a line 25-90 px long (log-uniform) hooked at both ends as the hooked family is (issue 25, session
  25: such a line, the hurried hand's through a coarse device, lost to `open_marks.SWUNG_WOBBLE`; `open_marks.
  hooked_straight` gives it back);
- **arc**: part of a circle swept 20-90 deg on purpose, its chord 40-500 px; expected an arc (a curve is counted apart:
  not a line, but not the arc drawn either).

Each is drawn by the careful virtual pen (windows-ink, through the points), the hurried hand (`penmodels.hurried`, its
own small hooks and bows; none of its own hooks on the hooked family), the hurried hand through a device sending an
event every 15-30 ms (`bench_device_stress.coarse`) and a slow shaky hand (`penmodels.hurried.SHAKY_SLOW`: a 4-7 Hz
tremor of 1-3 px, a slow wander of 1-2 px, 180-300 px/s, so many points), and read with the stroke's times and without.
Seeds 0-29 (`TUNING_SEEDS`) chose `recognition.lines`' rule with gtiwari333's lines; 1000-1029 (`HELD_SEEDS`) were read
once at the end.
"""

from __future__ import annotations

import argparse
import math
import random
import sys
from collections import Counter, defaultdict
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import numpy as np
from bench_device_stress import coarse
from bench_waves import careful
from penmodels.hurried import SHAKY_SLOW, Habits, HurriedPen, PenPoint, touching
from penmodels.shapes import Curve

from physink_tui.scene.recognition.recognize import recognize_stroke

TUNING_SEEDS = range(30)
HELD_SEEDS = range(1000, 1030)
Point = tuple[float, float]
FAMILIES = ("straight", "hooked", "bowed", "arc", "short-hooked")
EXPECTED = {"straight": "line", "hooked": "line", "bowed": "line", "arc": "arc", "short-hooked": "line"}
HOOKED = ("hooked", "short-hooked")
"""The families drawn with their own hooks (the hurried hand draws none of its own on them)."""
LENGTH_BINS = ((15.0, 40.0), (40.0, 150.0), (150.0, 800.0))


def _rot(d: Point, angle: float) -> Point:
    c, s = math.cos(angle), math.sin(angle)
    return (d[0] * c - d[1] * s, d[0] * s + d[1] * c)


def _hook(end: Point, heading: Point, size: float, turn_deg: float) -> list[Point]:
    """A hook ``size`` px long at ``end`` of a stroke running along ``heading`` (unit, away from the end into the
    stroke): the pen lands off to one side, turned back ``turn_deg`` from the heading, and curls into the line (a
    quadratic Bezier), the hook's points from its tip to just before ``end``."""
    away = _rot(heading, math.radians(turn_deg))
    tip = (end[0] + away[0] * size, end[1] + away[1] * size)
    ctrl = (end[0] - heading[0] * size * 0.5, end[1] - heading[1] * size * 0.5)
    n = max(4, int(size))
    return [((1 - u) ** 2 * tip[0] + 2 * u * (1 - u) * ctrl[0] + u * u * end[0],
             (1 - u) ** 2 * tip[1] + 2 * u * (1 - u) * ctrl[1] + u * u * end[1]) for u in (k / n for k in range(n))]


def shape(family: str, seed: int) -> tuple[list[Point], float]:
    """The ideal path of the ``family``'s stroke of ``seed`` (canvas pixels, dense enough to draw through) and its
    length (the line's, or the arc's chord)."""
    rng = random.Random(f"lines:{family}:{seed}")
    angle = rng.uniform(0.0, 2 * math.pi)
    cx, cy = rng.uniform(600, 1000), rng.uniform(400, 600)
    d = (math.cos(angle), math.sin(angle))
    if family == "arc":
        chord, sweep = rng.uniform(40.0, 500.0), math.radians(rng.uniform(20.0, 90.0)) * rng.choice((-1, 1))
        radius = chord / (2 * math.sin(abs(sweep) / 2))
        n = max(24, int(abs(sweep) * radius / 3))
        keys = []
        for k in range(n + 1):
            a = -sweep / 2 + sweep * k / n
            x, y = radius * math.sin(a), radius * (math.cos(a) - math.cos(sweep / 2))
            keys.append((cx + x * d[0] - y * d[1], cy + x * d[1] + y * d[0]))
        return keys, chord
    if family == "short-hooked":
        return _short_hooked(rng, cx, cy, d)
    length = math.exp(rng.uniform(math.log(15.0), math.log(800.0)))
    sag = rng.uniform(0.0, 0.04) * rng.choice((-1, 1)) if family == "bowed" else 0.0
    n = max(8, int(length / 3))
    keys = []
    for k in range(n + 1):
        u = k / n
        x, y = (u - 0.5) * length, sag * length * math.sin(math.pi * u)
        keys.append((cx + x * d[0] - y * d[1], cy + x * d[1] + y * d[0]))
    if family == "hooked":
        where = rng.choice(("start", "end", "both"))
        if where in ("start", "both"):
            keys = _hook(keys[0], d, min(rng.uniform(2.0, 8.0), length / 3), rng.choice((-1, 1))
                         * rng.uniform(100.0, 160.0)) + keys
        if where in ("end", "both"):
            back = (-d[0], -d[1])
            keys = keys + _hook(keys[-1], back, min(rng.uniform(2.0, 8.0), length / 3), rng.choice((-1, 1))
                                * rng.uniform(100.0, 160.0))[::-1]
    return keys, length


def _short_hooked(rng: random.Random, cx: float, cy: float, d: Point) -> tuple[list[Point], float]:
    """A line 25-90 px long centred on (``cx``, ``cy``) along ``d``, hooked where the pen lands and where it lifts, each
    hook 2-8 px (at most a third of the line) turned back 100-160 degrees to either side (`_hook`)."""
    length = math.exp(rng.uniform(math.log(25.0), math.log(90.0)))
    n = max(8, int(length / 3))
    keys = [(cx + (k / n - 0.5) * length * d[0], cy + (k / n - 0.5) * length * d[1]) for k in range(n + 1)]
    keys = _hook(keys[0], d, min(rng.uniform(2.0, 8.0), length / 3), rng.choice((-1, 1))
                 * rng.uniform(100.0, 160.0)) + keys
    back = (-d[0], -d[1])
    keys = keys + _hook(keys[-1], back, min(rng.uniform(2.0, 8.0), length / 3), rng.choice((-1, 1))
                        * rng.uniform(100.0, 160.0))[::-1]
    return keys, length


LAND = 0.3
"""When the hurried hand lands, seconds (its tremor runs on the session's clock): as in a session's journal
(`tests/test_lines_drawn.py`), so a seed draws there the stroke it draws here."""


def hurried_reports(points: list[Point], seed: int, habits: Habits | None) -> list[PenPoint]:
    """Every report of the hurried hand (with ``habits``) drawing along ``points``, landing at `LAND`."""
    return HurriedPen(random.Random(seed), habits=habits).draw(Curve(tuple(points)), LAND)[0]


def habits_of(pen: str, family: str) -> Habits | None:
    """The hurried hand's habits for ``pen`` (the slow shaky hand's, or the default) without its own hooks on the
    hooked families, which have their own (`HOOKED`)."""
    habits = SHAKY_SLOW if pen == "shaky" else Habits()
    return replace(habits, hook=0.0) if family in HOOKED else habits


def _hurried(points: list[Point], seed: int, habits: Habits | None) -> list[tuple[float, float, float]]:
    return touching(hurried_reports(points, seed, habits))


def hurried(points: list[Point], family: str, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand along ``points`` (its own hooks, but not on the hooked families, which have their own)."""
    return _hurried(points, seed, habits_of("hurried", family))


def hurried_coarse(points: list[Point], family: str, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand through a device sending an event every 15-30 ms."""
    drawn = np.array(hurried(points, family, seed))
    pts, when = coarse((drawn[:, :2], drawn[:, 2]), np.random.default_rng(seed))
    assert when is not None
    return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]


def shaky(points: list[Point], family: str, seed: int) -> list[tuple[float, float, float]]:
    """The slow shaky hand (`penmodels.hurried.SHAKY_SLOW`; its own hooks, but not on the hooked families)."""
    return _hurried(points, seed, habits_of("shaky", family))


def careful_pen(points: list[Point], family: str, seed: int) -> list[tuple[float, float, float]]:
    """The careful virtual pen through ``points``."""
    return careful(points, True, seed)


PENS: dict[str, Callable[[list[Point], str, int], list[tuple[float, float, float]]]] = {
    "careful": careful_pen, "hurried": hurried, "hurried-coarse": hurried_coarse, "shaky": shaky}


def drawn(family: str, pen: str, seed: int) -> tuple[list[tuple[float, float, float]], float]:
    """The ``family``'s stroke of ``seed`` as ``pen`` draws it: (x, y, t) reports, and its length (`shape`)."""
    keys, length = shape(family, seed)
    return PENS[pen](keys, family, seed), length


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> tuple[str | None, float]:
    """The kind the recogniser reads the ``family``'s stroke of ``seed`` drawn by ``pen`` as, and its length."""
    points, length = drawn(family, pen, seed)
    found = recognize_stroke([p[:2] for p in points], [p[2] for p in points] if timed else None, learned=learned)
    return found.kind, length


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--by", choices=("pen", "length"), default="pen", help="rows by pen (default) or by line length")
    ap.add_argument("--families", default=",".join(FAMILIES))
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print(f"| seeds | family | {args.by} | read as expected | readings |\n|---|---|---|---:|---|")
    for name, seeds in groups[args.seeds]:
        for family in args.families.split(","):
            rows: dict[str, list[str | None]] = defaultdict(list)
            for pen in PENS:
                for s in seeds:
                    for timed in (True, False):
                        kind, length = read(family, pen, s, timed, not args.rules)
                        key = pen if args.by == "pen" else next(
                            (f"{lo:.0f}-{hi:.0f} px" for lo, hi in LENGTH_BINS if length < hi), "800 px")
                        rows[key].append(kind)
            for key, got in rows.items():
                right = sum(k == EXPECTED[family] for k in got)
                kinds = ", ".join(f"{k} {c}" for k, c in Counter(got).most_common())
                print(f"| {name} | {family} | {key} | {right}/{len(got)} | {kinds} |", flush=True)


if __name__ == "__main__":
    main()
