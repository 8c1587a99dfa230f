"""Cornered closed shapes read cornered, round ones round (issue 25): hexagons, octagons, irregular many-sided
polygons, rhombi, parallelograms, trapezoids and rounded rectangles drawn by both pen models (the careful virtual
pen and the hurried hand of `tests/penmodels`) keep their corners, circles and ovals stay round, and a many-sided
polygon's outline overlaps the one drawn. The shapes are `benchmarks/bench_closed_shapes.py`'s, on its tuning seeds
(0-29), also as a coarse device sends the hurried hand's (an event every 15-30 ms); what a person expects of each
family is its `EXPECTED` (written down in docs/BENCHMARKS.md)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_closed_shapes import ALL_FAMILIES, EXPECTED, PENS, TUNING_SEEDS, class_right, read

CORNERED_FLOORS = {
    ("pentagon", "careful"): 30, ("pentagon", "hurried"): 30,
    ("hexagon", "careful"): 30, ("hexagon", "hurried"): 30,
    ("octagon", "careful"): 30, ("octagon", "hurried"): 30,
    ("pentagon-irregular", "careful"): 30, ("pentagon-irregular", "hurried"): 30,
    ("hexagon-irregular", "careful"): 30, ("hexagon-irregular", "hurried"): 30,
    ("octagon-irregular", "careful"): 27, ("octagon-irregular", "hurried"): 23,
    ("rhombus", "careful"): 30, ("rhombus", "hurried"): 30,
    ("parallelogram", "careful"): 30, ("parallelogram", "hurried"): 30,
    ("trapezoid", "careful"): 30, ("trapezoid", "hurried"): 30,
    ("rounded-rectangle", "careful"): 30, ("rounded-rectangle", "hurried"): 30,
    ("pentagon", "hurried-coarse"): 28, ("hexagon", "hurried-coarse"): 24, ("octagon", "hurried-coarse"): 24,
    ("pentagon-irregular", "hurried-coarse"): 28, ("hexagon-irregular", "hurried-coarse"): 27,
    ("octagon-irregular", "hurried-coarse"): 17, ("rhombus", "hurried-coarse"): 29,
    ("parallelogram", "hurried-coarse"): 30, ("trapezoid", "hurried-coarse"): 30,
    ("rounded-rectangle", "hurried-coarse"): 30,
    # session 20 (wt-polygons): heptagons, polygons with every corner rounded a little, and the slow, unsteady hand
    ("heptagon", "careful"): 30, ("heptagon", "hurried"): 28, ("heptagon", "hurried-coarse"): 26,
    ("heptagon-irregular", "careful"): 30, ("heptagon-irregular", "hurried"): 28,
    ("heptagon-irregular", "hurried-coarse"): 24,
    ("pentagon-rounded", "careful"): 30, ("pentagon-rounded", "hurried"): 30,
    ("pentagon-rounded", "hurried-coarse"): 30,
    ("hexagon-rounded", "careful"): 29, ("hexagon-rounded", "hurried"): 26, ("hexagon-rounded", "hurried-coarse"): 26,
    ("heptagon-rounded", "careful"): 27, ("heptagon-rounded", "hurried"): 17,
    ("heptagon-rounded", "hurried-coarse"): 13,
    ("octagon-rounded", "careful"): 23, ("octagon-rounded", "hurried"): 19, ("octagon-rounded", "hurried-coarse"): 15,
    ("pentagon", "slow"): 30, ("hexagon", "slow"): 29, ("heptagon", "slow"): 29, ("octagon", "slow"): 30,
    ("pentagon-irregular", "slow"): 30, ("hexagon-irregular", "slow"): 29, ("heptagon-irregular", "slow"): 30,
    ("octagon-irregular", "slow"): 26, ("pentagon-rounded", "slow"): 30, ("hexagon-rounded", "slow"): 29,
    ("heptagon-rounded", "slow"): 29, ("octagon-rounded", "slow"): 28,
}
"""(family, pen) -> how many of the 30 read cornered (a box or a polygon), measured on this branch; at main f7632ef
hexagons 24 and 22, octagons 0 and 0, irregular pentagons 29 and 30, hexagons 27 and 22, octagons 6 and 9, rounded
rectangles 29 and 28 (the rest read as circles or ellipses); through a device sending an event every 15-30 ms (the
hurried hand's "hurried-coarse"): pentagons 28, hexagons 21, octagons 0, irregular ones 27, 24 and 9, rhombi 29,
rounded rectangles 28. A many-sided polygon on so few points (fewer than four to a side) is left round: a circle
given as a few points round it, or as events in bursts, looks the same
(`polygon_checks.MAX_STEP_OF_SHORTEST_SIDE`). Session 20's families (heptagons; polygons whose every corner a hand
rounded by 0.08-0.2 of a side, `bench_closed_shapes.rounded_polygon`; the slow, unsteady hand
`penmodels.hurried.SHAKY_SLOW`) at their measured figures: rounded heptagons and octagons drawn in a hurry are read
round a third of the time or more (the hurried pen slows at a rounded corner to 0.64-0.9 of its pace, within people's
circles' 0.68 or more: `corner_pace` cannot tell them); the slow hand's polygons lost 7 of 360 to
`closed_loops.WITHIN_ROUND` (its tremor's turning back had refused them round, as it refused its circles)."""


@pytest.mark.parametrize(("family", "pen"), list(CORNERED_FLOORS))
def test_a_cornered_closed_shape_keeps_its_corners(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed=True)[0] for seed in TUNING_SEEDS]
    assert sum(class_right(family, k) for k in got) >= CORNERED_FLOORS[(family, pen)], got


ROUND_FAMILIES = [f for f in ALL_FAMILIES if EXPECTED[f][0] in ("circle", "ellipse")]


@pytest.mark.parametrize("pen", list(PENS))
@pytest.mark.parametrize("family", ROUND_FAMILIES)
def test_a_circle_or_an_oval_stays_round_with_or_without_times(family: str, pen: str) -> None:
    for timed in (True, False):
        got = [read(family, pen, seed, timed=timed)[0] for seed in TUNING_SEEDS]
        assert all(k in EXPECTED[family] for k in got), got


SLOW_ROUND_FLOORS = {"circle": 29, "oval-1.3-1.8": 30, "oval-1.8-3": 28, "egg": 18, "circle-lumpy": 26}
"""How many of 30 the slow, unsteady hand's round shapes read round (`penmodels.hurried.SHAKY_SLOW`; measured on this
branch, with or without times; held-back seeds 1000-1029: 29, 29, 23, 16, 25). At main 2996772: 22, 19, 19, 15, 20: its
tremor (4-7 Hz, 1-3 px, at 180-300 px/s) made the loop's coarse turning turn back by 190-850 degrees and
`closed_loops.no_round_shape` refused it round as a star (`closed_loops.WITHIN_ROUND` now asks the ellipse to miss it
as a star's does). The rest are still polygons: `round_or_cornered.cornered_after_all` finds the tremor's wiggles
sharp corners (`polygon_checks.sharp_corners`) on 7-8 sides of an egg or a lumpy circle."""


@pytest.mark.parametrize("family", ROUND_FAMILIES)
def test_a_round_shape_drawn_slowly_by_an_unsteady_hand_stays_round(family: str) -> None:
    for timed in (True, False):
        got = [read(family, "slow", seed, timed=timed)[0] for seed in TUNING_SEEDS]
        assert sum(k in EXPECTED[family] for k in got) >= SLOW_ROUND_FLOORS[family], got


IOU_FLOOR = 0.90
"""The issue's floor for an outline kept as drawn."""


@pytest.mark.parametrize("pen", ["careful", "hurried"])  # a coarse device's few points: `CORNERED_FLOORS`
@pytest.mark.parametrize("family", ["hexagon", "octagon"])
def test_a_many_sided_polygon_is_a_polygon_overlapping_the_one_drawn(family: str, pen: str) -> None:
    for seed in TUNING_SEEDS:
        kind, iou = read(family, pen, seed, timed=False)
        assert kind == "polygon" and iou is not None and iou >= IOU_FLOOR, (seed, kind, iou)
