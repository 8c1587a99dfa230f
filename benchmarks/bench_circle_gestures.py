"""Benchmark: circles, ovals and whole notes drawn as gestures (`tests/penmodels/circle_gestures`), either way round, by
the pen models through a tablet and through a device sending few events, read as circles or ellipses; each stroke is
read as drawn and mirrored top to bottom (the same stroke the other way round), and the two ways are counted apart.

Usage: .venv/bin/python benchmarks/bench_circle_gestures.py [--seeds tune|held|all] [--family NAME] [--pen NAME] [--why]

Issue 25, session 27: after session 26 the lead's held scoring lost 9 counter-clockwise circles of one held set (its
clockwise ones none) and 8 whole notes (small ovals) of a music set. The pens: the careful virtual pen, the hurried
hand, the hurried hand through a tablet sending an event every 15-30 ms (`bench_device_stress.coarse`), and both pens
through a device sending 8-40 events evenly in time over the whole stroke (a mouse or a touch screen drawn fast: a
round stroke of chords) and through whole pixels at the drawing's own size (`bench_circle_habits.whole_pixels`), and
the hurried hand through `bench_open_marks`' mouse (stair steps, bursts of events, repeated points); each read with
its times and without. ``--why`` names, for every stroke not read round, the
test of `closed_loops.polygon_left_open` that closed it as a polygon left open (if one did). Seeds 0-29
(`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
from bench_circle_habits import whole_pixels
from bench_device_stress import Stroke, events
from bench_open_marks import HELD_SEEDS, TUNING_SEEDS, Drawn
from penmodels.circle_gestures import EXPECTED, FAMILIES, mirrored
from penmodels.open_marks import Mark

from physink_tui.scene.recognition import closed_loops
from physink_tui.scene.recognition.recognize import recognize_stroke


def sparse(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """8-40 events evenly in time over the whole stroke, the first at pen-down and the last at pen-up (a mouse or a
    touch screen reporting every 15-30 ms under a stroke drawn in 0.15-1 s)."""
    return events(int(rng.integers(8, 41)))(stroke, rng)


def _careful_through(device: Callable[[Stroke, np.random.Generator], Stroke]) -> Callable[[Mark, int], Drawn]:
    def draw(mark: Mark, seed: int) -> Drawn:
        pts = np.array(bench_open_marks.careful(mark, seed))
        got, when = device((pts[:, :2], pts[:, 2]), np.random.default_rng(seed))
        assert when is not None
        return [(float(x), float(y), float(t)) for (x, y), t in zip(got, when, strict=True)]
    draw.__doc__ = f"The careful virtual pen through a device ({device.__name__})."
    return draw


PENS: dict[str, Callable[[Mark, int], Drawn]] = {
    "careful": bench_open_marks.careful, "hurried": bench_open_marks.hurried,
    "hurried-coarse": bench_open_marks.PENS["hurried-coarse"], "careful-sparse": _careful_through(sparse),
    "hurried-sparse": bench_open_marks._through(sparse), "careful-pixels": _careful_through(whole_pixels),
    "hurried-pixels": bench_open_marks._through(whole_pixels), "hurried-mouse": bench_open_marks.PENS["hurried-mouse"]}


def drawn(family: str, pen: str, seed: int, mirror: bool = False) -> Drawn:
    """The ``family``'s gesture of ``seed`` as ``pen`` draws it (mirrored top to bottom where ``mirror``)."""
    stroke = PENS[pen](FAMILIES[family](seed), seed)
    return mirrored(stroke) if mirror else stroke


def clockwise(stroke: Drawn) -> bool:
    """Whether ``stroke`` turns clockwise on the screen (y down): its signed area, shoelace over its points, is
    positive."""
    x, y = np.array([p[0] for p in stroke]), np.array([p[1] for p in stroke])
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)) > 0


def reading(stroke: Drawn, timed: bool) -> str | None:
    """The kind the recogniser reads ``stroke`` as, given its times (``timed``) or not."""
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None).kind


def why(stroke: Drawn, timed: bool) -> tuple[str | None, str]:
    """The kind ``stroke`` is read as, and which test of `closed_loops.polygon_left_open` closed it ("" for none)."""
    told: list[str] = []
    asked = closed_loops.polygon_left_open

    def spy(*args: object, **kwargs: object) -> closed_loops.LeftOpen | None:
        found = asked(*args, **kwargs)  # type: ignore[arg-type]
        if found:
            told.append(getattr(found, "name", "LEFT_OPEN"))  # a bool before session 27: "LEFT_OPEN"
        return found
    closed_loops.polygon_left_open = spy
    try:
        kind = reading(stroke, timed)
    finally:
        closed_loops.polygon_left_open = asked
    return kind, ",".join(told)


def main() -> None:
    """The table: for every family and pen, the readings round of each way round, the stroke and its mirror disagreeing,
    and (``--why``) the tests that closed the strokes not read round."""
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--seeds", choices=("tune", "held", "all"), default="tune")
    ap.add_argument("--family", choices=tuple(FAMILIES), action="append", help="only these families")
    ap.add_argument("--pen", choices=tuple(PENS), action="append", help="only these pens")
    ap.add_argument("--why", action="store_true", help="which left-open test closed the strokes not read round")
    args = ap.parse_args()
    groups = {"tune": [("tune 0-29", TUNING_SEEDS)], "held": [("held 1000-1029", HELD_SEEDS)]}
    groups["all"] = groups["tune"] + groups["held"]
    print("| seeds | family | pen | clockwise round | counter-clockwise round | mirror disagrees | not round |")
    print("|---|---|---|---:|---:|---:|---|")
    for name, seeds in groups[args.seeds]:
        total: Counter[str] = Counter()
        for family in args.family or FAMILIES:
            for pen in args.pen or PENS:
                ways: Counter[str] = Counter()
                misses: Counter[str] = Counter()
                split = 0
                for seed in seeds:
                    for timed in (True, False):
                        got = []
                        for mirror in (False, True):
                            stroke = drawn(family, pen, seed, mirror)
                            kind, told = why(stroke, timed) if args.why else (reading(stroke, timed), "")
                            way = "cw" if clockwise(stroke) else "ccw"
                            ways[way] += 1
                            ways[way + " round"] += kind in EXPECTED
                            if kind not in EXPECTED:
                                misses[f"{kind}{' <' + told + '>' if told else ''}"] += 1
                            got.append(kind in EXPECTED)
                        split += got[0] != got[1]
                for key in ("cw", "ccw", "cw round", "ccw round"):
                    total[key] += ways[key]
                total["split"] += split
                shown = ", ".join(f"{k} {c}" for k, c in misses.most_common())
                print(f"| {name} | {family} | {pen} | {ways['cw round']}/{ways['cw']} | {ways['ccw round']}/"
                      f"{ways['ccw']} | {split} | {shown} |", flush=True)
        print(f"| {name} | all | all | {total['cw round']}/{total['cw']} | {total['ccw round']}/{total['ccw']} | "
              f"{total['split']} | |")


if __name__ == "__main__":
    main()
