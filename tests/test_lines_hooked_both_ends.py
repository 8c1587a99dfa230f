"""A short line hooked where the pen lands and where it lifts reads as a line; a tiny square bracket, whose short arms
stand square off its spine to one side, stays a bracket (`recognition.lines.unhooked`'s cut at both ends,
`lines._hooked_both`, `lines.HOOK_BACK_DEG`; issue 25, session 26)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from physink_tui.scene.recognition import lines
from physink_tui.scene.recognition.recognize import recognize_stroke

Point = tuple[float, float]


def _hook(end: Point, heading: Point, size: float, turn_deg: float) -> list[Point]:
    """A hook ``size`` px long landing at ``end`` of a line running along ``heading`` (unit, from the end into the
    line), its tip turned ``turn_deg`` from the heading (positive: to the left), curling into the line; tip first."""
    a = math.radians(turn_deg)
    away = (heading[0] * math.cos(a) - heading[1] * math.sin(a), heading[0] * math.sin(a) + heading[1] * math.cos(a))
    tip = (end[0] + away[0] * size, end[1] + away[1] * size)
    ctrl = (end[0] - heading[0] * size / 2, end[1] - heading[1] * size / 2)
    n = max(4, int(size))
    return [((1 - u) ** 2 * tip[0] + 2 * u * (1 - u) * ctrl[0] + u * u * end[0],
             (1 - u) ** 2 * tip[1] + 2 * u * (1 - u) * ctrl[1] + u * u * end[1]) for u in (k / n for k in range(n))]


def hooked_line(length: float, start: tuple[float, float], end: tuple[float, float]) -> list[Point]:
    """A horizontal line ``length`` px long, hooked where the pen lands and where it lifts: each hook (size px, turn
    in degrees; positive turns put both tips on the same side, a C; opposite signs an S)."""
    keys = [(float(x), 0.0) for x in np.linspace(0.0, length, int(length) + 1)]
    landing = _hook(keys[0], (1.0, 0.0), *start)
    lifting = _hook(keys[-1], (-1.0, 0.0), end[0], -end[1])[::-1]
    return landing + keys + lifting


def square_bracket(spine: float, arm: float, radius: float = 0.0) -> list[Point]:
    """A left square bracket: a vertical spine ``spine`` px long, arms ``arm`` px standing square off it to the right,
    each corner rounded over ``radius`` px (a quarter circle)."""
    def corner(cx: float, cy: float, a_from: float, a_to: float) -> list[Point]:
        return [(cx + radius * math.cos(a), cy + radius * math.sin(a))
                for a in np.linspace(a_from, a_to, 8)[1:-1]] if radius > 0 else []
    top = [(float(x), 0.0) for x in np.linspace(arm, radius, int(arm - radius) + 1)]
    side = [(0.0, float(y)) for y in np.linspace(radius, spine - radius, int(spine - 2 * radius) + 1)]
    bottom = [(float(x), spine) for x in np.linspace(radius, arm, int(arm - radius) + 1)]
    return (top + corner(radius, radius, -math.pi / 2, -math.pi) + side
            + corner(radius, spine - radius, math.pi, math.pi / 2) + bottom)


@pytest.mark.parametrize(("length", "start", "end"), [
    (32.0, (6.0, 130.0), (6.0, 130.0)),  # both tips to one side, a C: turned back past square
    (40.0, (7.0, 120.0), (7.0, 120.0)),
    (32.0, (6.0, 100.0), (6.0, -100.0)),  # to opposite sides, an S: no bracket stands so
    (55.0, (8.0, 140.0), (3.0, 110.0)),
])
def test_a_short_line_hooked_at_both_ends_reads_as_a_line(length: float, start: tuple[float, float],
                                                          end: tuple[float, float]) -> None:
    """Main 7111cdc read each of these a polyline (one end cut at a time, the other hook taken for a corner)."""
    pts = hooked_line(length, start, end)
    assert recognize_stroke(pts).kind == "line"
    assert recognize_stroke(pts, learned=False).kind == "line"


@pytest.mark.parametrize(("spine", "arm", "radius"), [
    (30.0, 7.0, 0.0), (25.0, 6.0, 0.0), (40.0, 8.0, 0.0), (30.0, 7.0, 2.0), (22.0, 7.0, 2.0),
])
def test_a_tiny_square_bracket_whose_arms_a_hook_cut_would_take_stays_a_bracket(spine: float, arm: float,
                                                                                radius: float) -> None:
    """Arms within a hook's reach (`lines.HOOK_REACH` noise widths), standing square to one side: a bracket."""
    pts = square_bracket(spine, arm, radius)
    assert recognize_stroke(pts).kind == "polyline"
    assert recognize_stroke(pts, learned=False).kind == "polyline"


def test_hooks_cut_at_both_ends_only_where_no_bracket_stands_so() -> None:
    """`lines.unhooked` leaves a piece cut at both ends of a C hooked back past square, and of an S, but of a tiny
    square bracket only pieces cut at one end (its other arm left on them)."""
    def both_cut(pts: list[Point]) -> bool:
        raw = np.asarray(pts, dtype=float)
        return any(len(p) < len(raw) and not np.allclose(p[0], raw[0]) and not np.allclose(p[-1], raw[-1])
                   for p in lines.unhooked(raw, 1.0))
    assert both_cut(hooked_line(32.0, (6.0, 130.0), (6.0, 130.0)))
    assert both_cut(hooked_line(32.0, (6.0, 110.0), (6.0, -110.0)))
    assert not both_cut(square_bracket(30.0, 7.0))
    assert not both_cut(square_bracket(30.0, 7.0, 2.0))
