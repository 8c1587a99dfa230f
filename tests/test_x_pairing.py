"""Could a stroke be half an X, and do two strokes make one: hand-drawn arms bow, hook and cross off-centre."""

from __future__ import annotations

import math

import pytest
from hand_x import hand_x

from physink_tui.scene.interpretation.x_pairing import pair_x, x_arm
from physink_tui.scene.recognition.recognize import recognize_stroke


def test_hand_drawn_xs_pair_whatever_the_recogniser_calls_their_arms() -> None:
    kinds = set()
    for seed in range(60):
        first, second = hand_x(seed, (500.0, 500.0), (25.0, 45.0, 90.0)[seed % 3])
        kinds |= {recognize_stroke(first).kind, recognize_stroke(second).kind}
        x = pair_x(first, second)
        assert x is not None and x.kind == "x", seed
        assert math.dist(x.geometry.center, (500.0, 500.0)) < 0.4 * (25.0, 45.0, 90.0)[seed % 3]
    assert kinds - {"line"}, "the set should include arms the recogniser does not call lines"


def test_a_bowed_hooked_stroke_is_an_arm_and_a_caret_circle_or_zigzag_is_not() -> None:
    assert x_arm([(0, 0), (5, 0.6), (10, 0), (9, 2)]) is not None
    assert x_arm([(0, 0), (5, 5), (10, 0)]) is None
    assert x_arm([(10 * math.cos(a / 10), 10 * math.sin(a / 10)) for a in range(63)]) is None
    assert x_arm([(k, 3 * (k % 2)) for k in range(12)]) is None
    assert x_arm([(0, 0), (0, 0)]) is None


def test_an_arm_longer_than_the_limit_is_not_held_as_half_an_x() -> None:
    assert x_arm([(0, 0), (100, 0)], max_length=150) is not None
    assert x_arm([(0, 0), (200, 0)], max_length=150) is None


@pytest.mark.parametrize(("first", "second"), [
    ([(10, 0), (10, 20)], [(0, 0), (20, 0)]),     # a T: one crosses the other at its end
    ([(0, 0), (20, 0)], [(20, 0), (20, 20)]),     # an L
    ([(0, 0), (20, 20)], [(30, 0), (50, 20)]),    # apart
    ([(0, 0), (20, 20)], [(0, 3), (20, 23)]),     # side by side
    ([(0, 0), (20, 20)], [(0, 8), (20, 12)]),     # crossing at a shallow angle
])
def test_strokes_that_do_not_cross_near_their_middles_at_an_angle_make_no_x(first, second) -> None:
    assert pair_x(first, second) is None
