"""The project file's JSON, both ways, checked field by field; the one place that knows the format, and no file I/O.

A project is written as indented JSON with a fixed key order and one component per line, floats as ``repr``
writes them, so a value read back equals the one written and the same project always gives the same bytes::

    {
      "format": "physink-project",
      "version": 1,
      "program": "physink-tui 0.1.0",
      "canvas": {"width": 800.0, "height": 600.0},
      "components": [
        {"id": "b1", "type": "body", "shape": "circle", "outline": [], "radius": 20.0, ...},
        {"id": "j1", "type": "joint", "kind": "pivot", "a": "b1", "b": "background", "anchor": [100.0, 50.0]}
      ],
      "next_id": {"b": 2, "j": 2, "r": 1, "s": 1},
      "vocabulary": ["ball"],
      "timeline": null
    }

Components are in scene order. Numbers of the scene and canvas are written as floats (``5`` reads back as
``5.0``); ``next_id`` is written with sorted keys; the ``timeline`` object is kept as given (its key order
too). Reading names the first bad field by its JSON path and says what was expected, e.g.
``project.json: components[3].material.friction: expected a number >= 0, got "high"``; unknown keys are
ignored with a warning. Encoding checks the project with the same rules, so whatever is written reads back.
Both raise `SceneError`.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from physink_tui import __version__
from physink_tui.errors import SceneError
from physink_tui.formats.project.checks import (
    _MISSING,
    _Fields,
    _json_value,
    _object,
    _text,
    bad,
    show,
)
from physink_tui.formats.strict_json import DuplicateKey, unique_pairs
from physink_tui.scene.components import BACKGROUND, Body, Component, Joint, Material, Rope, Scene, Spring

FORMAT = "physink-project"
FORMAT_VERSION = 1
"""The version this program writes, and the newest it reads."""

TOP_KEYS = ("format", "version", "program", "canvas", "components", "next_id", "vocabulary", "timeline")
COMPONENT_KEYS = {
    "body": ("id", "type", "shape", "outline", "radius", "position", "angle", "material", "label"),
    "joint": ("id", "type", "kind", "a", "b", "anchor"),
    "rope": ("id", "type", "points", "start_body", "end_body", "label"),
    "spring": ("id", "type", "a", "b", "anchor_a", "anchor_b", "axis", "rest_length", "k", "label"),
}
"""Each component type's keys, in the order written."""
MATERIAL_KEYS = ("density", "restitution", "friction")
SHAPES = ("box", "circle", "ellipse", "polygon", "polyline")
MIN_POINTS = {"box": 3, "ellipse": 3, "polygon": 3, "polyline": 2}
"""The fewest outline points each non-circle shape may have."""
JOINT_KINDS = ("pivot", "weld")
AXES = ("horizontal", "vertical")
"""Offending values are shown with at most this many characters."""



@dataclass(frozen=True, slots=True)
class Project:
    """Everything a project file holds.

    Attributes:
        scene: the sketch's components, in scene order, and its id counters.
        vocabulary: the user's own words for labels and verbs, in the order given; may be empty.
        timeline: the demonstrated timeline as a JSON object, or None; opaque here, kept exactly as given.
        canvas: (width, height) of the canvas in canvas units, both > 0.
    """

    scene: Scene
    vocabulary: tuple[str, ...]
    timeline: dict[str, Any] | None
    canvas: tuple[float, float]




# NaN and Infinity are let through the parser so that the check of the field can name it.
_DECODER = json.JSONDecoder(object_pairs_hook=unique_pairs)


def encode_project(project: Project, *, where: str = "project") -> str:
    """The project as the text of a project file (ending in a newline), after checking every field.

    Args:
        project: the project.
        where: how messages name the project (``save_project`` passes the file's path).

    Raises:
        SceneError: ``<where>: <json path>: expected ..., got ...`` for the first bad field.
        TypeError: ``project`` is not a `Project`, its scene not a `Scene`, or a component of no known kind.

    >>> text = encode_project(Project(Scene(), ("ball",), None, (800, 600)))
    >>> print(text.partition('"canvas"')[2].strip())
    : {"width": 800.0, "height": 600.0},
      "components": [],
      "next_id": {"b": 1, "j": 1, "r": 1, "s": 1},
      "vocabulary": ["ball"],
      "timeline": null
    }
    """
    checked = _project(_plain_project(project, where), where, None)
    return _emit(_plain_project(checked, where))


