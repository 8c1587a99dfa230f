"""The timeline as JSON and as Graphviz DOT for `physink timeline` (DESIGN.md "Timeline JSON"); the text format
is `physink_tui.timeline.narrate.timeline_text`.

JSON: ``{"events": [...]}`` with one object per event in creation order and every key present for every type
(empty lists where a type has none), floats rounded to 6 decimals, so the same timeline always gives the same
bytes. `parse_timeline_json` reads it back (``label`` is the narration shown; ``user_label`` the user's phrase).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

from physink_tui.formats.json_checks import show
from physink_tui.formats.strict_json import DuplicateKey, unique_pairs
from physink_tui.timeline.events import Event, Timeline, TimelineError, TrajectoryPoint, event_label
from physink_tui.timeline.graph import check_acyclic

EVENT_KEYS = ("id", "type", "components", "causes", "t0", "t1", "label", "user_label", "sides", "regions", "point",
              "trajectory", "tracks")


def _r(v: float) -> float:
    r = round(float(v), 6)
    return 0.0 if r == 0 else r  # no "-0.0"


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
    }


def _frames(frames: tuple[TrajectoryPoint, ...]) -> list[list[float]]:
    return [[_r(p.t), _r(p.x), _r(p.y), _r(p.angle), _r(p.vx), _r(p.vy)] for p in frames]


def timeline_json(timeline: Timeline, names: Mapping[str, str]) -> str:
    """The timeline as one deterministic JSON document (ending in a newline)."""
    doc = {"events": [_event_obj(ev, names) for ev in timeline.events]}
    return json.dumps(doc, ensure_ascii=False, allow_nan=False, indent=1) + "\n"


def _dot_quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def timeline_dot(timeline: Timeline, names: Mapping[str, str]) -> str:
    """The timeline as a Graphviz digraph: one node per event labelled by its narration, edges cause -> effect."""
    lines = ["digraph timeline {", "  rankdir=TB;", "  node [shape=box];"]
    lines += [f"  {_dot_quote(ev.id)} [label={_dot_quote(event_label(ev, names))}];" for ev in timeline.events]
    lines += [f"  {_dot_quote(c)} -> {_dot_quote(ev.id)};" for ev in timeline.events for c in ev.causes]
    lines.append("}")
    return "\n".join(lines) + "\n"


#: The largest time or coordinate a timeline may hold: distances between such values stay far from overflow.
MAX_VALUE = 1e9


def _bad(path: str, expected: str, value: Any) -> TimelineError:
    return TimelineError(f"{path}: expected {expected}, got {show(value)}")


def _need(obj: dict[str, Any], key: str, path: str) -> Any:
    if key not in obj:
        raise TimelineError(f"{path}: missing key {key!r}")
    return obj[key]


def _obj(value: Any, path: str, expected: str = "an object") -> dict[str, Any]:
    if not isinstance(value, dict):
        raise _bad(path, expected, value)
    return value


def _list(value: Any, path: str, expected: str = "a list") -> list[Any]:
    if not isinstance(value, list):
        raise _bad(path, expected, value)
    return value


def _str(value: Any, path: str, expected: str = "a string") -> str:
    if not isinstance(value, str):
        raise _bad(path, expected, value)
    return value


def _opt_str(value: Any, path: str) -> str | None:
    return None if value is None else _str(value, path, "a string or null")


def _num(value: Any, path: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise _bad(path, "a number", value)
    try:
        v = float(value)
    except OverflowError:
        v = math.inf
    if not abs(v) <= MAX_VALUE:  # NaN and Infinity too
        raise _bad(path, f"a finite number of at most {MAX_VALUE:g} in size", value)
    return v


def _frames_at(rows: Any, path: str) -> tuple[TrajectoryPoint, ...]:
    frames = []
    for i, row in enumerate(_list(rows, path)):
        row = _list(row, f"{path}[{i}]", "a row [t, x, y, angle, vx, vy]")
        if len(row) != 6:
            raise _bad(f"{path}[{i}]", "a row [t, x, y, angle, vx, vy]", row)
        frames.append(TrajectoryPoint(*(_num(v, f"{path}[{i}][{j}]") for j, v in enumerate(row))))
    return tuple(frames)


def _event(obj: Any, path: str, names: dict[str, str]) -> Event:
    obj = _obj(obj, path, "an event object")
    components = []
    for j, comp in enumerate(_list(_need(obj, "components", path), f"{path}.components")):
        at = f"{path}.components[{j}]"
        comp = _obj(comp, at, 'an object {"id", "label"}')
        cid = _str(_need(comp, "id", at), f"{at}.id")
        components.append(cid)
        label = _opt_str(comp.get("label"), f"{at}.label")
        if label is not None:
            names[cid] = label
    sides = []
    for j, part in enumerate(_list(_need(obj, "sides", path), f"{path}.sides")):
        at = f"{path}.sides[{j}]"
        part = _obj(part, at, 'an object {"component", "side"}')
        side = _str(_need(part, "side", at), f"{at}.side")
        sides.append((_str(_need(part, "component", at), f"{at}.component"), side))
        label = _opt_str(part.get("label"), f"{at}.label")
        if label is not None:  # bodies touched but not among the components
            names[sides[-1][0]] = label
    regions = []
    for j, part in enumerate(_list(_need(obj, "regions", path), f"{path}.regions")):
        at = f"{path}.regions[{j}]"
        part = _obj(part, at, 'an object {"component", "regions"}')
        crossed = _list(_need(part, "regions", at), f"{at}.regions")
        regions.append((_str(_need(part, "component", at), f"{at}.component"),
                        tuple(_str(r, f"{at}.regions[{k}]") for k, r in enumerate(crossed))))
        label = _opt_str(part.get("label"), f"{at}.label")
        if label is not None:  # bodies passed by but never touched
            names[regions[-1][0]] = label
    point = obj.get("point")
    if point is not None:
        if not isinstance(point, list) or len(point) != 2:
            raise _bad(f"{path}.point", "null or a point [x, y]", point)
        point = (_num(point[0], f"{path}.point[0]"), _num(point[1], f"{path}.point[1]"))
    tracks = []
    for j, track in enumerate(_list(obj.get("tracks", []), f"{path}.tracks")):  # absent before tracks existed
        at = f"{path}.tracks[{j}]"
        track = _obj(track, at, 'an object {"component", "trajectory"}')
        tracks.append((_str(_need(track, "component", at), f"{at}.component"),
                       _frames_at(_need(track, "trajectory", at), f"{at}.trajectory")))
    causes = _list(_need(obj, "causes", path), f"{path}.causes", "a list of event ids")
    return Event(
        id=_str(_need(obj, "id", path), f"{path}.id"),
        type=_str(_need(obj, "type", path), f"{path}.type"),
        components=tuple(components),
        causes=tuple(_str(c, f"{path}.causes[{j}]", "an event id (a string)") for j, c in enumerate(causes)),
        t0=_num(_need(obj, "t0", path), f"{path}.t0"),
        t1=_num(_need(obj, "t1", path), f"{path}.t1"),
        label=_opt_str(obj.get("user_label"), f"{path}.user_label"),
        sides=tuple(sides),
        regions=tuple(regions),
        point=point,
        trajectory=_frames_at(_need(obj, "trajectory", path), f"{path}.trajectory"),
        tracks=tuple(tracks),
    )


def parse_timeline_json(text: str) -> tuple[Timeline, dict[str, str]]:
    """The timeline and the component labels (id -> label) from `timeline_json` output.

    Raises `TimelineError` naming the JSON path of the first bad value (``events[2].sides[0].side``; NaN,
    Infinity and numbers beyond `MAX_VALUE` refused), `graph.CausalCycleError` for a cycle.
    """
    try:
        doc = json.loads(text, object_pairs_hook=unique_pairs)  # NaN and Infinity are refused by path below
    except DuplicateKey as exc:
        raise TimelineError(f"timeline JSON repeats key {exc.key!r}") from None
    except RecursionError:
        raise TimelineError("timeline JSON is nested too deeply") from None
    except ValueError as exc:
        raise TimelineError(f"timeline JSON is not valid JSON: {exc}") from None
    doc = _obj(doc, "timeline JSON", 'an object {"events": [...]}')
    names: dict[str, str] = {}
    events = [_event(obj, f"events[{i}]", names)
              for i, obj in enumerate(_list(_need(doc, "events", "timeline JSON"), "events"))]
    timeline = Timeline(tuple(events))
    check_acyclic(timeline)
    return timeline, names
