"""Benchmark: curly braces drawn with different hands' habits (`tests/penmodels/brace_habits`), each a left and a
right brace drawn from its top and from its bottom, by the pen models, read as curves.

Usage: .venv/bin/python benchmarks/bench_brace_habits.py [--seeds tune|held|all] [--family NAME] [--pen NAME] [--by way]

Issue 25, session 21: held-back people read right braces worse than left ones (aggregate figures only). The families
(flattened point, lopsided, askew, hooked ends, two arcs at a cusp, tall and thin, a wide chevron with rounded ends,
straight runs) are drawn by the careful virtual pen, the hurried hand (`tests/penmodels/hurried`), the hurried hand
through a device sending 8-25 events in all (`bench_device_stress.fast`), through a mouse at 60-200 px
(`bench_device_stress`'s stairs, bursts, repeated points), in whole pixels at 20-40 px (a tiny mouse brace) and
through a trackpad's pointer acceleration (`device_habits.acceleration`: slow parts shrink, fast parts stretch; session
23). Every mark is read four ways (`brace_habits.WAYS`): a reading that depends on the way is an asymmetry of the
recogniser.
Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import numpy as np
from bench_device_stress import bursts, chain, duplicates, fast, pixels, stairs
from bench_open_marks import careful, hurried
from device_habits import acceleration
from penmodels.brace_habits import FAMILIES, WAYS
from penmodels.open_marks import Mark

from physink_tui.scene.recognition.recognize import recognize_stroke

TUNING_SEEDS = range(30)
HELD_SEEDS = range(1000, 1030)
Drawn = list[tuple[float, float, float]]


def _through(*steps: Callable[..., tuple[np.ndarray, np.ndarray | None]]) -> Callable[[Mark, int], Drawn]:
    device = chain(*steps)

    def draw(mark: Mark, seed: int) -> Drawn:
        drawn = np.array(hurried(mark, seed))
        pts, when = device((drawn[:, :2], drawn[:, 2]), np.random.default_rng(seed))
        assert when is not None
        return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]
    return draw


PENS: dict[str, Callable[[Mark, int], Drawn]] = {
    "careful": careful, "hurried": hurried, "hurried-fast": _through(fast),
    "hurried-mouse": _through(stairs, bursts, duplicates), "hurried-tiny": _through(pixels(20, 40), duplicates),
    "hurried-accel": _through(acceleration)}


def drawn(family: str, way: str, pen: str, seed: int) -> Drawn:
    """The ``family``'s brace of ``seed`` drawn ``way`` by ``pen``: ``(x, y, t)`` canvas pixels, seconds."""
    return PENS[pen](FAMILIES[family](seed, way), seed)


def read(family: str, way: str, pen: str, seed: int, timed: bool) -> str:
    """The kind the recogniser reads that brace as (with its times or without)."""
    stroke = drawn(family, way, pen, seed)
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None).kind


def main() -> None:
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--family", choices=tuple(FAMILIES), action="append", help="only these families")
    ap.add_argument("--pen", choices=tuple(PENS), action="append", help="only these pens")
    ap.add_argument("--by", choices=("pen", "way"), default="pen", help="rows by family and pen, or family and way")
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print(f"| seeds | family | {args.by} | read as curves | " + " | ".join(WAYS) + " | readings |")
    print("|---|---|---|---:|" + "---:|" * len(WAYS) + "---|")
    for name, seeds in groups[args.seeds]:
        total, by_way = Counter(), Counter()
        for family in args.family or FAMILIES:
            rows: dict[str, Counter] = {}
            for pen in args.pen or PENS:
                for way in WAYS:
                    for seed in seeds:
                        for timed in (True, False):
                            kind = read(family, way, pen, seed, timed)
                            row = rows.setdefault(pen if args.by == "pen" else way, Counter())
                            row[kind] += 1
                            row[("way", way, kind == "curve")] += 1
                            by_way[(way, kind == "curve")] += 1
                            total[kind == "curve"] += 1
            for key, row in rows.items():
                kinds = {k: v for k, v in row.items() if isinstance(k, str)}
                right, count = kinds.get("curve", 0), sum(kinds.values())
                ways = " | ".join(f"{row[('way', w, True)]}/{row[('way', w, True)] + row[('way', w, False)]}"
                                  for w in WAYS)
                readings = ", ".join(f"{k} {c}" for k, c in Counter(kinds).most_common())
                print(f"| {name} | {family} | {key} | {right}/{count} | {ways} | {readings} |", flush=True)
        ways = " | ".join(f"{by_way[(w, True)]}/{by_way[(w, True)] + by_way[(w, False)]}" for w in WAYS)
        print(f"| {name} | all | all | {total[True]}/{total[True] + total[False]} | {ways} | |")


if __name__ == "__main__":
    main()
