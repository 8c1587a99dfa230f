"""The causal timeline as JSON, both ways (DESIGN.md "Timeline JSON"); checks are `json_checks`', no file I/O.

A timeline file is ``{"format": "physink-timeline", "version": 2, "events": [...]}``; a project embeds the
``{"events": [...]}`` object alone (`timeline_object`), versioned by the project. One object per event in creation
order, every key present for every type (empty lists where a type has none), floats rounded to 6 decimals, so
the same timeline always gives the same bytes and decoding what was encoded gives an equal `Timeline` (once its
numbers are rounded: encoding a decoded timeline gives the same bytes back). ``label`` is the narration shown
and ``user_label`` the user's phrase; component ``label`` values are the names used for the narration.

``in_contact`` is the start event's: the pairs of movable bodies in contact when the demonstration began, each
a list of two ``{"id", "label"}`` objects (empty for every other event, and for a start with none).

Version 0 is the unversioned ``{"events": [...]}`` file written before the timeline carried a version; it reads
as version 1, and version 1 (before ``in_contact``) as version 2, through `migrations.upgrade`: a timeline written
before pairs in contact at the start were recorded names none.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any

from physink_tui.formats import json_checks as checks
from physink_tui.formats.json_checks import Place, joined
from physink_tui.formats.migrations import upgrade
from physink_tui.formats.strict_json import DuplicateKey, unique_pairs
from physink_tui.timeline.events import Event, Timeline, TimelineError, TrajectoryPoint, event_label
from physink_tui.timeline.graph import check_acyclic

FORMAT = "physink-timeline"
FORMAT_VERSION = 2
"""The version this program writes, and the newest it reads (0: the unversioned file of before; 1: before
``in_contact``)."""

EVENT_KEYS = ("id", "type", "components", "causes", "t0", "t1", "label", "user_label", "sides", "regions", "point",
              "trajectory", "tracks", "in_contact")
"""An event object's keys, in the order written."""

MAX_VALUE = 1e9
"""The largest time or coordinate a timeline may hold: distances between such values stay far from overflow."""

_ROW = "a row [t, x, y, angle, vx, vy]"


# --- writing -----------------------------------------------------------------------------------------------------


def _r(v: float) -> float:
    r = round(float(v), 6)
    return 0.0 if r == 0 else r  # no "-0.0"


def _frames(frames: tuple[TrajectoryPoint, ...]) -> list[list[float]]:
    return [[_r(p.t), _r(p.x), _r(p.y), _r(p.angle), _r(p.vx), _r(p.vy)] for p in frames]


def _event_obj(ev: Event, names: Mapping[str, str]) -> dict[str, Any]:
    return {
        "id": ev.id,
        "type": ev.type,
        "components": [{"id": c, "label": names.get(c)} for c in ev.components],
        "causes": list(ev.causes),
        "t0": _r(ev.t0),
        "t1": _r(ev.t1),
        "label": event_label(ev, names),
        "user_label": ev.label,
        "sides": [{"component": c, "label": names.get(c), "side": s} for c, s in ev.sides],
        "regions": [{"component": c, "label": names.get(c), "regions": list(rs)} for c, rs in ev.regions],
        "point": None if ev.point is None else [_r(ev.point[0]), _r(ev.point[1])],
        "trajectory": _frames(ev.trajectory),
        "tracks": [{"component": c, "trajectory": _frames(frames)} for c, frames in ev.tracks],
        "in_contact": [[{"id": c, "label": names.get(c)} for c in pair] for pair in ev.in_contact],
    }


def timeline_object(timeline: Timeline, names: Mapping[str, str]) -> dict[str, Any]:
    """The ``{"events": [...]}`` object of the timeline (what a project embeds), ``names`` labelling components."""
    if not isinstance(timeline, Timeline):
        raise TypeError(f"not a Timeline: {timeline!r}")
    return {"events": [_event_obj(ev, names) for ev in timeline.events]}


def encode_timeline_json(timeline: Timeline, names: Mapping[str, str]) -> str:
    """The timeline as one deterministic, versioned JSON document (ending in a newline)."""
    doc = {"format": FORMAT, "version": FORMAT_VERSION, **timeline_object(timeline, names)}
    return json.dumps(doc, ensure_ascii=False, allow_nan=False, indent=1) + "\n"


# --- reading -----------------------------------------------------------------------------------------------------


