"""The project file's JSON, both ways, checked field by field; the one place that knows the format, and no file I/O.

A project is written as indented JSON with a fixed key order and one component per line, floats as ``repr``
writes them, so a value read back equals the one written and the same project always gives the same bytes::

    {
      "format": "physink-project",
      "version": 2,
      "program": "physink-tui 0.1.0",
      "canvas": {"width": 800.0, "height": 600.0},
      "components": [
        {"id": "b1", "type": "body", "shape": "circle", "outline": [], "radius": 20.0, ...},
        {"id": "j1", "type": "joint", "kind": "pivot", "a": "b1", "b": "background", "anchor": [100.0, 50.0]}
      ],
      "next_id": {"b": 2, "j": 2, "r": 1, "s": 1},
      "vocabulary": ["verb plummets topples", "prep amid"],
      "timeline": {"events": [...]},
      "demonstration": null
    }

Components are in scene order. Numbers of the scene and canvas are written as floats (``5`` reads back as
``5.0``); ``next_id`` is written with sorted keys. ``vocabulary`` holds the lines of the user's vocabulary
(`physink_tui.timeline.phrases.parse_vocabulary`), each checked as such; ``timeline`` is null or the object
`physink_tui.formats.timeline_json.timeline_object` writes (its component labels are the scene's names, and
reading takes the names from the scene), versioned by the project's version; ``demonstration`` likewise, the
demonstrated timeline when ``timeline`` is a simulation adopted for it (else null). Version 1 (before
``demonstration`` and the timeline's ``in_contact``) reads as version 2 (`migrations.upgrade`). Reading names
the first bad field by its JSON path and says what was expected, e.g. ``project.json: components[3].material.friction:
expected a number >= 0, got "high"``; unknown keys are ignored with a warning. Encoding checks the project
with the same rules, so whatever is written reads back. Both raise `SceneError`. The values every command needs
(sizes, times, outlines, the timeline's components) are `physink_tui.formats.project.sanity`'s, checked by
`load_project` and wherever else a project is taken in; the codec itself round-trips any well-formed project.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from physink_tui import __version__
from physink_tui.errors import PhysinkError, SceneError
from physink_tui.formats import json_checks as checks
from physink_tui.formats.json_checks import MISSING, Place, show
from physink_tui.formats.migrations import upgrade
from physink_tui.formats.project.scene_fields import (
    Fields,
    decode_components,
    decode_next_id,
    plain,
    plain_component,
    sub_object,
)
from physink_tui.formats.strict_json import DuplicateKey, unique_pairs
from physink_tui.formats.timeline_json import events_with_in_contact, timeline_from_object, timeline_object
from physink_tui.scene.components import Scene
from physink_tui.timeline.events import Timeline, TimelineError
from physink_tui.timeline.phrases import Vocabulary, parse_vocabulary

FORMAT = "physink-project"
FORMAT_VERSION = 2
"""The version this program writes, and the newest it reads (1: before ``demonstration`` and ``in_contact``)."""

TOP_KEYS = ("format", "version", "program", "canvas", "components", "next_id", "vocabulary", "timeline",
            "demonstration")


@dataclass(frozen=True, slots=True)
class Project:
    """Everything a project file holds.

    Attributes:
        scene: the sketch's components, in scene order, and its id counters.
        vocabulary: the user's vocabulary, one line of a vocabulary file each (``"verb plummets topples"``,
            ``"prep amid"``), in the order given; may be empty. `vocabulary_lines` and `project_vocabulary`
            convert from and to the session's `Vocabulary` extension.
        timeline: the demonstrated timeline, or None. Its numbers are written rounded to 6 decimals, so a
            timeline read back equals the one written once they are (as every timeline read from a file is).
        canvas: (width, height) of the canvas in canvas units, both > 0.
        demonstration: when ``timeline`` is a simulation the user adopted (its parameters now the scene's), the
            demonstrated timeline it was found for, kept so that the two can be compared again
            (``physink equiv PROJECT --up-to-demonstrated``); None otherwise.
    """

    scene: Scene
    vocabulary: tuple[str, ...]
    timeline: Timeline | None
    canvas: tuple[float, float]
    demonstration: Timeline | None = None


def vocabulary_lines(vocabulary: Vocabulary) -> tuple[str, ...]:
    """The lines a project keeps for a vocabulary: its verbs, prepositions, then component names, each sorted; none
    if empty.

    >>> vocabulary_lines(Vocabulary(frozenset({"topples", "plummets"}), frozenset({"amid"})))
    ('verb plummets topples', 'prep amid')
    """
    lines = []
    if vocabulary.verbs:
        lines.append("verb " + " ".join(sorted(vocabulary.verbs)))
    if vocabulary.prepositions:
        lines.append("prep " + " ".join(sorted(vocabulary.prepositions)))
    if vocabulary.components:
        lines.append("component " + ", ".join(sorted(vocabulary.components)))
    return tuple(lines)


def project_vocabulary(project: Project) -> Vocabulary:
    """The project's vocabulary lines as a `Vocabulary` (to extend `DEFAULT_VOCABULARY` with)."""
    return parse_vocabulary("\n".join(project.vocabulary), "project vocabulary")




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

    >>> text = encode_project(Project(Scene(), ("verb topples",), None, (800, 600)))
    >>> print(text.partition('"canvas"')[2].strip())
    : {"width": 800.0, "height": 600.0},
      "components": [],
      "next_id": {"b": 1, "j": 1, "r": 1, "s": 1},
      "vocabulary": ["verb topples"],
      "timeline": null,
      "demonstration": null
    }
    """
    at = Place(where, SceneError)
    checked = _project(_plain_project(project, at), at, None)
    return _emit(_plain_project(checked, at))


def decode_project(text: str, path: Any, *, warnings: list[str] | None = None) -> Project:
    """The project in the text of a project file.

    Args:
        text: the whole file.
        path: how messages name the file (its path as the user gave it).
        warnings: when given, one message per unknown key (which is ignored) is appended.

    Raises:
        SceneError: the text is no JSON object, a project from a newer program, or a field is bad: the message
            starts with ``path`` and names the field's JSON path and what was expected.

    >>> decode_project('{"format": "physink-project", "version": 3}', "project.json")
    Traceback (most recent call last):
    ...
    physink_tui.errors.SceneError: project.json was written by format version 3; this program reads version 2 \
