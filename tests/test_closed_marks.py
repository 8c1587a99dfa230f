"""Closed strokes read as a person means them (issue 25, fourth pass): a box drawn with a hook where the pen landed
and an overshoot where it lifted, or with a bowed side or a cut corner, is a box; an arrow whose head closes back on
its shaft, or an x drawn as a loop between crossing tails, is an open mark, not a polygon; a lumpy round loop is
round, not a triangle through it. Fifth pass: a box whose upright sides a hurried hand slants (a parallelogram within
the box's 24 degrees) is a box, through a whole session and by both pens; a triangle the pen lifts short of its start,
with a wobble or hook at the end or a last side bowed as the hand swings home, is a closed polygon.

The hurried hand (`tests/penmodels`) always runs; people's strokes of the public sets are read from the caches that
`benchmarks/public_sets.py` and `benchmarks/student_sets.py` write (no licence: never committed), and skip without
them. Only design sources are named here (`bench_generalisation.is_held_back_new` and the first held-back group are
never read)."""

from __future__ import annotations

import math
import random

import pytest
from penmodels.hurried import HurriedPen, touching
from penmodels.shapes import Outline
from test_open_marks import cached_rows
from test_outlines_kept import drawn
from xerase_drawings import replayed_project

from physink_tui.scene.recognition.recognize import recognize_stroke

SEEDS = range(40)


def _placed(angle: float):
    c, s = math.cos(angle), math.sin(angle)
    return lambda x, y: (800 + x * c - y * s, 500 + x * s + y * c)


def _read(points: list[tuple[float, float, float]]) -> str | None:
    return recognize_stroke([p[:2] for p in points], [p[2] for p in points]).kind


def _box_landing_and_lifting_past_a_corner(seed: int) -> list[tuple[float, float, float]]:
    """A box begun with a short lead-in into its corner and ended on past that corner (neither end comes near the
    other's path: the pen crosses itself at the corner)."""
    rng = random.Random(seed)
    w, h = 160 + 10 * (seed % 12), 100 + 7 * (seed % 9)
    at = _placed(0.3 * (seed % 5) - 0.6)
    lead, over, hook = rng.uniform(0.06, 0.12) * h, rng.uniform(0.12, 0.2) * h, rng.uniform(0.03, 0.06) * w
    keys = [at(-w / 2 + hook, -h / 2 + lead), at(-w / 2, -h / 2), at(w / 2, -h / 2), at(w / 2, h / 2),
            at(-w / 2, h / 2), at(-w / 2, -h / 2 - over)]
    return touching(HurriedPen(rng).play(keys, 0.0))


def _arrow_with_a_closed_head(seed: int) -> list[tuple[float, float, float]]:
    """A shaft, then a head drawn round as a triangle back to the tip."""
    rng = random.Random(seed)
    length = 200 + 10 * (seed % 10)
    at = _placed(0.5 * (seed % 7))
    head = rng.uniform(0.22, 0.3) * length
    keys = [at(-length / 2, 0), at(length / 2, 0), at(length / 2 - head, -0.6 * head),
            at(length / 2 - head, 0.6 * head), at(length / 2, 0)]
    return touching(HurriedPen(rng).play(keys, 0.0))


def test_a_box_begun_before_its_corner_and_ended_past_it_is_a_box() -> None:
    read = {seed: _read(_box_landing_and_lifting_past_a_corner(seed)) for seed in SEEDS}
    assert all(kind == "box" for kind in read.values()), {s: k for s, k in read.items() if k != "box"}


def test_an_arrow_whose_head_closes_on_its_shaft_is_an_open_mark() -> None:
    read = {seed: _read(_arrow_with_a_closed_head(seed)) for seed in SEEDS}
    assert all(kind == "polyline" for kind in read.values()), {s: k for s, k in read.items() if k != "polyline"}


def _slanted_box(width: float, height: float, slant_deg: float, at) -> list[tuple[float, float]]:
    """A box whose upright sides lean by ``slant_deg`` (a parallelogram), corners round the origin placed by ``at``."""
    t = math.tan(math.radians(slant_deg)) * height / 2
    return [at(-width / 2 - t, -height / 2), at(width / 2 - t, -height / 2), at(width / 2 + t, height / 2),
            at(-width / 2 + t, height / 2)]


@pytest.mark.parametrize("slant", (12.0, 16.0, 20.0))
def test_a_box_whose_upright_sides_a_hurried_hand_slants_is_a_box(slant: float) -> None:
    """Squared, such a box reaches past the stroke by up to 9 % of its diagonal (`ranking.BOX_MARGIN`); at 16-20
    degrees about half of them fell back to the quad drawn before the fifth pass."""
    read = {}
    for seed in SEEDS:
        corners = _slanted_box(160 + 10 * (seed % 12), 100 + 7 * (seed % 9), slant, _placed(0.3 * (seed % 5) - 0.6))
        reports = HurriedPen(random.Random(seed)).draw(Outline(tuple(corners)), 0.3)[0]
        read[seed] = _read(touching(reports))
    assert all(kind == "box" for kind in read.values()), {s: k for s, k in read.items() if k != "box"}


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
def test_a_slanted_box_drawn_in_a_session_becomes_a_box_body(pen: str, tmp_path) -> None:
    for slant in (14.0, 20.0):
        for seed in range(1, 7):
            folder = tmp_path / f"{slant}-{seed}"
            folder.mkdir()
            corners = _slanted_box(220.0, 140.0, slant, lambda x, y: (800.0 + x, 500.0 + y))
            project, told = replayed_project(*drawn(pen, corners, seed), folder)
            shapes = [b.shape for b in project.scene.bodies()]
            assert shapes == ["box"], f"slant {slant}, {pen} pen seed {seed}: {shapes}\n{told}"


