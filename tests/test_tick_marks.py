"""Ticks, checks and v's swung round their point (issue 25, session 15): a hand in a hurry rounds a check's point
instead of stopping at it, the corner finder finds no corner, and the stroke read as a curve; now a polyline
(`bracket_marks.rounded_point`, and the learned ranker is not asked of it), drawn by both pen models (the careful
virtual pen and the hurried hand of `tests/penmodels`) and by people of the public sets; arcs turning as much, a
question mark whose stem curves on from its curl and straight-armed braces stay curves.

The pen models always run. People's strokes are read from the caches `benchmarks/public_sets.py` and
`benchmarks/student_sets.py` write (no licence lets the project hold them); without them those tests skip, saying so.
Design sources are named: of the first 55, and two of the second group (opened on 2026-12-04), whose strokes the
rule gained without having been looked at while it was designed (no stroke of the first held-back group).
"""

from __future__ import annotations

import math
import random

import pytest
from test_bracket_marks import PENS, _arc, _placed, _readings
from test_open_marks import cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

SEEDS = range(40)
Point = tuple[float, float]


def swung_tick(seed: int) -> list[Point]:
    """A tick 140-260 px long: a short arm 0.3-0.45 of the long one coming down at 35-55 degrees, a long arm going
    up at 40-60 degrees, the point rounded off by an arc tangent to both that takes 0.6-0.85 of the short arm; drawn
    short arm first, either way round (a mirror image for a left hand's tick)."""
    rng = random.Random(f"swung-tick:{seed}")
    long_arm = rng.uniform(140, 260)
    short_arm = rng.uniform(0.3, 0.45) * long_arm
    down, up = math.radians(rng.uniform(35, 55)), math.radians(rng.uniform(40, 60))
    inner = math.pi - down - up  # the angle between the arms at the point
    t = rng.uniform(0.6, 0.85) * short_arm  # from the point to where the round bend meets each arm
    r = t * math.tan(inner / 2)
    d_in, d_out = (math.cos(down), -math.sin(down)), (math.cos(up), math.sin(up))  # y up, heading in and out
    start = (-short_arm * d_in[0], -short_arm * d_in[1])
    enter, leave = (-t * d_in[0], -t * d_in[1]), (t * d_out[0], t * d_out[1])
    normal = (-d_in[1], d_in[0])  # the bend's centre lies to the left of the heading in (it turns left)
    centre = (enter[0] + r * normal[0], enter[1] + r * normal[1])
    a0 = math.atan2(enter[1] - centre[1], enter[0] - centre[0])
    a1 = math.atan2(leave[1] - centre[1], leave[0] - centre[0])
    if a1 < a0:
        a1 += 2 * math.pi
    pts = [start, *_arc(*centre, r, a0, a1, 12), (long_arm * d_out[0], long_arm * d_out[1])]
    pts = [(x, -y) for x, y in pts]  # y down, as on the canvas
    if rng.random() < 0.3:
        pts = [(-x, y) for x, y in pts]
    return _placed(pts, rng)


def even_arc(seed: int) -> list[Point]:
    """An arc of a circle turning 100-150 degrees (the turn of a tick), 120-260 px across, either way round."""
    rng = random.Random(f"even-arc:{seed}")
    turn = math.radians(rng.uniform(100, 150))
    r = rng.uniform(120, 260) / (2 * math.sin(turn / 2))
    a0 = rng.uniform(0, 2 * math.pi)
    pts = _arc(0.0, 0.0, r, a0, a0 + turn, 24)
    return _placed(pts[::-1] if rng.random() < 0.5 else pts, rng)


# (pen, learned) -> how many of the 40 read as a polyline (this branch's counts); at main d7f1057 none of the 160 (the
# careful pen's 31 curves and 9 arcs, the hurried hand's 40 curves, by the rules and shipped alike). The shipped
# recogniser keeps 29 of the hurried hand's 36: the model, asked where its own corner finder finds a corner, re-reads
# the rest as curves (the lead's refit takes the rules' answer among its inputs). With the fine path's turn alone (not
# the coarse lobe's) the hurried hand's hooks left 22 and 8. Session 23 (wt-marks): the model is not asked either once
# a hook where the pen landed or lifted is cut (`bracket_marks.swung_tick`, `bracket_marks.unhooked_point`): the
# hurried hand's 37 and 36 (rules, shipped), floors two under the shipped count.
SWUNG_FLOORS = {("careful", False): 40, ("hurried", False): 36, ("careful", True): 40, ("hurried", True): 34}


@pytest.mark.parametrize(("pen", "learned"), list(SWUNG_FLOORS))
def test_a_tick_swung_round_its_point_is_a_polyline(pen: str, learned: bool) -> None:
    read = _readings(swung_tick, pen, learned)
    assert read["polyline"] >= SWUNG_FLOORS[(pen, learned)], read


@pytest.mark.parametrize("pen", list(PENS))
@pytest.mark.parametrize("learned", [False, True])
def test_an_arc_turning_as_much_as_a_tick_is_never_a_polyline(pen: str, learned: bool) -> None:
    """An arc's turning is spread evenly: its longer arm bows as much as the turning makes it (at d7f1057 and on this
    branch: the careful pen's 40 arcs, the hurried hand's 22 arcs and 18 curves, by the rules and shipped)."""
    read = _readings(even_arc, pen, learned)
    assert read["polyline"] == 0, read


AHMAD = "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:"
PEOPLE = {
    # ticks, checks and v's swung round their point (`bracket_marks.rounded_point`), misread at main d7f1057
    ("public-sets/ahmadosama.jsonl", AHMAD + "TestData/Tick.xml#6"): ("polyline", True),
    ("public-sets/hcira.jsonl", "sinarest1608/HCIRA-HK@d91ccc6:Project1/usersamples/Subject4/check8.xml"):
        ("polyline", True),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/v10.xml"): ("polyline", True),
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user02/check7.xml"):
        ("polyline", False),
    # the same, in the second group (opened 2026-12-04; not looked at while the rule was designed: its validation)
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User01/check07.xml"):
        ("polyline", True),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s05/check07.xml"): ("polyline", True),
    # a short arm curling into the point a little tighter than a circle (`bracket_marks.SHORT_ARM_SLACK`, session 34):
    # read as curves at main 85a9ce3 (check06 by the rules a polyline, the model re-read it as a curve)
    ("public-sets/ahmadosama.jsonl", AHMAD + "TrainingData/Tick.xml#101"): ("polyline", True),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/check06.xml"): ("polyline", True),
    # a question mark whose stem curves on from its shallow curl (`bracket_marks.TICK_CONCENTRATED`): still a curve
    ("student-sets/itt.jsonl", "ITT-26/assignment-06-gesture-recognition-DerD4n@1ee2c34:datasets/my_gestures/"
                               "question_mark01.xml"): ("curve", True),
}
"""(cached set, file) -> the kind a reader names, and whether the shipped recogniser (with its learned ranker) reads it
so too (pixelfac/user02's check7: the rules do, the model still re-reads it as a curve: left to the lead's refit)."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.rsplit("/", 1)[-1] for _, f in PEOPLE])
def test_a_persons_swung_tick_is_read_as_what_it_is(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    stroke = row["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    points = [p[:2] for p in stroke]
    kind, shipped_too = PEOPLE[(name, file)]
    assert recognize_stroke(points, times, learned=False).kind == kind
    if shipped_too:
        assert recognize_stroke(points, times).kind == kind
