"""The pymunk world: bodies, materials, joints, springs, ropes, queries, stepping, freezing and dragging, contacts."""

from __future__ import annotations

import itertools
import math

import pymunk
import pytest
import shapely

from physink_tui.errors import SceneError
from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Material, Rope, Scene, Spring
from physink_tui.scene.physics.build import SPRING_UNITS
from physink_tui.scene.physics.world import GRAVITY, ContactRecord, World

G = GRAVITY[1]


def box(body_id: str, cx: float, cy: float, w: float, h: float, material: Material = MATERIALS["box"],
        angle: float = 0.0) -> Body:
    outline = ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))
    return Body(body_id, "box", outline, 0.0, (cx, cy), angle, material)


def ball(body_id: str, cx: float, cy: float, r: float = 25.0, material: Material = MATERIALS["round"]) -> Body:
    return Body(body_id, "circle", (), r, (cx, cy), 0.0, material)


def polygon(body_id: str, cx: float, cy: float, outline, material: Material = MATERIALS["freeform"]) -> Body:
    return Body(body_id, "polygon", tuple(outline), 0.0, (cx, cy), 0.0, material)


def ellipse(body_id: str, cx: float, cy: float, a: float, b: float) -> Body:
    outline = tuple((a * math.cos(2 * math.pi * i / 32), b * math.sin(2 * math.pi * i / 32)) for i in range(32))
    return Body(body_id, "ellipse", outline, 0.0, (cx, cy), 0.0, MATERIALS["round"])


def weld(joint_id: str, body_id: str, at, to: str = BACKGROUND) -> Joint:
    return Joint(joint_id, "weld", body_id, to, at)


def scene(*components) -> Scene:
    s = Scene()
    for c in components:
        s = s.add(c)
    return s


# An L, centroid-relative: area 20*10 + 10*20 = 400.
L_OUTLINE = ((-8.0, -13.0), (12.0, -13.0), (12.0, -3.0), (2.0, -3.0), (2.0, 17.0), (-8.0, 17.0))


def floor_scene(floor: Body, drop_y: float = 300.0) -> Scene:
    return scene(floor, ball("b2", 500.0, drop_y), weld("j1", floor.id, floor.position))


# -- bodies and materials ----------------------------------------------------------------------------------------


def test_ball_on_a_fixed_box_bounces_back_to_its_drop_height() -> None:
    """Restitution max(0.5, 1.0) = 1.0: a box platform returns the ball's energy (thesis footnote 3)."""
    world = World.from_scene(floor_scene(box("b1", 500.0, 800.0, 400.0, 40.0)))
    surface = 800.0 - 20.0 - 25.0  # where the ball's centre is when it touches the box
    ys = []
    for _ in range(360):
        world.step()
        ys.append(world.pose("b2")[1])
    lowest = max(range(len(ys)), key=ys.__getitem__)
    assert ys[lowest] > surface - 1.0  # it reached the box ...
    assert ys[lowest] - surface < 11.0  # ... sinking into it less than one step's travel at impact speed
    apex = min(ys[lowest:])
    assert apex < 300.0 + 0.1 * (surface - 300.0)  # back within 10% of the 455-unit drop


def test_ball_dropped_on_a_fixed_freeform_platform_comes_to_rest_on_it() -> None:
    """Restitution max(0.5, 0.2) = 0.5: bounces die out and the ball rests on the surface, not in it."""
    slab = polygon("b1", 500.0, 800.0, ((-200.0, -20.0), (200.0, -20.0), (200.0, 20.0), (-200.0, 20.0)))
    world = World.from_scene(floor_scene(slab))
    world.step(1200)
    surface = 800.0 - 20.0 - 25.0
    ys = []
    for _ in range(120):
        world.step()
        ys.append(world.pose("b2")[1])
    assert all(b <= a + 1e-6 for a, b in itertools.pairwise(ys)) or max(ys) - min(ys) < 0.01
    assert abs(ys[-1] - surface) < 1.0
    assert abs(world.velocity("b2")[1]) < 1.0