def decode_project(text: str, path: Any, *, warnings: list[str] | None = None) -> Project:
    """The project in the text of a project file.

    Args:
        text: the whole file.
        path: how messages name the file (its path as the user gave it).
        warnings: when given, one message per unknown key (which is ignored) is appended.

    Raises:
        SceneError: the text is no JSON object, a project from a newer program, or a field is bad: the message
            starts with ``path`` and names the field's JSON path and what was expected.

    >>> decode_project('{"format": "physink-project", "version": 2}', "project.json")
    Traceback (most recent call last):
    ...
    physink_tui.errors.SceneError: project.json was written by format version 2; this program reads version 1 \
(upgrade physink-tui)
    """
    where = str(path)
    try:
        value = _DECODER.decode(text)
    except DuplicateKey as e:
        raise SceneError(f'{where}: not valid JSON: key "{e.key}" appears twice in one object') from None
    except json.JSONDecodeError as e:
        raise SceneError(f"{where}: not valid JSON ({e.msg} at line {e.lineno}, column {e.colno})") from None
    except (ValueError, RecursionError) as e:
        raise SceneError(f"{where}: not valid JSON ({e})") from None
    if not isinstance(value, dict):
        raise SceneError(f"{where}: expected a JSON object (a physink project), got {show(value)}")
    return _project(value, where, warnings)


# --- writing -----------------------------------------------------------------------------------------------------


def _plain(value: Any) -> Any:
    """Tuples (points, outlines) as lists; everything else as it is, for the checks to judge."""
    return [_plain(v) for v in value] if isinstance(value, tuple | list) else value


def _plain_json(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _plain_json(v) for k, v in value.items()}
    return [_plain_json(v) for v in value] if isinstance(value, tuple | list) else value


def _plain_component(c: Component) -> dict[str, Any]:
    if isinstance(c, Body):
        m = c.material
        material = {"density": m.density, "restitution": m.restitution, "friction": m.friction} if isinstance(
            m, Material) else m
        return {"id": c.id, "type": "body", "shape": c.shape, "outline": _plain(c.outline), "radius": c.radius,
                "position": _plain(c.position), "angle": c.angle, "material": material, "label": c.label}
    if isinstance(c, Joint):
        return {"id": c.id, "type": "joint", "kind": c.kind, "a": c.a, "b": c.b, "anchor": _plain(c.anchor)}
    if isinstance(c, Rope):
        return {"id": c.id, "type": "rope", "points": _plain(c.points), "start_body": c.start_body,
                "end_body": c.end_body, "label": c.label}
    if isinstance(c, Spring):
        return {"id": c.id, "type": "spring", "a": c.a, "b": c.b, "anchor_a": _plain(c.anchor_a),
                "anchor_b": _plain(c.anchor_b), "axis": c.axis, "rest_length": c.rest_length, "k": c.k,
                "label": c.label}
    raise TypeError(f"not a scene component: {c!r}")


def _plain_project(project: Project, where: str) -> dict[str, Any]:
    if not isinstance(project, Project):
        raise TypeError(f"not a Project: {project!r}")
    if not isinstance(project.scene, Scene):
        raise TypeError(f"not a Scene: {project.scene!r}")
    components = []
    for i, (key, c) in enumerate(project.scene.components.items()):
        plain = _plain_component(c)
        if plain["id"] != key:
            raise bad(where, f"components[{i}].id", f"{show(key)}, the key the scene keeps it under", plain["id"])
        components.append(plain)
    canvas = project.canvas
    if not isinstance(canvas, tuple | list) or len(canvas) != 2:
        raise bad(where, "canvas", "(width, height)", _plain(canvas))
    width, height = canvas
    return {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "program": f"physink-tui {__version__}",
        "canvas": {"width": width, "height": height},
        "components": components,
        "next_id": dict(project.scene.next_id) if isinstance(project.scene.next_id, dict) else project.scene.next_id,
        "vocabulary": _plain(project.vocabulary),
        "timeline": _plain_json(project.timeline),
    }


