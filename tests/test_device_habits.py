"""Strokes as a trackpad or a touch screen gives them beyond how it samples (`benchmarks/device_habits.py`): a
fingertip's dwell where it lands or lifts, pointer acceleration, round shapes sampled by a few events; people's $1
strokes transformed and synthetic strokes, still read as drawn.

Figures on transformed strokes are figures on transformed strokes, not on people using those devices. The people's
strokes are read in place from ``../shared/data/strokes/dollar1-dev.jsonl`` (`shared_data`); floors only rise.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from physink_tui.scene.recognition import landing, pen_noise
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_device_stress import MORE, as_stroke, events  # the benchmark's own transforms, not copies
from test_device_sampling import people_rows, short_of_floors
from test_open_marks import cached_rows

TRACKPAD = "trackpad 2: acceleration, 8-25 events, start blob, lift hook"
TOUCH = "touch 2: start blob, touch grid, events every 15-30 ms, lift pause"

FLOORS: dict[str, dict[str, int]] = {
    "start blob": {"circle": 87, "star": 90, "check": 80, "pigtail": 88, "x": 88},
    "lift pause": {"circle": 89},
    TRACKPAD: {"rectangle": 90, "star": 90, "circle": 83, "check": 76, "pigtail": 87, "arrow": 85,
               "left_curly_brace": 83, "right_curly_brace": 82, "left_sq_bracket": 88, "right_sq_bracket": 87},
    TOUCH: {"circle": 89, "rectangle": 90},
}
"""Per transform and label, how many of the label's 90 strokes (three people, three speeds) must still be read right.
Closed shapes (circle, rectangle, star), which the learned ranker does not re-rank, at today's count; open marks two
under it, for the ranker's refits. Before a dwell where the finger lands or lifts was kept as one point (`landing`)
and a few events turning at every one were taken for a round shape (`pen_noise.turns_at_every_event`), on main
f7632ef: start blob circles 74, stars 88, checks 74, pigtails 85, x 88; lift pause circles 89; trackpad rectangles 77,
stars 81, circles 82, checks 74, pigtails 85, arrows 85; touch circles 89, rectangles 90. Before the events' step was
judged along the stroke's body (`pen_noise.path_step`: a landing's short steps outnumbered a trackpad's events) and a
brace's point by few events turned both ways at 20 degrees (`angular_braces.POINT_LOBE_DEG`), on main 2996772: trackpad
rectangles 89, stars 88, left braces 79, right braces 81, left brackets 88, right brackets 88 (now 90, 90, 84, 83, 90,
89)."""


@pytest.mark.parametrize("name", sorted(FLOORS))
def test_people_strokes_as_fingers_give_them(name: str) -> None:
    short = short_of_floors(MORE[name], name, FLOORS[name])
    assert not short, f"{name}: {short}"


ROUND_FLOORS = {8: 66, 9: 77}
"""Of the 90 $1 circles, how many must be read round when sampled by that many events evenly in time (an octagon or
a nonagon to a polygon fit): today's count. Before `pen_noise.turns_at_every_event`, 53 and 76."""


@pytest.mark.parametrize("n", sorted(ROUND_FLOORS))
def test_people_circles_by_a_few_events(n: int) -> None:
    right = 0
    for row in people_rows():
        if row["label"] == "circle":
            pts, times = events(n)(as_stroke(row), np.random.default_rng(0))
            right += recognize_stroke(pts.tolist(), None if times is None else times.tolist()).kind in {
                "circle", "ellipse"}
    assert right >= ROUND_FLOORS[n], f"{n} events: {right}/90 circles read round"


def _round_by_events(events: int, lean: float = 0.0) -> np.ndarray:
    """A circle 200 px across drawn at a steady pace from its top, sampled by ``events`` events evenly in time, the
    last back at the start; ``lean`` turns the whole sampling by that share of a step."""
    a = 2 * math.pi * (np.arange(events) / (events - 1) + lean / (events - 1))
    return np.column_stack([100 * np.sin(a), -100 * np.cos(a)])


@pytest.mark.parametrize("events", [8, 9, 10])
def test_a_circle_by_a_few_events_is_round(events: int) -> None:
    """Every event a corner at the same turn, evenly spaced: a round shape's samples, not a polygon's sides."""
    pts = _round_by_events(events)
    assert pen_noise.turns_at_every_event(pts, float(np.hypot(*np.ptp(pts, axis=0))))
    assert recognize_stroke(pts.tolist()).kind == "circle"


