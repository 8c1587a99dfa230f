"""Benchmark: circles and ovals drawn small, flat, lumpy, gone round again, with a tail, left open as a spiral's turn,
pointed where the ends meet, flat on one side or closed with a flick off the loop (`tests/penmodels/circle_habits`),
drawn by the pen models through poor devices, read as circles or ellipses.

Usage: .venv/bin/python benchmarks/bench_circle_habits.py [--seeds tune|held|all] [--rules] [--family NAME]

Issue 25, session 24: the held-back people read circles 93.3 %. The marks are drawn by the pens of `bench_round_habits`
(the careful virtual pen, the hurried hand, the hurried hand through a coarse device, through a mouse and through a
device sending 8-25 events over the whole stroke, `bench_device_stress.fast`: a circle of chords) and by the hurried
hand through a trackpad's pointer acceleration sampled every 15-30 ms (`device_habits.acceleration`, then
`bench_device_stress.coarse`) or over 10-25 events in all (`chords`), through a mouse at the drawing's own size
(`whole_pixels`), through a finger (`bench_device_stress.finger`, `device_habits.start_blob`, `device_habits.lift_hook`)
and through a trackpad (pointer acceleration, 10-25 events, the finger's landing and lift), each read with its times
and without. Seeds 0-29 (`TUNING_SEEDS`) were looked at while designing; 1000-1029 (`HELD_SEEDS`) were read once, at
the end.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import bench_open_marks
import bench_round_habits
from bench_device_stress import Stroke, chain, coarse, events, finger
from bench_open_marks import Drawn
from device_habits import acceleration, lift_hook, start_blob
from penmodels.circle_habits import EXPECTED, FAMILIES
from penmodels.open_marks import Mark


def chords(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """10-25 events evenly in time over the whole stroke: a circle drawn in 0.15-0.4 s on a device reporting every
    15-30 ms, the stroke itself a polygon of chords (`bench_device_stress.fast` is 8-25)."""
    return events(int(rng.integers(10, 26)))(stroke, rng)


def whole_pixels(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A mouse at the drawing's own size: an event every 8 ms (125 Hz), each at a whole pixel, an event that did not
    move left out (`bench_device_stress.stairs` scales the drawing to 60-200 px first, so a small circle is no longer
    small)."""
    pts, t = stroke
    clock = np.arange(len(pts)) * 0.01 if t is None else np.maximum.accumulate(t)
    when = np.arange(clock[0], clock[-1], 0.008)
    when = np.append(when, clock[-1]) if clock[-1] - when[-1] > 1e-9 else when
    at = np.column_stack([np.interp(when, clock, pts[:, k]) for k in range(2)])
    grid = np.round(at + rng.uniform(-0.5, 0.5, 2))
    moved = np.concatenate([[True], np.any(np.diff(grid, axis=0) != 0, axis=1)])
    return grid[moved], when[moved] if t is not None else None


PENS: dict[str, Callable[[Mark, int], Drawn]] = {
    **bench_round_habits.PENS, "hurried-accel": bench_open_marks._through(chain(acceleration, coarse)),
    "hurried-chords-accel": bench_open_marks._through(chain(acceleration, chords)),
    "hurried-pixels": bench_open_marks._through(whole_pixels),
    "hurried-finger": bench_open_marks._through(chain(finger, start_blob, lift_hook)),
    "hurried-trackpad": bench_open_marks._through(chain(acceleration, chords, start_blob, lift_hook))}


def drawn(family: str, pen: str, seed: int) -> Drawn:
    """The ``family``'s circle of ``seed`` as ``pen`` draws it: ``(x, y, t)`` canvas pixels, seconds."""
    return PENS[pen](FAMILIES[family](seed), seed)


def main() -> None:
    """The table of every family read by every pen (`bench_open_marks.main`), as a circle or an ellipse."""
    bench_open_marks.main(FAMILIES, dict.fromkeys(FAMILIES, EXPECTED), __doc__ or "", PENS)


if __name__ == "__main__":
    main()