(upgrade physink-tui)
    """
    where = str(path)
    text = text.removeprefix("\ufeff")  # a UTF-8 byte order mark, as editors on Windows write
    try:
        value = _DECODER.decode(text)
    except DuplicateKey as e:
        raise SceneError(f'{where}: not valid JSON: key "{e.key}" appears twice in one object') from None
    except json.JSONDecodeError as e:
        kind = _other_kind(text)
        if kind:
            raise SceneError(f"{where}: {kind}; expected a project (.physink.json)") from None
        raise SceneError(f"{where}: not valid JSON ({e.msg} at line {e.lineno}, column {e.colno})") from None
    except (ValueError, RecursionError) as e:
        raise SceneError(f"{where}: not valid JSON ({e})") from None
    if not isinstance(value, dict):
        raise SceneError(f"{where}: expected a JSON object (a physink project), got {show(value)}")
    return _project(value, Place(where, SceneError), warnings)


def _other_kind(text: str) -> str:
    """What a file that is no JSON document is, when it is one of this program's other files (else "")."""
    body = text.strip()
    first = body.split("\n", 1)[0].strip()
    if first.startswith(("#", "R:", "N:", "I:", "P:", "D:", "E:")):
        return "this is a capture (.hid)"
    try:
        head = json.loads(first)
    except (ValueError, RecursionError):
        return ""
    if isinstance(head, dict) and head.get("format") == "physink-journal":
        return "this is a journal (.physink.jsonl)"
    return ""


# --- writing -----------------------------------------------------------------------------------------------------


def _plain_project(project: Project, where: Place) -> dict[str, Any]:
    if not isinstance(project, Project):
        raise TypeError(f"not a Project: {project!r}")
    if not isinstance(project.scene, Scene):
        raise TypeError(f"not a Scene: {project.scene!r}")
    components = []
    for i, (key, c) in enumerate(project.scene.components.items()):
        plain_c = plain_component(c)
        if plain_c["id"] != key:
            raise where.bad(f"components[{i}].id", f"{show(key)}, the key the scene keeps it under", plain_c["id"])
        components.append(plain_c)
    canvas = project.canvas
    if not isinstance(canvas, tuple | list) or len(canvas) != 2:
        raise where.bad("canvas", "(width, height)", plain(canvas))
    width, height = canvas
    timeline, demonstration = project.timeline, project.demonstration
    return {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "program": f"physink-tui {__version__}",
        "canvas": {"width": width, "height": height},
        "components": components,
        "next_id": dict(project.scene.next_id) if isinstance(project.scene.next_id, dict) else project.scene.next_id,
        "vocabulary": plain(project.vocabulary),
        "timeline": None if timeline is None else timeline_object(timeline, project.scene.names()),
        "demonstration": None if demonstration is None else timeline_object(demonstration, project.scene.names()),
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
        f'  "demonstration": {_dump(obj["demonstration"])}',
    ]
    return "{\n" + ",\n".join(lines) + "\n}\n"


