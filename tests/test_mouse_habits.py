"""Issue 25, session 22: brackets and rectangles drawn as a hand on a mouse or a trackpad draws them read as what they
are (the held-back people who drew with a mouse and a trackpad read square brackets 89-90 %, rectangles 85.7 %). A
wrist swinging a mouse splays a bracket's arms, so its heading turns less than half a turn (120-145 degrees where a
drawn bracket turns 145-215): `round_brackets.HALF_TURN` takes it, and a spine with a brace's point in its middle is
no bracket's. The pen-model families (`tests/penmodels/mouse_habits`, `benchmarks/bench_mouse_habits.py`) are read on
the held seeds (1000-1029, read once, at the end), with and without times; each floor is the figure measured on this
branch. People's strokes are read from the public-set caches (design sources only); without them that test skips."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.mouse_habits import EXPECTED, FAMILIES
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import round_brackets
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_bracket_habits import drawn, mirrored, reading, reversed_stroke
from bench_mouse_habits import PENS
from bench_open_marks import HELD_SEEDS

HELD_FLOORS = {
    "splayed-bracket": {"careful": 58, "hurried": 58, "hurried-coarse": 58, "hurried-mouse": 54, "hurried-fast": 54,
                        "hurried-trackpad": 60, "hurried-slow-mouse": 58},
    "wrist-arc-bracket": {"careful": 60, "hurried": 54, "hurried-coarse": 56, "hurried-mouse": 60, "hurried-fast": 60,
                          "hurried-trackpad": 60, "hurried-slow-mouse": 58},
    "slow-corner-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60,
                            "hurried-fast": 60, "hurried-trackpad": 60, "hurried-slow-mouse": 60},
    "crossed-close-box": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60, "hurried-fast": 58,
                          "hurried-trackpad": 60, "hurried-slow-mouse": 60},
    "rounded-mouse-box": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 58, "hurried-fast": 54,
                          "hurried-trackpad": 60, "hurried-slow-mouse": 58},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are read as
`EXPECTED`, measured on this branch. Main 007872c read the splayed brackets 50, 38, 32, 40, 36, 48 and 42 (the rest
curves, a few arcs), the wrist-arc brackets through the fast device 58; the other rows as here. The rounded boxes
through the fast device (8-25 events) left as ellipses are octagons as much as boxes (left as found)."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_marks_drawn_with_a_mouse_or_a_trackpad_read_as_what_they_are(family: str, pen: str) -> None:
    got = [reading(drawn(family, pen, seed, FAMILIES, PENS), timed) for seed in HELD_SEEDS for timed in (True, False)]
    assert sum(k == EXPECTED[family] for k in got) >= HELD_FLOORS[family][pen], got


def test_a_splayed_bracket_reads_the_same_mirrored() -> None:
    changed = [seed for seed in HELD_SEEDS for stroke in [drawn("splayed-bracket", "hurried", seed, FAMILIES)]
               if reading(mirrored(stroke), False) != reading(stroke, False)]
    assert not changed


@pytest.mark.xfail(strict=True, reason=(
    "one held seed's hurried splayed bracket (1000-1029) turns under round_brackets.SPLAYED_TURN whichever way it is "
    "drawn, so round_brackets does not judge it; the other open-stroke rules read it a curve one way and a polyline "
    "the other (cause not found in session 22)"))
def test_a_splayed_bracket_reads_the_same_drawn_the_other_way() -> None:
    changed = [seed for seed in HELD_SEEDS for stroke in [drawn("splayed-bracket", "hurried", seed, FAMILIES)]
               if reading(reversed_stroke(stroke), False) != reading(stroke, False)]
    assert not changed


def _splayed_bracket(splay_deg: float, point: float = 0.0) -> np.ndarray:
    """A left bracket 200 tall, arms 60 long splayed ``splay_deg`` each away from square, both corners rounded off
    over 30 of them (a quadratic bend); a point ``point`` units high standing out of the spine's middle (y down, unit
    size as `recognize` judges it)."""
    t = math.radians(splay_deg)
    top_end = (60.0 * math.cos(t), -100.0 - 60.0 * math.sin(t))
    bottom_end = (60.0 * math.cos(t), 100.0 + 60.0 * math.sin(t))
    pts: list[tuple[float, float]] = []

    def run(a: tuple[float, float], b: tuple[float, float], n: int) -> None:
        pts.extend((a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n))

    def bend(a: tuple[float, float], c: tuple[float, float], b: tuple[float, float]) -> None:
        pts.extend(((1 - u) ** 2 * a[0] + 2 * u * (1 - u) * c[0] + u * u * b[0],
                    (1 - u) ** 2 * a[1] + 2 * u * (1 - u) * c[1] + u * u * b[1]) for u in np.linspace(0, 1, 12)[:-1])

    top_in = (30.0 * math.cos(t), -100.0 - 30.0 * math.sin(t))
    bottom_in = (30.0 * math.cos(t), 100.0 + 30.0 * math.sin(t))
    run(top_end, top_in, 8)
    bend(top_in, (0.0, -100.0), (0.0, -70.0))
    spine = [(point * max(0.0, 1 - abs(y) / 12.0), y) for y in np.linspace(-70.0, 70.0, 57)]
    pts.extend(spine[:-1])
    bend((0.0, 70.0), (0.0, 100.0), bottom_in)
    run(bottom_in, bottom_end, 8)
    pts.append(bottom_end)
    return np.asarray(pts) / 200.0


@pytest.mark.parametrize("splay_deg", [0.0, 10.0, 18.0])
def test_a_rounded_bracket_whose_arms_splay_is_a_bracket(splay_deg: float) -> None:
    work = sg.hooks_cut(_splayed_bracket(splay_deg), 128)
    assert round_brackets.rounded_bracket(work, sf.lobes(work)) is not None
    assert recognize_stroke((_splayed_bracket(splay_deg) * 200.0).tolist()).kind == "polyline"


def test_a_spine_with_a_brace_point_in_its_middle_is_no_bracket() -> None:
    work = sg.hooks_cut(_splayed_bracket(10.0, point=-14.0), 128)
    assert round_brackets.rounded_bracket(work, sf.lobes(work)) is None


HCIRA = "public-sets/hcira.jsonl"
PEOPLE = {
    (HCIRA, "hat359/HCIRA@69a6542:xml_collected_logs/user2/right_curly_brace03.xml"): "curve",
    (HCIRA, "klarubbio/hcira_p1@e8eb332:xml/s02/left_square_bracket08.xml"): "polyline",
}
"""(cached set, file) -> the kind a reader names: a right brace drawn with a mouse, its point small and its ends
curled off a long straight run (read as a bracket when the half turn was first widened, before the spine was asked
for no point), and a mouse bracket with rounded corners."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.split("/")[-1] for _, f in PEOPLE])
def test_a_persons_mouse_brace_or_bracket_reads_as_what_it_is(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]
