"""Benchmark: rectangles drawn with the slips of `tests/penmodels/box_slips.py` (a wide gap at the close, begun
mid-wall and left open, corners rounded and left open, a spur at a corner, a lead-in, two laps apart, a deep bow, a cut
corner) by the pens of `bench_boxes` and the hurried hand through a trackpad, each read as a box.

Usage: .venv/bin/python benchmarks/bench_box_slips.py [--seeds A:B] [--held-back] [--rules] [--families A,B]
       [--misread]

Each family draws its box from its own seeded generator (`box_slips.drawn`) and each pen draws it with the same seed:
the careful virtual pen (windows-ink), the hurried hand, the hurried hand through a device sending an event every
15-30 ms and through a mouse (`bench_boxes.PENS`), and through a trackpad (`device_habits.acceleration`, then
`device_habits.lift_hook`, as `bench_mouse_habits`). Every stroke is read with its times. Seeds 0-29 are the tuning
range; seeds 1000-1029 (``--held-back``) are never looked at while tuning and reported apart. Deterministic.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import bench_boxes
import device_habits
import numpy as np
from bench_closed_shapes import hurried
from bench_device_stress import chain
from penmodels.box_slips import FAMILIES, drawn
from penmodels.shapes import Shape

_TRACKPAD = chain(device_habits.acceleration, device_habits.lift_hook)


def hurried_trackpad(s: Shape, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand through a trackpad: pointer acceleration, then the finger's lift (`device_habits`)."""
    drawn_ = np.array(hurried(s, seed))
    pts, when = _TRACKPAD((drawn_[:, :2], drawn_[:, 2]), np.random.default_rng(seed))
    assert when is not None
    return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]


PENS = {**bench_boxes.PENS, "hurried-trackpad": hurried_trackpad}


def read(family: str, pen: str, seed: int, learned: bool = True) -> str | None:
    """The kind read from ``family``'s box for ``seed`` drawn by ``pen``, with its times."""
    return bench_boxes.read_drawn(PENS[pen], drawn(family, seed), seed, learned)


def main() -> None:
    bench_boxes.family_main(__doc__ or "", list(FAMILIES), PENS, read)


if __name__ == "__main__":
    main()
