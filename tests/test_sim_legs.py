"""SIMULATE's legs: the demonstration cut after each contact, prefix distances charged from one matching, and the
leg-by-leg search moving on leg after leg and adjusting only what a leg depends on."""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import given, settings

from physink_tui.sim.coordinates import coordinates
from physink_tui.sim.evaluate import Score
from physink_tui.sim.leg_search import FAMILY_ROUNDS, LegByLeg
from physink_tui.sim.legs import legs
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters
from physink_tui.timeline.equivalence import compare, compare_prefixes, prepare
from physink_tui.timeline.events import Timeline
from tests.sim_scenes import demonstration
from tests.test_equivalence import NAMES, behaviour, timelines

ON_A_THEN_B = [("b2", "bottom", "top"), ("b3", "top", "bottom")]


def test_legs_end_at_each_contact_and_the_last_is_everything() -> None:
    timeline = behaviour(ON_A_THEN_B)  # start, then movement + contact three times (A, B, the basket)
    cut = legs(timeline)
    assert [timeline.event(leg.last).type for leg in cut] == ["contact", "contact", "contact"]
    assert cut[-1].events == {ev.id for ev in timeline.events}
    assert [len(leg.events) for leg in cut] == [3, 5, 7]
    assert cut[0].components == {"b1", "b2"} and cut[1].components == {"b1", "b2", "b3"}
    for leg in cut:  # every prefix holds the causes of its events
        assert all(c in leg.events for e in leg.events for c in timeline.event(e).causes)


def test_prefix_distances_of_a_simulation_that_stops_short() -> None:
    demonstrated = behaviour(ON_A_THEN_B)
    simulated = behaviour(ON_A_THEN_B[:1])  # hits A, then lands in the basket without touching B
    cut = legs(demonstrated)
    whole, prefixes = compare_prefixes(prepare(demonstrated, NAMES), prepare(simulated, NAMES),
                                       [leg.events for leg in cut], simulation=True)
    assert whole.qualitative_distance == compare(demonstrated, simulated, NAMES, NAMES,
                                                 simulation=True).qualitative_distance
    assert prefixes[0].qualitative_distance == 0  # up to the contact with A: reproduced
    assert prefixes[1].qualitative_distance > 0 and prefixes[1].only_a  # the contact with B is missing
    assert prefixes[-1].qualitative_distance == whole.qualitative_distance


@settings(max_examples=60, deadline=None)
@given(timelines(), timelines())
def test_prefix_distances_only_grow_leg_by_leg(a: Timeline, b: Timeline) -> None:
    cut = legs(a)
    whole, prefixes = compare_prefixes(prepare(a), prepare(b), [leg.events for leg in cut], simulation=True)
    distances = [p.qualitative_distance for p in prefixes]
    assert distances == sorted(distances)
    if cut:  # the last leg is the whole demonstration
        assert math.isclose(distances[-1], whole.qualitative_distance)


def two_leg_scores(p: Parameters) -> Score:
    """A pure objective with two legs: leg 0 wants vx > 200, leg 1 also wants the mass above 5."""
    vx, _ = p.velocities["b1"]
    first = Score(0.0 if vx > 200 else 1.0, abs(300 - vx))
    second = Score(first.qualitative + (0.0 if p.bodies["b1"].mass > 5 else 1.0), abs(300 - vx))
    return replace(second, legs=(first, second))


def test_the_search_solves_leg_after_leg_with_what_each_depends_on() -> None:
    timeline = demonstration()
    cut = legs(timeline)
    start = Parameters({"b1": BodyParameters(1.0, 1.0), "b9": BodyParameters(1.0, 1.0)}, {}, {"b1": (50.0, 0.0)})
    strategy = LegByLeg(start, cut[:2], seed=2)
    strategy.told([start], [two_leg_scores(start)])
    asked_while = {0: set(), 1: set()}
    for _ in range(60):
        generation = strategy.generation(None)
        if not generation:
            break
        leg = strategy.leg
        asked_while[leg] |= {name for p in generation for name in _changed(start, p)}
        strategy.told(generation, [two_leg_scores(p) for p in generation])
        if strategy.centre_score.qualitative == 0:
            break
    assert strategy.centre_score.qualitative == 0
    assert asked_while[0] == {"b1"} and asked_while[1] == {"b1"}
    assert "b9" not in asked_while[0] | asked_while[1]  # b9 is in no leg: never adjusted
    assert [c.component for c in coordinates(start, ("vx", "vy"), cut[0].components)] == ["b1"] * 4


