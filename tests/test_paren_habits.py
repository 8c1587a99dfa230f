"""Issue 25, session 24: parentheses as people and devices not seen draw them read as arcs or curves (laviola's label,
benchmarks/label_kinds.tsv). The pen-model families (`tests/penmodels/paren_habits`, `benchmarks/bench_paren_habits.py`:
shallow and deep bows, small ones, ones with a landing hook, lopsided ones curling tightly near one end) are read by the
four pens of `bench_open_marks`, with and without times, on the held seeds (1000-1029, not looked at while designing);
each floor is the figure measured on this branch.

Two readings were wrong for a reason of the recogniser's, and are pinned here:
- a small parenthesis (15-60 px) bows a few pixels, and the circle misses the hurried hand's bow by about a pixel: that
  was taken for a line the hand's swing bowed (`open_marks.swung_line`); now a circle missing a bow by no more than the
  pen's own wobble explains it (`open_marks.SWUNG_WOBBLE`), unless a line explains it as closely and an end curls as a
  pen's hook does (`open_marks.hooked_straight`, session 25: a short line hooked at both ends), which no small
  parenthesis does;
- a lopsided parenthesis passes `bracket_marks.rounded_point` (a tick swung round its point) and since session 23 was
  kept from the learned ranker as such a tick (`bracket_marks.swung_tick`, `unhooked_point`), where before the ranker
  read it as the curve it is; its long side curls on round the bend all along it, a tick's arm does not
  (`bracket_marks.curling_arm`).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.mark_habits import hooked_swung_tick
from penmodels.paren_habits import EXPECTED, FAMILIES, lopsided_paren

from physink_tui.scene.recognition import bracket_marks, lines, open_marks, ranker, shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import bench_lines
from bench_open_marks import HELD_SEEDS, PENS, read

HELD_FLOORS = {
    "shallow-paren": {"careful": 60, "hurried": 54, "hurried-coarse": 56, "hurried-mouse": 58},
    "deep-paren": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60},
    "small-paren": {"careful": 56, "hurried": 50, "hurried-coarse": 48, "hurried-mouse": 30},
    "hooked-paren": {"careful": 58, "hurried": 58, "hurried-coarse": 56, "hurried-mouse": 54},
    "small-hooked-paren": {"careful": 46, "hurried": 48, "hurried-coarse": 46, "hurried-mouse": 20},
    "lopsided-paren": {"careful": 54, "hurried": 34, "hurried-coarse": 44, "hurried-mouse": 28},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are arcs or
curves, as measured on this branch; main 40b8114 read the same but small-paren hurried 48, hooked-paren hurried 56 and
hurried-mouse 52, shallow-paren hurried-mouse 56 (lines: swung), lopsided-paren 44, 30, 40, 22 (polylines: ticks)."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_a_parenthesis_is_a_bow(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed, families=FAMILIES) for seed in HELD_SEEDS for timed in (True, False)]
    assert sum(k in EXPECTED for k in got) >= HELD_FLOORS[family][pen], got


TAKEN = {"careful": 2, "hurried": 4, "hurried-coarse": 4, "hurried-mouse": 2}
"""pen -> how many of the lopsided parentheses it draws (tuning seeds 0-29) `rounded_point` takes for a tick on the
ranker's points, as measured."""


def _work(points: np.ndarray) -> tuple[np.ndarray, float]:
    """A mark's points as the learned ranker judges them (`ranker._unit_work`: at unit diagonal, 64 along the path,
    smoothed) and a pixel's noise in those units."""
    diag = sg.bbox_diagonal(points)
    return sg.smooth(sg.resample((points - points.mean(axis=0)) / diag, ranker.WORK_POINTS)), 1.0 / diag


@pytest.mark.parametrize("pen", list(PENS))
def test_a_lopsided_parenthesis_taken_for_a_tick_curls_on_round_its_bend(pen: str) -> None:
    """Of the lopsided parentheses drawn by ``pen`` (tuning seeds 0-29) that `rounded_point` takes for a tick swung
    round its point on the ranker's points, every one's long side curls on the bend's way (`curling_arm`), so none is
    kept from the ranker as a tick (`swung_tick`); there are such parentheses for every pen (`TAKEN`)."""
    taken = 0
    for seed in range(30):
        stroke = PENS[pen](lopsided_paren(seed), seed)
        work, noise = _work(np.asarray([p[:2] for p in stroke]))
        th = sg.turning(work)
        lobes = sf.turn_lobes(shape_turning.coarse_turning(work, noise))
        point = bracket_marks.rounded_point(work, th, lobes)
        if point is None:
            continue
        taken += 1
        assert bracket_marks.curling_arm(work, point), seed
        assert not bracket_marks.swung_tick(work, th, lobes, noise), seed
    assert taken >= TAKEN[pen]


