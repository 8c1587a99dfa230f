"""Issue 25: a box with a low roof on one side (a house, a home plate) or a swallowtail's notch in it is the pentagon
drawn, not a box (`recognition.roofs`), while a box whose side a hand kinked a little or bowed stays a box; the pen
models' houses and swallowtails (`penmodels.box_bows`, tuning seeds 0-29, five pens) read as polygons at least as often
as measured on wt-roof (session 26), and the bowed boxes beside them as boxes; a person's rectangle with a long cut
corner the rule reached stays a box."""

from __future__ import annotations

import itertools
import math
import sys
from pathlib import Path

import pytest
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_box_bows import meant, read
from bench_box_slips import PENS

Point = tuple[float, float]

TUNING = range(30)
FLOORS: dict[str, tuple[int, int, int, int, int]] = {
    "house": (27, 19, 21, 14, 15), "house-in": (29, 25, 22, 22, 22),
    "bowed-out": (30, 29, 30, 29, 29), "bowed-in": (29, 30, 29, 29, 30), "bow-swung": (26, 24, 24, 24, 26),
    "cut-deep": (26, 29, 28, 28, 29),
}
"""family -> of the 30 tuning seeds, how many read as a polygon (house, house-in, cut-deep) or a box (the bows) by the
careful pen, the hurried hand, through a coarse device, a mouse and a trackpad (`bench_box_slips.PENS`), measured on
wt-roof. At main 7111cdc: house 10/11/16/4/10, house-in 14/12/11/10/10 (most low roofs and swallowtails read as
boxes); bowed-out 30/30/30/29/29 (seed 27 by the hurried hand, a bow whose middle turns within 0.27 of its halves,
is a pentagon now), bowed-in, bow-swung and cut-deep as here."""


@pytest.mark.parametrize("family", list(FLOORS))
def test_roofs_and_notches_read_as_pentagons_and_bowed_boxes_as_boxes(family: str) -> None:
    for pen, floor in zip(PENS, FLOORS[family], strict=True):
        got = [read(family, pen, seed) for seed in TUNING]
        assert sum(k == meant(family) for k in got) >= floor, (pen, got)


CENTRE = (600.0, 400.0)


def _outline(corners: list[Point], per_side: int = 40) -> list[Point]:
    """A closed stroke through ``corners`` (drawn round and back to the first), ``per_side`` points a side."""
    ring = [*corners, corners[0]]
    pts = [(a[0] + (b[0] - a[0]) * j / per_side, a[1] + (b[1] - a[1]) * j / per_side)
           for a, b in itertools.pairwise(ring) for j in range(per_side)]
    return [*pts, ring[-1]]


def _box_with_a_point(width: float, height: float, rise: float, at: float = 0.5) -> list[Point]:
    """A ``width`` x ``height`` box (y down) whose right side has a fifth corner ``at`` along it, ``rise`` of the side
    out of the box (into it where negative), drawn from the top left corner."""
    x0, y0 = CENTRE[0] - width / 2, CENTRE[1] - height / 2
    x1, y1 = x0 + width, y0 + height
    return _outline([(x0, y0), (x1, y0), (x1 + rise * height, y0 + at * height), (x1, y1), (x0, y1)])


@pytest.mark.parametrize("rise", (0.18, 0.2, -0.18, -0.2, -0.25))
def test_a_long_box_with_a_low_roof_on_its_short_side_is_a_pentagon(rise: float) -> None:
    """A 2.5:1 box whose 100 px short side rises to a ridge 18-20 % of it out (each half 20-22 degrees off the side:
    a house, a home plate) or is notched 18-25 % in (a swallowtail): its box covers it by 0.95 or more, so main
    7111cdc read every one as a box (`rounded_corners.box_as_drawn`); the corner is drawn, sharp, between two straight
    halves, as no hurried bow is. (At 13-16 % out, on so short a side, the judged points smooth the ridge over half of
    each 52 px half: still a box, as at main.)"""
    got = recognize_stroke(_box_with_a_point(250, 100, rise))
    assert got.kind == "polygon" and got.geometry is not None and len(got.geometry.points) == 5, got


@pytest.mark.parametrize("rise", (0.05, 0.08, -0.08))
def test_a_box_whose_side_a_hand_kinked_a_little_stays_a_box(rise: float) -> None:
    """A fifth corner 5-8 % of the side off its line (`box_habits` side-kinked: 4-9 %, a hand regripping mid-side) is
    under `roofs.RIDGE_LOW` (0.11): a box, as at main."""
    assert recognize_stroke(_box_with_a_point(250, 100, rise)).kind == "box"


@pytest.mark.parametrize("bow", (0.18, -0.18))
def test_a_box_with_a_side_bowed_round_stays_a_box(bow: float) -> None:
    """The same short side bowed round by 18 % (a sine's half wave): it turns all along, no corner at its middle."""
    x0, y0 = CENTRE[0] - 125, CENTRE[1] - 50
    right = [(x0 + 250 + bow * 100 * math.sin(math.pi * j / 40), y0 + 100 * j / 40) for j in range(41)]
    pts = [*[(x0 + 250 * j / 40, y0) for j in range(40)], *right,
           *[(x0 + 250 - 250 * j / 40, y0 + 100) for j in range(1, 41)],
           *[(x0, y0 + 100 - 100 * j / 40) for j in range(1, 41)]]
    assert recognize_stroke(pts).kind == "box"


def test_a_persons_rectangle_with_a_cut_corner_beside_a_side_stays_a_box() -> None:
    """hcira jonathanzhang53/s03 rectangle1 (a design source): its top right corner cut long and the right side
    stepped near its foot; its best pentagon's fifth corner lies on the right side with the upper half running on
    along the side (`roofs.RIDGE_LEAN`: no roof). A box at main; an earlier version of the rule read it a pentagon."""
    rows = cached_rows("public-sets/hcira.jsonl")
    file = "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s03/rectangle1.xml"
    if file not in rows:
        pytest.skip(f"{file} is not in the cached hcira set")
    assert recognize_stroke(*_stroke(rows[file])).kind == "box"
