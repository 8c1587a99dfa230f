"""SIMULATE's first step: seeding (thesis 3.4.3) on the thesis journals, and headless rollouts (settle, record,
stop, explode, fork)."""

from __future__ import annotations

import math
from functools import cache

import pytest

from physink_tui.errors import SimulationError
from physink_tui.formats.journal.reader import read_journal
from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Scene, Spring, material_class
from physink_tui.scene.physics.build import SPRING_UNITS, body_area
from physink_tui.scene.physics.world import GRAVITY, World
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters, apply
from physink_tui.sim.rollout import Stop, rollout, rollout_from, settled_state
from physink_tui.sim.seeding import first_contact, seed, start_movements

JOURNALS = ("egg_cracker", "bouncing_hits_a", "golf_ball_helper", "cup_dispenser")
START_BODY = {"egg_cracker": "b2", "bouncing_hits_a": "b1", "golf_ball_helper": "b2", "cup_dispenser": "b2"}
CANVAS = (1600.0, 1000.0)


@cache
def demonstrated(name: str) -> Session:
    journal = read_journal(f"tests/journals/{name}.physink.jsonl")
    return replay(Session.from_header(journal.header), journal.entries)


def square(w: float, h: float) -> tuple[tuple[float, float], ...]:
    return ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))


def dropped_ball(*, platform: bool = True) -> Scene:
    """A ball (b1) above a low-bounce platform (b2) welded to the background."""
    scene = Scene().add(Body("b1", "circle", (), 25.0, (800.0, 300.0), 0.0, MATERIALS["round"], "ball"))
    if platform:
        scene = scene.add(Body("b2", "box", square(600, 40), 0.0, (800.0, 700.0), 0.0, MATERIALS["freeform"]))
        scene = scene.add(Joint("j1", "weld", "b2", BACKGROUND, (800.0, 700.0)))
    return scene


def ball_parameters(velocity: tuple[float, float] = (0.0, 0.0)) -> Parameters:
    return Parameters({"b1": BodyParameters(math.pi * 25.0**2, 1.0)}, {}, {"b1": velocity})


# -- seeding ------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", JOURNALS)
def test_seed_masses_frictions_and_springs(name: str) -> None:
    s = demonstrated(name)
    params = seed(s.scene, s.timeline, s.canvas)
    movable = {b.id for b in s.scene.bodies() if not s.scene.is_fixed(b.id)}
    assert set(params.bodies) == movable
    for body in s.scene.bodies():
        if body.id in movable:
            p = params.bodies[body.id]
            assert p.mass == pytest.approx(body_area(body) * 1.0)
            if body.shape == "circle":
                assert p.mass == pytest.approx(math.pi * body.radius**2)
            assert p.friction == (0.0 if material_class(body.shape) == "freeform" else 1.0)
    springs = [c for c in s.scene.components.values() if isinstance(c, Spring)]
    assert set(params.springs) == {c.id for c in springs}
    for spring in springs:
        assert params.springs[spring.id].k == 20.0
        assert params.springs[spring.id].rest_length == spring.rest_length


@pytest.mark.parametrize("name", JOURNALS)
def test_seed_start_velocity_reaches_the_first_contact(name: str) -> None:
    s = demonstrated(name)
    params = seed(s.scene, s.timeline, s.canvas)
    assert params.start_bodies == (START_BODY[name],)
    ((movement, body),) = start_movements(s.scene, s.timeline)
    contact = first_contact(s.timeline, movement)
    assert contact is not None and body.id in contact.components
    goal = movement.trajectory[-1]
    vx, vy = params.velocities[body.id]
    dx = goal.x - body.position[0]
    assert vx * dx > 0  # towards the destination
    if any(isinstance(c, Spring) and body.id in (c.a, c.b) for c in s.scene.components.values()):
        assert vy == 0.0  # slides along its horizontal spring
        return
    # the ballistic flight from where it was drawn passes through where its first contact happened
    gx, gy = GRAVITY
    t = dx / vx
    x, y = body.position[0] + vx * t + gx * t * t / 2, body.position[1] + vy * t + gy * t * t / 2
    assert math.hypot(x - goal.x, y - goal.y) < 1.0


def test_apply_writes_density_friction_and_springs() -> None:
    s = demonstrated("golf_ball_helper")
    params = seed(s.scene, s.timeline, s.canvas)
    heavier = Parameters({**params.bodies, "b6": BodyParameters(params.bodies["b6"].mass * 3, 0.25)},
                         params.springs, params.velocities)
    scene = apply(s.scene, heavier)
    assert scene.components["b6"].material.density == pytest.approx(3.0)
    assert scene.components["b6"].material.friction == 0.25
    assert scene.components["b6"].material.restitution == s.scene.components["b6"].material.restitution
    assert scene.components["s1"].k == 20.0
    with pytest.raises(SimulationError, match="mass of 'b6'"):
        apply(s.scene, Parameters({"b6": BodyParameters(math.nan, 1.0)}, {}, {}))
    with pytest.raises(SimulationError, match="'b99'"):
        apply(s.scene, Parameters({"b99": BodyParameters(1.0, 1.0)}, {}, {}))