# --- checking ----------------------------------------------------------------------------------------------------


def decode_project_object(obj: Any, where: Place, warnings: list[str] | None = None) -> Project:
    """The project in a parsed JSON object (a journal's ``load`` line embeds one), checked as a file is.

    Raises ``where.error`` (`JournalError` for a journal line) naming the first bad field's JSON path.
    """
    if not isinstance(obj, dict):
        raise where.fail(f"expected a JSON object (a physink project), got {show(obj)}")
    return _project(obj, where, warnings)


def _project(obj: dict[str, Any], where: Place, warnings: list[str] | None) -> Project:
    """The project in a parsed (or plain-built) JSON object, every field checked in the order written."""
    fmt = obj.get("format", MISSING)
    if fmt != FORMAT:
        raise where.bad("format", show(FORMAT), fmt)
    version = checks.get(obj, where, "version", "version", f"an integer from 1 to {FORMAT_VERSION}")
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        raise where.bad("version", f"an integer from 1 to {FORMAT_VERSION}", version)
    obj = upgrade(obj, version, {2: _v1_to_v2}, FORMAT_VERSION, what="format", where=where)
    checks.known_keys(where, "", obj, TOP_KEYS, warnings)
    top = Fields(where, "", obj, {})
    top.text("program", "a string naming the program that wrote it")
    expected = 'an object {"width": number > 0, "height": number > 0}'
    canvas = Fields(where, "canvas", sub_object(where, "canvas", top.get("canvas", expected), ("width", "height"),
                                                expected, warnings), {})
    width = canvas.number("width", "a number > 0", above=0.0)
    height = canvas.number("height", "a number > 0", above=0.0)
    components = decode_components(where, top.get("components", "a list of components"), warnings)
    next_id = decode_next_id(where, top.get("next_id", 'an object of id counters, e.g. {"b": 3, "j": 1}'),
                             components)
    vocabulary = checks.a_list(where, "vocabulary", top.get("vocabulary", "a list of vocabulary lines (strings)"),
                               "a list of vocabulary lines (strings)")
    words = tuple(_vocabulary_line(where, f"vocabulary[{i}]", w) for i, w in enumerate(vocabulary))
    timeline, demonstration = (_timeline(where, top, key) for key in ("timeline", "demonstration"))
    return Project(Scene({c.id: c for c in components}, next_id), words, timeline, (width, height), demonstration)


def _timeline(where: Place, top: Fields, key: str) -> Timeline | None:
    """The timeline object under ``key`` (null: None)."""
    raw = checks.optional(checks.an_object, where, key, top.get(key, "null or an object"), "null or an object")
    if raw is None:
        return None
    try:
        timeline, _ = timeline_from_object(raw, where, key)
    except TimelineError as e:  # an event's own rules, or a cycle: not tied to one key
        raise where.fail(f"{key}: {e}") from None
    return timeline


def _v1_to_v2(doc: dict[str, Any]) -> dict[str, Any]:
    """Version 1 as version 2: no demonstration kept, and the timeline's events naming no pairs in contact at the
    start (timeline format 2)."""
    timeline = doc.get("timeline")
    if isinstance(timeline, dict):
        timeline = events_with_in_contact(timeline)
    return {**doc, "version": 2, "timeline": timeline, "demonstration": None}


def _vocabulary_line(where: Place, key: str, value: Any) -> str:
    """One line of a vocabulary file, with at least one word and no line break."""
    expected = "a vocabulary line, 'verb WORD...' or 'prep WORD...'"
    line = checks.text(where, key, value, expected, empty=False)
    try:
        vocabulary = parse_vocabulary(line)
    except PhysinkError:
        raise where.bad(key, expected, value) from None
    if "\n" in line or "\r" in line or not (vocabulary.verbs or vocabulary.prepositions):
        raise where.bad(key, expected, value)
    return line
