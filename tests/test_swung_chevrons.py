"""Chevrons with an end swung back against their corner's turn, and the curves they must not take (issue 25, session
38, wt-chevrons3): a C curled back at its end, and the `sign` set's ST5022 writers' `curve_*` gestures curled at an
end that come nearest to a chevron once that end is cut, stay curves. A rule reading such chevrons (judged with the
swung end cut, their point about halfway along the whole stroke) gained 7 of these writers' chevrons and took none
of these curves, but read two of the pen models' held small parentheses drawn with a hurried mouse as polylines, and
was not shipped (branch `wt-chevrons3-rule`, docs/BENCHMARKS.md); these guards hold what any later rule must keep.

People's strokes are read from the cache `benchmarks/public_sets.py` writes (no licence lets the project hold them);
without it those tests skip, saying so.
"""

from __future__ import annotations

import math

import pytest
from test_open_marks import cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

GESTER = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
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


def _arc(turn_deg: float, n: int = 60) -> list[tuple[float, float]]:
    a0 = math.radians(90 - turn_deg / 2)
    return [(800 + 150 * math.cos(a0 + math.radians(turn_deg) * k / n),
             500 - 150 * math.sin(a0 + math.radians(turn_deg) * k / n)) for k in range(n + 1)]


@pytest.mark.parametrize("turn", [90.0, 120.0, 150.0])
@pytest.mark.parametrize("swing", [50.0, 90.0, 120.0])
def test_an_arc_curled_back_at_its_end_is_no_chevron(turn: float, swing: float) -> None:
    """A C turning as much as a chevron, its end swung back: its sides bow, and its turn is spread along it."""
    assert recognize_stroke(_swung(_arc(turn), swing, 60.0)).kind in ("arc", "curve")
