"""Issue 12: the physics layer as SIMULATE will use it — a world's state as a frozen value, worlds forked from it,
and the step-and-observe loop, without a session."""

from __future__ import annotations

import dataclasses

import pytest

from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Scene
from physink_tui.scene.physics.state import Motion, WorldState
from physink_tui.scene.physics.stepping import demo_world, step_and_observe
from physink_tui.scene.physics.world import World


def square(half: float) -> tuple[tuple[float, float], ...]:
    return ((-half, -half), (half, -half), (half, half), (-half, half))


def ball_over_box() -> Scene:
    scene = Scene().add(Body("b1", "circle", (), 20.0, (400.0, 100.0), 0.0, MATERIALS["round"], "ball"))
    return scene.add(Body("b2", "box", square(40), 0.0, (410.0, 400.0), 0.3, MATERIALS["box"], "box"))


def test_a_state_is_a_frozen_value_of_every_body() -> None:
    world = World.from_scene(ball_over_box())
    world.step(30)
    state = world.state()
    assert state.step == 30 and set(state.bodies) == {"b1", "b2"}
    assert isinstance(state.bodies["b1"], Motion) and state.bodies["b1"].vy > 0  # falling
    with pytest.raises(dataclasses.FrozenInstanceError):
        state.step = 0  # type: ignore[misc]
    with pytest.raises(TypeError):
        state.bodies["b1"] = state.bodies["b2"]  # type: ignore[index]
    world.step(30)
    assert state.step == 30 and state.bodies["b1"].y < world.pose("b1").y  # the value did not move on


def test_worlds_forked_from_one_state_agree_with_each_other_and_closely_with_the_original() -> None:
    scene = ball_over_box()
    world = World.from_scene(scene)
    world.step(40)
    state = world.state()
    forks = [World.from_state(scene, state) for _ in range(2)]
    assert all(f.state() == state for f in forks)
    for w in (world, *forks):
        w.step(80)  # the ball lands on the box and rolls off its slope
    assert forks[0].state() == forks[1].state()
    for body in ("b1", "b2"):
        assert forks[0].pose(body)[:2] == pytest.approx(world.pose(body)[:2], abs=1.0)


def test_state_round_trips_through_a_new_world_with_a_changed_scene() -> None:
    """A search forks the state into a scene with other parameters (here a heavier ball) and runs on."""
    scene = ball_over_box()
    world = World.from_scene(scene)
    world.step(20)
    heavy = scene.update(dataclasses.replace(scene.components["b1"],
                                             material=dataclasses.replace(MATERIALS["round"], density=5.0)))
    fork = World.from_state(heavy, world.state())
    assert fork.motion("b1") == world.motion("b1") and fork.steps == 20
    assert isinstance(fork.state(), WorldState)


def test_step_and_observe_reports_motions_and_the_contacts_begun() -> None:
    world = demo_world(ball_over_box())
    world.set_velocity("b1", (0.0, 600.0))
    frames = [step_and_observe(world, ("b1", "b2")) for _ in range(120)]
    assert [f.step for f in frames] == list(range(1, 121))
    hits = [(f.step, c) for f in frames for c in f.contacts]
    assert hits and {hits[0][1].a_id, hits[0][1].b_id} == {"b1", "b2"}
    assert any(frozenset(("b1", "b2")) in f.touching for f in frames)
    assert frames[0].motions["b1"].vy == pytest.approx(600.0, rel=0.05)  # no gravity in a demo world


def box_on_floor_under_a_ball() -> Scene:
    floor = Body("b1", "box", ((-200.0, -10.0), (200.0, -10.0), (200.0, 10.0), (-200.0, 10.0)), 0.0, (400.0, 600.0),
                 0.0, MATERIALS["box"], "floor")
    scene = Scene().add(floor).add(Joint("j1", "weld", "b1", BACKGROUND, (400.0, 600.0)))
    scene = scene.add(Body("b2", "box", square(40), 0.0, (400.0, 550.0), 0.0, MATERIALS["box"], "box"))
    return scene.add(Body("b3", "circle", (), 20.0, (400.0, 200.0), 0.0, MATERIALS["round"], "ball"))


@pytest.mark.parametrize(("warm", "floor_again"), [(0, True), (4, False)])
def test_a_warmed_fork_keeps_the_contacts_of_what_it_holds_asleep(warm: int, floor_again: bool) -> None:
    """A box resting on the floor, held asleep in a fork, is woken by a falling ball. Forked cold, it has no contact
    with the floor while asleep, and one begins again the step after it wakes; forked warm, the resting contact goes
    on (Chipmunk keeps a sleeping body's contacts with their impulses)."""
    scene = box_on_floor_under_a_ball()
    world = World.from_scene(scene)
    world.follow("b3", world.pose("b3"), world.velocity("b3"))  # the ball held where it is while the box settles
    world.step(60)
    world.let_go("b3")
    state = world.state()
    fork = World.from_state(scene, state, warm=warm)
    assert fork.steps == state.step and fork.state() == state
    fork.hold_until_touched({"b3"})
    frames = [step_and_observe(fork, ("b1", "b2", "b3")) for _ in range(150)]
    pairs = [frozenset((c.a_id, c.b_id)) for f in frames for c in f.contacts]
    assert frozenset(("b3", "b2")) in pairs
    assert (frozenset(("b2", "b1")) in pairs) == floor_again