def test_a_swung_ticks_long_arm_does_not_curl() -> None:
    """The ticks `swung_tick` was made for (`mark_habits.hooked_swung_tick`, as meant, their landing hook cut; tuning
    seeds 0-29) are ticks to `rounded_point` (29 of 30 measured), their long arms straight: not one curls on
    (`curling_arm`)."""
    ticks = 0
    for seed in range(30):
        work, noise = _work(np.asarray(hooked_swung_tick(seed).points))
        work = sg.resample(sg.remove_hooks(work), len(work))
        lobes = sf.turn_lobes(shape_turning.coarse_turning(work, noise))
        point = bracket_marks.rounded_point(work, sg.turning(work), lobes)
        if point is None:
            continue
        ticks += 1
        assert not bracket_marks.curling_arm(work, point), seed
    assert ticks >= 20


SWUNG = ("line", (("curve", 0.4),))
"""How the rules answer a swung line (`open_marks.swung_line`): a line whose alternative is the curve it was not read
as."""


@pytest.mark.parametrize("family", ["small-paren", "small-hooked-paren"])
def test_a_small_parenthesis_by_the_hurried_hand_is_no_swung_line(family: str) -> None:
    """Small parentheses (15-60 px) drawn by the hurried hand on a tablet, tuning seeds 0-29: the circle misses each
    bow by about the pen's own wobble, so none is read by the rules as a line the hand swung (main 40b8114: small-paren
    seeds 1 and 5, small-hooked-paren seed 26); each of those three is now an arc or a curve, shipped too."""
    swung = []
    for seed in range(30):
        stroke = PENS["hurried"](FAMILIES[family](seed), seed)
        found = recognize_stroke([p[:2] for p in stroke], None, learned=False)
        if (found.kind, found.alternatives) == SWUNG:
            swung.append(seed)
    assert swung == []
    for seed in {"small-paren": (1, 5), "small-hooked-paren": (26,)}[family]:
        assert read(family, "hurried", seed, True, families=FAMILIES) in EXPECTED, seed


def _line_test_points(stroke: list[tuple[float, float, float]]) -> np.ndarray:
    """A stroke's points as the line test judges them, in canvas pixels (a pixel's noise): resampled, smoothed, a sharp
    hook cut (`open_shapes._line`)."""
    raw = np.asarray([p[:2] for p in stroke], dtype=float)
    n = lines.line_test_points(sg.path_length(raw), 1.0)
    return sg.resample(sg.remove_hooks(sg.smooth(sg.resample(raw, n))), n)


def test_a_small_bow_is_not_a_line_between_hooks_and_a_hooked_short_line_often_is() -> None:
    """`open_marks.hooked_straight` (a line explains what the hooks left within the pen's wobble and an end curls as a
    hook does) takes none of the small parentheses the hurried hand draws (tuning seeds 0-29, both small families: some,
    flat in the middle, are straight there, but their ends bend off gently), and 41 of the 90 short lines hooked at both
    ends that the hurried hand, the coarse device and the careful pen draw (`bench_lines`' short-hooked family, tuning
    seeds), as measured."""
    for family in ("small-paren", "small-hooked-paren"):
        for seed in range(30):
            work = _line_test_points(PENS["hurried"](FAMILIES[family](seed), seed))
            assert not open_marks.hooked_straight(work, lines.without_hooked_ends(work, 1.0), 1.0), (family, seed)
    taken = 0
    for pen in ("hurried", "hurried-coarse", "careful"):
        for seed in range(30):
            work = _line_test_points(bench_lines.drawn("short-hooked", pen, seed)[0])
            taken += open_marks.hooked_straight(work, lines.without_hooked_ends(work, 1.0), 1.0)
    assert taken >= 41
