"""Square brackets and curly braces as a hand draws them quickly (issue 25, fifth pass): a bracket with one corner
rounded off is still a bracket (a polyline), a brace with straight arms or a small loop at its point is still a brace
(a curve), drawn by both pen models (the careful virtual pen and the hurried hand of `tests/penmodels`), and people's
strokes of the public sets that were misread.

The pen models always run. People's strokes are read from the caches `benchmarks/public_sets.py` and
`benchmarks/student_sets.py` write (no licence lets the project hold them); without them those tests skip, saying
so. Only design sources are named (never `bench_generalisation.is_held_back_new`, nor the first held-back group).
"""

from __future__ import annotations

import math
import random
from collections import Counter

import pytest
from penmodels.hurried import HurriedPen, touching
from test_open_marks import cached_rows

from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition.recognize import recognize_stroke

SEEDS = range(40)
CANVAS = (1600.0, 1000.0)
Point = tuple[float, float]


def _placed(points: list[Point], rng: random.Random) -> list[Point]:
    """Turned a little (a person draws these about upright) and put mid-canvas."""
    a = rng.uniform(-0.25, 0.25)
    c, s = math.cos(a), math.sin(a)
    return [(800 + x * c - y * s, 500 + x * s + y * c) for x, y in points]


def _arc(cx: float, cy: float, r: float, a0: float, a1: float, n: int = 10) -> list[Point]:
    angles = (a0 + (a1 - a0) * k / n for k in range(n + 1))
    return [(cx + r * math.cos(a), cy + r * math.sin(a)) for a in angles]


def bracket_with_a_round_corner(seed: int) -> list[Point]:
    """A square bracket, 160-300 px tall, one corner rounded off over a fifth to a quarter of its height (a radius of
    0.2-0.28 of it), the other sharp; either corner round, left or right facing, drawn either way."""
    rng = random.Random(f"rounded-bracket:{seed}")
    h = rng.uniform(160, 300)
    arm, r = rng.uniform(0.3, 0.45) * h, rng.uniform(0.2, 0.28) * h
    pts = [(arm, -h / 2), (r, -h / 2), *_arc(r, -h / 2 + r, r, -math.pi / 2, -math.pi)[1:], (0.0, h / 2), (arm, h / 2)]
    if rng.random() < 0.5:
        pts = [(x, -y) for x, y in pts]  # the round corner at the bottom
    if rng.random() < 0.5:
        pts = [(-x, y) for x, y in pts]  # a right bracket
    if rng.random() < 0.5:
        pts = pts[::-1]
    return _placed(pts, rng)


def brace_with_straight_arms(seed: int) -> list[Point]:
    """A curly brace, 160-300 px tall: small round curls at the ends (0.05-0.1 of its height), straight arms and a
    pointed tip sticking out 0.06-0.12 of its height; left or right facing, drawn either way."""
    rng = random.Random(f"straight-brace:{seed}")
    h = rng.uniform(160, 300)
    curl, tip = rng.uniform(0.05, 0.1) * h, rng.uniform(0.06, 0.12) * h
    pts = [*_arc(curl, curl, curl, -math.pi / 2, -math.pi, 6), (0.0, h / 2 - 0.3 * tip), (-tip, h / 2),
           (0.0, h / 2 + 0.3 * tip), *_arc(curl, h - curl, curl, math.pi, math.pi / 2, 6)]
    if rng.random() < 0.5:
        pts = [(-x, y) for x, y in pts]
    if rng.random() < 0.5:
        pts = pts[::-1]
    return _placed([(x, y - h / 2) for x, y in pts], rng)


def careful(points: list[Point], seed: int) -> list[tuple[float, float, float]]:
    """The virtual pen's touching samples along ``points`` (canvas pixels), with their times."""
    w, h = CANVAS
    pen = VirtualPen(REFERENCE_DEVICES["windows-ink"], seed=seed)
    samples = pen.samples([Stroke(tuple((x / w, y / h) for x, y in points))])
    return [(s.state.x * w, s.state.y * h, s.t) for s in samples if s.phase == "touch"]


