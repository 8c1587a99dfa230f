"""Benchmark: rectangles one side of which a hurried hand bowed out or in, or swung round with its corners
(`tests/penmodels/box_bows.py`), each read as a box, and the low pentagons, swallowtails and deeply cut boxes beside
them, each read as a polygon, by the pens of `bench_box_slips`.

Usage: .venv/bin/python benchmarks/bench_box_bows.py [--seeds A:B] [--held-back] [--rules] [--families A,B]
       [--misread]

Each family draws its shape from its own seeded generator (`box_bows.drawn`) and each pen draws it with the same seed:
the careful virtual pen (windows-ink), the hurried hand, the hurried hand through a device sending an event every
15-30 ms, through a mouse and through a trackpad (`bench_box_slips.PENS`). Every stroke is read with its times. A box
family is right when it reads as a box; a polygon family when it reads as a polygon (the table counts the right
readings; "other readings" lists the others for both). Seeds 0-29 are the tuning range; seeds 1000-1029
(``--held-back``) are never looked at while tuning and reported apart. Deterministic.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import bench_boxes
from bench_box_slips import PENS
from penmodels.box_bows import BOXES, FAMILIES, drawn


def read(family: str, pen: str, seed: int, learned: bool = True) -> str | None:
    """The kind read from ``family``'s shape for ``seed`` drawn by ``pen``, with its times."""
    return bench_boxes.read_drawn(PENS[pen], drawn(family, seed), seed, learned)


def meant(family: str) -> str:
    """The kind a person means by ``family``'s shape."""
    return "box" if family in BOXES else "polygon"


def main() -> None:
    bench_boxes.family_main(__doc__ or "", list(FAMILIES), PENS, read, meant)


if __name__ == "__main__":
    main()
