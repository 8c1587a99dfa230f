"""Benchmark: circles whose ends do not meet as an outline's do (a lead in from inside, an end curling in past the
start: `tests/penmodels/round_habits`), drawn by the pen models, read as circles or ellipses.

Usage: .venv/bin/python benchmarks/bench_round_habits.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25, session 22: the design sources' circles read as curves were drawn so (dollar1 s02, itt lvht1203, hcira
jonathanzhang53/s04, klarubbio/s06), and the held-back people read circles 93 %. The marks are drawn by the pens of
`bench_open_marks` (the careful virtual pen, the hurried hand, the hurried hand through a coarse device and through a
mouse) and by the hurried hand through a fast device (`bench_device_stress.fast`: 8-25 events over the stroke), each
read with its times and without. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029
(`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
from bench_device_stress import fast
from bench_open_marks import Drawn
from penmodels.open_marks import Mark
from penmodels.round_habits import EXPECTED, FAMILIES

from physink_tui.scene.recognition.recognize import recognize_stroke

PENS: dict[str, Callable[[Mark, int], Drawn]] = {
    **bench_open_marks.PENS, "hurried-fast": bench_open_marks._through(fast)}


def drawn(family: str, pen: str, seed: int) -> Drawn:
    """The ``family``'s circle of ``seed`` as ``pen`` draws it: ``(x, y, t)`` canvas pixels, seconds."""
    return PENS[pen](FAMILIES[family](seed), seed)


def reading(stroke: Drawn, timed: bool, learned: bool = True) -> str | None:
    """The kind the recogniser reads ``stroke`` as, given its times (``timed``) or not."""
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None, learned=learned).kind


def main() -> None:
    """The table of every family read by every pen (`bench_open_marks.main`), as a circle or an ellipse."""
    bench_open_marks.main(FAMILIES, dict.fromkeys(FAMILIES, EXPECTED), __doc__ or "", PENS)


if __name__ == "__main__":
    main()
