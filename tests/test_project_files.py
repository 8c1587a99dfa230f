"""Project files: exact round trips, identical bytes, errors naming the JSON path, newer versions, atomic saves."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physink_tui import __version__
from physink_tui.errors import PhysinkError, SceneError
from physink_tui.formats.project.codec import (
    FORMAT_VERSION,
    Project,
    decode_project,
    encode_project,
    project_vocabulary,
    vocabulary_lines,
)
from physink_tui.formats.project.files import load_project, save_project
from physink_tui.formats.timeline_json import timeline_object
from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Material, Rope, Scene, Spring
from physink_tui.timeline.events import Event, Timeline, TrajectoryPoint
from physink_tui.timeline.phrases import Vocabulary


def _ellipse(rx: float, ry: float, sides: int = 32) -> tuple[tuple[float, float], ...]:
    return tuple((rx * math.cos(2 * math.pi * k / sides), ry * math.sin(2 * math.pi * k / sides)) for k in range(sides))


def _every_kind() -> Scene:
    """A scene with one of everything, built as the interpreter builds scenes: ids from the scene, then add."""
    scene = Scene()
    bodies = [
        ("box", ((-50.0, -10.0), (50.0, -10.0), (50.0, 10.0), (-50.0, 10.0)), 0.0, (400.0, 550.0), "floor"),
        ("circle", (), 20.0, (0.1 + 0.2, 100.0), "ball"),
        ("ellipse", _ellipse(30.0, 15.0), 0.0, (250.5, 300.25), None),
        ("polygon", ((0.0, 0.0), (40.0, 0.0), (40.0, 40.0), (20.0, 10.0), (0.0, 40.0)), 0.0, (600.0, 200.0), None),
        ("polyline", ((-100.0, -20.0), (0.0, 0.0), (100.0, 25.0)), 0.0, (300.0, 400.0), "ramp"),
    ]
    ids = []
    for shape, outline, radius, position, label in bodies:
        bid, scene = scene.new_id("b")
        material = MATERIALS["box" if shape == "box" else "round" if shape in ("circle", "ellipse") else "freeform"]
        scene = scene.add(Body(bid, shape, outline, radius, position, 0.125 * len(ids), material, label))
        ids.append(bid)
    floor, ball, egg, lever, ramp = ids
    jid, scene = scene.new_id("j")
    scene = scene.add(Joint(jid, "pivot", lever, BACKGROUND, (600.0, 200.0)))
    jid, scene = scene.new_id("j")
    scene = scene.add(Joint(jid, "weld", ramp, floor, (350.0, 420.0)))
    rid, scene = scene.new_id("r")
    scene = scene.add(Rope(rid, ((0.3, 120.0), (10.0, 150.0), (20.0, 180.5)), ball, None, "string"))
    sid, scene = scene.new_id("s")
    return scene.add(Spring(sid, floor, egg, (380.0, 540.0), (250.5, 315.25), "vertical", 224.75, 20.0, "spring"))


def _demonstration() -> Timeline:
    """The ball (b2) falls onto the floor (b1) and bounces; numbers as a file holds them (6 decimals)."""
    frames = (TrajectoryPoint(0.0, 0.3, 100.0, 0.0, 0.0, 0.0), TrajectoryPoint(0.5, 0.3, 520.5, 0.125, 0.0, 490.5))
    return Timeline((
        Event("e1", "start"),
        Event("e2", "movement", ("b2", "r1"), ("e1",), 0.0, 0.5, None, (), (("b5", ("above",)),), frames),
        Event("e3", "contact", ("b2", "b1"), ("e2",), 0.5, 0.5, "the ball lands", (("b2", "bottom"), ("b1", "top")),
              (), (), (0.3, 540.0)),
    ))


PROJECT = Project(_every_kind(), ("verb plummets Topples", "prep amid", "verb écrase"), _demonstration(),
                  (800.0, 600.0))
"""Every component kind, user vocabulary, a timeline; the base of the error cases below."""


def _raw() -> dict[str, Any]:
    return json.loads(encode_project(PROJECT))


# --- round trips ---------------------------------------------------------------------------------------------------


def test_every_component_kind_round_trips_in_scene_order() -> None:
    text = encode_project(PROJECT)

    back = decode_project(text, "project.json")

    assert back == PROJECT
    assert list(back.scene.components) == list(PROJECT.scene.components)
    assert back.scene.next_id == {"b": 6, "j": 3, "r": 2, "s": 2}
    assert [type(c).__name__ for c in back.scene.components.values()] == (
        ["Body"] * 5 + ["Joint", "Joint", "Rope", "Spring"])


def test_encoding_is_deterministic_and_survives_a_round_trip_byte_for_byte() -> None:
    text = encode_project(PROJECT)

    assert encode_project(PROJECT) == text
    assert encode_project(decode_project(text, "project.json")) == text


def test_the_layout_is_indented_json_with_one_component_a_line_in_a_fixed_key_order() -> None:
    lines = encode_project(PROJECT).splitlines()

    assert lines[:5] == ["{", '  "format": "physink-project",', '  "version": 2,',
                         f'  "program": "physink-tui {__version__}",', '  "canvas": {"width": 800.0, "height": 600.0},']
    assert lines[5] == '  "components": ['
    assert lines[6].startswith('    {"id": "b1", "type": "body", "shape": "box", "outline": [[-50.0, -10.0], ')
    assert lines[6].endswith('"material": {"density": 1.0, "restitution": 1.0, "friction": 1.0}, "label": "floor"},')
    assert lines[11] == ('    {"id": "j1", "type": "joint", "kind": "pivot", "a": "b4", "b": "background", '
                         '"anchor": [600.0, 200.0]},')
    assert lines[13] == ('    {"id": "r1", "type": "rope", "points": [[0.3, 120.0], [10.0, 150.0], [20.0, 180.5]], '
                         '"start_body": "b2", "end_body": null, "label": "string"},')
    timeline = json.dumps(timeline_object(_demonstration(), PROJECT.scene.names()), ensure_ascii=False,
                          separators=(", ", ": "))
    assert lines[-6:] == ["  ],", '  "next_id": {"b": 6, "j": 3, "r": 2, "s": 2},',
                          '  "vocabulary": ["verb plummets Topples", "prep amid", "verb écrase"],',
                          f'  "timeline": {timeline},', '  "demonstration": null', "}"]
    assert '"components": [{"id": "b2", "label": "ball"}, {"id": "r1", "label": "string"}]' in timeline


def test_floats_are_written_exactly_and_integers_become_floats() -> None:
    body = Body("b1", "circle", (), 7, (0.1 + 0.2, -0.0), 1e-300, Material(2, 1, 0))
    project = Project(Scene({"b1": body}, {"b": 2}), (), None, (1024, 768))

    text = encode_project(project)
    back = decode_project(text, "p.json")

    assert '"position": [0.30000000000000004, -0.0]' in text and '"angle": 1e-300' in text
    assert back.scene.components["b1"].position == (0.30000000000000004, -0.0)
    assert math.copysign(1.0, back.scene.components["b1"].position[1]) == -1.0
    assert type(back.scene.components["b1"].radius) is float and back.canvas == (1024.0, 768.0)
    assert encode_project(back) == text


def test_the_timeline_is_typed_and_named_by_the_scene() -> None:
    back = decode_project(encode_project(PROJECT), "p.json")

    assert isinstance(back.timeline, Timeline) and back.timeline == _demonstration()
    raw = _raw()
    raw["timeline"]["events"][1]["components"][0]["label"] = "not the scene's name"
    assert decode_project(json.dumps(raw), "p.json") == PROJECT  # names come from the scene's labels


def test_an_adopted_simulation_keeps_the_demonstration_it_was_found_for() -> None:
    simulated = Timeline((Event("e1", "start"), Event("e2", "movement", ("b2",), ("e1",), 0.0, 0.75)))
    adopted = replace(PROJECT, timeline=simulated, demonstration=_demonstration())
    text = encode_project(adopted)

    assert decode_project(text, "p.json") == adopted and encode_project(decode_project(text, "p.json")) == text
    assert json.loads(text)["demonstration"] == json.loads(encode_project(PROJECT))["timeline"]
    raw = json.loads(text)
    raw["demonstration"]["events"][1]["causes"] = ["e9"]
    with pytest.raises(SceneError, match=r"^p\.json: demonstration: event 'e2' names unknown cause 'e9'"):
        decode_project(json.dumps(raw), "p.json")


@pytest.mark.parametrize("change", [
    lambda raw: raw["demonstration"]["events"][1]["components"][0].update(id="b99"),
    lambda raw: raw["demonstration"]["events"][0]["in_contact"].append([{"id": "b2"}, {"id": "b99"}]),
])
def test_a_kept_demonstration_naming_a_body_the_scene_lacks_still_loads(change, tmp_path) -> None:
    """What a user gets by erasing a body after adopting a simulation (sketch edits keep the demonstration) and
    saving: still their work, so it loads with the ids it names, as a timeline naming an erased body does
    (tests/test_newer_commands_faults.py); `physink simulate` is what refuses such a timeline."""
    simulated = Timeline((Event("e1", "start"), Event("e2", "movement", ("b2",), ("e1",), 0.0, 0.75)))
    raw = json.loads(encode_project(replace(PROJECT, timeline=simulated, demonstration=_demonstration())))
    change(raw)
    target = tmp_path / "adopted.physink.json"
    target.write_text(json.dumps(raw), encoding="utf-8")
    loaded = load_project(target)
    assert loaded.demonstration is not None
    named = {c for ev in loaded.demonstration.events for c in (*ev.components, *(i for pair in ev.in_contact
                                                                                   for i in pair))}
    assert "b99" in named


def test_the_vocabulary_round_trips_as_the_sessions_vocabulary() -> None:
    vocabulary = Vocabulary(frozenset({"plummets", "topples"}), frozenset({"amid"}))
    project = Project(Scene(), vocabulary_lines(vocabulary), None, (10.0, 10.0))

    back = decode_project(encode_project(project), "p.json")

    assert back.vocabulary == ("verb plummets topples", "prep amid")
    assert project_vocabulary(back) == vocabulary
    assert project_vocabulary(PROJECT) == Vocabulary(frozenset({"plummets", "topples", "écrase"}), frozenset({"amid"}))


finite = st.floats(allow_nan=False, allow_infinity=False)
points = st.tuples(finite, finite)


@st.composite
def bodies(draw: st.DrawFn, bid: str) -> Body:
    shape = draw(st.sampled_from(["box", "circle", "ellipse", "polygon", "polyline"]))
    least = 2 if shape == "polyline" else 3
    outline = () if shape == "circle" else tuple(draw(st.lists(points, min_size=least, max_size=40)))
    radius = draw(st.floats(min_value=0.0, exclude_min=True, allow_infinity=False)) if shape == "circle" else 0.0
    material = Material(
        draw(st.floats(min_value=0.0, exclude_min=True, allow_infinity=False)),
        draw(st.floats(min_value=0.0, max_value=1.0)),
        draw(st.floats(min_value=0.0, allow_infinity=False)),
    )
    label = draw(st.none() | st.text(min_size=1, max_size=20))
    return Body(bid, shape, outline, radius, draw(points), draw(finite), material, label)


@settings(max_examples=150, deadline=None)
@given(st.integers(min_value=0, max_value=6).flatmap(lambda n: st.tuples(*(bodies(f"b{i + 1}") for i in range(n)))),
       st.lists(st.sampled_from(["verb plummets", "prep amid AMONG", "verb écrase", "verb it's  re-lands"]),
                max_size=4))
def test_random_bodies_round_trip_exactly(drawn: tuple[Body, ...], words: list[str]) -> None:
    scene = Scene({b.id: b for b in drawn}, {"b": len(drawn) + 1, "j": 1, "r": 1, "s": 1})
    project = Project(scene, tuple(words), None, (640.0, 480.0))

    text = encode_project(project)
    back = decode_project(text, "p.json")

    assert back == project
    assert encode_project(back) == text


# --- errors that name the field ------------------------------------------------------------------------------------


def _set(path: tuple[Any, ...], value: Any) -> Callable[[dict[str, Any]], None]:
    def change(raw: dict[str, Any]) -> None:
        target = raw
        for step in path[:-1]:
            target = target[step]
        target[path[-1]] = value
    return change


def _drop(path: tuple[Any, ...]) -> Callable[[dict[str, Any]], None]:
    def change(raw: dict[str, Any]) -> None:
        target = raw
        for step in path[:-1]:
            target = target[step]
        del target[path[-1]]
    return change


def _append(component: dict[str, Any]) -> Callable[[dict[str, Any]], None]:
    return lambda raw: raw["components"].append(component)


# Scene order of PROJECT: 0 b1 box, 1 b2 circle, 2 b3 ellipse, 3 b4 polygon, 4 b5 polyline,
# 5 j1 pivot, 6 j2 weld, 7 r1 rope, 8 s1 spring.
ERRORS = [
    pytest.param(_set(("components", 3, "material", "friction"), "high"),
                 'components[3].material.friction: expected a number >= 0, got "high"', id="friction-text"),
    pytest.param(_set(("components", 0, "material", "density"), 0), "components[0].material.density: expected a "
                 "number > 0, got 0", id="density-zero"),
    pytest.param(_set(("components", 1, "material", "restitution"), 1.5),
                 "components[1].material.restitution: expected a number in [0, 1], got 1.5", id="restitution-high"),
    pytest.param(_drop(("components", 2, "material")), 'components[2].material: expected an object {"density", '
                 '"restitution", "friction"}, but it is missing', id="missing-material"),
    pytest.param(_drop(("components", 0, "position")), "components[0].position: expected a point [x, y], but it is "
                 "missing", id="missing-position"),
    pytest.param(_drop(("canvas", "height")), "canvas.height: expected a number > 0, but it is missing",
                 id="missing-canvas-height"),
    pytest.param(_drop(("vocabulary",)), "vocabulary: expected a list of vocabulary lines (strings), but it is missing",
                 id="missing-vocabulary"),
    pytest.param(_set(("components", 5, "type"), "motor"),
                 'components[5].type: expected one of "body", "joint", "rope", "spring", got "motor"',
                 id="unknown-type"),
    pytest.param(_set(("components", 4, "id"), "b1"),
                 'components[4].id: expected an id no other component has, got "b1" (already the id of components[0])',
                 id="duplicate-id"),
    pytest.param(_set(("components", 2, "id"), "background"), 'components[2].id: expected an id other than '
                 '"background"', id="background-id"),
    pytest.param(_set(("components", 5, "a"), "b9"),
                 'components[5].a: expected the id of a body, got "b9" (no component has that id)',
                 id="joint-unknown-body"),
    pytest.param(_set(("components", 5, "a"), "background"),
                 'components[5].a: expected the id of a body, got "background" (the background)',
                 id="joint-drawn-in-background"),
    pytest.param(_set(("components", 6, "b"), "b5"),
                 'components[6].b: expected something other than the other end "b5", got "b5"', id="weld-to-itself"),
    pytest.param(_set(("components", 8, "b"), "j1"), 'components[8].b: expected "background" or the id of a body, '
                 'got "j1" (a joint, not a body)', id="spring-to-joint"),
    pytest.param(_set(("components", 7, "end_body"), "b7"), 'components[7].end_body: expected null, "background" or '
                 'the id of a body, got "b7" (no component has that id)', id="rope-unknown-body"),
    pytest.param(_set(("components", 0, "angle"), math.nan), "components[0].angle: expected a finite number "
                 "(radians), got NaN", id="nan-angle"),
    pytest.param(_set(("components", 1, "position"), [1.0, math.inf]), "components[1].position[1]: expected a finite "
                 "number, got Infinity", id="infinite-position"),
    pytest.param(_set(("components", 7, "points", 1), [1.0, 2.0, 3.0]), "components[7].points[1]: expected a point "
                 "[x, y], got [1.0, 2.0, 3.0]", id="point-of-three"),
    pytest.param(_set(("components", 6, "anchor", 0), True), "components[6].anchor[0]: expected a finite number, got "
                 "true", id="bool-is-no-number"),
    pytest.param(_set(("components", 0, "outline"), [[0, 0], [1, 0]]), "components[0].outline: expected a list of at "
                 "least 3 points [x, y], got [[0, 0], [1, 0]]", id="box-two-points"),
    pytest.param(_set(("components", 2, "outline"), [[0, 0], [1, 1]]), "components[2].outline: expected a list of at "
                 "least 3 points", id="ellipse-two-points"),
    pytest.param(_set(("components", 3, "outline"), []), "components[3].outline: expected a list of at least 3 points "
                 "[x, y], got []", id="polygon-no-points"),
    pytest.param(_set(("components", 4, "outline"), [[0, 0]]), "components[4].outline: expected a list of at least 2 "
                 "points [x, y], got [[0, 0]]", id="polyline-one-point"),
    pytest.param(_set(("components", 7, "points"), [[0, 0]]), "components[7].points: expected a list of at least 2 "
                 "points", id="rope-one-point"),
    pytest.param(_set(("components", 1, "outline"), [[0, 0], [1, 0], [0, 1]]), "components[1].outline: expected [] "
                 "(a circle is given by its radius)", id="circle-with-outline"),
    pytest.param(_set(("components", 1, "radius"), 0.0), "components[1].radius: expected a number > 0, got 0.0",
                 id="circle-radius-zero"),
    pytest.param(_set(("components", 0, "radius"), 3.0), "components[0].radius: expected 0 (only a circle has a "
                 "radius), got 3.0", id="box-with-radius"),
    pytest.param(_set(("components", 0, "shape"), "star"), 'components[0].shape: expected one of "box", "circle", '
                 '"ellipse", "polygon", "polyline", got "star"', id="unknown-shape"),
    pytest.param(_set(("components", 5, "kind"), "hinge"), 'components[5].kind: expected one of "pivot", "weld"',
                 id="unknown-joint-kind"),
    pytest.param(_set(("components", 8, "axis"), "diagonal"), 'components[8].axis: expected one of "horizontal", '
                 '"vertical", got "diagonal"', id="unknown-axis"),
    pytest.param(_set(("components", 8, "k"), -1), "components[8].k: expected a number > 0, got -1",
                 id="negative-k"),
    pytest.param(_set(("components", 8, "label"), ""), 'components[8].label: expected null or a non-empty string, '
                 'got ""', id="empty-label"),
    pytest.param(_set(("components", 3), [1, 2]), "components[3]: expected an object (a component), got [1, 2]",
                 id="component-not-object"),
    pytest.param(_append({"type": "body"}), "components[9].id: expected a non-empty string, but it is missing",
                 id="missing-id"),
    pytest.param(_set(("components",), {}), "components: expected a list of components, got {}",
                 id="components-not-list"),
    pytest.param(_set(("canvas", "width"), -800), "canvas.width: expected a number > 0, got -800",
                 id="negative-canvas"),
    pytest.param(_set(("next_id", "b"), 3), "next_id.b: expected an integer > 5, so that no id is made twice, got 3 "
                 '(components[4] has the id "b5")', id="next-id-would-reuse"),
    pytest.param(_set(("next_id", "j"), 1.5), "next_id.j: expected an integer >= 1, got 1.5", id="next-id-float"),
    pytest.param(_set(("vocabulary", 1), 7), "vocabulary[1]: expected a vocabulary line, 'verb WORD...' or "
                 "'prep WORD...', got 7", id="vocabulary-number"),
    pytest.param(_set(("vocabulary", 1), "ball"), "vocabulary[1]: expected a vocabulary line, 'verb WORD...' or "
                 "'prep WORD...', got \"ball\"", id="vocabulary-not-a-line"),
    pytest.param(_set(("vocabulary", 1), "verb a\nprep b"), "vocabulary[1]: expected a vocabulary line",
                 id="vocabulary-two-lines"),
    pytest.param(_set(("timeline",), [1]), "timeline: expected null or an object, got [1]", id="timeline-list"),
    pytest.param(_set(("timeline", "events", 1, "t0"), math.nan), "timeline.events[1].t0: expected a finite number "
                 "of at most 1e+09 in size, got NaN", id="timeline-nan"),
    pytest.param(_drop(("timeline", "events", 2, "sides")), "timeline.events[2].sides: expected a list, but it is "
                 "missing", id="timeline-missing-sides"),
    pytest.param(_set(("timeline", "events", 0, "causes"), ["e3"]), "timeline: the timeline has a causal cycle",
                 id="timeline-cycle"),
    pytest.param(_set(("version",), "1"), 'version: expected an integer from 1 to 2, got "1"', id="version-text"),
    pytest.param(_set(("format",), "physink-journal"), 'format: expected "physink-project", got "physink-journal"',
                 id="wrong-format"),
    pytest.param(_drop(("program",)), "program: expected a string naming the program that wrote it, but it is "
                 "missing", id="missing-program"),
]


@pytest.mark.parametrize(("change", "message"), ERRORS)
def test_a_bad_field_is_named_by_its_json_path(change: Callable[[dict[str, Any]], None], message: str) -> None:
    raw = _raw()
    change(raw)
    text = json.dumps(raw, ensure_ascii=False, indent=2)

    with pytest.raises(SceneError) as caught:
        decode_project(text, "project.json")

    assert str(caught.value).startswith(f"project.json: {message}")
    assert "\n" not in str(caught.value)


@pytest.mark.parametrize(("text", "message"), [
    pytest.param("", "project.json: not valid JSON (Expecting value at line 1, column 1)", id="empty"),
    pytest.param('{\n  "format": "physink-project",\n  "version": 1,,\n}', "project.json: not valid JSON (Expecting "
                 'property name enclosed in double quotes at line 3, column 16)', id="syntax"),
    pytest.param('{"format": "physink-project", "format": "physink-project"}', 'project.json: not valid JSON: key '
                 '"format" appears twice in one object', id="duplicate-key"),
    pytest.param("[1, 2]", "project.json: expected a JSON object (a physink project), got [1, 2]", id="not-object"),
])
def test_text_that_is_no_project_object_is_refused_in_one_line(text: str, message: str) -> None:
    with pytest.raises(SceneError) as caught:
        decode_project(text, "project.json")

    assert str(caught.value) == message


def test_a_project_from_a_newer_version_is_refused_naming_both_versions() -> None:
    raw = {"format": "physink-project", "version": FORMAT_VERSION + 1, "scene": "laid out some new way"}

    with pytest.raises(SceneError) as caught:
        decode_project(json.dumps(raw), "project.json")

    assert str(caught.value) == ("project.json was written by format version 3; this program reads version 2 "
                                 "(upgrade physink-tui)")


def test_a_rope_end_may_name_a_body_made_after_the_rope() -> None:
    rope = Rope("r1", ((0.0, 0.0), (5.0, 5.0)), None, "b1")
    ball = Body("b1", "circle", (), 2.0, (5.0, 5.0), 0.0, MATERIALS["round"])
    project = Project(Scene({"r1": rope, "b1": ball}, {"b": 2, "r": 2}), (), None, (100.0, 100.0))

    assert decode_project(encode_project(project), "p.json") == project


def test_unknown_keys_are_ignored_with_a_warning() -> None:
    raw = _raw()
    raw["colour"] = "blue"
    raw["components"][0]["friction_note"] = 1
    raw["components"][1]["material"]["hardness"] = 2
    warnings: list[str] = []

    project = decode_project(json.dumps(raw), "p.json", warnings=warnings)

    assert project == PROJECT
    assert warnings == ['p.json: unknown key "colour" ignored', 'p.json: unknown key "components[0].friction_note" '
                        'ignored', 'p.json: unknown key "components[1].material.hardness" ignored']


def test_encoding_checks_the_project_with_the_same_rules() -> None:
    bad_body = Body("b1", "circle", (), math.nan, (0.0, 0.0), 0.0, MATERIALS["round"])
    with pytest.raises(SceneError, match=r"^project: components\[0\]\.radius: expected a number > 0, got NaN$"):
        encode_project(Project(Scene({"b1": bad_body}, {"b": 2}), (), None, (10.0, 10.0)))

    moved = Body("b2", "circle", (), 1.0, (0.0, 0.0), 0.0, MATERIALS["round"])
    with pytest.raises(SceneError, match=r'components\[0\]\.id: expected "b1", the key the scene keeps it under'):
        encode_project(Project(Scene({"b1": moved}, {"b": 3}), (), None, (10.0, 10.0)))

    endless = Timeline((Event("e1", "start", t1=math.inf),))
    with pytest.raises(SceneError, match=r"^out\.json: timeline\.events\[0\]\.t1: expected a finite number of at "
                                         r"most 1e\+09 in size, got Infinity$"):
        encode_project(Project(Scene(), (), endless, (10.0, 10.0)), where="out.json")

    with pytest.raises(TypeError):
        encode_project(Project(Scene(), (), {"events": []}, (10.0, 10.0)))  # type: ignore[arg-type]

    with pytest.raises(TypeError):
        encode_project(Scene())  # type: ignore[arg-type]


# --- files ---------------------------------------------------------------------------------------------------------


def test_save_then_load_gives_the_project_back(tmp_path) -> None:
    target = tmp_path / "machine.physink.json"

    save_project(PROJECT, target)

    assert load_project(target) == PROJECT
    assert target.read_text(encoding="utf-8") == encode_project(PROJECT)
    assert os.listdir(tmp_path) == ["machine.physink.json"]


@pytest.mark.parametrize("failing", ["replace", "fsync"], ids=["rename-fails", "fsync-fails"])
def test_a_failed_save_keeps_the_old_file_and_leaves_no_temporary(tmp_path, monkeypatch, failing) -> None:
    target = tmp_path / "machine.physink.json"
    old = encode_project(Project(Scene(), (), None, (10.0, 10.0)))
    target.write_text(old, encoding="utf-8")

    def fail(*args: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, failing, fail)
    with pytest.raises(SceneError) as caught:
        save_project(PROJECT, target)

    assert str(caught.value) == f"cannot save project {target}: No space left on device"
    assert os.listdir(tmp_path) == ["machine.physink.json"]
    assert target.read_text(encoding="utf-8") == old


def test_a_bad_project_is_not_saved_and_is_named_by_the_path(tmp_path) -> None:
    target = tmp_path / "p.json"
    bad_body = Body("b1", "box", ((0.0, 0.0), (1.0, 0.0)), 0.0, (0.0, 0.0), 0.0, MATERIALS["box"])

    with pytest.raises(SceneError, match=r"p\.json: components\[0\]\.outline: expected a list of at least 3 points"):
        save_project(Project(Scene({"b1": bad_body}, {"b": 2}), (), None, (10.0, 10.0)), target)

    assert os.listdir(tmp_path) == []


def test_loading_a_missing_file_is_one_line_naming_it(tmp_path) -> None:
    missing = tmp_path / "nowhere.physink.json"

    with pytest.raises(PhysinkError) as caught:
        load_project(missing)

    assert str(caught.value) == f"cannot read project {missing}: No such file or directory"


def test_loading_names_the_file_for_bad_bytes_and_bad_fields(tmp_path) -> None:
    binary = tmp_path / "binary.json"
    binary.write_bytes(b'{"format": "\xff"}')
    with pytest.raises(SceneError, match=r"binary\.json: not UTF-8 text \(byte 12 is 0xff\)$"):
        load_project(binary)

    bad = tmp_path / "bad.json"
    raw = _raw()
    raw["components"][3]["material"]["friction"] = "high"
    bad.write_text(json.dumps(raw), encoding="utf-8")
    with pytest.raises(SceneError) as caught:
        load_project(bad)
    assert str(caught.value) == f'{bad}: components[3].material.friction: expected a number >= 0, got "high"'
