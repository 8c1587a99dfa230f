"""The thesis's equivalence judgements (2.4, figures 2-12 to 2-15) from real demonstrations: the ball-and-platforms
machine of ``tests/scenarios/bouncing.py`` drawn with the virtual pen, each behaviour demonstrated by dragging the
ball in demo mode and journalled under ``tests/journals/bouncing_*.physink.jsonl``.

Each journal becomes the machine, is exactly what its scenario records, records the causal events the thesis
describes (the contacts in order, with their sides; for the straight drops, the regions of platform B the ball
passes through), replays to the same timeline bytes, and the replayed timelines compare as the thesis judges them.

Regenerate the journals with ``python tests/scenarios/make_journals.py`` after changing a drawing or demonstration.
"""

from __future__ import annotations

import contextlib
import io
from itertools import pairwise
from pathlib import Path

import pytest
from scenarios.bouncing import all_scenarios
from scenarios.make_journals import journal_path, replayed, write_scenario_journal
from scenarios.thesis import BACKGROUND, Scenario

from physink_tui.cli import main
from physink_tui.commands.timeline_source import load_timeline
from physink_tui.scene.components import Joint
from physink_tui.session.session import Session
from physink_tui.timeline.equivalence import UNMATCHED_EVENT_COST, Comparison, compare
from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.qualitative import outline_of

SCENARIOS = {s.name: s for s in all_scenarios()}
MAX_JOURNAL_BYTES = 400_000
REGENERATE = "regenerate with `python tests/scenarios/make_journals.py`"

CONTACTS = {
    # behaviour: the ball's contacts in order, as (what it hits, the ball's side, the side hit)
    "bouncing_hits_a": (("platform a", "bottom", "top"), ("basket", "bottom", "inside")),
    "bouncing_hits_b_once": (("platform b", "bottom", "top"), ("basket", "bottom", "inside")),
    "bouncing_hits_b_twice": (("platform b", "bottom", "top"), ("platform b", "bottom", "top"),
                              ("basket", "bottom", "inside")),
    "bouncing_hits_b_bottom": (("platform b", "top", "bottom"), ("basket", "bottom", "inside")),
    "bouncing_above_b": (("basket", "bottom", "inside"),),
    "bouncing_below_b": (("basket", "bottom", "inside"),),
    "bouncing_a_then_b_bottom": (("platform a", "bottom", "top"), ("platform b", "top", "bottom"),
                                 ("basket", "bottom", "inside")),
    "bouncing_a_then_b_bottom_again": (("platform a", "bottom", "top"), ("platform b", "top", "bottom"),
                                       ("basket", "bottom", "inside")),
}
FIRST_MOVEMENT_REGIONS = {
    # the straight drops into the basket (figures 2-14, 3-22): the regions of the platforms the ball passes through
    "bouncing_above_b": {"platform b": ("above", "right")},
    "bouncing_below_b": {"platform a": ("above", "right"), "platform b": ("below", "left")},
}


def session_over(name: str) -> Session:
    return replayed(name, journal_path(SCENARIOS[name]))


def labels(session: Session) -> dict[str, str]:
    return session.scene.labels()