def test_non_convex_polygon_is_triangulated_and_weighs_its_area_times_density() -> None:
    heavy = Material(2.5, 0.2, 0.0)
    world = World.from_scene(scene(polygon("b1", 300.0, 300.0, L_OUTLINE, heavy)))
    shapes = world.pymunk_parts.shapes["b1"]
    assert len(shapes) == 4
    assert all(isinstance(s, pymunk.Poly) and len(s.get_vertices()) == 3 for s in shapes)
    assert sum(s.area for s in shapes) == pytest.approx(400.0, rel=1e-9)
    assert world.pymunk_parts.bodies["b1"].mass == pytest.approx(400.0 * 2.5, rel=1e-9)
    union = shapely.union_all([shapely.Polygon(s.get_vertices()) for s in shapes])
    assert union.symmetric_difference(shapely.Polygon(L_OUTLINE)).area < 1e-6


def test_body_kinds_become_the_right_shapes() -> None:
    ramp = Body("b4", "polyline", ((-100.0, -50.0), (0.0, 0.0), (100.0, 20.0)), 0.0, (500.0, 500.0), 0.0,
                MATERIALS["freeform"])
    world = World.from_scene(scene(box("b1", 100, 100, 60, 20), ball("b2", 300, 100), ellipse("b3", 500, 100, 40, 20),
                                   ramp, polygon("b5", 700, 100, ((-10, -10), (10, -10), (0, 10)))))
    assert [type(s).__name__ for s in world.pymunk_parts.shapes["b1"]] == ["Poly"]
    assert world.pymunk_parts.bodies["b1"].mass == pytest.approx(1200.0)
    assert [type(s).__name__ for s in world.pymunk_parts.shapes["b2"]] == ["Circle"]
    assert world.pymunk_parts.bodies["b2"].mass == pytest.approx(math.pi * 25**2)
    (oval,) = world.pymunk_parts.shapes["b3"]
    assert len(oval.get_vertices()) == 32
    segments = world.pymunk_parts.shapes["b4"]
    assert [type(s).__name__ for s in segments] == ["Segment", "Segment"]
    length = math.dist((-100, -50), (0, 0)) + math.dist((0, 0), (100, 20))
    r = segments[0].radius
    assert 0 < r <= 3.0
    assert world.pymunk_parts.bodies["b4"].mass == pytest.approx(2 * r * length, rel=0.05)  # a thin strip
    assert len(world.pymunk_parts.shapes["b5"]) == 1  # a convex freeform stays one polygon


def test_materials_set_the_shapes_and_contacts_take_max_restitution_and_mean_friction() -> None:
    soft, hard = Material(1.0, 0.3, 0.4), Material(1.0, 0.6, 0.8)
    ramp = polygon("b1", 500.0, 800.0, ((-200.0, -20.0), (200.0, -20.0), (200.0, 20.0), (-200.0, 20.0)), soft)
    s = scene(ramp, weld("j1", "b1", (500.0, 800.0)), ball("b2", 500.0, 735.0, material=hard))  # 20 above it
    world = World.from_scene(s)
    (shape,) = world.pymunk_parts.shapes["b2"]
    assert world.pymunk_parts.surfaces.of(shape) == (0.6, 0.8)

    def arbiters() -> list[tuple[float, float]]:
        seen: list[tuple[float, float]] = []
        body = world.pymunk_parts.bodies["b2"]
        body.each_arbiter(lambda arbiter: seen.append((arbiter.restitution, arbiter.friction)))
        return seen

    while not world.take_contacts():
        world.step()
    assert arbiters() == [(pytest.approx(0.6), pytest.approx(0.6))]  # pymunk alone would give 0.18 and 0.32
    world.step(240)  # bounced, settled: a lasting contact does not bounce again
    assert arbiters() == [(0.0, pytest.approx(0.6))]


def test_slow_contacts_do_not_bounce() -> None:
    """Below the bounce threshold even a fully elastic box absorbs the impact (Box2D's velocity threshold)."""
    world = World.from_scene(floor_scene(box("b1", 500.0, 800.0, 400.0, 40.0), drop_y=754.0))
    world.step(240)
    assert world.pose("b2")[1] == pytest.approx(755.0, abs=0.5)
    assert abs(world.velocity("b2")[1]) < 1.0


