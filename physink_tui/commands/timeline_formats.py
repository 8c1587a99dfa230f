"""The timeline as JSON and as Graphviz DOT for `physink timeline` (DESIGN.md "Timeline JSON"); the text format
is `physink_tui.timeline.narrate.timeline_text`.

JSON: ``{"events": [...]}`` with one object per event in creation order and every key present for every type
(empty lists where a type has none), floats rounded to 6 decimals, so the same timeline always gives the same
bytes. `parse_timeline_json` reads it back (``label`` is the narration shown; ``user_label`` the user's phrase).
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any

from physink_tui.strict_json import DuplicateKey, unique_pairs
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


def _read_frames(rows: Any) -> tuple[TrajectoryPoint, ...]:
    return tuple(TrajectoryPoint(*(float(v) for v in row)) for row in rows)


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


def _need(obj: Any, key: str, kind: type | tuple[type, ...], where: str) -> Any:
    if not isinstance(obj, dict) or key not in obj:
        raise TimelineError(f"{where}: missing key {key!r}")
    value = obj[key]
    kinds = kind if isinstance(kind, tuple) else (kind,)
    if not isinstance(value, kinds) or (isinstance(value, bool) and bool not in kinds):
        raise TimelineError(f"{where}: {key!r} is {value!r}; expected {kind}")
    return value


def parse_timeline_json(text: str) -> tuple[Timeline, dict[str, str]]:
    """The timeline and the component labels (id -> label) from `timeline_json` output.

    Raises `TimelineError` naming the event and key for malformed input, `graph.CausalCycleError` for a cycle.
    """
    try:
        doc = json.loads(text, object_pairs_hook=unique_pairs)
    except DuplicateKey as exc:
        raise TimelineError(f"timeline JSON repeats key {exc.key!r}") from None
    except ValueError as exc:
        raise TimelineError(f"timeline JSON is not valid JSON: {exc}") from None
    events: list[Event] = []
    names: dict[str, str] = {}
    num = (int, float)
    for i, obj in enumerate(_need(doc, "events", list, "timeline JSON")):
        where = f"timeline JSON event {i}"
        components = []
        for comp in _need(obj, "components", list, where):
            cid = _need(comp, "id", str, where)
            components.append(cid)
            if isinstance(comp.get("label"), str):
                names[cid] = comp["label"]
        for part in (*obj.get("sides", []), *obj.get("regions", [])):  # bodies passed by but never touched
            if isinstance(part, dict) and isinstance(part.get("component"), str) and isinstance(part.get("label"), str):
                names[part["component"]] = part["label"]
        point = obj.get("point")
        try:
            events.append(Event(
                id=_need(obj, "id", str, where),
                type=_need(obj, "type", str, where),
                components=tuple(components),
                causes=tuple(_need(obj, "causes", list, where)),
                t0=float(_need(obj, "t0", num, where)),
                t1=float(_need(obj, "t1", num, where)),
                label=obj.get("user_label"),
                sides=tuple((_need(s, "component", str, where), _need(s, "side", str, where))
                            for s in _need(obj, "sides", list, where)),
                regions=tuple((_need(r, "component", str, where), tuple(_need(r, "regions", list, where)))
                              for r in _need(obj, "regions", list, where)),
                point=None if point is None else (float(point[0]), float(point[1])),
                trajectory=_read_frames(_need(obj, "trajectory", list, where)),
                tracks=tuple((_need(tr, "component", str, where), _read_frames(_need(tr, "trajectory", list, where)))
                             for tr in obj.get("tracks", [])),  # absent in timelines written before tracks
            ))
        except (TypeError, IndexError, ValueError) as exc:
            raise TimelineError(f"{where}: malformed value ({exc})") from None
    timeline = Timeline(tuple(events))
    check_acyclic(timeline)
    return timeline, names