class Replays:
    """``physink replay`` of the journals into one folder, each journal replayed once per run name."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self._timelines: dict[str, tuple[Timeline, dict[str, str]]] = {}

    def folder(self, name: str, run: str = "a") -> Path:
        out = self.root / name / run
        if not (out / "timeline.json").exists():
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                assert main(["replay", str(journal_path(SCENARIOS[name])), "--out", str(out)]) == 0
        return out

    def timeline(self, name: str) -> tuple[Timeline, dict[str, str]]:
        """The replayed timeline.json and the labels it carries (bodies only passed by included)."""
        if name not in self._timelines:
            self._timelines[name] = load_timeline(self.folder(name) / "timeline.json")
        return self._timelines[name]

    def judge(self, a: str, b: str, *, simulation: bool = False) -> Comparison:
        (ta, na), (tb, nb) = self.timeline(f"bouncing_{a}"), self.timeline(f"bouncing_{b}")
        return compare(ta, tb, na, nb, simulation=simulation)


@pytest.fixture(scope="module")
def replays(tmp_path_factory: pytest.TempPathFactory) -> Replays:
    return Replays(tmp_path_factory.mktemp("bouncing-replays"))


# -- the drawing and the journals -----------------------------------------------------------------------------


@pytest.mark.parametrize("name", SCENARIOS)
def test_the_drawing_becomes_the_ball_platforms_and_basket(name: str) -> None:
    scenario: Scenario = SCENARIOS[name]
    session = session_over(name)
    scene = session.scene
    want = scenario.expect
    bodies = scene.bodies()
    assert [(b.shape, b.label) for b in bodies] == [(x.shape, x.label) for x in want.bodies]
    assert [b.id for b in bodies] == [f"b{i}" for i in range(1, len(want.bodies) + 1)]
    named = {b.id: x.name for b, x in zip(bodies, want.bodies, strict=True)}
    named[BACKGROUND] = BACKGROUND
    joints = sorted((c.kind, named[c.a], named[c.b]) for c in scene.components.values() if isinstance(c, Joint))
    assert joints == sorted((j.kind, j.a, j.b) for j in want.joints)
    assert sorted(named[b.id] for b in bodies if scene.is_fixed(b.id)) == sorted(want.fixed)
    assert [m.text for m in session.messages if m.t < scenario.demo_start and m.kind == "note"] == list(want.messages)
    basket = next(b for b in bodies if b.label == "basket")
    assert outline_of(basket).container, "the basket must be a concave container (what lands in it is inside)"


@pytest.mark.parametrize("name", SCENARIOS)
def test_the_stored_journal_is_exactly_what_the_scenario_records(name: str, tmp_path) -> None:
    stored = journal_path(SCENARIOS[name])
    fresh = write_scenario_journal(SCENARIOS[name], tmp_path / stored.name)
    assert stored.read_bytes() == fresh.read_bytes(), f"{stored} differs from its scenario; {REGENERATE}"
    assert stored.stat().st_size < MAX_JOURNAL_BYTES


# -- what each demonstration records --------------------------------------------------------------------------


def the_chain(timeline: Timeline, ball: str) -> list[Event]:
    """The events, checked to be one causal chain: start, the ball's movement, then contact and the ball's new
    movement it causes, again and again (the pen holds the ball throughout; nothing else moves)."""
    events = list(timeline.events)
    kinds = [ev.type for ev in events]
    n = (len(events) - 2) // 2
    assert kinds == ["start", "movement", *["contact", "movement"] * n], kinds
    for cause, ev in pairwise(events):
        assert ev.causes == (cause.id,), f"{ev.id} should be caused by {cause.id} alone: {ev.causes}"
    for ev in events:
        if ev.type == "movement":
            assert ev.components == (ball,)
        elif ev.type == "contact":
            assert ev.components[0] == ball, "the ball's movement brought about every contact"
    return events


@pytest.mark.parametrize("name", SCENARIOS)
def test_the_demonstration_records_the_contacts_the_thesis_describes(name: str) -> None:
    session = session_over(name)
    names = labels(session)
    ball = next(cid for cid, label in names.items() if label == "ball")
    events = the_chain(session.timeline, ball)
    contacts = []
    for ev in events:
        if ev.type == "contact":
            other = ev.components[1]
            sides = dict(ev.sides)
            contacts.append((names.get(other, other), sides.get(ball), sides.get(other)))
    assert tuple(contacts) == CONTACTS[name]
    assert not [m.text for m in session.messages if m.t >= SCENARIOS[name].demo_start]


@pytest.mark.parametrize("name", FIRST_MOVEMENT_REGIONS)
def test_a_straight_drop_passes_above_or_below_platform_b(name: str) -> None:
    session = session_over(name)
    names = labels(session)
    movement = next(ev for ev in session.timeline.events if ev.type == "movement")
    regions = {names.get(c, c): rs for c, rs in movement.regions}
    for body, want in FIRST_MOVEMENT_REGIONS[name].items():
        assert regions.get(body) == want, f"relative to {body}: {regions}"


@pytest.mark.parametrize("name", SCENARIOS)
def test_replaying_a_demonstration_twice_gives_identical_timeline_files(name: str, replays: Replays) -> None:
    first, second = replays.folder(name, "a"), replays.folder(name, "b")
    text = (first / "timeline.json").read_bytes()
    assert text == (second / "timeline.json").read_bytes()
    assert b'"events"' in text
    assert (first / "timeline.txt").read_bytes() == (second / "timeline.txt").read_bytes()


# -- the thesis's judgements, on the replayed timelines ----------------------------------------------------------


def _says(result: Comparison, *words: str) -> bool:
    return any(all(w in reason for w in words) for reason in result.reasons)


def test_2_12_another_platform_hit_is_another_behaviour(replays: Replays) -> None:
    result = replays.judge("hits_a", "hits_b_once")
    assert not result.equivalent and result.qualitative_distance > 0
    assert _says(result, "platform a", "only in A") and _says(result, "platform b", "only in B"), result.reasons


def test_2_12_one_bounce_more_is_another_behaviour(replays: Replays) -> None:
    result = replays.judge("hits_b_once", "hits_b_twice")
    assert not result.equivalent and result.qualitative_distance > 0
    assert _says(result, "Contact between ball and platform b", "only in B"), result.reasons
    assert not result.only_a


@pytest.mark.parametrize(("a", "b"), [("hits_b_once", "hits_b_twice"), ("hits_b_twice", "hits_b_once")])
def test_2_12_one_bounce_more_stays_another_behaviour_for_a_simulation(a: str, b: str, replays: Replays) -> None:
    # SIMULATE forgives a simulation's bounces coming to rest after the demonstrated behaviour, not a bounce more
    # on platform B before the ball lands in the basket
    result = replays.judge(a, b, simulation=True)
    assert not result.equivalent and result.qualitative_distance >= 2 * UNMATCHED_EVENT_COST
    assert _says(result, "Contact between ball and platform b", "only in"), result.reasons


def test_2_13_the_top_and_the_bottom_of_platform_b_are_different_sides(replays: Replays) -> None:
    result = replays.judge("hits_b_once", "hits_b_bottom")
    assert not result.equivalent and result.qualitative_distance > 0
    assert not result.only_a and not result.only_b  # the same events: only their geometry differs
    assert _says(result, "platform b's side", "top in A", "bottom in B"), result.reasons
    assert _says(result, "ball's side", "bottom in A", "top in B"), result.reasons


def test_2_14_passing_above_or_below_platform_b_are_different_movements(replays: Replays) -> None:
    result = replays.judge("above_b", "below_b")
    assert not result.equivalent and result.qualitative_distance > 0
    assert not result.only_a and not result.only_b
    assert _says(result, "relative to platform b", "above", "below"), result.reasons
    assert all("platform b" in reason for reason in result.reasons), result.reasons  # nothing else differs


def test_2_15_the_same_events_along_other_paths_are_equivalent(replays: Replays) -> None:
    result = replays.judge("a_then_b_bottom", "a_then_b_bottom_again")
    assert result.equivalent, result.reasons
    assert result.qualitative_distance == 0 and not result.reasons
    assert result.quantitative_distance > 0  # the trajectories differ, visibly
    first, again = (replays.timeline(f"bouncing_{name}")[0] for name in ("a_then_b_bottom", "a_then_b_bottom_again"))
    times = [[ev.t0 for ev in timeline.events if ev.type == "contact"] for timeline in (first, again)]
    assert max(abs(x - y) for x, y in zip(*times, strict=True)) > 0.5  # and at other times


@pytest.mark.parametrize(("a", "b"), [("hits_a", "hits_b_once"), ("hits_b_once", "hits_b_twice"),
                                      ("hits_b_once", "hits_b_bottom"), ("above_b", "below_b"),
                                      ("a_then_b_bottom", "a_then_b_bottom_again")])
def test_each_judgement_is_the_same_either_way_round(a: str, b: str, replays: Replays) -> None:
    forth, back = replays.judge(a, b), replays.judge(b, a)
    assert (forth.equivalent, forth.qualitative_distance) == (back.equivalent, back.qualitative_distance)
    assert forth.quantitative_distance == pytest.approx(back.quantitative_distance)
