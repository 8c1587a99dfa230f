"""SIMULATE on a machine's later legs (issue 27, the portfolio cup dispenser): a contact met on the wrong side is scored
by how far the two bodies lay from their demonstrated placement; a later leg's first run adjusts what that leg brings
in; once the start body is delivered, the aims and the throw's scan are skipped."""

from __future__ import annotations

import contextlib
import io
import math
from pathlib import Path

import pytest

from physink_tui.cli import main
from physink_tui.formats.project.codec import Project
from physink_tui.formats.project.files import load_project
from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Scene
from physink_tui.sim.chain import aimed_legs
from physink_tui.sim.evaluate import Score, side_misses
from physink_tui.sim.leg_search import FAMILY_ROUNDS, LegByLeg
from physink_tui.sim.legs import legs
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters
from physink_tui.sim.seeding import seed
from physink_tui.timeline.events import Event, Timeline
from tests.test_sim_cup import cup_pushed, frames

JOURNAL = Path(__file__).parent / "journals" / "cup_dispenser.physink.jsonl"


@pytest.fixture(scope="module")
def cup_dispenser(tmp_path_factory: pytest.TempPathFactory) -> Project:
    out = tmp_path_factory.mktemp("cup") / "demo"
    with contextlib.redirect_stdout(io.StringIO()):
        assert main(["replay", str(JOURNAL), "--out", str(out)]) == 0
    return load_project(out / "project.json")


def on_top(demonstrated: Timeline) -> Timeline:
    """``demonstrated`` with the cup-peg contact (e7) met on the peg's top by the cup's bottom, the cup 60 units
    higher than where it lay beside the peg."""
    events = []
    for ev in demonstrated.events:
        if ev.id == "e6":  # the cup, carried 60 units higher
            ev = Event("e6", "movement", ("b2",), ("e4",), 1.0, 2.0, trajectory=frames(1.0, 2.0, 500, 500, 420, 1))
        if ev.id == "e7":
            ev = Event("e7", "contact", ev.components, ev.causes, ev.t0, ev.t1,
                       sides=(("b2", "bottom"), ("b3", "top")), point=(470.0, 440.0))
        events.append(ev)
    return Timeline(tuple(events))


def test_a_contact_on_the_wrong_side_is_scored_by_the_bodies_placement() -> None:
    demonstrated = cup_pushed(rattles=False)
    pairs = [(ev.id, ev.id) for ev in demonstrated.events]
    assert side_misses(Scene(), demonstrated, demonstrated, pairs) == {}  # the same sides: nothing to add
    misses = side_misses(Scene(), demonstrated, on_top(demonstrated), pairs)
    # the peg (b3) at 440 beside the cup in both; the cup 60 units higher in the simulation
    assert set(misses) == {"e7"} and math.isclose(misses["e7"], 60.0)


def test_a_body_that_never_moved_is_placed_where_it_is_drawn_and_a_fixed_one_is_left_out() -> None:
    demonstrated = Timeline((Event("e1", "start"),
                             Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0,
                                   trajectory=frames(0.0, 1.0, 0, 100, 0, 100)),
                             Event("e3", "contact", ("b1", "b2"), ("e2",), 1.0, 1.0,
                                   sides=(("b1", "right"), ("b2", "left")), point=(110.0, 0.0))))
    simulated = Timeline((demonstrated.events[0],
                          Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0,
                                trajectory=frames(0.0, 1.0, 0, 100, 0, 100)[:1]
                                + frames(0.0, 1.0, 0, 110, 20, 100)[1:]),
                          Event("e3", "contact", ("b1", "b2"), ("e2",), 1.0, 1.0,
                                sides=(("b1", "bottom"), ("b2", "top")), point=(110.0, 30.0))))
    wall = Scene().add(Body("b2", "circle", (), 10.0, (120.0, 30.0), 0.0, MATERIALS["round"]))
    misses = side_misses(wall, demonstrated, simulated, [("e1", "e1"), ("e2", "e2"), ("e3", "e3")])
    assert misses == {"e3": pytest.approx(math.hypot(10.0, 20.0))}  # the ball 10 right, 20 lower; the wall still
    welded = wall.add(Joint("j1", "weld", "b2", BACKGROUND, (120.0, 30.0)))
    assert side_misses(welded, demonstrated, simulated, [("e3", "e3")]) == {}  # a fixed body's side: the throw's


