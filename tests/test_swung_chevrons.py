"""Chevrons with an end swung back against their corner's turn (issue 25, session 38): the hand carried on past the
chevron's end. Judged with that end cut, the point still about halfway along the whole stroke
(`rounded_chevrons.SWUNG`), people's chevrons of the `sign` set's ST5022 writers (design material) read as polylines;
a C with a curled end, and the set's `curve_*` gestures nearest to passing, stay curves.

People's strokes are read from the cache `benchmarks/public_sets.py` writes (no licence lets the project hold them);
without it those tests skip, saying so.
"""

from __future__ import annotations

import math

import pytest
from test_open_marks import cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

GESTER = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
SWUNG = [
    "writer003/sessionA/chevron_left-1-10.json",
    "writer003/sessionB/chevron_left-1-11.json",
    "writer004/sessionB/chevron_right-1-7.json",
    "writer004/sessionC/chevron_right-1-0.json",
    "writer004/sessionD/chevron_left-1-14.json",
    "writer007/sessionB/chevron_right-1-24.json",
    "writer1010/sessionC/chevron_up-1-14.json",
]
NEAREST_CURVES = [  # swung at an end too; each fails one test of the cut stroke (bow 0.129, or the turn spread)
    "writer001/sessionC/curve_rightDown-1-4.json",
    "writer1010/sessionB/curve_downRight-1-18.json",
    "writer1010/sessionC/curve_rightUp-1-1.json",
    "writer1010/sessionD/curve_rightUp-1-4.json",
    "writer1010/sessionD/curve_rightUp-1-9.json",
]


def _read(file: str) -> list[list[float]]:
    row = cached_rows("public-sets/sign.jsonl").get(GESTER + file)
    assert row is not None, f"{file} is not in the sign set"
    return [p[:2] for p in row["strokes"][0]]


@pytest.mark.parametrize("file", SWUNG)
def test_a_persons_chevron_swung_at_an_end_is_a_polyline(file: str) -> None:
    found = recognize_stroke(_read(file))
    assert found.kind == "polyline"
    assert len(found.geometry.points) == 3  # two sides meeting at one corner, the swung end left off


@pytest.mark.parametrize("file", NEAREST_CURVES)
def test_a_persons_curve_gesture_curled_at_an_end_stays_a_curve(file: str) -> None:
    assert recognize_stroke(_read(file)).kind in ("curve", "arc")


def _swung(path: list[tuple[float, float]], turn_deg: float, length: float, n: int = 12) -> list[tuple[float, float]]:
    """``path`` carried on from its end, bending ``turn_deg`` degrees against the way it turns over ``length`` px."""
    turned = sum(math.atan2((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]),
                            (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]))
                 for a, b, c in zip(path, path[1:], path[2:], strict=False))
    way = -1.0 if turned > 0 else 1.0
    heading = math.atan2(path[-1][1] - path[-2][1], path[-1][0] - path[-2][0])
    x, y = path[-1]
    out = list(path)
    for _ in range(n):
        heading += way * math.radians(turn_deg) / n
        x, y = x + length / n * math.cos(heading), y + length / n * math.sin(heading)
        out.append((x, y))
    return out


def _rounded_v(share: float = 0.4) -> list[tuple[float, float]]:
    """A v with sides 200 px long and 60 degrees apart, its corner rounded over ``share`` of each side."""
    apex, ends = (800.0, 600.0), ((700.0, 600.0 - 173.2), (900.0, 600.0 - 173.2))
    def on(end: tuple[float, float], t: float) -> tuple[float, float]:
        return (apex[0] + t * (end[0] - apex[0]), apex[1] + t * (end[1] - apex[1]))
    p0, p2 = on(ends[0], share), on(ends[1], share)
    return ([on(ends[0], 1 - k / 20 * (1 - share)) for k in range(20)]
            + [((1 - u) ** 2 * p0[0] + 2 * u * (1 - u) * apex[0] + u * u * p2[0],
                (1 - u) ** 2 * p0[1] + 2 * u * (1 - u) * apex[1] + u * u * p2[1]) for u in (k / 20 for k in range(21))]
            + [on(ends[1], share + k / 20 * (1 - share)) for k in range(1, 21)])


@pytest.mark.parametrize("turn", [90.0, 120.0])
def test_a_rounded_v_swung_off_at_its_end_is_a_polyline(turn: float) -> None:
    """A v rounded over 40 % of each side, its last 60 px swung back 90-120 degrees, read as a curve before."""
    assert recognize_stroke(_swung(_rounded_v(), turn, 60.0)).kind == "polyline"
    assert recognize_stroke(_swung(_rounded_v()[::-1], turn, 60.0)).kind == "polyline"


def _arc(turn_deg: float, n: int = 60) -> list[tuple[float, float]]:
    a0 = math.radians(90 - turn_deg / 2)
    return [(800 + 150 * math.cos(a0 + math.radians(turn_deg) * k / n),
             500 - 150 * math.sin(a0 + math.radians(turn_deg) * k / n)) for k in range(n + 1)]


@pytest.mark.parametrize("turn", [90.0, 120.0, 150.0])
@pytest.mark.parametrize("swing", [50.0, 90.0, 120.0])
def test_an_arc_curled_back_at_its_end_is_no_chevron(turn: float, swing: float) -> None:
    """A C turning as much as a chevron, its end swung back: its sides bow, and its turn is spread along it."""
    assert recognize_stroke(_swung(_arc(turn), swing, 60.0)).kind in ("arc", "curve")
