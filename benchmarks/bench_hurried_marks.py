"""Benchmark: an x swung round at its far side, a plain one-stroke x, a tick whose short arm is a few percent of the
stroke, a pigtail whose arms cross as an x's do, and a zig-zag whose sides the hand bowed (session 20), drawn by the pen
models, read as the kinds people's labels say (x's, ticks and zig-zags polylines, pigtails curves).

Usage: .venv/bin/python benchmarks/bench_hurried_marks.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25 (session 19): one-stroke x's read as curves and ticks with short first arms read as curves on people's strokes
(`recognition.hooked_ticks`; the x's are read as before: a rule for them was tried and not kept). The marks
(`tests/penmodels/hurried_marks`) are drawn by the pens of `bench_open_marks` (the careful virtual pen, the hurried
hand, the hurried hand through a coarse device and through a mouse), each read with its times and without. Seeds 0-29
(`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
from penmodels.hurried_marks import EXPECTED, FAMILIES


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> str | None:
    """The kind the recogniser reads the ``family``'s mark of ``seed`` drawn by ``pen`` (`bench_open_marks.PENS`) as."""
    return bench_open_marks.read(family, pen, seed, timed, learned, FAMILIES)


if __name__ == "__main__":
    bench_open_marks.main(FAMILIES, EXPECTED, __doc__ or "")
