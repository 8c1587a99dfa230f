"""The causal timeline as a graph: events, ancestors/descendants/generations, cycles, and the
text, JSON and DOT outputs (thesis 2.3.3, 3.3.1-3.3.3), on hand-built egg-cracker timelines."""

from __future__ import annotations

import json
import re

import pytest

from physink_tui.errors import PhysinkError
from physink_tui.formats.timeline_dot import encode_timeline_dot as timeline_dot
from physink_tui.formats.timeline_json import EVENT_KEYS
from physink_tui.formats.timeline_json import decode_timeline_json as parse_timeline_json
from physink_tui.formats.timeline_json import encode_timeline_json as timeline_json
from physink_tui.timeline.events import Event, Timeline, TimelineError, TrajectoryPoint, default_label
from physink_tui.timeline.graph import (
    CausalCycleError,
    ancestors,
    check_acyclic,
    descendants,
    topological_generations,
)
from physink_tui.timeline.narrate import timeline_text

NAMES = {
    "b1": "ball", "b2": "rotating platform", "r1": "rope", "b3": "knife", "b4": "egg", "b5": "paddles",
    "b6": "frying pan", "b7": "second ball",
}


def _traj(x0: float, y0: float, t0: float, n: int = 3) -> tuple[TrajectoryPoint, ...]:
    return tuple(TrajectoryPoint(t0 + i / 3, x0 + i * 0.1, y0 + i / 3, 0.0, 0.3, 1.0) for i in range(n))


def mov(eid: str, cause: str, *components: str, t0: float = 0.0) -> Event:
    return Event(eid, "movement", components, (cause,), t0, t0 + 1, trajectory=_traj(1.0, 2.0, t0))


def con(eid: str, cause: str, a: str, sa: str, b: str, sb: str, t: float = 0.0) -> Event:
    return Event(eid, "contact", (a, b), (cause,), t, t, sides=((a, sa), (b, sb)), point=(1.5, 2.5))


def egg_cracker() -> Timeline:
    """Figure 3-4's timeline plus an unrelated second ball falling from the start (the pinball's ball 2)."""
    tl = Timeline()
    for ev in (
        Event("e1", "start"),
        Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0, trajectory=_traj(1.0, 0.0, 0.0),
              regions=(("b2", ("above", "left")),)),
        con("e3", "e2", "b1", "bottom", "b2", "top", t=1.0),
        mov("e4", "e3", "b1", t0=1.0),
        mov("e5", "e3", "b2", "r1", "b3", t0=1.0),
        con("e6", "e5", "b3", "bottom", "b4", "top", t=2.0),
        mov("e7", "e6", "b3", t0=2.0),
        mov("e8", "e6", "b4", t0=2.0),
        con("e9", "e8", "b4", "bottom", "b5", "top", t=3.0),
        mov("e10", "e9", "b5", t0=3.0),
        mov("e11", "e9", "b4", t0=3.0),
        con("e12", "e11", "b4", "bottom", "b6", "inside", t=4.0),
        mov("e13", "e1", "b7", t0=0.5),
    ):
        tl = tl.add(ev)
    return tl


EGG_TEXT = """\
Movement of ball CAUSES
-- Contact between ball and rotating platform CAUSES
---- Movement of ball
---- Movement of rotating platform [attached to rope, knife] CAUSES
------ Contact between knife and egg CAUSES
-------- Movement of knife
-------- Movement of egg CAUSES
---------- Contact between egg and paddles CAUSES
------------ Movement of paddles
------------ Movement of egg CAUSES
-------------- Contact between egg and frying pan
Movement of second ball"""


# --- events and the Timeline value -------------------------------------------------------------------------------

def test_timeline_is_a_frozen_value_and_add_returns_a_new_one() -> None:
    tl = egg_cracker()
    bigger = tl.add(mov("e14", "e12", "b4"))
    assert len(tl) == 13 and len(bigger) == 14
    assert tl.ids() == tuple(f"e{i}" for i in range(1, 14))
    assert tl.event("e5").components == ("b2", "r1", "b3")
    assert tl.children("e3") == ("e4", "e5")
    assert tl.children("e1") == ("e2", "e13")
    assert tl.children("e12") == ()
    with pytest.raises(AttributeError):
        tl.events = ()  # type: ignore[misc]


@pytest.mark.parametrize(
    ("make", "fragment"),
    [
        (lambda tl: tl.add(Event("e2", "start")), "'e2' is already"),
        (lambda tl: tl.add(Event("e99", "movement", ("b1",), ("e42",))), "unknown cause 'e42'"),
        (lambda tl: tl.event("e42"), "no event 'e42'"),
        (lambda tl: tl.children("e42"), "no event 'e42'"),
        (lambda tl: tl.remove(["e42"]), "no event 'e42'"),
        (lambda tl: tl.remove(["e3"]), "'e4' is caused by it"),
    ],
)
def test_bad_timeline_operations_raise_timeline_errors(make, fragment: str) -> None:
    with pytest.raises(TimelineError, match=re.escape(fragment)) as info:
        make(egg_cracker())
    assert isinstance(info.value, PhysinkError)


