"""`stroke_geometry.line_meet`, the one line-line intersection the recogniser's rules share."""

from __future__ import annotations

import math

import numpy as np
import pytest

from physink_tui.scene.recognition import stroke_geometry as sg


def _meet(p: tuple[float, float], r: tuple[float, float], q: tuple[float, float], s: tuple[float, float],
          **kw: float) -> tuple[np.ndarray, float, float] | None:
    return sg.line_meet(np.array(p), np.array(r), np.array(q), np.array(s), **kw)


def test_crossing_segments_meet_inside_both() -> None:
    met = _meet((0.0, 0.0), (4.0, 4.0), (0.0, 4.0), (4.0, -4.0))
    assert met is not None
    point, t, u = met
    assert np.allclose(point, [2.0, 2.0]) and t == pytest.approx(0.5) and u == pytest.approx(0.5)


def test_parallel_lines_do_not_meet() -> None:
    assert _meet((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (3.0, 0.0)) is None
    assert _meet((0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (-5.0, -5.0)) is None  # the same line, drawn back
    assert _meet((0.0, 0.0), (0.0, 0.0), (0.0, 1.0), (1.0, 0.0)) is None  # a direction of no length


def test_the_tolerance_is_the_sine_of_the_angle_at_any_scale() -> None:
    angle = 1e-6
    for scale in (1e-3, 1.0, 1e4):
        r, s = (scale, 0.0), (scale * math.cos(angle), scale * math.sin(angle))
        assert _meet((0.0, 0.0), r, (0.0, scale), s) is not None
        assert _meet((0.0, 0.0), r, (0.0, scale), s, min_sine=1e-5) is None
    assert _meet((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1e-12), min_sine=0.0) is not None


def test_segments_touching_at_an_end_meet_at_parameters_zero_and_one() -> None:
    met = _meet((0.0, 0.0), (2.0, 0.0), (2.0, 3.0), (0.0, -3.0))  # the second ends on the first's end
    assert met is not None
    point, t, u = met
    assert np.array_equal(point, [2.0, 0.0]) and t == 1.0 and u == 1.0
    met = _meet((1.0, 1.0), (1.0, 2.0), (1.0, 1.0), (-3.0, 1.0))  # both start at one point
    assert met is not None and np.array_equal(met[0], [1.0, 1.0]) and met[1:] == (0.0, 0.0)


def test_lines_meeting_far_outside_their_segments_give_parameters_beyond_zero_to_one() -> None:
    met = _meet((0.0, 0.0), (1.0, 0.0), (10.0, 5.0), (0.0, 1.0))  # x = 10 on the first, y = 0 on the second
    assert met is not None
    point, t, u = met
    assert np.allclose(point, [10.0, 0.0]) and t == pytest.approx(10.0) and u == pytest.approx(-5.0)
    assert np.allclose(np.array([10.0, 5.0]) + u * np.array([0.0, 1.0]), point)  # u locates it on the second line


def test_the_meeting_point_is_where_each_parameter_puts_it_on_its_line() -> None:
    rng = np.random.default_rng(7)
    for _ in range(200):
        p, r, q, s = rng.normal(size=(4, 2))
        met = sg.line_meet(p, r, q, s)
        assert met is not None
        point, t, u = met
        assert np.allclose(point, p + t * r) and np.allclose(point, q + u * s, atol=1e-6 * (1 + abs(u)))
