"""Benchmark: curly braces, question marks, square brackets (sharp and rounded corners) and pigtails drawn by the pen
models, read as the kinds people's labels say (braces, question marks, pigtails curves; brackets polylines).

Usage: .venv/bin/python benchmarks/bench_open_marks.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25 names them on people the project never saw ("square brackets as curves; curly braces and question marks as
polylines"). The marks (`tests/penmodels/open_marks`) are drawn by the careful virtual pen (windows-ink, through the
points), the hurried hand (`tests/penmodels/hurried`: a smooth mark as a smooth path, a sharp bracket's corners
overshot, rounded or turned cleanly, hooks where the pen lands and lifts), the hurried hand through a device sending an
event every 15-30 ms (`bench_device_stress.coarse`) and through a mouse (`bench_device_stress`'s "mouse": whole-pixel
stair steps at 60-200 px, bursts of events, repeated points), each read with its times and without. Seeds 0-29
(`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import argparse
import random
import sys
from collections import Counter
from collections.abc import Callable, Mapping
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import numpy as np
from bench_device_stress import bursts, chain, coarse, duplicates, stairs
from penmodels.hurried import HurriedPen, touching
from penmodels.open_marks import EXPECTED, FAMILIES, Mark
from penmodels.shapes import Curve
from penmodels.shapes import Path as PenPath

from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition.recognize import recognize_stroke

CANVAS = (1600, 1000)
TUNING_SEEDS = range(30)
HELD_SEEDS = range(1000, 1030)
Drawn = list[tuple[float, float, float]]


def careful(mark: Mark, seed: int) -> Drawn:
    """The careful virtual pen through the mark's points."""
    w, h = CANVAS
    samples = VirtualPen(REFERENCE_DEVICES["windows-ink"], seed=seed).samples(
        [Stroke(tuple((x / w, y / h) for x, y in mark.points))])
    return [(p.state.x * w, p.state.y * h, p.t) for p in samples if p.phase == "touch"]


def hurried(mark: Mark, seed: int) -> Drawn:
    """The hurried hand along the mark: a smooth path (`Curve`) or a chain of straight sides (`Path`)."""
    shape = Curve(mark.points) if mark.smooth else PenPath(mark.points)
    return touching(HurriedPen(random.Random(seed)).draw(shape, 0.0)[0])


def _through(device: Callable[[tuple[np.ndarray, np.ndarray | None], np.random.Generator],
                              tuple[np.ndarray, np.ndarray | None]]) -> Callable[[Mark, int], Drawn]:
    def draw(mark: Mark, seed: int) -> Drawn:
        drawn = np.array(hurried(mark, seed))
        pts, when = device((drawn[:, :2], drawn[:, 2]), np.random.default_rng(seed))
        assert when is not None
        return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]
    draw.__doc__ = f"The hurried hand through a device ({device.__name__})."
    return draw


PENS: dict[str, Callable[[Mark, int], Drawn]] = {
    "careful": careful, "hurried": hurried, "hurried-coarse": _through(coarse),
    "hurried-mouse": _through(chain(stairs, bursts, duplicates))}


def drawn(family: str, pen: str, seed: int) -> Drawn:
    """The ``family``'s mark of ``seed`` as ``pen`` draws it: ``(x, y, t)`` canvas pixels, seconds."""
    return PENS[pen](FAMILIES[family](seed), seed)


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True,
         families: Mapping[str, Callable[[int], Mark]] = FAMILIES,
         pens: Mapping[str, Callable[[Mark, int], Drawn]] = PENS) -> str | None:
    """The kind the recogniser reads the ``family``'s mark of ``seed`` (one of ``families``) drawn by ``pen`` (one of
    ``pens``) as."""
    stroke = pens[pen](families[family](seed), seed)
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None, learned=learned).kind


def main(families: Mapping[str, Callable[[int], Mark]] = FAMILIES,
         expected: Mapping[str, str | tuple[str, ...]] = EXPECTED, doc: str = __doc__ or "",
         pens: Mapping[str, Callable[[Mark, int], Drawn]] = PENS) -> None:
    """The table of ``families`` read by every one of ``pens``, against the kind (or kinds) ``expected`` of each
    (`bench_hurried_marks` and `bench_round_habits` read their own families through it)."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    ap.add_argument("--family", choices=tuple(families), action="append", help="only these families")
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print("| seeds | family | pen | read as expected | readings |\n|---|---|---|---:|---|")
    for name, seeds in groups[args.seeds]:
        total = Counter()
        for family in args.family or families:
            want = expected[family]
            accepted = (want,) if isinstance(want, str) else want
            for pen in pens:
                got = [read(family, pen, s, timed, not args.rules, families, pens)
                       for s in seeds for timed in (True, False)]
                right = sum(k in accepted for k in got)
                total["right"] += right
                total["all"] += len(got)
                kinds = ", ".join(f"{k} {c}" for k, c in Counter(got).most_common())
                print(f"| {name} | {family} | {pen} | {right}/{len(got)} | {kinds} |", flush=True)
        print(f"| {name} | all | all | {total['right']}/{total['all']} | |")


if __name__ == "__main__":
    main()