@pytest.mark.parametrize("events", range(8, 41))
def test_only_events_a_sparse_step_apart_are_a_round_shapes_samples(events: int) -> None:
    """A circle by events evenly in time turns at every one; it is taken for a round shape's few samples only where
    they are at least `pen_noise.SPARSE_STEP_OF_DIAGONAL` of its diagonal apart (a circle 200 px across: 28 events
    or fewer); denser events are judged by the shape they draw."""
    pts = _round_by_events(events)
    diag = float(np.hypot(*np.ptp(pts, axis=0)))
    step = float(np.median(np.hypot(*np.diff(pts, axis=0).T)))
    assert pen_noise.turns_at_every_event(pts, diag) == (step >= pen_noise.SPARSE_STEP_OF_DIAGONAL * diag)


def test_a_pentagram_by_its_points_is_not_round() -> None:
    """A star drawn through its five points turns as evenly at each, but goes round twice: it keeps its corners."""
    a = math.pi / 2 + 4 * math.pi * np.arange(6) / 5
    star = np.column_stack([100 * np.cos(a), 100 * np.sin(a)])
    assert not pen_noise.turns_at_every_event(star, float(np.hypot(*np.ptp(star, axis=0))))
    assert recognize_stroke(star.tolist()).kind == "polygon"


def _landing(start: np.ndarray, points: int, spread: float, seed: int) -> np.ndarray:
    return start + np.random.default_rng(seed).normal(0, spread, (points, 2))


@pytest.mark.parametrize("seed", range(5))
def test_a_line_with_a_fingers_landing_is_a_line(seed: int) -> None:
    """A 200 px line by 15 events, the finger settling for 8 events within a few px of where it landed first: the
    settling is one point, not a scribble that makes the line a shaky curve."""
    line = np.column_stack([np.linspace(0, 200, 15), np.linspace(0, 40, 15)])
    pts = np.vstack([line[:1], _landing(line[0], 8, 3.0, seed), line[1:]])
    assert landing.settled(pts, float(np.hypot(*np.ptp(pts, axis=0))), 1.0).sum() < len(pts) - 4
    assert recognize_stroke(pts.tolist()).kind == "line"


@pytest.mark.parametrize("seed", range(5))
def test_a_box_with_a_fingers_lift_is_a_box(seed: int) -> None:
    """A 240 x 150 box by 40 events, the finger resting 10 events at its end before it lifts."""
    corners = np.array([[0, 0], [240, 0], [240, 150], [0, 150], [0, 0]], dtype=float)
    u = np.linspace(0, 4, 41)[:-1]
    side = np.minimum(u.astype(int), 3)
    box = corners[side] + (corners[side + 1] - corners[side]) * (u - side)[:, None]
    box = np.vstack([box, corners[-1:]])
    pts = np.vstack([box, _landing(box[-1], 10, 2.5, seed)])
    assert recognize_stroke(pts.tolist()).kind == "box"


def test_a_tablet_stroke_without_a_dwell_is_kept_whole() -> None:
    """A dense stroke that leaves its start straight away loses no point."""
    a = np.linspace(0, 2 * math.pi, 200)
    circle = np.column_stack([100 * np.cos(a), 100 * np.sin(a)])
    assert landing.settled(circle, 200 * math.sqrt(2), 1.0).all()


BRACKET = "pixelfac/hcira-project-23@80d4cc7:src/dataset/user03/right square bracket6.xml"


def test_a_bracket_whose_pen_goes_back_along_its_last_arm_is_a_polyline() -> None:
    """The pen goes back and forth along the bracket's short bottom arm as it lifts (17 points within 6 % of the
    diagonal): a hook, not a dwell, for it goes out and back along one line (`landing.DWELL_BREADTH`); a first version
    of `landing` took it for a dwell and read the bracket as a curve. Polyline at main f7632ef."""
    row = cached_rows("public-sets/hcira.jsonl").get(BRACKET)
    assert row is not None, f"{BRACKET} is not in hcira"
    stroke = row["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    assert recognize_stroke([p[:2] for p in stroke], times).kind == "polyline"
