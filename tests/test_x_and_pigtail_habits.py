"""Issue 25, session 22: one-stroke x's and pigtails drawn with the habits of people we have not seen (held back, the
HCIRA people read x's 92 % and pigtails 94 %) read as what they are, by every pen, on the held seeds (1000-1029, read
once, at the end; each floor is the figure measured on this branch). A stroke that goes round more than once is taken
once round from either end alike (`closed_loops._once_round`): a pigtail, or a person's circle drawn on past its start
and out, reads the same drawn the other way. People's strokes are read from the public-set caches (design sources
only); without them those tests skip."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from penmodels import pigtail_habits, x_habits
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_bracket_habits import PENS, drawn, reading, reversed_stroke
from bench_open_marks import HELD_SEEDS

ALL_PENS = {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60, "hurried-fast": 60}
X_HELD_FLOORS = {
    "looped-turn-x": ALL_PENS, "long-tail-x": ALL_PENS, "hooked-x": ALL_PENS, "unequal-x": ALL_PENS,
    "rounded-turn-x": {**ALL_PENS, "hurried-fast": 58},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are polylines,
measured on this branch (main 007872c read them the same: these habits were read right already)."""
PIGTAIL_HELD_FLOORS = {
    "round-loop-pigtail": {"careful": 54, "hurried": 52, "hurried-coarse": 52, "hurried-mouse": 52,
                           "hurried-fast": 54},
    "narrow-loop-pigtail": ALL_PENS, "long-tail-pigtail": ALL_PENS,
    "loop-first-pigtail": {"careful": 56, "hurried": 56, "hurried-coarse": 56, "hurried-mouse": 56, "hurried-fast": 60},
}
"""family -> pen -> of the 60 readings on the held seeds, how many are curves, measured on this branch; main 007872c
read the round loops 50, 50, 52, 52, 54 (circles and ellipses where once round from the start came back to it), the
other rows the same. The round loops still read round (6-8 of 60) have tails short enough both ways that they are a
circle drawn past its start and on, as people draw circles too (hcira shriyansnidhish/s05 circle06, 07). Pigtails
drawn loop first (session 27, hcira klarubbio/s02 pigtail04, s07 pigtail03: tails of 1.6-3 of the loop's half-length)
284 of 300 held (main 9f69154: 122, their loops read round); the 16 left are ellipses where the fitted loop's ellipse
is long enough that the tail stays within 1.2 of its half-length (`closed_loops.tail_runs_off`)."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in X_HELD_FLOORS for p in PENS])
def test_an_x_drawn_with_unseen_habits_reads_as_an_x(family: str, pen: str) -> None:
    got = [reading(drawn(family, pen, seed, x_habits.FAMILIES), timed) for seed in HELD_SEEDS
           for timed in (True, False)]
    assert sum(k == x_habits.EXPECTED[family] for k in got) >= X_HELD_FLOORS[family][pen], got


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in PIGTAIL_HELD_FLOORS for p in PENS])
def test_a_pigtail_drawn_with_unseen_habits_reads_as_a_pigtail(family: str, pen: str) -> None:
    got = [reading(drawn(family, pen, seed, pigtail_habits.FAMILIES), timed) for seed in HELD_SEEDS
           for timed in (True, False)]
    assert sum(k == pigtail_habits.EXPECTED[family] for k in got) >= PIGTAIL_HELD_FLOORS[family][pen], got


CROSSING_TAILS = ("round-loop-pigtail", "narrow-loop-pigtail", "long-tail-pigtail")
"""The pigtail families whose two tails cross (session 22's); the fourth, drawn loop first, has its own test below."""


@pytest.mark.parametrize("pen", list(PENS))
def test_a_pigtail_reads_the_same_drawn_the_other_way(pen: str) -> None:
    """Main 007872c read 42 of the 450 held seeds' pigtails (every pen) otherwise drawn the other way: a loop with
    crossing tails, once round from its start, came back to the start when that tail was short (a circle), and not
    from the other end (a curve)."""
    changed = [(family, seed) for family in CROSSING_TAILS for seed in HELD_SEEDS
               for stroke in [drawn(family, pen, seed, pigtail_habits.FAMILIES)]
               if reading(reversed_stroke(stroke), False) != reading(stroke, False)]
    assert not changed


def test_a_pigtail_drawn_loop_first_mostly_reads_the_same_drawn_the_other_way() -> None:
    """Of the 150 held loop-first pigtails (every pen, read without times) main 9f69154 read 5 otherwise drawn the
    other way, this branch 2 (a loop-first pigtail whose loop fits its ellipse loosely: closed once round from the
    loop's end, left open from the tail's, and an open round reading there is an ellipse left open; tuning seed 8 of
    the hurried hand). Both directions must be read right as often as the floors above say; this bounds the rest."""
    changed = [(pen, seed) for pen in PENS for seed in HELD_SEEDS
               for stroke in [drawn("loop-first-pigtail", pen, seed, pigtail_habits.FAMILIES)]
               if reading(reversed_stroke(stroke), False) != reading(stroke, False)]
    assert len(changed) <= 2, changed


PEOPLE = {
    ("student-sets/itt.jsonl", "ITT-25/assignment-06-gesture-recognition-uniUbungsAccount@1b61d95:datasets/"
                               "own_recorded_gestures/pigtail10.xml"): ("curve",),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/circle07.xml"): ("circle", "ellipse"),
}
"""(cached set, file) -> the kinds a reader may name: a pigtail whose big loop sits between tails crossing at 31
degrees (an ellipse at main 007872c as drawn, a curve drawn the other way) and a circle drawn on past its start and out
without crossing itself (an ellipse as drawn, a curve drawn the other way: the guard that keeps a stroke that does not
cross itself once round from whichever end comes back)."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.split("/")[-1] for _, f in PEOPLE])
def test_a_persons_loop_reads_as_what_it_is_drawn_either_way(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    back = None if times is None else [times[-1] - t for t in reversed(times)]
    assert recognize_stroke(points, times).kind in PEOPLE[(name, file)]
    assert recognize_stroke(list(reversed(points)), back).kind in PEOPLE[(name, file)]


ROUND_SIDE_X_HELD_FLOORS = {"careful": 50, "hurried": 34, "hurried-coarse": 30, "hurried-mouse": 28, "hurried-fast": 6}
"""pen -> of the 60 readings of `x_habits.round_side_x` on the held seeds, how many are polylines: main 3b9e40f's
figures (session 30, wt-alpha; no rule was added: a floor, not a goal). An x whose side is one round loop is the
geometry of a pigtail drawn as a ribbon (`STRAIGHT_ARM_PIGTAIL_HELD_FLOORS`), which people draw too (`RIBBONS`):
a rule reading one more of these as a polyline must not read fewer ribbons as curves."""
STRAIGHT_ARM_PIGTAIL_HELD_FLOORS = {"careful": 30, "hurried": 44, "hurried-coarse": 50, "hurried-mouse": 46,
                                    "hurried-fast": 56}
"""pen -> of the 60 readings of `pigtail_habits.straight_arm_pigtail` on the held seeds, how many are curves: main
3b9e40f's figures (session 30, wt-alpha)."""


@pytest.mark.parametrize("pen", list(PENS))
def test_an_x_with_a_round_side_reads_as_an_x_as_often_as_before(pen: str) -> None:
    got = [reading(drawn("round-side-x", pen, seed, x_habits.FAMILIES), timed) for seed in HELD_SEEDS
           for timed in (True, False)]
    assert sum(k == x_habits.EXPECTED["round-side-x"] for k in got) >= ROUND_SIDE_X_HELD_FLOORS[pen], got


@pytest.mark.parametrize("pen", list(PENS))
def test_a_pigtail_drawn_as_a_ribbon_reads_as_a_pigtail_as_often_as_before(pen: str) -> None:
    got = [reading(drawn("straight-arm-pigtail", pen, seed, pigtail_habits.FAMILIES), timed) for seed in HELD_SEEDS
           for timed in (True, False)]
    assert sum(k == pigtail_habits.EXPECTED["straight-arm-pigtail"] for k in got) >= \
        STRAIGHT_ARM_PIGTAIL_HELD_FLOORS[pen], got


RIBBONS = {
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user1/pigtail05.xml"): ("curve",),
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user3/pigtail10.xml"): ("curve",),
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user6/pigtail04.xml"): ("curve",),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/pigtail05.xml"): ("curve",),
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/x04.xml"): ("polyline",),
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/x09.xml"): ("polyline",),
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/x10.xml"): ("polyline",),
}
"""(cached set, file) -> the kinds a reader may name (session 30, wt-alpha): pigtails drawn as ribbons, two straight
arms crossing near their middles joined by a loop (hat359 user1 pigtail05 and user3 pigtail10 are, turned a quarter
turn, the x's with a round side that jd4386 User05 drew, which read as curves), and three of User05's x's whose
round side keeps a corner, read as x's. A rule that reads the round-sided x's must leave these as they are."""


@pytest.mark.parametrize(("name", "file"), list(RIBBONS), ids=["/".join(f.split("/")[-2:]) for _, f in RIBBONS])
def test_a_ribbon_stays_a_pigtail_and_a_cornered_x_an_x_drawn_either_way(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    back = None if times is None else [times[-1] - t for t in reversed(times)]
    assert recognize_stroke(points, times).kind in RIBBONS[(name, file)]
    assert recognize_stroke(list(reversed(points)), back).kind in RIBBONS[(name, file)]
