"""Benchmark: squiggles drawn smoothly (an S of two round bends, round humps) read as curves, and zig-zags whose
points are rounded read as polylines (`tests/penmodels/squiggles`), drawn by the pen models of `bench_open_marks`; a
line with curls in it read as a curve and a spring drawn as a coil as a helix (session 33), and a line with two curls
in it as a curve (session 34).

Usage: .venv/bin/python benchmarks/bench_squiggles.py [--seeds tune|held|all] [--rules] [--family NAME]

Seeds 0-29 (`bench_open_marks.TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once,
at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_open_marks import main
from penmodels.squiggles import EXPECTED, FAMILIES

if __name__ == "__main__":
    main(FAMILIES, EXPECTED, __doc__ or "")