def _triangle_lifted_short(seed: int, ending: str) -> list[tuple[float, float, float]]:
    """A triangle whose last side stops 20-30 % short of the start: ``plain``, its last side ``bowed`` out as the hand
    swings home, or with a ``hook`` where the pen lifted."""
    rng = random.Random(seed)
    r = 110 + 5 * (seed % 8)
    at = _placed(0.4 * (seed % 7))
    v = [(r * math.cos(math.pi / 2 + k * 2 * math.pi / 3), r * math.sin(math.pi / 2 + k * 2 * math.pi / 3))
         for k in range(3)]
    short = rng.uniform(0.7, 0.8)
    end = (v[2][0] + short * (v[0][0] - v[2][0]), v[2][1] + short * (v[0][1] - v[2][1]))
    keys = [v[0], v[1], v[2]]
    if ending == "bowed":
        keys.append((0.625 * (v[2][0] + end[0]), 0.625 * (v[2][1] + end[1])))
    keys.append(end)
    if ending == "hook":
        d = (v[0][0] - v[2][0], v[0][1] - v[2][1])
        n = math.hypot(*d)
        keys.append((end[0] + (0.05 * d[0] - 0.1 * d[1]) * r / n, end[1] + (0.05 * d[1] + 0.1 * d[0]) * r / n))
    return touching(HurriedPen(rng).play([at(*k) for k in keys], 0.0))


@pytest.mark.parametrize("ending", ("plain", "bowed", "hook"))
def test_a_triangle_lifted_short_of_its_start_is_a_polygon(ending: str) -> None:
    """Before the fifth pass 14, 11 and 2 of the 40 were polylines: a wobble or hook at the end undid the path's
    turning (`closed_loops.LEFT_OPEN_WOBBLE`), or the last side bowed past `open_shapes.STRAIGHT` (`LAST_SIDE_BOW`)."""
    read = {seed: _read(_triangle_lifted_short(seed, ending)) for seed in SEEDS}
    assert all(kind == "polygon" for kind in read.values()), {s: k for s, k in read.items() if k != "polygon"}


ROUND = ("circle", "ellipse")  # as `benchmarks/label_kinds.tsv` counts a drawn circle
PEOPLE = [  # (cache file, the stroke's file in its set, what it is read as): each was misread before this pass
    ("student-sets/itt.jsonl", "ITT-25/assignment-06-gesture-recognition-Coldjack007@1fa71eb:datasets/rectangle3.xml",
     "box"),  # a hook where the pen lifted, turned into the box
    ("student-sets/itt.jsonl", "ITT-25/assignment-06-gesture-recognition-Coldjack007@1fa71eb:datasets/rectangle7.xml",
     "box"),  # a tail past the corner it closed on
    ("student-sets/itt.jsonl", "ITT-26/assignment-06-gesture-recognition-GixD42@78545e5:datasets/mylogs/"
     "rectangle07.xml", "box"),  # a bowed side
    ("student-sets/itt.jsonl", "ITT-26/assignment-06-gesture-recognition-lvht1203@925708d:datasets/logs_custom/"
     "rectangle/rectangle04.xml", "box"),  # begun before its corner, ended past it with a hook
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user03/rectangle4.xml", "box"),
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user03/rectangle8.xml", "box"),
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User04/rectangle09.xml", "box"),
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/rectangle01.xml", "box"),
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user3/rectangle08.xml", "box"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/rectangle01.xml", "box"),
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user02/arrow6.xml", "polyline"),
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user03/arrow10.xml", "polyline"),
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user03/arrow3.xml", "polyline"),
    ("public-sets/hcira.jsonl", "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s05/arrow3.xml",
     "polyline"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/arrow03.xml", "polyline"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/x02.xml", "polyline"),  # a loop between tails
    ("public-sets/hcira.jsonl", "Nikhil-Kumar-Singh0612/HCIRA@767a65a:$1 Recognizer/data_set/user5/circle04.xml",
     "round"),  # a lumpy round loop with a flat side, was a triangle
    ("public-sets/ahmadosama.jsonl", "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TestData/Circle.xml#5",
     "round"),  # the same, left a little open
    # fifth pass: boxes whose upright sides lean (squared, they reach past the stroke), triangles lifted short
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User04/rectangle07.xml", "box"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/rectangle07.xml", "box"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/rectangle10.xml", "box"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/triangle03.xml", "polygon"),  # last side bowed
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/triangle10.xml", "polygon"),  # a hook at the end
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/star04.xml", "polygon"),  # run on past its start
]


def _strokes(name: str) -> dict[str, list[list[float | None]]]:
    return {f: r["strokes"][0] for f, r in cached_rows(name).items() if len(r["strokes"]) == 1}


@pytest.mark.parametrize(("name", "file", "kind"), PEOPLE, ids=[p[1].rsplit(":", 1)[-1] for p in PEOPLE])
def test_peoples_closed_strokes_misread_before_are_read_as_drawn(name: str, file: str, kind: str) -> None:
    stroke = _strokes(name)[file]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    read = recognize_stroke([p[:2] for p in stroke], times).kind
    assert read in (ROUND if kind == "round" else (kind,)), read
