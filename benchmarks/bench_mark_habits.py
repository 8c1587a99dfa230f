"""Benchmark: open marks as people of the design sets drew them (`tests/penmodels/mark_habits`: a tick swung round its
point with a landing hook, a question mark whose hook meets its stem at a corner), drawn by the pen models of
`bench_open_marks` and read as the kinds people's labels say (ticks polylines, question marks curves).

Usage: .venv/bin/python benchmarks/bench_mark_habits.py [--seeds tune|held|all] [--rules] [--family NAME]

Seeds 0-29 (`bench_open_marks.TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once,
at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_open_marks import main
from penmodels.mark_habits import EXPECTED, FAMILIES

if __name__ == "__main__":
    main(FAMILIES, EXPECTED, __doc__ or "")