def test_friction_is_the_mean_so_a_box_grips_a_frictionless_slope() -> None:
    """Box (1.0) on freeform (0.0): mean 0.5 > tan 20° holds a box on a 20-degree slope.

    With pymunk's product (0) it would slide g sin 20° t² / 2 ~ 600 units in these two seconds; it creeps a few units
    (a box's restitution of 1.0 makes the resting contact chatter).
    """
    slope = math.radians(20)
    ramp = Body("b1", "polygon", ((-300.0, -10.0), (300.0, -10.0), (300.0, 10.0), (-300.0, 10.0)), 0.0,
                (500.0, 600.0), slope, MATERIALS["freeform"])
    # A box resting on the ramp's top face, rotated with it.
    nx, ny = math.sin(slope), -math.cos(slope)  # the ramp's outward normal (up the canvas)
    block = box("b2", 500.0 + 30.0 * nx, 600.0 + 30.0 * ny, 40.0, 40.0, angle=slope)
    world = World.from_scene(scene(ramp, weld("j1", "b1", (500.0, 600.0)), block))
    world.step(240)
    x, y, _ = world.pose("b2")
    assert math.dist((x, y), block.position) < 10.0


# -- queries -----------------------------------------------------------------------------------------------------


def test_body_at_picks_the_topmost_of_overlapping_bodies_and_none_on_empty_canvas() -> None:
    pts = tuple((100.0 + 10.0 * i, 600.0) for i in range(11))
    world = World.from_scene(scene(box("b1", 300, 300, 200, 100), ball("b2", 350, 300, 40), Rope("r1", pts)))
    assert world.body_at((350.0, 300.0)) == "b2"
    assert world.bodies_at((350.0, 300.0)) == ["b2", "b1"]
    assert world.body_at((220.0, 300.0)) == "b1"
    assert world.body_at((900.0, 900.0)) is None
    assert world.body_at((150.0, 600.0)) is None  # ropes are not bodies
    assert world.bodies_at((900.0, 900.0)) == []


def test_pose_and_velocity_follow_the_body() -> None:
    world = World.from_scene(scene(ball("b1", 100.0, 100.0)), gravity=(0.0, 0.0))
    world.set_velocity("b1", (120.0, -60.0), 2.0)
    world.step(120)
    x, y, angle = world.pose("b1")
    assert (x, y) == (pytest.approx(220.0), pytest.approx(40.0))
    assert angle == pytest.approx(2.0)
    assert world.velocity("b1") == (pytest.approx(120.0), pytest.approx(-60.0), pytest.approx(2.0))
    with pytest.raises(SceneError, match="'b9'"):
        world.pose("b9")


# -- joints, springs, ropes --------------------------------------------------------------------------------------


def test_pivot_to_the_background_lets_a_plank_turn_about_the_pin_but_not_fall() -> None:
    plank = box("b1", 500.0, 300.0, 300.0, 20.0)
    pin = (400.0, 300.0)  # 100 units left of the centre: the plank swings down about it
    world = World.from_scene(scene(plank, Joint("j1", "pivot", "b1", BACKGROUND, pin)))
    body = world.pymunk_parts.bodies["b1"]
    local_pin = body.world_to_local(pin)
    angles = []
    for _ in range(240):
        world.step()
        assert math.dist(body.local_to_world(local_pin), pin) < 1.0
        x, y, angle = world.pose("b1")
        assert math.dist((x, y), pin) == pytest.approx(100.0, abs=1.0)
        angles.append(angle)
    assert max(angles) > 1.0  # it swung well past 57 degrees


def test_weld_to_the_background_keeps_a_body_still() -> None:
    world = World.from_scene(scene(box("b1", 500.0, 300.0, 300.0, 20.0), weld("j1", "b1", (420.0, 300.0))))
    world.step(600)
    assert world.pose("b1") == (500.0, 300.0, 0.0)
    assert world.velocity("b1") == (0.0, 0.0, 0.0)
    assert not world.is_dynamic("b1")  # documented: a body welded to the background is static