# -- rollouts ------------------------------------------------------------------------------------------------------

def test_rollout_is_deterministic() -> None:
    s = demonstrated("egg_cracker")
    params = seed(s.scene, s.timeline, s.canvas)
    a = rollout(s.scene, s.canvas, params, max_seconds=6.0)
    b = rollout(s.scene, s.canvas, params, max_seconds=6.0)
    assert a == b
    assert a.timeline.events


@pytest.mark.parametrize("name", JOURNALS)
def test_rollout_settles_before_the_start(name: str) -> None:
    """Bodies drawn resting on others (the egg on its paddles) settle unrecorded: the first movement recorded is a
    start-moved body's, caused by the start."""
    s = demonstrated(name)
    params = seed(s.scene, s.timeline, s.canvas)
    result = rollout(s.scene, s.canvas, params, max_seconds=3.0)
    movements = sorted((ev for ev in result.timeline.events if ev.type == "movement"), key=lambda ev: ev.t0)
    assert movements[0].components[0] in params.start_bodies
    (start,) = [ev.id for ev in result.timeline.events if ev.type == "start"]
    assert movements[0].causes == (start,)
    first_step = [ev.components[0] for ev in movements if ev.t0 == movements[0].t0]
    assert set(first_step) <= set(params.start_bodies)  # nothing drawn resting starts with them


def test_settling_holds_what_the_drawing_does_not_hold_up_and_the_start_body() -> None:
    s = demonstrated("egg_cracker")
    params = seed(s.scene, s.timeline, s.canvas)
    settled = settled_state(s.scene, s.canvas, params)
    state = settled.state
    ball = s.scene.components["b2"]
    assert state.bodies["b2"][:2] == pytest.approx(ball.position, abs=1e-6)
    assert all(math.hypot(state.bodies[b.id].vx, state.bodies[b.id].vy) < 5.0 for b in s.scene.bodies())
    # the knife (on its rope) and the egg fall under gravity as drawn: they are held where drawn, and said so
    held = dict(settled.held)
    assert held["b5"] > 100 and held["b6"] > 100
    for body in ("b5", "b6"):
        assert state.bodies[body][:2] == pytest.approx(s.scene.components[body].position, abs=1e-6)
    result = rollout(s.scene, s.canvas, params, max_seconds=1.0)
    assert any(flag.startswith("the knife would not stay where it is drawn") for flag in result.flagged)


def test_a_held_body_stays_put_until_touched_then_falls() -> None:
    """A crate drawn in mid-air (nothing under it) waits where it is drawn until the ball hits it."""
    scene = dropped_ball().add(Body("b3", "box", square(60, 60), 0.0, (1000.0, 250.0), 0.0, MATERIALS["box"],
                                    "crate"))
    params = Parameters({"b1": BodyParameters(math.pi * 25.0**2, 1.0), "b3": BodyParameters(3600.0, 1.0)}, {},
                        {"b1": (500.0, -450.0)})
    settled = settled_state(scene, CANVAS, params)
    assert dict(settled.held).keys() == {"b3"}
    result = rollout(scene, CANVAS, params, max_seconds=3.0)
    crate = [ev for ev in result.timeline.events if ev.type == "movement" and ev.components[0] == "b3"]
    hit = next(ev for ev in result.timeline.events if ev.type == "contact" and set(ev.components) == {"b1", "b3"})
    assert crate and crate[0].t0 == pytest.approx(hit.t0) and crate[0].causes == (hit.id,)
    assert crate[0].trajectory[-1].y > 400  # and then it falls
    alone = rollout(scene, CANVAS, params.with_velocities({"b1": (-300.0, 0.0)}), max_seconds=3.0)
    assert not [ev for ev in alone.timeline.events if "b3" in ev.components]  # never touched: never moves


