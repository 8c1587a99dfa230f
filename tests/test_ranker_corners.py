"""The ranker's rounded-corner features (`ranker_corners`, issue 25, session 40): a bracket or a check drawn with a
slightly rounded corner turns within a short span between straight sides, an arc turns all along; the same from
either end, every time."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import ranker, ranker_corners
from physink_tui.scene.recognition import stroke_geometry as sg


def _rounded_bracket(radius: float) -> np.ndarray:
    """A [ of two sharp-ish corners each rounded by ``radius`` (of a side 1 tall, arms 0.4 long), 200 points."""
    pts = [(0.4, 0.0), (radius, 0.0)]
    for cx, cy, a0 in ((radius, radius, -math.pi / 2), (radius, 1 - radius, math.pi)):
        pts += [(cx + radius * math.cos(a0 - t), cy + radius * math.sin(a0 - t))
                for t in np.linspace(0, math.pi / 2, 12)]
    pts += [(0.4, 1.0)]
    return sg.resample(np.array(pts), 200)


def _arc(turn_deg: float) -> np.ndarray:
    t = np.linspace(0, math.radians(turn_deg), 200)
    return np.c_[np.cos(t), np.sin(t)]


def _features(points: np.ndarray) -> dict[str, float]:
    phi = ranker.features(points.tolist(), None)
    return {f: float(phi[ranker.FEATURES.index(f)]) for f in ("turn_spread", "peak_turn", "outside_turn", "side_bow")}


def test_a_rounded_corner_is_told_from_an_even_bend() -> None:
    bracket, arc = _features(_rounded_bracket(0.08)), _features(_arc(180.0))
    assert bracket["turn_spread"] < 0.35 < 0.8 < arc["turn_spread"]
    assert bracket["peak_turn"] > 0.35 > 0.2 > arc["peak_turn"]
    assert bracket["outside_turn"] < 0.3 < 0.6 < arc["outside_turn"]
    assert bracket["side_bow"] < 0.05 < 0.3 < arc["side_bow"]


def test_the_features_are_the_same_from_either_end_and_every_time() -> None:
    for pts in (_rounded_bracket(0.05), _rounded_bracket(0.15), _arc(120.0), _arc(250.0)):
        ahead, back = _features(pts), _features(pts[::-1])
        assert ahead == _features(pts)
        for name, value in ahead.items():
            assert math.isclose(value, back[name], abs_tol=1e-9), name


def test_a_straight_or_empty_turning_is_no_corner() -> None:
    work = np.c_[np.linspace(0, 1, 64), np.zeros(64)]
    assert ranker_corners.corner_features(work, sg.turning(work)) == (1.0, 0.0, 1.0, 0.0)