def hurried(points: list[Point], seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand along ``points``: hooks where it lands and lifts, tremor, its own speed."""
    return touching(HurriedPen(random.Random(seed)).play(points, 0.0))


PENS = {"careful": careful, "hurried": hurried}


def _readings(shape, pen: str, learned: bool) -> Counter[str | None]:
    out: Counter[str | None] = Counter()
    for seed in SEEDS:
        drawn = PENS[pen](shape(seed), seed)
        out[recognize_stroke([p[:2] for p in drawn], [p[2] for p in drawn], learned=learned).kind] += 1
    return out


# (pen, learned) -> how many of the 40 read as a polyline (today's counts); at main f2aa8a5 19, 16, 40 and 34
ROUND_CORNER_FLOORS = {("careful", False): 40, ("hurried", False): 28, ("careful", True): 40, ("hurried", True): 35}


@pytest.mark.parametrize(("pen", "learned"), list(ROUND_CORNER_FLOORS))
def test_a_square_bracket_with_one_corner_rounded_off_is_a_polyline(pen: str, learned: bool) -> None:
    read = _readings(bracket_with_a_round_corner, pen, learned)
    assert read["polyline"] >= ROUND_CORNER_FLOORS[(pen, learned)], read


@pytest.mark.parametrize("pen", list(PENS))
@pytest.mark.parametrize("learned", [False, True])
def test_a_brace_with_straight_arms_is_never_a_polyline(pen: str, learned: bool) -> None:
    """At f2aa8a5 the rules read 5 of the hurried hand's 40 as polylines (its tip taken for the one corner between
    straight arms); a brace so small that it is nearly straight may read as a line (one of the careful pen's)."""
    read = _readings(brace_with_straight_arms, pen, learned)
    assert read["polyline"] == 0 and read["curve"] >= 39, read


PIXELFAC = "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/"
JD = "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/"
PEOPLE = {
    # square brackets with one corner rounded off (`bracket_marks.rounded_bracket_corners`)
    ("public-sets/hcira.jsonl", PIXELFAC + "left square bracket4.xml"): "polyline",
    ("public-sets/hcira.jsonl", PIXELFAC + "left square bracket8.xml"): "polyline",
    ("public-sets/hcira.jsonl", PIXELFAC + "left square bracket9.xml"): "polyline",
    ("public-sets/hcira.jsonl", PIXELFAC + "right square bracket7.xml"): "polyline",
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/right_square_bracket09.xml"): "polyline",
    # braces whose point is a small loop (`bracket_marks.looped_point`)
    ("public-sets/hcira.jsonl", JD + "User04/left_curly_brace02.xml"): "curve",
    ("public-sets/hcira.jsonl", JD + "User05/left_curly_brace01.xml"): "curve",
    # braces whose curls or point were taken for corners between straight sides (`bracket_marks.brace_point`)
    ("public-sets/hcira.jsonl", JD + "User04/right_curly_brace01.xml"): "curve",
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user1/left_curly_brace02.xml"): "curve",
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user1/right_curly_brace06.xml"): "curve",
    ("public-sets/hcira.jsonl", PIXELFAC + "right curly brace10.xml"): "curve",
    ("student-sets/itt.jsonl", "ITT-26/assignment-06-gesture-recognition-GixD42@78545e5:datasets/mylogs/"
                               "left_curly_brace07.xml"): "curve",
}
"""(cached set, file) -> the kind a reader names; every one was misread by the rules and by the recogniser at main
f2aa8a5."""




KNOWN_FAILING: dict[str, str] = {}
"""Files of `PEOPLE` read wrong today -> why: strict xfails, so a fix turns them red; delete the entry then
(pixelfac/user01's right brace 10, a polyline since session 20, is a brace again by `lopsided_braces`: session 22)."""


@pytest.mark.parametrize(("name", "file"), [
    pytest.param(name, file, marks=pytest.mark.xfail(strict=True, reason=KNOWN_FAILING[file]))
    if file in KNOWN_FAILING else (name, file) for name, file in PEOPLE],
    ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1] for _, f in PEOPLE])
def test_a_persons_bracket_or_brace_is_read_as_what_it_is(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    stroke = row["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    points = [p[:2] for p in stroke]
    assert recognize_stroke(points, times, learned=False).kind == PEOPLE[(name, file)]
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]
