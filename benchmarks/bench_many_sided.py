"""Benchmark: many-sided outlines and squiggles drawn in a hurry (`tests/penmodels/many_sided`) read by the pen models
as polygons and curves.

Usage: .venv/bin/python benchmarks/bench_many_sided.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25, session 23: the fourth group's hexagons (10/24) and octagons (19/31) were read as curves, circles and
ellipses, its squiggles (87/110) as polylines and helices. The marks are drawn by the pens of `bench_open_marks` (the
careful virtual pen, the hurried hand, the hurried hand through a coarse device and through a mouse), each read with
its times and without. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read
once, at the end. Session 26 added hexagons to octagons left open with every corner rounded (`shape_corners`) and
lumpy circles left open, which must stay round.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
from penmodels.many_sided import EXPECTED, FAMILIES


def main() -> None:
    """The table of every family read by every pen (`bench_open_marks.main`)."""
    bench_open_marks.main(FAMILIES, EXPECTED, __doc__ or "", bench_open_marks.PENS)


if __name__ == "__main__":
    main()
