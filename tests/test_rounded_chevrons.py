"""Chevrons whose corner the hand rounded over part of each side (issue 25, session 36): people's chevrons of the
`sign` set's ST5022 writers (design material) read as polylines, and a parenthesis or an arc turning as much stays a
curve or an arc (`recognition.rounded_chevrons`).

People's strokes are read from the cache `benchmarks/public_sets.py` writes (no licence lets the project hold them);
without it those tests skip, saying so.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest
from penmodels.paren_habits import lopsided_paren
from test_open_marks import cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_open_marks import PENS

GESTER = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
CHEVRONS = [
    "writer002/sessionA/chevron_left-1-22.json",
    "writer003/sessionB/chevron_left-1-0.json",
    "writer004/sessionA/chevron_down-1-16.json",
    "writer005/sessionC/chevron_left-1-4.json",
    "writer007/sessionB/chevron_right-1-23.json",
    "writer1010/sessionA/chevron_up-1-3.json",
]


@pytest.mark.parametrize("file", CHEVRONS)
def test_a_persons_chevron_rounded_at_its_corner_is_a_polyline(file: str) -> None:
    row = cached_rows("public-sets/sign.jsonl").get(GESTER + file)
    assert row is not None, f"{file} is not in the sign set"
    points = [p[:2] for p in row["strokes"][0]]
    found = recognize_stroke(points)
    assert found.kind == "polyline"
    assert len(found.geometry.points) == 3  # two sides meeting at one corner


def _arc(turn_deg: float, n: int = 60) -> list[tuple[float, float]]:
    """An arc of radius 150 px turning ``turn_deg`` degrees, drawn evenly."""
    a0 = math.radians(90 - turn_deg / 2)
    return [(800 + 150 * math.cos(a0 + math.radians(turn_deg) * k / n),
             500 - 150 * math.sin(a0 + math.radians(turn_deg) * k / n)) for k in range(n + 1)]


@pytest.mark.parametrize("turn", [90.0, 120.0, 150.0])
def test_an_arc_turning_as_much_as_a_chevron_stays_round(turn: float) -> None:
    assert recognize_stroke(_arc(turn)).kind in ("arc", "curve")


def _rounded_v(share: float) -> list[tuple[float, float]]:
    """A v with sides 200 px long and 60 degrees apart, its corner rounded over ``share`` of each side (a quadratic
    curve from one side to the other with the corner as its control point), drawn from left to right."""
    apex, ends = (800.0, 600.0), ((700.0, 600.0 - 173.2), (900.0, 600.0 - 173.2))
    def on(end: tuple[float, float], t: float) -> tuple[float, float]:  # t of the way from the apex to the end
        return (apex[0] + t * (end[0] - apex[0]), apex[1] + t * (end[1] - apex[1]))
    left = [on(ends[0], 1 - k / 20 * (1 - share)) for k in range(20)]
    p0, p2 = on(ends[0], share), on(ends[1], share)
    bend = [((1 - u) ** 2 * p0[0] + 2 * u * (1 - u) * apex[0] + u * u * p2[0],
             (1 - u) ** 2 * p0[1] + 2 * u * (1 - u) * apex[1] + u * u * p2[1]) for u in (k / 20 for k in range(21))]
    right = [on(ends[1], share + k / 20 * (1 - share)) for k in range(1, 21)]
    return left + bend + right


@pytest.mark.parametrize("share", [0.3, 0.4])
def test_a_v_rounded_at_its_point_is_a_polyline(share: float) -> None:
    assert recognize_stroke(_rounded_v(share)).kind == "polyline"


@pytest.mark.parametrize(("pen", "seed"), [("hurried", 5), ("hurried-mouse", 15)])
def test_a_parenthesis_curling_tightly_near_one_end_is_no_chevron(pen: str, seed: int) -> None:
    """The pen models' lopsided parentheses with straight-looking sides and a tight curl 0.62-0.64 of the way along
    stay round, read with their times or without: a chevron's sides are about alike (`rounded_chevrons.SIDE_SHARE`;
    allowing 0.3-0.7 read them as chevrons)."""
    stroke = PENS[pen](lopsided_paren(seed), seed)
    points = [p[:2] for p in stroke]
    assert recognize_stroke(points, [p[2] for p in stroke]).kind in ("arc", "curve")
    assert recognize_stroke(points).kind in ("arc", "curve")