def trampoline(*, crate: bool = False, k: float = 20.0, rest: float = 155.0) -> tuple[Scene, Parameters]:
    """The ball (b1) left of a trampoline (b3: a box on a vertical spring, drawn at its natural length, from a
    welded base b2 under it); with ``crate``, a crate (b4) drawn 100 units above the trampoline."""
    scene = dropped_ball(platform=False)
    scene = scene.add(Body("b2", "box", square(200, 60), 0.0, (800.0, 760.0), 0.0, MATERIALS["box"], "base"))
    scene = scene.add(Joint("j1", "weld", "b2", BACKGROUND, (800.0, 760.0)))
    scene = scene.add(Body("b3", "box", square(300, 30), 0.0, (800.0, 560.0), 0.0, MATERIALS["box"], "trampoline"))
    scene = scene.add(Spring("s1", "b2", "b3", (800.0, 730.0), (800.0, 575.0), "vertical", 155.0, k))
    bodies = {"b1": BodyParameters(math.pi * 25.0**2, 1.0), "b3": BodyParameters(300.0 * 30.0, 1.0)}
    if crate:
        scene = scene.add(Body("b4", "box", square(60, 60), 0.0, (800.0, 415.0), 0.0, MATERIALS["box"], "crate"))
        bodies["b4"] = BodyParameters(3600.0, 1.0)
    return scene, Parameters(bodies, {"s1": SpringParameters(k, rest)}, {"b1": (0.0, 0.0)})


@pytest.mark.parametrize(("k", "rest"), [(4.0, 155.0), (20.0, 155.0), (80.0, 155.0), (20.0, 232.5), (20.0, 100.0)])
def test_a_spring_taking_its_load_is_held_but_not_flagged(k: float, rest: float) -> None:
    """A spring is drawn at its natural length (thesis 4.2), so the trampoline on it sinks under gravity while the
    scene settles: held where drawn like any body that would not stay, but that is the spring taking its load, not a
    flaw of the drawing, and the rollout says nothing of it (it said "the trampoline would not stay where it is
    drawn" on every spring machine); nor when the search made the spring longer or shorter than sketched."""
    scene, params = trampoline(k=k, rest=rest)
    settled = settled_state(scene, CANVAS, params)
    sag = 300.0 * 30.0 * GRAVITY[1] / (k * SPRING_UNITS) - (rest - 155.0)
    if abs(sag) > 10.0:  # the flush distance: a stiff spring's sag is a body coming flush
        assert dict(settled.held).keys() == {"b3"} and settled.sagged == ("b3",)
    assert settled.state.bodies["b3"][:2] == pytest.approx((800.0, 560.0), abs=1e-6)
    result = rollout(scene, CANVAS, params, max_seconds=0.5)
    assert not [flag for flag in result.flagged if "would not stay" in flag], result.flagged


def test_a_body_falling_onto_a_spring_is_still_flagged() -> None:
    """A crate drawn in mid-air above the trampoline falls further than any spring's sag: that is the drawing's."""
    scene, params = trampoline(crate=True)
    settled = settled_state(scene, CANVAS, params)
    assert {"b3", "b4"} <= dict(settled.held).keys() and "b4" not in settled.sagged
    result = rollout(scene, CANVAS, params, max_seconds=0.5)
    assert [flag for flag in result.flagged if flag.startswith("the crate would not stay where it is drawn")]


def test_a_ball_drawn_above_its_shelf_comes_flush() -> None:
    """The golf ball drawn 5 units above its shelf rests on it, unflagged, instead of bouncing for ever."""
    s = demonstrated("golf_ball_helper")
    params = seed(s.scene, s.timeline, s.canvas)
    state = settled_state(s.scene, s.canvas, params).state
    ball = state.bodies["b6"]
    assert 0 < ball.y - s.scene.components["b6"].position[1] < 10.0
    assert math.hypot(ball.vx, ball.vy) < 5.0


def test_a_dropped_ball_stops_at_rest_well_before_max_seconds() -> None:
    result = rollout(dropped_ball(), CANVAS, ball_parameters(), max_seconds=30.0)
    assert result.stopped_because == Stop.AT_REST
    assert result.steps / 120 < 10.0
    types = [ev.type for ev in result.timeline.events]
    assert types[:3] == ["start", "movement", "contact"]
    assert result.flagged == ()


def test_a_body_gone_off_the_canvas_stops_the_rollout() -> None:
    result = rollout(dropped_ball(platform=False), CANVAS, ball_parameters((300.0, 0.0)), max_seconds=30.0)
    assert result.stopped_because == Stop.OFF_CANVAS
    assert result.steps / 120 < 5.0


def test_absurd_velocities_explode() -> None:
    result = rollout(dropped_ball(), CANVAS, ball_parameters((1e12, 0.0)), max_seconds=5.0)
    assert result.stopped_because == Stop.EXPLODED
    assert result.steps <= 2


def test_fast_bodies_are_flagged_not_limited() -> None:
    result = rollout(dropped_ball(), CANVAS, ball_parameters((0.0, 4000.0)), max_seconds=5.0)
    assert result.stopped_because != Stop.EXPLODED
    assert any("demo mode's limit" in flag for flag in result.flagged)