def _dump(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False, allow_nan=False, separators=(", ", ": "))


def _emit(obj: dict[str, Any]) -> str:
    """The checked, normalised project as text: floats by ``repr`` (what ``json`` does), one component a line."""
    components = ",\n".join(f"    {_dump(c)}" for c in obj["components"])
    listed = f"[\n{components}\n  ]" if components else "[]"
    lines = [
        f'  "format": {_dump(obj["format"])}',
        f'  "version": {_dump(obj["version"])}',
        f'  "program": {_dump(obj["program"])}',
        f'  "canvas": {_dump(obj["canvas"])}',
        f'  "components": {listed}',
        f'  "next_id": {_dump(dict(sorted(obj["next_id"].items())))}',
        f'  "vocabulary": {_dump(obj["vocabulary"])}',
        f'  "timeline": {_dump(obj["timeline"])}',
    ]
    return "{\n" + ",\n".join(lines) + "\n}\n"


# --- checking ----------------------------------------------------------------------------------------------------


def _project(obj: dict[str, Any], where: str, warnings: list[str] | None) -> Project:
    """The project in a parsed (or plain-built) JSON object, every field checked in the order written."""
    top = _Fields(where, "", obj, {})
    fmt = obj.get("format", _MISSING)
    if fmt != FORMAT:
        raise bad(where, "format", show(FORMAT), fmt)
    version = top.get("version", f"an integer from 1 to {FORMAT_VERSION}")
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        raise bad(where, "version", f"an integer from 1 to {FORMAT_VERSION}", version)
    if version > FORMAT_VERSION:
        raise SceneError(f"{where} was written by format version {version}; this program reads version "
                         f"{FORMAT_VERSION} (upgrade physink-tui)")
    _object(where, "", obj, TOP_KEYS, "an object", warnings)
    top.text("program", "a string naming the program that wrote it")
    expected = 'an object {"width": number > 0, "height": number > 0}'
    canvas = _Fields(where, "canvas", _object(where, "canvas", top.get("canvas", expected), ("width", "height"),
                                              expected, warnings), {})
    width = canvas.number("width", "a number > 0", above=0.0)
    height = canvas.number("height", "a number > 0", above=0.0)
    components = _components(top, warnings)
    next_id = _next_id(top, components)
    vocabulary = top.get("vocabulary", "a list of words (strings)")
    if not isinstance(vocabulary, list):
        raise bad(where, "vocabulary", "a list of words (strings)", vocabulary)
    words = tuple(_text(where, f"vocabulary[{i}]", w) for i, w in enumerate(vocabulary))
    timeline = top.get("timeline", "null or an object")
    if timeline is not None and not isinstance(timeline, dict):
        raise bad(where, "timeline", "null or an object", timeline)
    _json_value(where, "timeline", timeline)
    return Project(Scene({c.id: c for c in components}, next_id), words, timeline, (width, height))


def _components(top: _Fields, warnings: list[str] | None) -> list[Component]:
    where = top.where
    raw = top.get("components", "a list of components")
    if not isinstance(raw, list):
        raise bad(where, "components", "a list of components", raw)
    kinds: dict[str, str] = {}  # id -> type where first named, so that a rope end may name a later body
    for item in raw:
        if isinstance(item, dict) and isinstance(item.get("id"), str) and isinstance(item.get("type"), str):
            kinds.setdefault(item["id"], item["type"])
    seen: dict[str, int] = {}
    out: list[Component] = []
    for i, item in enumerate(raw):
        path = f"components[{i}]"
        if not isinstance(item, dict):
            raise bad(where, path, "an object (a component)", item)
        f = _Fields(where, path, item, kinds)
        cid = f.text("id")
        if cid == BACKGROUND:
            raise bad(where, f.key("id"), f"an id other than {show(BACKGROUND)} (it names the background)", cid)
        if cid in seen:
            raise bad(where, f.key("id"), "an id no other component has", cid,
                      f" (already the id of components[{seen[cid]}])")
        seen[cid] = i
        kind = f.one_of("type", tuple(COMPONENT_KEYS))
        _object(where, path, item, COMPONENT_KEYS[kind], "an object", warnings)
        out.append(_READERS[kind](f, cid, warnings))
    return out