@pytest.mark.parametrize(
    ("kwargs", "fragment"),
    [
        ({"type": "bounce"}, "type 'bounce'"),
        ({"type": "contact", "sides": (("b1", "middle"),)}, "side 'middle'"),
        ({"type": "movement", "regions": (("b2", ("behind",)),)}, "region 'behind'"),
        ({"type": "movement", "t0": 2.0, "t1": 1.0}, "before it starts"),
        ({"type": "contact", "trajectory": _traj(0, 0, 0)}, "only movements"),
        ({"type": "movement", "sides": (("b1", "top"),)}, "only contacts"),
        ({"type": "movement", "causes": ("e5",)}, "names itself"),
    ],
)
def test_invalid_events_are_refused(kwargs: dict, fragment: str) -> None:
    with pytest.raises(TimelineError, match=re.escape(fragment)):
        Event(**{"id": "e5", "components": ("b1",), **kwargs})


def test_default_labels_follow_the_thesis() -> None:
    tl = egg_cracker()
    assert default_label(tl.event("e1"), NAMES) == "Start"
    assert default_label(tl.event("e2"), NAMES) == "Movement of ball"
    assert default_label(tl.event("e3"), NAMES) == "Contact between ball and rotating platform"
    assert default_label(tl.event("e5"), NAMES) == "Movement of rotating platform [attached to rope, knife]"
    assert default_label(Event("e9", "end_contact", ("b1", "b8")), NAMES) == "End of contact between ball and b8"
    assert default_label(Event("e9", "contact", ("b1", "b2", "b3")), {}) == "Contact between b1, b2 and b3"


def test_a_user_label_replaces_the_default_narration() -> None:
    tl = egg_cracker().relabel("e12", "the egg lands in the frying pan")
    assert timeline_text(tl, NAMES).splitlines()[-2] == "-------------- the egg lands in the frying pan"
    assert timeline_text(tl.relabel("e12", None), NAMES) == EGG_TEXT


# --- graph vocabulary ----------------------------------------------------------------------------------------------

def test_ancestors_and_descendants() -> None:
    tl = egg_cracker()
    assert ancestors(tl, "e12") == {"e1", "e2", "e3", "e5", "e6", "e8", "e9", "e11"}
    assert ancestors(tl, "e13") == {"e1"}
    assert ancestors(tl, "e1") == set()
    assert descendants(tl, "e8") == {"e9", "e10", "e11", "e12"}
    assert descendants(tl, "e1") == set(tl.ids()) - {"e1"}
    assert descendants(tl, "e13") == set()
    with pytest.raises(TimelineError, match="'e42'"):
        ancestors(tl, "e42")


def test_topological_generations_are_layers_in_creation_order() -> None:
    assert topological_generations(egg_cracker()) == [
        ["e1"], ["e2", "e13"], ["e3"], ["e4", "e5"], ["e6"], ["e7", "e8"], ["e9"], ["e10", "e11"], ["e12"],
    ]
    assert topological_generations(Timeline()) == []


def test_an_event_with_two_causes_waits_for_both() -> None:
    """The basketball collision: a contact caused by both balls' movements."""
    tl = Timeline((
        Event("e1", "start"),
        mov("e2", "e1", "b1"),
        mov("e3", "e1", "b2"),
        Event("e4", "contact", ("b1", "b2"), ("e2", "e3"), 1.0, 1.0),
        mov("e5", "e4", "b1"),
        mov("e6", "e4", "b2"),
    ))
    assert topological_generations(tl) == [["e1"], ["e2", "e3"], ["e4"], ["e5", "e6"]]
    assert ancestors(tl, "e5") == {"e1", "e2", "e3", "e4"}
    assert timeline_text(tl, {"b1": "ball 1", "b2": "ball 2"}) == """\
Movement of ball 1 CAUSES
-- Contact between ball 1 and ball 2 (#1) CAUSES
---- Movement of ball 1
---- Movement of ball 2
Movement of ball 2 CAUSES
-- Contact between ball 1 and ball 2 (#1, see above)"""


def cyclic() -> Timeline:
    # Only a timeline built directly (e.g. read from a file) can hold a cycle: `add` needs causes to exist already.
    return Timeline((
        Event("e1", "start"),
        Event("e2", "movement", ("b1",), ("e1", "e4")),
        Event("e3", "contact", ("b1", "b2"), ("e2",)),
        Event("e4", "movement", ("b2",), ("e3",)),
    ))


def test_a_cycle_raises_causal_cycle_error_naming_it() -> None:
    check_acyclic(egg_cracker())
    with pytest.raises(CausalCycleError) as info:
        check_acyclic(cyclic())
    assert isinstance(info.value, PhysinkError)
    assert info.value.cycle == ("e2", "e3", "e4")
    assert "'e2' -> 'e3' -> 'e4' -> 'e2'" in str(info.value)
    for use in (topological_generations, lambda tl: timeline_text(tl, {})):
        with pytest.raises(CausalCycleError, match="'e2' -> 'e3' -> 'e4' -> 'e2'"):
            use(cyclic())