def test_weld_between_bodies_carries_one_with_the_other() -> None:
    """A ball welded to a pinned plank turns with it rigidly, at the same distance and relative angle."""
    s = scene(box("b1", 500.0, 300.0, 300.0, 20.0), ball("b2", 620.0, 300.0, 15.0),
              Joint("j1", "pivot", "b1", BACKGROUND, (500.0, 300.0)), weld("j2", "b2", (620.0, 300.0), "b1"))
    world = World.from_scene(s)
    world.step(120)
    (x1, y1, a1), (x2, y2, a2) = world.pose("b1"), world.pose("b2")
    assert a1 > 0.3  # the ball's weight tipped the plank
    assert math.dist((x1, y1), (x2, y2)) == pytest.approx(120.0, abs=1.0)
    assert a2 - a1 == pytest.approx(0.0, abs=0.02)


def test_vertical_spring_settles_at_rest_length_plus_mg_over_k_and_never_moves_sideways() -> None:
    k = 2.0  # thesis units (N/m): SPRING_UNITS times stiffer in canvas units
    ceiling = box("b1", 500.0, 100.0, 200.0, 20.0)
    weight = box("b2", 500.0, 400.0, 40.0, 40.0)
    # Hooked near the weight's top-left corner, so gravity also pulls it sideways and twists it about the hook.
    spring = Spring("s1", "b1", "b2", (485.0, 110.0), (485.0, 380.0), "vertical", 270.0, k)
    world = World.from_scene(scene(ceiling, weight, weld("j1", "b1", (500.0, 100.0)), spring))
    m = world.pymunk_parts.bodies["b2"].mass
    world.set_velocity("b2", (0.0, 400.0))  # plucked
    for _ in range(3000):
        world.step()
        x, _, angle = world.pose("b2")
        assert x == pytest.approx(500.0, abs=0.5)
        assert angle == pytest.approx(0.0, abs=0.01)  # prismatic, like the thesis's Box2D joint
    length = world.pose("b2")[1] - 20.0 - 110.0
    assert length == pytest.approx(270.0 + m * G / (k * SPRING_UNITS), abs=1.0)


def test_horizontal_spring_holds_its_free_end_on_the_axis_against_gravity() -> None:
    wall = box("b1", 100.0, 500.0, 20.0, 200.0)
    puck = box("b2", 400.0, 500.0, 40.0, 40.0)
    spring = Spring("s1", "b2", "b1", (380.0, 500.0), (110.0, 500.0), "horizontal", 200.0, 5.0)
    world = World.from_scene(scene(wall, puck, weld("j1", "b1", (100.0, 500.0)), spring))
    xs = []
    for _ in range(600):
        world.step()
        x, y, _ = world.pose("b2")
        assert y == pytest.approx(500.0, abs=0.5)
        xs.append(x)
    assert min(xs) < 360.0  # stretched 70 past its rest length, it pulled the puck towards the wall


def test_rope_from_a_fixed_peg_holds_a_hanging_ball_within_its_length() -> None:
    peg = box("b1", 500.0, 200.0, 30.0, 30.0)
    # A slack rope, drawn as a sagging curve of 21 points from the peg's centre to the ball's.
    pts = tuple((500.0 + 10.0 * i, 200.0 + 60.0 * math.sin(math.pi * i / 20)) for i in range(21))
    length = sum(math.dist(p, q) for p, q in itertools.pairwise(pts))
    world = World.from_scene(scene(peg, ball("b2", 700.0, 200.0), weld("j1", "b1", (500.0, 200.0)),
                                   Rope("r1", pts, "b1", "b2")))
    assert len(world.pymunk_parts.links["r1"]) == 20
    rope_mass = sum(link.mass for link in world.pymunk_parts.links["r1"])
    assert rope_mass < 0.05 * world.pymunk_parts.bodies["b2"].mass  # light next to what it holds
    lowest = 0.0
    for _ in range(1200):
        world.step()
        x, y, _ = world.pose("b2")
        assert math.dist((x, y), (500.0, 200.0)) < 1.01 * length  # the solver lets it stretch under 1%
        lowest = max(lowest, y)
    assert lowest > 200.0 + 0.95 * length  # it swung through the bottom, taut
    links, shapes = world.pymunk_parts.links["r1"], world.pymunk_parts.shapes["r1"]
    for (l1, s1), (l2, s2) in zip(zip(links, shapes, strict=True), zip(links[1:], shapes[1:], strict=True),
                                  strict=False):
        assert math.dist(l1.local_to_world(s1.b), l2.local_to_world(s2.a)) < 1.0  # the chain holds together


