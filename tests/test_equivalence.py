"""Qualitative equivalence of timelines agrees with the thesis (figures 2-12 to 2-15): which platform, how many
bounces, which side, above or below are differences; trajectories, timings and contact points are not."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physink_tui.timeline.equivalence import (
    CAUSE_COST,
    REGION_COST,
    SIDE_COST,
    UNMATCHED_EVENT_COST,
    compare,
    compare_prepared,
    prepare,
)
from physink_tui.timeline.events import REGIONS, SIDES, Event, Timeline, TrajectoryPoint

NAMES = {"b1": "ball", "b2": "platform A", "b3": "platform B", "b4": "basket"}
CENTRES = {"b2": (250.0, 300.0), "b3": (450.0, 420.0), "b4": (650.0, 600.0)}
OFFSET = {"top": (0.0, -12.0), "bottom": (0.0, 12.0), "left": (-40.0, 0.0), "right": (40.0, 0.0),
          "inside": (0.0, 0.0)}

Hit = tuple[str, str, str]  # (body hit, the ball's side, that body's side)
Regions = Mapping[str, tuple[str, ...]]


def behaviour(hits: Sequence[Hit], regions: Sequence[Regions] = (), *, wobble: float = 0.0, pace: float = 1.0,
              shift: float = 0.0, frames: int = 20) -> Timeline:
    """The ball dropped at (100, 100), hitting each of ``hits`` in turn, then landing in the basket.

    ``regions[k]`` is what the k-th movement passes; ``wobble`` bends every trajectory sideways by that many
    units at its middle, ``pace`` scales every duration, ``shift`` moves every contact point along x.
    """
    hits = [*hits, ("b4", "bottom", "inside")]
    events = [Event("e1", "start")]
    t, cause, at = 0.0, "e1", (100.0, 100.0)
    for k, (body, ball_side, body_side) in enumerate(hits):
        cx, cy = CENTRES[body]
        ox, oy = OFFSET[body_side]
        point = (cx + ox + shift, cy + oy)
        duration = pace * (1.0 + 0.25 * k)
        path = []
        for f in range(frames):
            s = f / (frames - 1)
            bend = wobble * math.sin(math.pi * s)
            x, y = at[0] + (point[0] - at[0]) * s + bend, at[1] + (point[1] - at[1]) * s
            path.append(TrajectoryPoint(t + duration * s, x, y, 0.0, 0.0, 0.0))
        crossed = tuple(regions[k].items()) if k < len(regions) else ()
        mid, cid = f"e{len(events) + 1}", f"e{len(events) + 2}"
        events.append(Event(mid, "movement", ("b1",), (cause,), t, t + duration, regions=crossed,
                            trajectory=tuple(path)))
        t += duration
        events.append(Event(cid, "contact", ("b1", body), (mid,), t, t, sides=(("b1", ball_side), (body, body_side)),
                            point=point))
        cause, at = cid, point
    return Timeline(tuple(events))


def renamed(timeline: Timeline, ids: Mapping[str, str]) -> Timeline:
    """The same timeline with component ids replaced (another drawing of the same scene)."""
    def r(c: str) -> str:
        return ids.get(c, c)
    return Timeline(tuple(replace(ev, components=tuple(map(r, ev.components)),
                                  sides=tuple((r(c), s) for c, s in ev.sides),
                                  regions=tuple((r(c), rs) for c, rs in ev.regions)) for ev in timeline.events))


ON_A = [("b2", "bottom", "top")]
ON_B = [("b3", "bottom", "top")]
UNDER_B = [("b3", "top", "bottom")]
FIG_2_15 = [("b2", "bottom", "top"), ("b3", "top", "bottom")]


def _cmp(a: Timeline, b: Timeline):
    return compare(a, b, NAMES, NAMES)


# --- the thesis's judgements ---------------------------------------------------------------------------------------


def test_fig_2_12_hitting_platform_a_or_platform_b_is_not_equivalent() -> None:
    result = _cmp(behaviour(ON_A), behaviour(ON_B))
    assert not result.equivalent
    assert result.qualitative_distance >= 2 * UNMATCHED_EVENT_COST
    assert '"Contact between ball and platform A" only in A (t=1.00)' in result.reasons
    assert '"Contact between ball and platform B" only in B (t=1.00)' in result.reasons


def test_fig_2_12_one_bounce_or_two_on_platform_b_is_not_equivalent() -> None:
    once, twice = behaviour(ON_B), behaviour([*ON_B, *ON_B])
    result = _cmp(once, twice)
    assert not result.equivalent
    assert len(result.only_b) == 2 and not result.only_a  # one contact and one movement more
    assert {twice.event(e).type for e in result.only_b} == {"contact", "movement"}
    assert any(r.startswith('"Contact between ball and platform B" only in B') for r in result.reasons)


def test_fig_2_13_one_bounce_on_the_top_or_the_bottom_of_platform_b_is_not_equivalent() -> None:
    result = _cmp(behaviour(ON_B), behaviour(UNDER_B))
    assert not result.equivalent
    assert result.qualitative_distance == 2 * SIDE_COST
    assert result.reasons == (
        "Contact between ball and platform B (t=1.00): ball's side is bottom in A, top in B",
        "Contact between ball and platform B (t=1.00): platform B's side is top in A, bottom in B",
    )
    assert not result.only_a and not result.only_b


def test_fig_2_14_passing_above_or_below_platform_b_is_not_equivalent() -> None:
    above = behaviour([], [{"b2": ("below",), "b3": ("above",)}])
    below = behaviour([], [{"b2": ("below",), "b3": ("below",)}])
    result = _cmp(above, below)
    assert not result.equivalent
    assert result.qualitative_distance == 2 * REGION_COST
    assert result.reasons == ("Movement of ball (t=0.00): relative to platform B it passes above in A, below in B",)


def test_fig_2_15_same_events_sides_and_regions_are_equivalent_however_the_paths_differ() -> None:
    regions = [{"b3": ("above",)}, {"b3": ("left", "below")}, {"b2": ("right",), "b3": ("below", "right")}]
    demonstrated = behaviour(FIG_2_15, regions)
    simulated = behaviour(FIG_2_15, regions, wobble=15.0, pace=0.7, shift=6.0, frames=33)
    result = _cmp(demonstrated, simulated)
    assert result.equivalent
    assert result.qualitative_distance == 0
    assert result.reasons == ()
    assert result.quantitative_distance > 0
    assert len(result.matches) == len(demonstrated) and not result.only_a and not result.only_b


def test_the_quantitative_distance_grows_as_the_trajectories_part() -> None:
    base = behaviour(FIG_2_15)
    distances = [_cmp(base, behaviour(FIG_2_15, wobble=w)).quantitative_distance for w in (0.0, 5.0, 10.0, 40.0)]
    assert distances[0] == 0
    assert distances == sorted(distances) and len(set(distances)) == 4
    shifted = [_cmp(base, behaviour(FIG_2_15, shift=s)).quantitative_distance for s in (2.0, 8.0)]
    assert 0 < shifted[0] < shifted[1]


def test_speed_alone_changes_nothing_since_trajectories_are_normalised_by_duration() -> None:
    result = _cmp(behaviour(FIG_2_15), behaviour(FIG_2_15, pace=2.5, frames=57))
    assert result.equivalent
    assert result.quantitative_distance == pytest.approx(0.0, abs=1e-9)


# --- matching by name, symmetry, explanations ----------------------------------------------------------------------


def test_a_timeline_is_equivalent_to_itself_at_distance_zero() -> None:
    tl = behaviour(FIG_2_15, [{"b3": ("above",)}])
    result = _cmp(tl, tl)
    assert (result.equivalent, result.qualitative_distance, result.quantitative_distance) == (True, 0.0, 0.0)
    assert result.matches == tuple((e, e) for e in ("e1", "e2", "e3", "e4", "e5", "e6", "e7"))


def test_components_are_matched_by_label_when_ids_differ() -> None:
    ids = {"b1": "b9", "b2": "b7", "b3": "b8", "b4": "b5"}
    other = renamed(behaviour(FIG_2_15, [{"b3": ("above",)}]), ids)
    other_names = {ids[k]: v for k, v in NAMES.items()}
    result = compare(behaviour(FIG_2_15, [{"b3": ("above",)}]), other, NAMES, other_names)
    assert result.equivalent and result.quantitative_distance == 0
    # Without the labels the ids are all there is to go by, and they differ.
    assert not compare(behaviour(FIG_2_15), other).equivalent


def test_creation_order_does_not_matter_only_time_and_causes() -> None:
    tl = behaviour(FIG_2_15)
    backwards = Timeline(tuple(reversed(tl.events)))  # every cause created after what it causes
    assert _cmp(tl, backwards).equivalent


def test_concurrent_unrelated_events_may_happen_in_either_order() -> None:
    names = {**NAMES, "b6": "second ball", "b7": "floor"}

    def with_second_ball(t: float) -> Timeline:
        tl = behaviour(ON_B)
        return tl.add(Event("m9", "movement", ("b6",), ("e1",), 0.0, t)).add(
            Event("c9", "contact", ("b6", "b7"), ("m9",), t, t, sides=(("b6", "bottom"), ("b7", "top"))))

    early, late = with_second_ball(0.5), with_second_ball(1.5)  # the ball hits platform B at t = 1
    assert compare(early, late, names, names).equivalent


def test_a_different_causal_order_is_a_difference() -> None:
    a = behaviour(FIG_2_15)  # platform A, then platform B
    b = behaviour([FIG_2_15[1], FIG_2_15[0]])  # platform B, then platform A
    result = _cmp(a, b)
    assert not result.equivalent
    assert not result.only_a and not result.only_b  # the same events ...
    assert result.qualitative_distance == 8 * CAUSE_COST  # ... four of them with both causes swapped
    assert ('Contact between ball and platform A (t=1.00 in A, t=2.25 in B) is caused by "Movement of ball" '
            '(t=0.00) in A but by "Movement of ball" (t=1.00) in B') in result.reasons


def test_a_rewired_cause_costs_and_is_explained() -> None:
    a = behaviour(FIG_2_15)
    b = a.update(replace(a.event("e7"), causes=("e1",)))  # the basket contact now caused by the start
    result = _cmp(a, b)
    assert result.qualitative_distance == CAUSE_COST * 2
    assert result.reasons == (
        'Contact between ball and basket (t=3.75) is caused by "Movement of ball" (t=2.25) in A but by "Start" '
        "(t=0.00) in B",
    )


def test_the_user_labels_of_both_sides_name_a_matched_event() -> None:
    a = behaviour(ON_B)
    a = a.relabel("e3", "the ball bounces on platform B")
    result = _cmp(a, behaviour(UNDER_B))
    assert result.reasons[0].startswith("the ball bounces on platform B / Contact between ball and platform B (t=1.00)")


def test_a_region_passed_in_one_timeline_only_with_nothing_opposed_is_no_difference() -> None:
    # a body passed near in one timeline only, or a corner strip brushed (thesis figure 3-22: a simulated parabola
    # is equivalent to a straight drop through the same regions)
    a = behaviour([], [{"b3": ("left", "above", "right")}])
    assert _cmp(a, behaviour([])).equivalent
    corner = behaviour([], [{"b3": ("above", "right")}])
    assert _cmp(corner, behaviour([], [{"b3": ("right",)}])).equivalent


def test_passing_on_the_opposite_sides_costs_each_opposed_region() -> None:
    a = behaviour([], [{"b3": ("above", "right")}])
    b = behaviour([], [{"b3": ("below", "left")}])
    result = _cmp(a, b)
    assert result.qualitative_distance == 4 * REGION_COST
    assert result.reasons == ("Movement of ball (t=0.00): relative to platform B it passes above and right in A, "
                              "below and left in B",)


def landed(timeline: Timeline, bounces: int = 0, *, then: str | None = None) -> Timeline:
    """``timeline`` (a `behaviour`) with the ball's movement after it lands in the basket (a leaf), then
    ``bounces`` more contacts with the basket, each causing a movement, then a contact with ``then``."""
    events = list(timeline.events)
    landing = events[-1]
    t, cause = landing.t0, landing.id
    for k in range(bounces + 1 + (then is not None)):
        mid = f"e{len(events) + 1}"
        events.append(Event(mid, "movement", ("b1",), (cause,), t, t + 0.2,
                            trajectory=(TrajectoryPoint(t, 650.0, 590.0, 0, 0, 0),
                                        TrajectoryPoint(t + 0.2, 652.0, 580.0, 0, 0, 0))))
        if k == bounces + (then is not None):
            break
        t += 0.2
        cid = f"e{len(events) + 1}"
        other = then if k == bounces else "b4"
        events.append(Event(cid, "contact", ("b1", other), (mid,), t, t, point=(650.0, 600.0),
                            sides=(("b1", "bottom"), (other, "inside" if other == "b4" else "top"))))
        cause = cid
    return Timeline(tuple(events))


def test_a_simulation_bouncing_to_rest_where_the_demonstration_landed_is_equivalent() -> None:
    demonstrated = landed(behaviour(ON_B))
    simulated = landed(behaviour(ON_B), bounces=3)
    assert compare(demonstrated, simulated, NAMES, NAMES, simulation=True).equivalent
    plain = compare(demonstrated, simulated, NAMES, NAMES)
    assert not plain.equivalent and plain.qualitative_distance == 6 * UNMATCHED_EVENT_COST  # not a simulation


def test_what_a_simulation_does_after_the_demonstration_has_played_out_is_not_compared() -> None:
    # the comparison covers the demonstrated behaviour: the ball bouncing out of the basket onto platform B after
    # the demonstration ended is the simulation's own business (not so for a plain comparison)
    demonstrated = landed(behaviour(ON_B))
    later = landed(behaviour(ON_B), bounces=1, then="b3")
    assert compare(demonstrated, later, NAMES, NAMES, simulation=True).equivalent
    assert not compare(demonstrated, later, NAMES, NAMES).equivalent


def test_fig_2_12_one_bounce_more_stays_a_difference_for_a_simulation() -> None:
    # the rule merges only bounces coming to rest after the demonstrated behaviour: a second bounce on platform B
    # before the ball lands in the basket is another behaviour
    once, twice = landed(behaviour(ON_B)), landed(behaviour([*ON_B, *ON_B]))
    result = compare(once, twice, NAMES, NAMES, simulation=True)
    assert not result.equivalent and len(result.only_b) == 2
    assert any(r.startswith('"Contact between ball and platform B" only in B') for r in result.reasons)


def test_a_demonstration_bouncing_where_the_simulation_rests_is_still_a_difference() -> None:
    # the simulation must reproduce what was demonstrated: only the simulation's own tail is forgiven
    result = compare(landed(behaviour(ON_B), bounces=2), landed(behaviour(ON_B)), NAMES, NAMES, simulation=True)
    assert not result.equivalent and len(result.only_a) == 4


def test_explain_false_gives_the_same_distances_without_reasons() -> None:
    a, b = behaviour(ON_A), behaviour(FIG_2_15, wobble=3.0)
    full, quiet = _cmp(a, b), compare(a, b, NAMES, NAMES, explain=False)
    assert quiet.reasons == () and full.reasons
    assert (quiet.qualitative_distance, quiet.quantitative_distance) == (full.qualitative_distance,
                                                                         full.quantitative_distance)
    assert compare_prepared(prepare(a, NAMES), prepare(b, NAMES)) == full


def test_an_empty_timeline_compares() -> None:
    empty = Timeline()
    assert compare(empty, empty).equivalent
    result = compare(empty, behaviour([]), {}, NAMES)
    assert result.qualitative_distance == 3 * UNMATCHED_EVENT_COST
    assert result.reasons[0] == '"Start" only in B (t=0.00)'


# --- properties on random timelines --------------------------------------------------------------------------------

POOL = ("b1", "b2", "b3", "b4")


@st.composite
def timelines(draw: st.DrawFn) -> Timeline:
    events = [Event("e0", "start")]
    for k in range(1, draw(st.integers(0, 10)) + 1):
        kind = draw(st.sampled_from(("movement", "movement", "contact", "end_contact", "start")))
        eid = f"e{k}"
        t0 = draw(st.sampled_from((0.0, 0.5, 1.0, 2.0)))  # ties on purpose
        if kind == "start":
            events.append(Event(eid, "start", (), (), t0, t0))
            continue
        causes = tuple(draw(st.lists(st.sampled_from([e.id for e in events]), max_size=2, unique=True)))
        comps = tuple(draw(st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)))
        if kind == "movement":
            n = draw(st.integers(0, 4))
            traj = tuple(TrajectoryPoint(t0 + i * 0.1, draw(st.floats(0, 100)), draw(st.floats(0, 100)), 0, 0, 0)
                         for i in range(n))
            regions = tuple((c, tuple(draw(st.lists(st.sampled_from(REGIONS), max_size=2, unique=True))))
                            for c in draw(st.lists(st.sampled_from(POOL), max_size=2, unique=True)))
            events.append(Event(eid, kind, comps, causes, t0, t0 + 0.1 * max(n - 1, 0), regions=regions,
                                trajectory=traj))
        elif kind == "contact":
            sides = tuple((c, draw(st.sampled_from(SIDES))) for c in comps)
            point = draw(st.none() | st.tuples(st.floats(0, 100), st.floats(0, 100)))
            events.append(Event(eid, kind, comps, causes, t0, t0, sides=sides, point=point))
        else:
            events.append(Event(eid, kind, comps, causes, t0, t0))
    return Timeline(tuple(events))


@settings(max_examples=150, deadline=None)
@given(timelines())
def test_any_timeline_is_equivalent_to_itself(tl: Timeline) -> None:
    result = compare(tl, tl, NAMES, NAMES)
    assert result.equivalent and result.qualitative_distance == 0 and result.quantitative_distance == 0
    assert result.reasons == () and len(result.matches) == len(tl)


@settings(max_examples=300, deadline=None)
@given(timelines(), timelines())
def test_the_distances_are_symmetric(a: Timeline, b: Timeline) -> None:
    ab, ba = compare(a, b, NAMES, NAMES), compare(b, a, NAMES, NAMES)
    assert ab.qualitative_distance == ba.qualitative_distance
    assert ab.quantitative_distance == pytest.approx(ba.quantitative_distance, abs=1e-9)
    assert sorted(ab.matches) == sorted((y, x) for x, y in ba.matches)
    assert ab.equivalent == (ab.qualitative_distance == 0) == (ab.reasons == ())
    assert ab.qualitative_distance >= UNMATCHED_EVENT_COST * (len(ab.only_a) + len(ab.only_b))


@settings(max_examples=100, deadline=None)
@given(timelines())
def test_other_ids_with_the_same_labels_are_equivalent(tl: Timeline) -> None:
    ids = {"b1": "x4", "b2": "x3", "b3": "x2", "b4": "x1"}
    result = compare(tl, renamed(tl, ids), NAMES, {ids[k]: v for k, v in NAMES.items()})
    assert result.equivalent and result.quantitative_distance == 0


def test_what_lands_inside_a_container_may_touch_it_with_any_side() -> None:
    # thesis 3.4.6: the ball lands inside the basket in both; which side of the ball met the basket's wall first
    # is the trajectory's business. The basket's side still counts.
    bottom = behaviour([], [])
    right = Timeline(tuple(replace(ev, sides=(("b1", "right"), ("b4", "inside"))) if ev.type == "contact" else ev
                           for ev in bottom.events))
    assert _cmp(bottom, right).equivalent
    on_top = Timeline(tuple(replace(ev, sides=(("b1", "right"), ("b4", "top"))) if ev.type == "contact" else ev
                            for ev in bottom.events))
    assert _cmp(bottom, on_top).qualitative_distance == 2 * SIDE_COST


def test_regions_relative_to_a_body_moving_meanwhile_are_not_compared() -> None:
    # the thesis's regions are against the scenery a body passes (figure 3-6); a paddle swinging while the ball goes
    # by is no scenery, so passing "above" it in one timeline and "below" in the other is trajectory, not behaviour
    def with_paddle_swinging(timeline: Timeline) -> Timeline:
        first = next(ev for ev in timeline.events if ev.type == "movement")
        swing = Event("p1", "movement", ("b3",), ("e1",), first.t0, first.t1)
        return Timeline((*timeline.events, swing))

    above = with_paddle_swinging(behaviour([], [{"b3": ("above",)}]))
    below = with_paddle_swinging(behaviour([], [{"b3": ("below",)}]))
    assert _cmp(above, below).equivalent
    assert not _cmp(behaviour([], [{"b3": ("above",)}]), behaviour([], [{"b3": ("below",)}])).equivalent
