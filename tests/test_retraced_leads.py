"""Issue 25, session 23: a lead the pen draws out and back along its own path before the shape (`loop_ends.
retraced_lead`) is cut only where the shape draws it again: a circle's first arc drawn twice over reads as the circle,
while a star the pen began with half a side there and back, then went on round without that side, and a line drawn to
and fro keep every stroke they have."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.loop_ends import retraced_lead
from physink_tui.scene.recognition.recognize import recognize_stroke


def _arc(start: float, sweep: float, radius: float = 100.0) -> list[tuple[float, float]]:
    n = max(2, int(abs(math.degrees(sweep)) / 3))
    return [(radius * math.cos(start + sweep * k / n), radius * math.sin(start + sweep * k / n)) for k in range(n + 1)]


def _work(points: list[tuple[float, float]]) -> tuple[np.ndarray, float]:
    pts = np.asarray(points, dtype=float)
    return sg.resample(pts, 200), sg.bbox_diagonal(pts)


def test_a_circles_first_arc_drawn_twice_over_is_cut_at_its_return() -> None:
    drawn = _arc(0.0, math.radians(60)) + _arc(math.radians(60), -math.radians(60))[1:] + _arc(0.0, 2 * math.pi)[1:]
    work, diag = _work(drawn)
    cut = retraced_lead(work, diag)
    assert cut > 0 and float(np.hypot(*(work[cut] - work[0]))) < 0.05 * diag
    assert recognize_stroke(drawn).kind == "circle"


def test_a_stars_first_side_drawn_there_and_back_is_kept() -> None:
    tips = [(100 * math.sin(math.radians(144 * k)), -100 * math.cos(math.radians(144 * k))) for k in range(5)]
    # half the first side down and back up, then round the star the other way from its top, ending where that side ends
    half = ((tips[0][0] + tips[1][0]) / 2, (tips[0][1] + tips[1][1]) / 2)
    star = [tips[0], half, tips[0]] + [tips[(-k) % 5] for k in range(1, 5)]
    work, diag = _work(star)
    assert retraced_lead(work, diag) == 0


def test_a_line_drawn_to_and_fro_is_no_lead() -> None:
    for laps in (2, 3):
        drawn = [(0.0, 0.0), (200.0, 10.0)] * laps
        work, diag = _work(drawn)
        assert retraced_lead(work, diag) == 0
