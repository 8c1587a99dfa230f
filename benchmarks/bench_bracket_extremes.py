"""Benchmark: square brackets at the edges of how people draw them (arms swept in past square, arms splayed out as a
trapezoid's, corners rounded over the whole arm, tiny brackets, a kinked spine, arms of very unequal length), drawn by
the pen models, read as people's labels say (a bracket is a polyline).

Usage: .venv/bin/python benchmarks/bench_bracket_extremes.py [--seeds tune|held|all] [--rules] [--family NAME]
       [--symmetry]

Issue 25: the held-back HCIRA people read square brackets 89-90 %. The marks (`tests/penmodels/bracket_extremes`)
are drawn by the pens of `bench_mouse_habits` (the careful virtual pen; the hurried hand, through a coarse device, a
mouse, a fast device of 8-25 events, a trackpad and a slow mouse), each read with its times and without. Seeds 0-29
(`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_bracket_habits
from bench_mouse_habits import PENS
from penmodels.bracket_extremes import EXPECTED, FAMILIES

if __name__ == "__main__":
    bench_bracket_habits.main(FAMILIES, EXPECTED, __doc__ or "", PENS)
