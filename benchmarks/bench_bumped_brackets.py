"""Benchmark: square brackets whose spine has a bump, a dent or a jog about halfway, the last arm flicked back half the
time, and curly braces wobbled and flicked alike, drawn by the pen models, read as people's labels say (a bracket is a
polyline, a brace a curve).

Usage: .venv/bin/python benchmarks/bench_bumped_brackets.py [--seeds tune|held|all] [--rules] [--family NAME]
       [--symmetry]

Issue 25: hcira pixelfac/user01's left bracket 5 (its spine bulging toward the opening, its top corner rounded over the
whole arm) and jonathanzhang53/s02's left bracket 1 (its spine dented in, its lower arm flicked back) were read as
polylines by the rules and turned into curves by the learned ranker. The marks (`tests/penmodels/bumped_brackets`) are
drawn by the pens of `bench_mouse_habits` (the careful virtual pen; the hurried hand, through a coarse device, a mouse,
a fast device of 8-25 events, a trackpad and a slow mouse), each read with its times and without. Seeds 0-29
(`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_bracket_habits
from bench_mouse_habits import PENS
from penmodels.bumped_brackets import EXPECTED, FAMILIES

if __name__ == "__main__":
    bench_bracket_habits.main(FAMILIES, EXPECTED, __doc__ or "", PENS)