def test_a_later_leg_brings_in_its_own_components(cup_dispenser: Project) -> None:
    assert cup_dispenser.timeline is not None
    cut = legs(cup_dispenser.timeline)
    assert cut[0].own == cut[0].components
    # the cup meeting the peg: the platform, the cup, the peg and their springs, not the ball that set them moving
    last_contact = next(k for k, leg in enumerate(cut) if leg.last == "e17")
    assert cut[last_contact].own == {"b4", "s1", "b5", "b7", "s2"}
    assert all(leg.own <= leg.components for leg in cut)


def test_the_aims_address_the_legs_up_to_the_start_body_meeting_a_movable_body(cup_dispenser: Project) -> None:
    assert cup_dispenser.timeline is not None
    cut = legs(cup_dispenser.timeline)
    # the ball (b2) rolls down the fixed ramp (b1), then lands on the cup (b5, movable): two legs
    assert aimed_legs(cup_dispenser.scene, cup_dispenser.timeline, cut) == 2
    assert cup_dispenser.timeline.event(cut[1].last).components == ("b2", "b5")


def reproduced(legs_: int, of: int) -> Score:
    """A score reproducing the first ``legs_`` of ``of`` legs."""
    return Score(1.0, 10.0, legs=tuple(Score(0.0 if k < legs_ else 1.0, 10.0) for k in range(of)))


@pytest.mark.parametrize(("delivered", "phase"), [(2, "springs"), (1, "aim")])
def test_once_the_family_delivers_the_start_body_the_aims_and_the_scan_are_skipped(delivered: int,
                                                                                   phase: str) -> None:
    from physink_tui.sim.aim import Aim, Aimed

    start = Parameters({"b1": BodyParameters(1.0, 1.0)}, {"s1": SpringParameters(20.0, 150.0)}, {"b1": (100.0, 0.0)})
    aim = Aimed(start.with_velocities({"b1": (90.0, 0.0)}), Aim((0.0, 0.0), (0.0, -1.0), (0.0, -1.0), False),
                1.0, "b1", (0.0, 0.0))
    cut = legs(cup_pushed(rattles=False))
    strategy = LegByLeg(start, cut, seed=0, family=lambda f: start.with_velocities({"b1": (100.0 / f, 0.0)}),
                        aims=[aim], aimed_legs=2)
    strategy.told([start], [reproduced(0, len(cut))])
    for _ in range(FAMILY_ROUNDS):
        generation = strategy.generation(None)
        strategy.told(generation, [reproduced(delivered if k == 0 else 0, len(cut))
                                   for k in range(len(generation))])
    strategy.generation(None)
    assert strategy.phase == phase  # delivered: on to the stiffer springs; else the aims first


def test_a_later_legs_first_run_adjusts_its_own_components_then_everything_on_a_restart(
        cup_dispenser: Project) -> None:
    assert cup_dispenser.timeline is not None
    cut = legs(cup_dispenser.timeline)
    start = seed(cup_dispenser.scene, cup_dispenser.timeline, cup_dispenser.canvas)
    strategy = LegByLeg(start, cut, seed=0)
    strategy.told([start], [reproduced(5, len(cut))])
    strategy.told(strategy.generation(None), [reproduced(5, len(cut))] * 48)  # the scan
    strategy.told(strategy.generation(None), [reproduced(5, len(cut))] * 9)  # the springs
    first = strategy.generation(None)  # the run on the cup meeting the peg: the ball's throw stays
    assert strategy.phase == "run" and strategy.leg == 5
    assert all(p.velocities == start.velocities and p.bodies["b2"] == start.bodies["b2"] for p in first)
    assert any(p.springs != start.springs for p in first)
    strategy.restarts = 1  # a restart adjusts everything up to the leg's end, the throw too
    assert strategy._components(cut[5]) == cut[5].components
