"""Issue 25: a four-cornered loop is a box or the quad drawn, as a person means it (`quads`). A rhombus standing on
its point and a trapezoid whose legs both turn in, drawn within a box's 24-degree corner tolerance, keep their corners
through a whole session (journal -> replay -> project) by both pen models, overlapping the outline drawn with IoU
>= 0.90 (squared into boxes they overlapped it by 0.79-0.88); on `benchmarks/bench_closed_shapes.py`'s tuning seeds
they overlap so at least as often as measured here. People's rectangles drawn askew (one wall turned out, both
walls turned in a little, a square with a corner pulled) stay boxes, and a rectangle with a cut corner reads as a box.

People's strokes are read from the public-set caches (`benchmarks/public_sets.py`; no licence: never committed) and
skip without them; only design sources are named."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from shapely.geometry import Polygon
from test_open_marks import cached_rows
from test_outlines_kept import IOU_FLOOR, drawn, iou, placed
from xerase_drawings import replayed_project

from physink_tui.scene.interpretation.body_shapes import body_geometry
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_closed_shapes import TUNING_SEEDS, read

Point = tuple[float, float]

QUADS: dict[str, list[Point]] = {
    "tall rhombus": [(0, -145), (100, 0), (0, 145), (-100, 0)],  # corners 69 and 111 degrees
    "wide rhombus": [(-150, 0), (0, -105), (150, 0), (0, 105)],  # corners 70 and 110 degrees
    "trapezoid": [(-150, 75), (150, 75), (90, -75), (-90, -75)],  # legs 22 degrees in, top 0.6 of the base
    "slid trapezoid": [(-150, 80), (150, 80), (105, -90), (-85, -90)],  # legs 21 and 15 degrees in, top 0.63
}
"""What the pen is asked to draw, in canvas pixels round the centre (y down): within a box's corner tolerance."""
SCALES = (0.75, 1.0)
SEEDS = (1, 2, 3)


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize("name", QUADS)
def test_a_rhombus_or_a_trapezoid_keeps_its_corners_through_a_session(pen: str, name: str, tmp_path) -> None:
    for scale in SCALES:
        for seed in SEEDS:
            meant = placed(QUADS[name], scale)
            folder = tmp_path / f"{scale}-{seed}"
            folder.mkdir()
            project, told = replayed_project(*drawn(pen, meant, seed), folder)
            bodies = project.scene.bodies()
            case = f"{name} at {scale}x, {pen} pen seed {seed}"
            assert len(bodies) == 1, f"{case}: {[(b.id, b.shape) for b in bodies]}\n{told}"
            overlap = iou(body_geometry(bodies[0]), Polygon(meant))
            assert bodies[0].shape == "polygon" and overlap >= IOU_FLOOR, (
                f"{case}: a {bodies[0].shape} overlapping by IoU {overlap:.3f}\n{told}")


KEPT_FLOORS = {
    ("rhombus", "careful"): 30, ("rhombus", "hurried"): 28, ("rhombus", "hurried-coarse"): 28,
    ("trapezoid", "careful"): 28, ("trapezoid", "hurried"): 27, ("trapezoid", "hurried-coarse"): 27,
    ("parallelogram", "careful"): 30, ("parallelogram", "hurried"): 29, ("parallelogram", "hurried-coarse"): 28,
}
"""(family, pen) -> of the 30 tuning seeds, how many read cornered with an outline overlapping the one meant by IoU
>= 0.90, measured on this branch; at main cb69115 rhombi 24, 20 and 19, trapezoids 20, 20 and 19 (squared into
boxes), parallelograms 30, 28 and 27 (their corners cut at the fit's vertices). The trapezoids short of 30 have one
leg square to the base: a box with a wall askew to people (see `quads`)."""


@pytest.mark.parametrize(("family", "pen"), list(KEPT_FLOORS))
def test_quads_drawn_by_the_pen_models_keep_their_outline(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed=True) for seed in TUNING_SEEDS]
    kept = sum(1 for kind, overlap in got if kind in ("box", "polygon") and overlap is not None and overlap >= 0.90)
    assert kept >= KEPT_FLOORS[(family, pen)], got


HCIRA = "public-sets/hcira.jsonl"
BOXES = [
    "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s04/rectangle7.xml",  # a corner cut: was a polygon
    "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User04/rectangle03.xml",  # one wall 26 degrees out
    "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User04/rectangle07.xml",  # walls 9 and 18 degrees in
    "sinarest1608/HCIRA-HK@d91ccc6:Project1/usersamples/Subject5/rectangle6.xml",  # one wall 25 degrees out
    "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/rectangle1.xml",  # walls 9 and 7 degrees in
    "klarubbio/hcira_p1@e8eb332:xml/s04/rectangle04.xml",  # walls 8 degrees in, top 0.66 of the base
    "hat359/HCIRA@69a6542:xml_collected_logs/user1/rectangle01.xml",  # a square, one corner pulled: a rhombus on a side
]
"""People's rectangles (hcira, a design set) on the edge of the decision: a box, not the quad drawn."""


def _kind(name: str, file: str) -> str | None:
    rows = cached_rows(name)
    if file not in rows:
        pytest.skip(f"{file} not in the cached {name}")
    stroke = rows[file]["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    return recognize_stroke([p[:2] for p in stroke], times).kind


@pytest.mark.parametrize("file", BOXES, ids=[f.rsplit(":", 1)[-1] for f in BOXES])
def test_peoples_rectangles_drawn_askew_are_boxes(file: str) -> None:
    assert _kind(HCIRA, file) == "box"