def test_rope_is_resampled_into_8_to_40_links() -> None:
    short = World.from_scene(scene(Rope("r1", ((0.0, 0.0), (40.0, 0.0)))))
    long = World.from_scene(scene(Rope("r1", ((0.0, 0.0), (500.0, 0.0), (500.0, 900.0)))))
    assert len(short.pymunk_parts.links["r1"]) == 8
    assert len(long.pymunk_parts.links["r1"]) == 40


def test_bad_components_raise_scene_errors_naming_them() -> None:
    with pytest.raises(SceneError, match="'blob'"):
        World.from_scene(scene(Body("b1", "blob", (), 0.0, (0.0, 0.0), 0.0, MATERIALS["box"])))
    with pytest.raises(SceneError, match="'b7'"):
        World.from_scene(scene(ball("b1", 0.0, 0.0), Joint("j1", "pivot", "b1", "b7", (0.0, 0.0))))
    with pytest.raises(SceneError, match="'diagonal'"):
        World.from_scene(scene(ball("b1", 0.0, 0.0), Spring("s1", "b1", BACKGROUND, (0, 0), (0, 50), "diagonal", 50)))
    with pytest.raises(SceneError, match="zero area"):
        World.from_scene(scene(polygon("b1", 0.0, 0.0, ((0, 0), (10, 0), (20, 0)))))


# -- stepping, contacts, the scene -------------------------------------------------------------------------------


def machine() -> Scene:
    """A bit of everything, for determinism and round trips."""
    pts = tuple((620.0 + 8.0 * i, 200.0 + 3.0 * i) for i in range(16))
    return scene(
        box("b1", 500.0, 900.0, 900.0, 40.0), weld("j1", "b1", (500.0, 900.0)),
        box("b2", 400.0, 500.0, 300.0, 20.0, angle=0.2), Joint("j2", "pivot", "b2", BACKGROUND, (380.0, 500.0)),
        ball("b3", 300.0, 300.0), ball("b4", 740.0, 245.0, 15.0),
        polygon("b5", 750.0, 600.0, L_OUTLINE), ellipse("b6", 200.0, 700.0, 40.0, 25.0),
        box("b7", 620.0, 200.0, 30.0, 30.0), weld("j3", "b7", (620.0, 200.0)),
        Rope("r1", pts, "b7", "b4"),
        box("b8", 850.0, 300.0, 60.0, 60.0),
        Spring("s1", "b1", "b8", (850.0, 880.0), (850.0, 330.0), "vertical", 500.0, 30_000.0),
    )


def snapshot(world: World) -> list[tuple[float, ...]]:
    bodies = [world.pose(i) + world.velocity(i) for i in world.body_ids()]
    links = [(*link.position, link.angle) for link in world.pymunk_parts.links["r1"]]
    return bodies + links


def test_the_same_scene_stepped_twice_gives_bit_identical_poses_and_contacts() -> None:
    runs = []
    for _ in range(2):
        world = World.from_scene(machine())
        contacts = []
        for _ in range(6):
            world.step(100)
            contacts += world.take_contacts()
        runs.append((snapshot(world), contacts))
    assert runs[0][1]  # things did touch
    assert runs[0] == runs[1]


