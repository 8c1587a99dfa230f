"""Benchmark: brackets and rectangles drawn as a hand on a mouse or a trackpad draws them (arms splayed by the wrist,
corners swung round, a spine on the wrist's arc, a corner overshot where the mouse stops, a box begun and closed past
its first corner, a box swung round at every corner), drawn by the pen models, read as people's labels say (a bracket
is a polyline, a rectangle a box).

Usage: .venv/bin/python benchmarks/bench_mouse_habits.py [--seeds tune|held|all] [--rules] [--family NAME]
       [--symmetry]

Issue 25: the held-back people who drew with a mouse and a trackpad read rectangles 85.7 % and square brackets
89-90 %. The marks (`tests/penmodels/mouse_habits`) are drawn by the pens of `bench_bracket_habits` (the careful
virtual pen, the hurried hand, the hurried hand through a coarse device, a mouse and a fast device) and by two more
(`PENS`): the hurried hand through a trackpad (`device_habits.acceleration`, then `device_habits.lift_hook`) and
through a slow mouse that dwells at each corner (`device_habits.slow_corners`, then `bench_device_stress.stairs`),
each read with its times and without. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029
(`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_bracket_habits
import device_habits
from bench_device_stress import chain, stairs
from bench_open_marks import Drawn, _through
from penmodels.mouse_habits import EXPECTED, FAMILIES
from penmodels.open_marks import Mark

PENS: dict[str, Callable[[Mark, int], Drawn]] = {
    **bench_bracket_habits.PENS,
    "hurried-trackpad": _through(chain(device_habits.acceleration, device_habits.lift_hook)),
    "hurried-slow-mouse": _through(chain(device_habits.slow_corners, stairs))}
"""The pens of `bench_bracket_habits` and a trackpad's and a slow mouse's."""

if __name__ == "__main__":
    bench_bracket_habits.main(FAMILIES, EXPECTED, __doc__ or "", PENS)