def test_a_fork_from_the_settled_state_equals_a_full_rollout() -> None:
    s = demonstrated("egg_cracker")
    params = seed(s.scene, s.timeline, s.canvas)
    state = settled_state(s.scene, s.canvas, params)
    for velocity in ((300.0, -450.0), (200.0, -300.0)):
        candidate = params.with_velocities({"b2": velocity})
        assert candidate.structure() == params.structure()
        forked = rollout_from(s.scene, state, s.canvas, candidate, max_seconds=4.0)
        assert forked == rollout(s.scene, s.canvas, candidate, max_seconds=4.0)


def test_settled_state_forks_a_world() -> None:
    s = demonstrated("cup_dispenser")
    params = seed(s.scene, s.timeline, s.canvas)
    state = settled_state(s.scene, s.canvas, params).state
    world = World.from_state(apply(s.scene, params), state)
    assert world.steps == state.step > 0


def test_a_fork_puts_the_rope_where_settling_left_it() -> None:
    """The rope's links are part of the settled state: the fork's rope ends at the knife."""
    s = demonstrated("egg_cracker")
    params = seed(s.scene, s.timeline, s.canvas)
    settled = settled_state(s.scene, s.canvas, params)
    state = settled.state
    assert len(state.links["r1"]) >= 8
    scene = apply(s.scene, params)
    forked = rollout_from(s.scene, settled, s.canvas, params, max_seconds=0.1)
    assert forked.stopped_because != Stop.EXPLODED
    world = World.from_state(scene, state)  # what the fork starts from, on a world we can inspect
    end = world.to_scene(scene).components["r1"].points[-1]
    knife = state.bodies["b5"]
    assert math.hypot(end[0] - knife.x, end[1] - knife.y) < 100.0


def test_a_fast_ball_does_not_tunnel_through_a_thin_platform() -> None:
    """Demo mode's speed limit is not applied in a simulation: sub-steps keep a fast ball from passing through."""
    scene = Scene().add(Body("b1", "circle", (), 10.0, (800.0, 100.0), 0.0, MATERIALS["freeform"], "ball"))
    scene = scene.add(Body("b2", "box", square(600, 4), 0.0, (800.0, 700.0), 0.0, MATERIALS["freeform"]))
    scene = scene.add(Joint("j1", "weld", "b2", BACKGROUND, (800.0, 700.0)))
    params = Parameters({"b1": BodyParameters(math.pi * 100.0, 0.0)}, {}, {"b1": (0.0, 6000.0)})
    result = rollout(scene, CANVAS, params, max_seconds=1.0)
    contacts = [ev for ev in result.timeline.events if ev.type == "contact"]
    assert contacts and set(contacts[0].components) == {"b1", "b2"}
    assert not any("tunnel" in flag for flag in result.flagged)
    assert any("demo mode's limit" in flag for flag in result.flagged)


def test_a_body_that_came_flush_while_settling_touches_what_it_rests_on_when_first_set_moving() -> None:
    """The golf ball drawn a little above its shelf (thesis 4.2): settling brings it down onto the shelf, which is no
    event; the demonstration, without gravity, shows that contact when the ball is pushed onto the shelf, so the
    simulation's is the step the ball is first set moving (after the blow that moves it), and only then."""
    shelf = Body("b1", "box", square(400, 40), 0.0, (800.0, 620.0), 0.0, MATERIALS["box"], "shelf")
    scene = Scene().add(shelf).add(Joint("j1", "weld", "b1", BACKGROUND, (800.0, 620.0)))
    scene = scene.add(Body("b2", "circle", (), 25.0, (800.0, 569.0), 0.0, MATERIALS["round"], "golf ball"))
    scene = scene.add(Body("b3", "circle", (), 25.0, (700.0, 575.0), 0.0, MATERIALS["round"], "ball"))
    masses = {b: BodyParameters(math.pi * 625.0, 0.5) for b in ("b2", "b3")}
    result = rollout(scene, CANVAS, Parameters(masses, {}, {"b3": (600.0, 0.0)}), max_seconds=1.0)
    contacts = [ev for ev in result.timeline.events if ev.type == "contact"]
    assert [set(ev.components) for ev in contacts[:2]] == [{"b2", "b3"}, {"b1", "b2"}]
    pushed, onto = contacts[0], contacts[1]
    (moved,) = [result.timeline.event(c) for c in onto.causes]
    assert moved.type == "movement" and moved.components[0] == "b2" and pushed.id in moved.causes
    assert dict(onto.sides) == {"b2": "bottom", "b1": "top"}