def decode_timeline_json(text: str) -> tuple[Timeline, dict[str, str]]:
    """The timeline and the component labels (id -> label) of a timeline file, of any version up to the current.

    Raises `TimelineError` naming the JSON path of the first bad value (``events[2].sides[0].side``; NaN,
    Infinity and numbers beyond `MAX_VALUE` refused) or a version newer than this program's,
    `graph.CausalCycleError` for a cycle. Callers add the file's name.

    >>> decode_timeline_json('{"format": "physink-timeline", "version": 1, "events": []}')
    (Timeline(events=()), {})
    """
    try:
        doc = json.loads(text, object_pairs_hook=unique_pairs)  # NaN and Infinity are refused by path below
    except DuplicateKey as exc:
        raise TimelineError(f"timeline JSON repeats key {exc.key!r}") from None
    except RecursionError:
        raise TimelineError("timeline JSON is nested too deeply") from None
    except ValueError as exc:
        raise TimelineError(f"timeline JSON is not valid JSON: {exc}") from None
    where = Place("", TimelineError)
    doc = checks.an_object(where, "timeline JSON", doc, 'an object {"format", "version", "events": [...]}')
    doc = upgrade(doc, _version(doc, where), {1: _from_unversioned, 2: _with_in_contact}, FORMAT_VERSION,
                  what="timeline format", where=Place("timeline JSON", TimelineError))
    return timeline_from_object(doc, where, "")


def _version(doc: dict[str, Any], where: Place) -> int:
    if "format" not in doc and "version" not in doc:
        return 0
    if doc.get("format") != FORMAT:
        raise where.bad("format", checks.show(FORMAT), doc.get("format", checks.MISSING))
    version = checks.get(doc, where, "version", "version", f"an integer from 1 to {FORMAT_VERSION}")
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        raise where.bad("version", f"an integer from 1 to {FORMAT_VERSION}", version)
    return version


def _from_unversioned(doc: dict[str, Any]) -> dict[str, Any]:
    """Version 0 (``{"events": [...]}``, no format or version) as version 1: the same events, now labelled."""
    return {"format": FORMAT, "version": 1, **doc}


def _with_in_contact(doc: dict[str, Any]) -> dict[str, Any]:
    """Version 1 as version 2: the same events, none naming pairs in contact at the start."""
    return {**events_with_in_contact(doc), "version": 2}


def events_with_in_contact(obj: dict[str, Any]) -> dict[str, Any]:
    """An ``{"events": [...]}`` object of before ``in_contact`` (timeline version 1, project version 1) with an
    empty ``in_contact`` on every event; what is not an event object is left for the checks to name."""
    events = obj.get("events")
    if not isinstance(events, list):
        return dict(obj)
    return {**obj, "events": [{"in_contact": [], **ev} if isinstance(ev, dict) else ev for ev in events]}


def timeline_from_object(obj: dict[str, Any], where: Place, path: str) -> tuple[Timeline, dict[str, str]]:
    """The timeline and component labels in an ``{"events": [...]}`` object found at ``path`` of ``where``.

    Raises ``where.error`` naming the key path of the first bad value; `TimelineError` from the events'
    own rules (an end before its start...) and `graph.CausalCycleError` for a cycle.
    """
    names: dict[str, str] = {}
    key = joined(path, "events")
    raw = checks.a_list(where, key, checks.get(obj, where, "events", key, "a list of events"), "a list of events")
    timeline = Timeline(tuple(_event(where, f"{key}[{i}]", item, names) for i, item in enumerate(raw)))
    check_acyclic(timeline)
    return timeline, names


def _field(where: Place, obj: dict[str, Any], path: str, key: str, expected: str) -> Any:
    return checks.get(obj, where, key, f"{path}.{key}", expected)


def _str(where: Place, key: str, value: Any, expected: str = "a string") -> str:
    if not isinstance(value, str):
        raise where.bad(key, expected, value)
    return value


def _label(where: Place, key: str, value: Any) -> str | None:
    return None if value is None else _str(where, key, value, "a string or null")


def _num(where: Place, key: str, value: Any) -> float:
    return checks.limited(where, key, value, MAX_VALUE)


def _parts(where: Place, obj: dict[str, Any], path: str, key: str, keys: str) -> list[tuple[str, dict[str, Any]]]:
    """The objects listed under ``key``, each with its path; ``keys`` says what each holds, for messages."""
    at = f"{path}.{key}"
    listed = checks.a_list(where, at, _field(where, obj, path, key, "a list"))
    return [(f"{at}[{j}]", checks.an_object(where, f"{at}[{j}]", part, f"an object {keys}"))
            for j, part in enumerate(listed)]