def test_contact_records_name_the_ball_and_the_box_when_they_meet() -> None:
    world = World.from_scene(floor_scene(box("b1", 500.0, 800.0, 400.0, 40.0)))
    assert world.take_contacts() == []
    first = None
    while first is None:
        world.step()
        for record in world.take_contacts():
            first = record
            break
    assert isinstance(first, ContactRecord)
    assert {first.a_id, first.b_id} == {"b1", "b2"}
    assert first.step == world.steps
    assert first.point[1] == pytest.approx(780.0, abs=12.0)  # on the box's top face
    ny = first.normal[1] if first.a_id == "b2" else -first.normal[1]
    assert ny == pytest.approx(1.0)  # from the ball down into the box
    assert world.take_contacts() == []  # drained; resting contact does not begin again
    with pytest.raises(AttributeError):
        first.step = 0  # frozen


def test_to_scene_round_trip() -> None:
    original = machine()
    world = World.from_scene(original)
    assert world.to_scene(original) == original  # nothing moved: nothing changes, bit for bit
    world.step(200)
    moved = world.to_scene(original)
    assert moved.next_id == original.next_id
    assert moved.components.keys() == original.components.keys()
    for body_id in world.body_ids():
        b = moved.components[body_id]
        assert (*b.position, b.angle) == world.pose(body_id)
    # The pin stays where the plank still turns about; the rope's points are its link ends now.
    assert moved.components["j2"].anchor == pytest.approx((380.0, 500.0), abs=0.5)
    rope = moved.components["r1"]
    assert rope.points[-1] == pytest.approx(world.pose("b4")[:2], abs=0.5)
    again = World.from_scene(moved)
    for body_id in world.body_ids():
        assert again.pose(body_id) == pytest.approx(world.pose(body_id), rel=1e-12)
    assert again.to_scene(moved) == moved


def test_a_world_can_run_without_gravity() -> None:
    world = World.from_scene(scene(ball("b1", 100.0, 100.0)))
    world.gravity = (0.0, 0.0)
    world.step(100)
    assert world.pose("b1") == (100.0, 100.0, 0.0)
    assert world.gravity == (0.0, 0.0)


# -- editing: freezing and dragging ------------------------------------------------------------------------------


def test_freeze_all_except_and_drag_move_one_body_while_the_others_stay_put() -> None:
    world = World.from_scene(machine())
    world.step(30)  # everything is in motion
    world.freeze_all_except("b3")
    others = {i: world.pose(i) for i in world.body_ids() if i != "b3"}
    links = [tuple(link.position) for link in world.pymunk_parts.links["r1"]]
    start = world.pose("b3")
    for _ in range(240):
        world.drag("b3", (150.0, 150.0), grab_point=start[:2])
        world.step()
    assert math.dist(world.pose("b3")[:2], (150.0, 150.0)) < 2.0
    assert {i: world.pose(i) for i in others} == others
    assert [tuple(link.position) for link in world.pymunk_parts.links["r1"]] == links
    assert all(not math.isnan(v) for i in world.body_ids() for v in world.pose(i))
    world.release()
    world.unfreeze()
    assert world.is_dynamic("b2") and world.is_dynamic("b5") and not world.is_dynamic("b1")
    world.step(60)
    assert world.pose("b5") != others["b5"]  # it falls again


def test_a_dragged_body_stops_flush_against_a_frozen_one() -> None:
    s = scene(box("b1", 500.0, 500.0, 100.0, 100.0), ball("b2", 300.0, 500.0, 20.0))
    world = World.from_scene(s, gravity=(0.0, 0.0))
    world.freeze_all_except("b2")
    for _ in range(240):
        world.drag("b2", (500.0, 500.0))  # into the box's middle
        world.step()
        assert world.pose("b2")[0] < 450.0 - 20.0 + 5.0  # pressed against the box's left face, hardly into it
    world.release()
    world.step(30)
    assert world.pose("b2")[0] < 450.0 - 20.0 + 0.5  # let go, no overlap is left
    assert world.pose("b1") == (500.0, 500.0, 0.0)