def _body(f: _Fields, cid: str, warnings: list[str] | None) -> Body:
    shape = f.one_of("shape", SHAPES)
    if shape == "circle":
        outline = f.get("outline", "[] (a circle is given by its radius)")
        if outline != []:
            raise bad(f.where, f.key("outline"), "[] (a circle is given by its radius)", outline)
        points: tuple[tuple[float, float], ...] = ()
        radius = f.number("radius", "a number > 0", above=0.0)
    else:
        points = f.points("outline", MIN_POINTS[shape])
        radius = f.number("radius", "0 (only a circle has a radius)", low=0.0, high=0.0)
    position = f.point("position")
    angle = f.number("angle", "a finite number (radians)")
    expected = 'an object {"density", "restitution", "friction"}'
    m = _Fields(f.where, f.key("material"),
                _object(f.where, f.key("material"), f.get("material", expected), MATERIAL_KEYS, expected, warnings),
                {})
    material = Material(
        m.number("density", "a number > 0", above=0.0),
        m.number("restitution", "a number in [0, 1]", low=0.0, high=1.0),
        m.number("friction", "a number >= 0", low=0.0),
    )
    return Body(cid, shape, points, radius, position, angle, material, f.label())


def _joint(f: _Fields, cid: str, warnings: list[str] | None) -> Joint:
    kind = f.one_of("kind", JOINT_KINDS)
    a = f.body("a", background=False)
    return Joint(cid, kind, a, f.body("b", other=a), f.point("anchor"))


def _rope(f: _Fields, cid: str, warnings: list[str] | None) -> Rope:
    points = f.points("points", 2)
    return Rope(cid, points, f.end("start_body"), f.end("end_body"), f.label())


def _spring(f: _Fields, cid: str, warnings: list[str] | None) -> Spring:
    a = f.body("a")
    b = f.body("b", other=a)
    anchor_a, anchor_b = f.point("anchor_a"), f.point("anchor_b")
    axis = f.one_of("axis", AXES)
    rest = f.number("rest_length", "a number >= 0", low=0.0)
    return Spring(cid, a, b, anchor_a, anchor_b, axis, rest, f.number("k", "a number > 0", above=0.0), f.label())


_READERS = {"body": _body, "joint": _joint, "rope": _rope, "spring": _spring}


def _next_id(top: _Fields, components: list[Component]) -> dict[str, int]:
    """The id counters: integers >= 1, each above every id already made from its prefix (ids are never reused)."""
    where = top.where
    expected = 'an object of id counters, e.g. {"b": 3, "j": 1}'
    raw = top.get("next_id", expected)
    if not isinstance(raw, dict):
        raise bad(where, "next_id", expected, raw)
    counters: dict[str, int] = {}
    for prefix, n in raw.items():
        _text(where, "next_id", prefix, "an object whose keys are id prefixes (non-empty strings)")
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise bad(where, f"next_id.{prefix}", "an integer >= 1", n)
        counters[prefix] = n
    for prefix in sorted({*counters, "b", "j", "r", "s"}):
        used = []
        for i, c in enumerate(components):
            digits = c.id[len(prefix):] if c.id.startswith(prefix) else ""
            if digits.isascii() and digits.isdecimal() and digits[0] != "0":
                used.append((int(digits), i))
        if used:
            highest, index = max(used)
            if counters.get(prefix, 1) <= highest:
                note = f" (components[{index}] has the id {show(components[index].id)})"
                raise bad(where, f"next_id.{prefix}", f"an integer > {highest}, so that no id is made twice",
                          counters.get(prefix, _MISSING), note)
    return counters
