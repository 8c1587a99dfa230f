"""Interpretation of recognised strokes in context (thesis 3.2.2): bodies, erasing, joints, springs, ropes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from shapely.geometry import MultiPoint

from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Rope, Scene, Spring
from physink_tui.scene.interpretation import interpret as it
from physink_tui.scene.interpretation.interpret import interpret
from physink_tui.scene.recognition.primitives import Box, Circle, Curve, Helix, Line, Polygon, Recognition, XSymbol


def rec(kind: str, geometry) -> Recognition:
    return Recognition(kind, 0.9, geometry)


def ring(cx: float, cy: float, r: float, n: int = 24) -> list[tuple[float, float]]:
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n)) for k in range(n + 1)]


def add_box(scene: Scene, x0: float, y0: float, x1: float, y1: float) -> tuple[Scene, str]:
    box = Box(((x0 + x1) / 2, (y0 + y1) / 2), x1 - x0, y1 - y0, 0.0)
    result = interpret(scene, rec("box", box), [[*box.corners, box.corners[0]]])
    assert result.action == "body"
    return result.scene, result.created[0]


def weld_to_background(scene: Scene, body_id: str, at: tuple[float, float]) -> Scene:
    x = XSymbol(at, Line((at[0] - 5, at[1] - 5), (at[0] + 5, at[1] + 5)),
                Line((at[0] - 5, at[1] + 5), (at[0] + 5, at[1] - 5)))
    result = interpret(scene, rec("x", x), [[x.first.start, x.first.end], [x.second.start, x.second.end]])
    assert result.action == "weld" and result.scene.components[result.created[0]].a == body_id
    return result.scene


def test_shapes_become_bodies_with_their_materials() -> None:
    scene, box = add_box(Scene(), 0, 0, 100, 20)
    result = interpret(scene, rec("circle", Circle((300, 300), 20)), [ring(300, 300, 20)])
    ball = result.scene.components[result.created[0]]
    assert isinstance(ball, Body) and ball.shape == "circle" and ball.radius == 20 and ball.position == (300, 300)
    assert ball.material == MATERIALS["round"] and result.scene.components[box].material == MATERIALS["box"]
    tri = Polygon(((500, 500), (600, 500), (550, 420)))
    result = interpret(result.scene, rec("polygon", tri), [list(tri.points)])
    body = result.scene.components[result.created[0]]
    assert body.shape == "polygon" and body.material == MATERIALS["freeform"]
    assert sorted(result.scene.components) == ["b1", "b2", "b3"]


def test_a_self_crossing_polygon_is_repaired_and_the_user_told() -> None:
    bowtie = Polygon(((0, 0), (100, 100), (100, 0), (0, 100)))
    result = interpret(Scene(), rec("polygon", bowtie), [list(bowtie.points)])
    assert result.action == "body" and "crossed itself" in result.message


def test_a_line_through_a_body_erases_it_and_what_holds_it() -> None:
    scene, box = add_box(Scene(), 100, 100, 200, 140)
    scene = weld_to_background(scene, box, (150, 120))
    cut = Line((150, 60), (150, 180))
    result = interpret(scene, rec("line", cut), [[cut.start, cut.end]])
    assert result.action == "erase" and set(result.removed) == {box, "j1"}
    assert not result.scene.components


def test_a_line_elsewhere_is_a_body_a_ramp() -> None:
    ramp = Line((0, 0), (300, 100))
    result = interpret(Scene(), rec("line", ramp), [[ramp.start, ramp.end]])
    assert result.action == "body" and result.scene.components["b1"].shape == "polyline"


@pytest.mark.parametrize("kind", ["circle", "curve"])
def test_a_small_circle_or_curve_in_a_body_pins_it(kind: str) -> None:
    scene, plank = add_box(Scene(), 0, 100, 400, 120)
    geometry = Circle((200, 110), 6) if kind == "circle" else Curve(((194, 110), (200, 104), (206, 110), (200, 116)))
    result = interpret(scene, rec(kind, geometry), [ring(200, 110, 6)])
    assert result.action == "pivot"
    joint = result.scene.components[result.created[0]]
    assert isinstance(joint, Joint) and (joint.a, joint.b) == (plank, BACKGROUND)


def test_a_pin_through_two_bodies_joins_them() -> None:
    scene, lower = add_box(Scene(), 0, 0, 200, 200)
    scene, upper = add_box(scene, 50, 50, 150, 150)
    result = interpret(scene, rec("circle", Circle((100, 100), 5)), [ring(100, 100, 5)])
    joint = result.scene.components[result.created[0]]
    assert (joint.kind, joint.a, joint.b) == ("pivot", upper, lower)


def test_a_big_circle_over_a_body_is_a_body_not_a_joint() -> None:
    scene, _ = add_box(Scene(), 0, 0, 100, 100)
    result = interpret(scene, rec("circle", Circle((50, 50), 45)), [ring(50, 50, 45)])
    assert result.action == "body"


def test_an_x_outside_every_body_becomes_bodies_and_says_so() -> None:
    x = XSymbol((500, 500), Line((495, 495), (505, 505)), Line((495, 505), (505, 495)))
    result = interpret(Scene(), rec("x", x), [[x.first.start, x.first.end], [x.second.start, x.second.end]])
    assert result.action == "body" and len(result.created) == 2 and "outside every body" in result.message


def test_a_helix_from_a_fixed_body_is_a_spring_on_its_axis() -> None:
    scene, wall = add_box(Scene(), 0, 0, 20, 200)
    scene = weld_to_background(scene, wall, (10, 100))
    scene, peg = add_box(scene, 150, 90, 190, 110)
    coil = [(10 + 150 * k / 100, 100 + 10 * math.sin(k / 3)) for k in range(101)]
    result = interpret(scene, rec("helix", Helix((15, 100), (155, 100), 10, 5)), [coil])
    spring = result.scene.components[result.created[0]]
    assert isinstance(spring, Spring)
    assert (spring.a, spring.b, spring.axis, spring.k) == (wall, peg, "horizontal", 20.0)
    assert spring.rest_length == pytest.approx(150)


def test_a_helix_without_a_fixed_end_is_kept_as_a_rope_and_the_user_told() -> None:
    coil = [(10 + k, 100 + 10 * math.sin(k / 3)) for k in range(100)]
    result = interpret(Scene(), rec("helix", Helix((10, 100), (110, 100), 10, 5)), [coil])
    assert result.action == "rope" and "fixed body" in result.message


def test_a_curve_is_a_rope_holding_on_to_what_its_ends_touch() -> None:
    scene, peg = add_box(Scene(), 0, 0, 40, 40)
    path = [(20, 20), (80, 90), (160, 120)]
    result = interpret(scene, rec("curve", Curve(((20, 20), (60, 60), (120, 110), (160, 120)))), [path])
    rope = result.scene.components[result.created[0]]
    assert isinstance(rope, Rope) and (rope.start_body, rope.end_body) == (peg, None)
    # a ball drawn later round the free end catches it
    later = interpret(result.scene, rec("circle", Circle((160, 120), 15)), [ring(160, 120, 15)])
    assert later.scene.components[rope.id].end_body == later.created[0]
    assert "rope ends attached" in later.message


def test_nothing_recognised_changes_nothing_and_says_why() -> None:
    scene, _ = add_box(Scene(), 0, 0, 10, 10)
    result = interpret(scene, Recognition(None, 0.0, None, (), "too short to recognise"), [[(0, 0)]])
    assert result.scene == scene and result.action == "none" and "too short" in result.message


def test_ids_are_never_reused_after_erasing() -> None:
    scene, first = add_box(Scene(), 0, 0, 10, 10)
    cut = Line((5, -10), (5, 20))
    scene = interpret(scene, rec("line", cut), [[cut.start, cut.end]]).scene
    scene, second = add_box(scene, 0, 0, 10, 10)
    assert (first, second) == ("b1", "b2")


@pytest.mark.parametrize("n", [1, 2, 3, 41, 300])
def test_a_strokes_centre_and_size_are_those_of_shapelys_multipoint_to_the_bit(n: int) -> None:
    """`_inside` builds the stroke's MultiPoint once from an array (session 43, issue 25): the centre, size and bounds
    a joint is judged by are those of ``MultiPoint(points)`` built point by point, to the last bit."""
    rng = np.random.default_rng(43 + n)
    points = [(float(x), float(y)) for x, y in rng.normal(500.0, 137.0, size=(n, 2))]
    slow = MultiPoint(points)
    fast = it._multipoint(points)
    assert fast.wkb == slow.wkb
    assert fast.bounds == slow.bounds
    assert it._centre(points) == (slow.centroid.x, slow.centroid.y)
    minx, miny, maxx, maxy = slow.bounds
    assert it._size(points) == math.hypot(maxx - minx, maxy - miny)