def test_a_body_dragged_into_a_platform_under_gravity_ends_flush_on_it() -> None:
    """Thesis 3.2.4: the ball placed on the platform overlaps it; physics leaves it resting on top, flush."""
    slab = polygon("b1", 500.0, 600.0, ((-150.0, -20.0), (150.0, -20.0), (150.0, 20.0), (-150.0, 20.0)))
    world = World.from_scene(scene(slab, ball("b2", 500.0, 300.0)))
    world.freeze_all_except("b2")
    for _ in range(240):
        world.drag("b2", (500.0, 590.0))
        world.step()
    world.release()
    world.step(600)
    x, y, _ = world.pose("b2")
    assert y == pytest.approx(600.0 - 20.0 - 25.0, abs=1.0)
    assert x == pytest.approx(500.0, abs=1.0)


def test_dragging_a_fixed_body_moves_it_and_release_fixes_it_where_it_is() -> None:
    world = World.from_scene(scene(box("b1", 500.0, 500.0, 200.0, 20.0), weld("j1", "b1", (500.0, 500.0))))
    world.freeze_all_except("b1")
    for _ in range(240):
        world.drag("b1", (600.0, 400.0), rotate=False)
        world.step()
    world.release()
    world.unfreeze()
    x, y, angle = world.pose("b1")
    assert math.dist((x, y), (600.0, 400.0)) < 2.0
    assert angle == pytest.approx(0.0, abs=0.01)
    assert not world.is_dynamic("b1")
    assert world.body_at((680.0, 400.0)) == "b1"
    world.step(120)
    assert world.pose("b1") == (x, y, angle)
    assert world.to_scene(scene(box("b1", 500.0, 500.0, 200.0, 20.0))).components["b1"].position == (x, y)


def test_dragging_a_different_body_releases_the_first() -> None:
    world = World.from_scene(scene(ball("b1", 100.0, 100.0), ball("b2", 300.0, 100.0)), gravity=(0.0, 0.0))
    world.drag("b1", (100.0, 200.0))
    world.step(60)
    world.drag("b2", (300.0, 200.0))
    world.step(120)
    assert len(world.pymunk_parts.space.bodies) == 4  # background, two balls, one control body
    assert len(world.pymunk_parts.space.constraints) == 1
    world.release()
    assert len(world.pymunk_parts.space.bodies) == 3
    assert len(world.pymunk_parts.space.constraints) == 0


def test_a_frozen_body_can_be_dragged_and_thaws_with_the_others() -> None:
    world = World.from_scene(scene(ball("b1", 100.0, 100.0), ball("b2", 300.0, 100.0)))
    world.freeze_all_except("b1")
    world.drag("b2", (300.0, 50.0))
    world.step(120)
    world.release()
    assert not world.is_dynamic("b2")  # frozen again where it was put
    y = world.pose("b2")[1]
    assert y == pytest.approx(50.0, abs=5.0)
    world.step(10)
    assert world.pose("b2")[1] == y
    world.unfreeze()
    assert world.is_dynamic("b2")
    world.step(10)
    assert world.pose("b2")[1] > y


# -- the questions a simulation asks (it never touches the pymunk space) -----------------------------------------


def test_the_world_answers_half_size_damping_sleep_and_the_contact_between_two_bodies() -> None:
    world = World.from_scene(scene(box("floor", 500.0, 600.0, 800.0, 40.0), weld("j1", "floor", (500.0, 600.0)),
                                   ball("b2", 500.0, 555.0), ball("b3", 200.0, 100.0)))
    assert world.half_size("floor") == pytest.approx(20.0)  # its thinnest side is 40 units
    assert world.half_size("b2") == pytest.approx(25.0)
    assert world.half_size(BACKGROUND) == math.inf  # no shapes
    world.damping = 0.25
    assert world.damping == 0.25
    world.step(60)  # the ball drawn 5 units above the floor comes to rest on it
    record = world.contact_between("b2", "floor", world.steps)
    assert record is not None and (record.a_id, record.b_id, record.step) == ("b2", "floor", world.steps)
    assert record.normal[1] == pytest.approx(1.0, abs=1e-6)  # from the ball down into the floor
    assert world.contact_between("b3", "floor", world.steps) is None  # b3 is still falling, far above
    world.hold_until_touched({"b3"})
    world.step()
    assert world.is_asleep("b2") and not world.is_asleep("b3")
    before = world.pose("b2")
    world.step(30)
    assert world.pose("b2") == before  # asleep: gravity does not move it
