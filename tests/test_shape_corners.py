"""Issue 25, session 26: `shape_corners` tells a many-sided polygon left open by one side, its corners rounded, from a
round shape left open, by how its turning is gathered: at a few short bends between straight runs, or all along."""

from __future__ import annotations

import math

import numpy as np
import pytest

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.shape_corners import bends, corner_bends, rounded_many_sided_left_open


def _left_open_polygon(sides: int, rounded: float) -> np.ndarray:
    """A regular polygon of ``sides`` drawn round all but its last side, each inner corner swept round over
    ``rounded`` of the sides meeting there (a quadratic through the corner), densely sampled."""
    corners = [(math.cos(2 * math.pi * k / sides), math.sin(2 * math.pi * k / sides)) for k in range(sides)]
    pts: list[tuple[float, float]] = [corners[0]]
    for k in range(1, sides - 1):
        c, before, after = np.array(corners[k]), np.array(corners[k - 1]), np.array(corners[k + 1])
        a, b = c + (before - c) * rounded, c + (after - c) * rounded
        pts += [tuple((1 - u) ** 2 * a + 2 * u * (1 - u) * c + u * u * b) for u in np.linspace(0, 1, 9)]
    pts.append(corners[-1])
    return sg.resample(np.array(pts), 200)


def _arc(sweep_deg: float, lumps: float = 0.0) -> np.ndarray:
    """A circle drawn round ``sweep_deg`` degrees, its radius wandering by ``lumps`` in its third harmonic."""
    a = np.radians(np.linspace(0.0, sweep_deg, 200))
    r = 1.0 + lumps * np.cos(3 * a)
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


@pytest.mark.parametrize("sides", [6, 7, 8])
@pytest.mark.parametrize("rounded", [0.0, 0.1, 0.2])
def test_a_polygon_left_open_by_a_side_turns_at_its_corners(sides: int, rounded: float) -> None:
    """Its n - 2 inner corners each turn 360 / n degrees within a short bend (less a little where the rounding's ends
    turn by under a straight step's limit): every one is found, and the gap closes it."""
    work = _left_open_polygon(sides, rounded)
    _, _, found = bends(work)
    turns = [abs(b.degrees) for b in corner_bends(found)]
    assert len(turns) == sides - 2
    assert all(0.75 * 360 / sides <= t <= 360 / sides + 1 for t in turns)
    assert rounded_many_sided_left_open(work)


@pytest.mark.parametrize("sweep", [250.0, 290.0, 330.0])
@pytest.mark.parametrize("lumps", [0.0, 0.04])
def test_a_circle_left_open_is_no_polygon(sweep: float, lumps: float) -> None:
    """A round shape turns at every step: no short bends, no straight runs."""
    assert not rounded_many_sided_left_open(_arc(sweep, lumps))


def test_a_polygon_missing_two_sides_is_not_closed_by_its_gap() -> None:
    """Half an octagon and one side more (five sides of eight): the gap is longer than `GAP_SIDES` of a side."""
    full = _left_open_polygon(8, 0.1)
    half = full[: int(len(full) * 5 / 7)]
    assert not rounded_many_sided_left_open(half)


def test_a_circle_left_open_sampled_by_a_few_events_is_no_polygon() -> None:
    """Eight events evenly round 300 degrees: straight chords and a turn at every event, the device's corners, not the
    hand's; with the stroke's own points given, no point lies between two corners."""
    a = np.radians(np.linspace(0.0, 300.0, 8))
    drawn = np.column_stack([np.cos(a), np.sin(a)])
    work = sg.resample(drawn, 200)
    assert not rounded_many_sided_left_open(work, drawn)


def test_a_polygon_left_open_drawn_through_its_sides_keeps_its_corners() -> None:
    """The same outline as a hand draws it, points all along its sides: the corners are the hand's."""
    work = _left_open_polygon(8, 0.1)
    assert rounded_many_sided_left_open(work, work[::5])