def test_the_cycle_of_an_event_causing_itself_is_refused_at_once() -> None:
    with pytest.raises(TimelineError, match="names itself"):
        Event("e2", "movement", ("b1",), ("e2",))


# --- outputs -------------------------------------------------------------------------------------------------------

def test_text_has_the_thesis_shape() -> None:
    tl = egg_cracker()
    assert timeline_text(tl, NAMES) == EGG_TEXT
    assert timeline_text(tl, NAMES) == timeline_text(egg_cracker(), dict(reversed(NAMES.items())))
    shown = timeline_text(tl, NAMES, show_start=True).splitlines()
    assert shown[0] == "Start CAUSES" and shown[1] == "-- Movement of ball CAUSES"
    assert shown[-1] == "-- Movement of second ball"
    assert timeline_text(Timeline((Event("e1", "start"),)), NAMES) == "Start"
    assert timeline_text(Timeline(), NAMES) == ""


def test_json_has_the_design_keys_and_is_deterministic() -> None:
    text = timeline_json(egg_cracker(), NAMES)
    assert text == timeline_json(egg_cracker(), dict(NAMES))
    doc = json.loads(text)
    assert [e["id"] for e in doc["events"]] == list(egg_cracker().ids())
    for obj in doc["events"]:
        assert tuple(obj) == EVENT_KEYS
    e3, e5, e12 = (doc["events"][i] for i in (2, 4, 11))
    assert e3["components"] == [{"id": "b1", "label": "ball"}, {"id": "b2", "label": "rotating platform"}]
    assert e3["causes"] == ["e2"] and e3["label"] == "Contact between ball and rotating platform"
    assert e12["sides"] == [{"component": "b4", "label": NAMES.get("b4"), "side": "bottom"},
                            {"component": "b6", "label": NAMES.get("b6"), "side": "inside"}]
    assert doc["events"][1]["regions"] == [{"component": "b2", "label": "rotating platform",
                                            "regions": ["above", "left"]}]
    assert e5["trajectory"][1] == [1.333333, 1.1, 2.333333, 0.0, 0.3, 1.0]
    assert e5["sides"] == [] and e3["trajectory"] == [] and e3["point"] == [1.5, 2.5]


def test_json_round_trips() -> None:
    tl = egg_cracker().relabel("e2", "the ball falls")
    text = timeline_json(tl, NAMES)
    back, names = parse_timeline_json(text)
    assert names == NAMES
    assert back.ids() == tl.ids()
    assert back.event("e2").label == "the ball falls" and back.event("e3").label is None
    assert back.event("e12").sides == tl.event("e12").sides
    assert back.event("e2").regions == tl.event("e2").regions
    assert timeline_json(back, names) == text


def test_json_keeps_the_label_of_a_body_only_passed_by() -> None:
    passed = Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0, regions=(("b9", ("below",)),))
    tl = Timeline((Event("e1", "start"), passed))
    _, names = parse_timeline_json(timeline_json(tl, {"b1": "ball", "b9": "platform b"}))
    assert names == {"b1": "ball", "b9": "platform b"}


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("[", "not valid JSON"),
        ('{"events": [], "events": []}', "repeats key 'events'"),
        ("{}", "events: expected a list of events, but it is missing"),
        ('{"events": [{"id": "e1"}]}', "events[0].components: expected a list, but it is missing"),
        ('{"events": [{"id": "e1", "type": "start", "components": [], "causes": [], "sides": [], "regions": [], '
         '"trajectory": [], "t1": 0, "t0": true}]}', "events[0].t0: expected a number, got true"),
    ],
)
def test_bad_json_names_the_problem(text: str, fragment: str) -> None:
    with pytest.raises(TimelineError, match=re.escape(fragment)):
        parse_timeline_json(text)


def test_json_with_a_cycle_is_refused() -> None:
    with pytest.raises(CausalCycleError):
        parse_timeline_json(timeline_json(cyclic(), {}))


def test_dot_has_every_event_and_every_edge() -> None:
    tl = egg_cracker().relabel("e12", 'the egg lands "in" the pan')
    dot = timeline_dot(tl, NAMES)
    assert dot.startswith("digraph timeline {") and dot.rstrip().endswith("}")
    assert dot == timeline_dot(tl, NAMES)
    edges = set(re.findall(r'^  "(e\d+)" -> "(e\d+)";$', dot, re.M))
    assert edges == {(c, ev.id) for ev in tl.events for c in ev.causes}
    assert len(edges) == 12
    assert '"e5" [label="Movement of rotating platform [attached to rope, knife]"];' in dot
    assert '"e12" [label="the egg lands \\"in\\" the pan"];' in dot
    assert len(re.findall(r"\[label=", dot)) == len(tl)
