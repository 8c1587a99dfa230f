"""A trackpad's few events with a fingertip's landing and lift: the events' step judged along the stroke's body
(`pen_noise.path_step`), so a box's corners are not taken for a shaky hand's jitter, and a brace whose point a few
events sample still turns both ways (`angular_braces.POINT_LOBE_DEG`).

The pen models' marks and shapes (`tests/penmodels`: the hurried hand) go through the benchmark's own trackpad
(`bench_device_stress.MORE`: pointer acceleration, 8-25 events evenly in time, a finger settling where it lands and
rolling off as it lifts). Floors are the held seeds' (1000-1029) counts on this branch, read once after the change was
made on transformed design strokes (`docs/BENCHMARKS.md`, "Trackpad landings and braces by few events"); figures on
transformed strokes, not on people using trackpads.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import bench_closed_shapes as closed  # the benchmarks' own shapes and pens, not copies
import bench_open_marks as marks
from bench_device_stress import MORE
from penmodels.open_marks import EXPECTED, FAMILIES

TRACKPAD = MORE["trackpad 2: acceleration, 8-25 events, start blob, lift hook"]
HELD_SEEDS = range(1000, 1030)

SHAPE_FLOORS = {"box-corners-rounded": 27, "box-corner-cut": 25, "rounded-rectangle": 30, "star-5": 27,
                "triangle-crossed": 29, "rhombus": 30}
"""Of 30 held seeds, how many of each closed family the hurried hand draws through the trackpad are read as meant
(`bench_closed_shapes.EXPECTED`). On main 2996772: 26, 24, 28, 22, 28, 29."""
MARK_FLOORS = {"brace": 30, "angular-brace": 29, "bracket": 30}
"""The same for open marks (`penmodels.open_marks.EXPECTED`). On main 2996772: 29, 29, 30."""


def _through_trackpad(drawn: list[tuple[float, float, float]], seed: int) -> tuple[np.ndarray, np.ndarray]:
    d = np.array(drawn)
    pts, times = TRACKPAD((d[:, :2], d[:, 2]), np.random.default_rng(seed))
    assert times is not None
    return pts, times


@pytest.mark.parametrize("family", sorted(SHAPE_FLOORS))
def test_closed_shapes_through_a_trackpad(family: str) -> None:
    right = 0
    for seed in HELD_SEEDS:
        pts, times = _through_trackpad(closed.hurried(closed.shape(family, seed), seed), seed)
        right += recognize_stroke(pts.tolist(), times.tolist()).kind in closed.EXPECTED[family]
    assert right >= SHAPE_FLOORS[family], f"{family}: {right}/30"


@pytest.mark.parametrize("family", sorted(MARK_FLOORS))
def test_open_marks_through_a_trackpad(family: str) -> None:
    right = 0
    for seed in HELD_SEEDS:
        pts, times = _through_trackpad(marks.hurried(FAMILIES[family](seed), seed), seed)
        right += recognize_stroke(pts.tolist(), times.tolist()).kind == EXPECTED[family]
    assert right >= MARK_FLOORS[family], f"{family}: {right}/30"
