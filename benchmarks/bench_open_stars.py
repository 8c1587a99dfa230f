"""Benchmark: stars' outlines left open by a side (`tests/penmodels/open_stars`) read by the pen models as polygons,
and the zig-zags and open crowns they must not be taken for read as polylines.

Usage: .venv/bin/python benchmarks/bench_open_stars.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25, session 33: tutorboard seed260730's star #102, an outline of five points drawn round and left open by a side,
was read as a curve (`open_stars.star_left_open` now closes it). The marks are drawn by the pens of `bench_open_marks`
(the careful virtual pen, the hurried hand, the hurried hand through a coarse device and through a mouse), each read
with its times and without. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were
read once, at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
from penmodels.open_stars import EXPECTED, FAMILIES


def main() -> None:
    """The table of every family read by every pen (`bench_open_marks.main`)."""
    bench_open_marks.main(FAMILIES, EXPECTED, __doc__ or "", bench_open_marks.PENS)


if __name__ == "__main__":
    main()
