"""Chevrons hooked at both ends (issue 25, session 37): a v whose hooks curl the way its point turns turns past two
half turns, and its last hook runs back over the end of its first lap; it is no shape drawn twice
(`closed_loops.closed_loop`, `loop_ends.turned_by_hooks`) but a polyline. People's chevrons of the `sign` set's ST5022
writers (design material) read so; a triangle drawn round twice stays a polygon.

People's strokes are read from the cache `benchmarks/public_sets.py` writes (no licence lets the project hold them);
without it those tests skip, saying so.
"""

from __future__ import annotations

import pytest
from test_open_marks import cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

GESTER = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
HOOKED = [
    "writer001/sessionC/chevron_down-1-23.json",
    "writer001/sessionC/chevron_left-1-14.json",
    "writer001/sessionC/chevron_left-1-5.json",
    "writer1010/sessionC/chevron_left-1-1.json",
]


@pytest.mark.parametrize("file", HOOKED)
def test_a_persons_chevron_hooked_at_both_ends_is_a_polyline(file: str) -> None:
    row = cached_rows("public-sets/sign.jsonl").get(GESTER + file)
    assert row is not None, f"{file} is not in the sign set"
    found = recognize_stroke([p[:2] for p in row["strokes"][0]])
    assert found.kind == "polyline"


def _side(a: tuple[float, float], b: tuple[float, float], n: int = 25) -> list[tuple[float, float]]:
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)]


def test_a_triangle_drawn_round_twice_stays_a_polygon() -> None:
    corners = [(800.0, 300.0), (950.0, 560.0), (650.0, 560.0)]
    path = [corners[0]]
    for _lap in range(2):
        for i in range(3):
            path += _side(corners[i], corners[(i + 1) % 3])
    assert recognize_stroke(path).kind == "polygon"