def _changed(a: Parameters, b: Parameters) -> set[str]:
    bodies = {k for k in a.bodies if a.bodies[k] != b.bodies[k]}
    return bodies | {k for k in a.velocities if a.velocities[k] != b.velocities[k]}


def test_the_flight_time_family_is_tried_first_zooming_in() -> None:
    start = Parameters({"b1": BodyParameters(1.0, 1.0)}, {}, {"b1": (100.0, 0.0)})
    asked: list[float] = []

    def family(factor: float) -> Parameters:
        asked.append(factor)
        return start.with_velocities({"b1": (100.0 / factor, 0.0)})

    strategy = LegByLeg(start, (), seed=0, family=family)
    strategy.told([start], [Score(1.0, 100.0)])
    for _ in range(FAMILY_ROUNDS):
        generation = strategy.generation(None)
        # the one nearest to vx = 160 is best: the next round zooms around it
        strategy.told(generation, [Score(1.0, abs(p.velocities["b1"][0] - 160.0)) for p in generation])
    first = [round(f, 3) for f in asked[:16]]  # 1/8 to 2 times the demonstrated flight time, in quarter octaves
    assert first == [round(2 ** (k / 4), 3) for k in range(-12, 5) if k != 0]
    assert abs(100.0 / strategy.centre.velocities["b1"][0] - 100.0 / 160.0) < 0.01


def test_after_the_family_the_start_velocities_are_turned_and_scaled_together() -> None:
    start = Parameters({"b1": BodyParameters(1.0, 1.0), "b2": BodyParameters(1.0, 1.0)}, {},
                       {"b1": (100.0, 0.0), "b2": (0.0, -50.0)})
    strategy = LegByLeg(start, (), seed=0)
    strategy.told([start], [Score(1.0, 100.0)])
    scan = strategy.generation(None)
    assert len(scan) == 48 and start not in scan
    for p in scan:  # both bodies turned by the same angle and scaled by the same factor
        (ax, ay), (bx, by) = p.velocities["b1"], p.velocities["b2"]
        assert math.isclose(math.hypot(ax, ay) / 100.0, math.hypot(bx, by) / 50.0)
        turn_a = math.atan2(ay, ax)
        turn_b = math.atan2(by, bx) + math.pi / 2
        assert math.isclose(math.cos(turn_a - turn_b), 1.0)
    best = scan[17]
    strategy.told(scan, [Score(0.5 if p is best else 1.0, 1.0) for p in scan])
    assert strategy.centre is best


def test_after_the_scan_a_scene_with_springs_tries_them_stiffer_and_longer() -> None:
    """A spring drawn at its natural length under a body struck hard lets it strike what the spring is fixed to (the
    trampoline its base); after the scan the best is tried with its springs stiffer and longer, and the best of those
    leads (tests/test_sim_springs.py's spring-1 needs it)."""
    start = Parameters({"b1": BodyParameters(1.0, 1.0)}, {"s1": SpringParameters(20.0, 150.0)}, {"b1": (100.0, 0.0)})
    strategy = LegByLeg(start, (), seed=0)
    strategy.told([start], [Score(1.0, 100.0)])
    scan = strategy.generation(None)
    strategy.told(scan, [Score(1.0, 100.0) for _ in scan])
    stiffer = strategy.generation(None)
    assert {(p.springs["s1"].k, p.springs["s1"].rest_length) for p in stiffer} == \
        {(20.0 * k, 150.0 * r) for k in (2.0, 4.0, 8.0) for r in (1.0, 1.25, 1.5)}
    assert all(p.velocities == start.velocities and p.bodies == start.bodies for p in stiffer)
    best = stiffer[4]
    strategy.told(stiffer, [Score(0.5 if p is best else 1.0, 1.0) for p in stiffer])
    assert strategy.centre is best


def test_a_scene_without_springs_goes_from_the_scan_to_the_legs() -> None:
    start = Parameters({"b1": BodyParameters(1.0, 1.0)}, {}, {"b1": (100.0, 0.0)})
    strategy = LegByLeg(start, (), seed=0)
    strategy.told([start], [Score(1.0, 100.0)])
    scan = strategy.generation(None)
    strategy.told(scan, [Score(1.0, 100.0) for _ in scan])
    strategy.generation(None)
    assert strategy.phase == "run"
