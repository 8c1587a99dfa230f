"""Benchmark: parentheses as people and devices not seen draw them, read as an arc or a curve (laviola's label).

Usage: .venv/bin/python benchmarks/bench_paren_habits.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25, session 24: small parentheses (15-60 px) with a landing hook were read as lines or polylines by the hurried
pens a quarter to a half of the time (session 23's lead). The marks (`tests/penmodels/paren_habits`: shallow bows of
60-120 degrees and deep ones of 120-220, 60-320 px tall, small ones 15-60 px, round or flat in the middle, each size
with a hook where the pen landed, and lifted a third of the time) are drawn by the pens of `bench_open_marks` (the
careful virtual pen, the hurried hand, the hurried hand through a device sending an event every 15-30 ms and through a
mouse), each read with its times and without. Seeds 0-29 (`bench_open_marks.TUNING_SEEDS`) were looked at while
designing; 1000-1029 (`HELD_SEEDS`) only measured.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_open_marks import main
from penmodels.paren_habits import EXPECTED, FAMILIES

if __name__ == "__main__":
    main(FAMILIES, dict.fromkeys(FAMILIES, EXPECTED), __doc__ or "")