def _named(where: Place, at: str, part: dict[str, Any], key: str, names: dict[str, str]) -> str:
    """The component id under ``key``, its ``label`` (when given) added to ``names``."""
    cid = _str(where, f"{at}.{key}", _field(where, part, at, key, "a string"))
    label = _label(where, f"{at}.label", part.get("label"))
    if label is not None:
        names[cid] = label
    return cid


def _frames_at(where: Place, path: str, rows: Any) -> tuple[TrajectoryPoint, ...]:
    frames = []
    for i, row in enumerate(checks.a_list(where, path, rows)):
        row = checks.a_list(where, f"{path}[{i}]", row, _ROW)
        if len(row) != 6:
            raise where.bad(f"{path}[{i}]", _ROW, row)
        frames.append(TrajectoryPoint(*(_num(where, f"{path}[{i}][{j}]", v) for j, v in enumerate(row))))
    return tuple(frames)


def _event(where: Place, path: str, obj: Any, names: dict[str, str]) -> Event:
    obj = checks.an_object(where, path, obj, "an event object")
    components = [_named(where, at, part, "id", names)
                  for at, part in _parts(where, obj, path, "components", '{"id", "label"}')]
    sides = [(_named(where, at, part, "component", names), _str(where, f"{at}.side", _field(where, part, at, "side",
                                                                                           "a string")))
             for at, part in _parts(where, obj, path, "sides", '{"component", "side"}')]
    regions = []
    for at, part in _parts(where, obj, path, "regions", '{"component", "regions"}'):
        crossed = checks.a_list(where, f"{at}.regions", _field(where, part, at, "regions", "a list"))
        regions.append((_named(where, at, part, "component", names),
                        tuple(_str(where, f"{at}.regions[{k}]", r) for k, r in enumerate(crossed))))
    point = obj.get("point")
    if point is not None:
        if not isinstance(point, list) or len(point) != 2:
            raise where.bad(f"{path}.point", "null or a point [x, y]", point)
        point = (_num(where, f"{path}.point[0]", point[0]), _num(where, f"{path}.point[1]", point[1]))
    tracks = []
    if "tracks" in obj:  # absent before tracks existed
        for at, track in _parts(where, obj, path, "tracks", '{"component", "trajectory"}'):
            tracks.append((_str(where, f"{at}.component", _field(where, track, at, "component", "a string")),
                           _frames_at(where, f"{at}.trajectory", _field(where, track, at, "trajectory", "a list"))))
    in_contact = []
    for j, pair in enumerate(checks.a_list(where, f"{path}.in_contact",
                                           _field(where, obj, path, "in_contact", "a list of pairs"),
                                           "a list of pairs")):
        at = f"{path}.in_contact[{j}]"
        pair = checks.a_list(where, at, pair, 'a pair [{"id", "label"}, {"id", "label"}]')
        if len(pair) != 2:
            raise where.bad(at, 'a pair [{"id", "label"}, {"id", "label"}]', pair)
        ids = [_named(where, f"{at}[{k}]", checks.an_object(where, f"{at}[{k}]", part, 'an object {"id", "label"}'),
                      "id", names) for k, part in enumerate(pair)]
        in_contact.append((ids[0], ids[1]))
    causes = checks.a_list(where, f"{path}.causes", _field(where, obj, path, "causes", "a list of event ids"),
                           "a list of event ids")
    return Event(
        id=_str(where, f"{path}.id", _field(where, obj, path, "id", "a string")),
        type=_str(where, f"{path}.type", _field(where, obj, path, "type", "a string")),
        components=tuple(components),
        causes=tuple(_str(where, f"{path}.causes[{j}]", c, "an event id (a string)") for j, c in enumerate(causes)),
        t0=_num(where, f"{path}.t0", _field(where, obj, path, "t0", "a number")),
        t1=_num(where, f"{path}.t1", _field(where, obj, path, "t1", "a number")),
        label=_label(where, f"{path}.user_label", obj.get("user_label")),
        sides=tuple(sides),
        regions=tuple(regions),
        point=point,
        trajectory=_frames_at(where, f"{path}.trajectory", _field(where, obj, path, "trajectory", "a list")),
        tracks=tuple(tracks),
        in_contact=tuple(in_contact),
    )
