"""A timeline prepared for comparison (`prepare`): each event's signature, causes, qualitative geometry and
resampled trajectory, computed once; the comparison itself is equivalence.py's.

Events are put in *comparison order*: (t0, causal depth, signature, creation order) -- depth so that a cause comes
before what it causes at the same instant, the signature so that simultaneous events are ordered alike whatever
their ids.
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from itertools import accumulate, chain
from operator import attrgetter

import numpy as np

from physink_tui.timeline.events import REGIONS, Event, Timeline
from physink_tui.timeline.graph import topological_generations

SAMPLES = 32
"""Points at which two matched movements are compared, evenly spaced over each one's duration (0 to 1)."""

_TYPE_RANK = {"start": "0", "contact": "1", "end_contact": "2", "movement": "3"}
_SEP, _SUB = "\x1e", "\x1f"  # separators inside signature strings: never part of a name
_TXY = attrgetter("t", "x", "y")

Geometry = tuple[tuple[str, str | tuple[str, ...]], ...]
"""A contact's ``(name, side)`` or a movement's ``(name, regions crossed)`` pairs, sorted by name."""


@dataclass(frozen=True, slots=True, eq=False)
class Prepared:
    """What `compare` needs of one timeline, computed once: prepare the demonstrated timeline once and compare it
    with many simulated ones (`compare_prepared`). Indices are positions in ``timeline.events``.

    Attributes:
        timeline: the timeline.
        names: component id -> label, as given.
        starts: the start events in order.
        others: the other events in comparison order (t0, causal depth, signature, creation order).
        signatures: one string per event (type, moving component, other components by name), equal for
            events that may match.
        causes: per event, the indices of its causes.
        geometry: per event, ``(name, side)`` pairs of a contact or ``(name, regions)`` pairs of a movement
            (regions in `REGIONS` order, bodies passed through no region left out), sorted by name.
        rows: per event, its row in ``paths`` (a movement with a trajectory) or -1.
        paths: float array (movements, `SAMPLES`, 2): each trajectory resampled at evenly spaced fractions of
            its duration, canvas units.
    """

    timeline: Timeline
    names: Mapping[str, str]
    starts: tuple[int, ...]
    others: tuple[int, ...]
    signatures: tuple[str, ...]
    causes: tuple[tuple[int, ...], ...]
    geometry: tuple[Geometry, ...]
    rows: tuple[int, ...]
    paths: np.ndarray



def _depths(timeline: Timeline, index: Mapping[str, int]) -> list[int]:
    """Longest chain of causes above each event; one pass when causes come first (as recorded)."""
    depth = [0] * len(timeline.events)
    for i, ev in enumerate(timeline.events):
        d = 0
        for c in ev.causes:
            j = index[c]
            if j >= i:  # a cause created later (a hand-made timeline): take the general way
                return _depths_any_order(timeline, index)
            d = max(d, depth[j] + 1)
        depth[i] = d
    return depth


def _depths_any_order(timeline: Timeline, index: Mapping[str, int]) -> list[int]:
    depth = [0] * len(timeline.events)
    for level, layer in enumerate(topological_generations(timeline)):  # raises CausalCycleError on a cycle
        for event_id in layer:
            depth[index[event_id]] = level  # a layer is one more than the deepest of its causes
    return depth


def _signature(ev: Event, names: Mapping[str, str]) -> str:
    comps = [names.get(c) or c for c in ev.components]
    if ev.type == "movement" and comps:
        return f"{_TYPE_RANK['movement']}{_SEP}{comps[0]}{_SEP}{_SUB.join(sorted(set(comps[1:])))}"
    return f"{_TYPE_RANK[ev.type]}{_SEP}{_SEP}{_SUB.join(sorted(set(comps)))}"


def _geometry(ev: Event, names: Mapping[str, str], moving: frozenset[str] = frozenset()) -> Geometry:
    if ev.sides:
        return tuple(sorted((names.get(c) or c, side) for c, side in ev.sides))
    if ev.regions:
        crossed: dict[str, set[str]] = {}
        for c, regions in ev.regions:
            if c not in moving:
                crossed.setdefault(names.get(c) or c, set()).update(regions)
        return tuple(sorted((n, tuple(r for r in REGIONS if r in rs)) for n, rs in crossed.items() if rs))
    return ()


def _moving_meanwhile(events: Sequence[Event]) -> dict[int, frozenset[str]]:
    """Per movement (by index), the bodies that other movements move while it lasts: a movement's regions count
    relative to the scenery it passes, not to a body swinging at the same time (the ball and the paddle it hits).

    Per body, its movements' spans sorted by start with the latest end so far, so each (movement, body) question is
    one bisection: O(movements x bodies x log) rather than every pair of movements.
    """
    spans: dict[str, list[tuple[float, float]]] = {}
    for ev in events:
        if ev.type == "movement":
            for c in ev.components:
                spans.setdefault(c, []).append((ev.t0, ev.t1))
    starts: dict[str, list[float]] = {}
    latest_end: dict[str, list[float]] = {}
    for c, body_spans in spans.items():
        body_spans.sort()
        starts[c] = [t0 for t0, _ in body_spans]
        latest_end[c] = list(accumulate((t1 for _, t1 in body_spans), max))
    out: dict[int, frozenset[str]] = {}
    for i, ev in enumerate(events):
        if ev.type != "movement":
            continue
        own = set(ev.components)
        out[i] = frozenset(c for c in starts if c not in own and (k := bisect_left(starts[c], ev.t1)) > 0
                           and latest_end[c][k - 1] > ev.t0)
    return out


def _resample(movements: Sequence[Event]) -> np.ndarray:
    """Every trajectory at `SAMPLES` evenly spaced fractions of its duration, in one numpy pass."""
    if not movements:
        return np.zeros((0, SAMPLES, 2))
    lengths = np.fromiter((len(ev.trajectory) for ev in movements), dtype=np.intp, count=len(movements))
    frames = chain.from_iterable(ev.trajectory for ev in movements)
    flat = np.fromiter(chain.from_iterable(map(_TXY, frames)), dtype=float, count=3 * int(lengths.sum()))
    flat = flat.reshape(-1, 3)
    ends = np.cumsum(lengths)
    starts = ends - lengths
    seg = np.repeat(np.arange(len(movements)), lengths)
    local = np.arange(len(flat)) - starts[seg]
    t_first, dur = flat[starts, 0], flat[ends - 1, 0] - flat[starts, 0]
    by_index = local / np.maximum(lengths - 1, 1)[seg]  # a movement of zero duration: its frames evenly spaced
    by_time = (flat[:, 0] - t_first[seg]) / np.where(dur > 0, dur, 1.0)[seg]
    u = np.where((dur > 0)[seg], by_time, by_index)
    key = 2.0 * seg + u  # segments kept apart on one axis, so one np.interp serves them all
    query = (2.0 * np.arange(len(movements))[:, None] + np.linspace(0.0, 1.0, SAMPLES)[None, :]).ravel()
    out = np.empty((len(movements), SAMPLES, 2))
    out[:, :, 0] = np.interp(query, key, flat[:, 1]).reshape(len(movements), SAMPLES)
    out[:, :, 1] = np.interp(query, key, flat[:, 2]).reshape(len(movements), SAMPLES)
    single = lengths == 1
    if single.any():
        out[single] = flat[starts[single], 1:3][:, None, :]
    return out


def prepare(timeline: Timeline, names: Mapping[str, str] | None = None) -> Prepared:
    """The timeline ready for `compare_prepared`; ``names`` maps component ids to labels (default: none).

    Raises `graph.CausalCycleError` when the timeline has a cycle.
    """
    names = {} if names is None else names
    events = timeline.events
    index = {ev.id: i for i, ev in enumerate(events)}
    depth = _depths(timeline, index)
    signatures = tuple(_signature(ev, names) for ev in events)
    causes = tuple(tuple(index[c] for c in ev.causes) for ev in events)
    moving_meanwhile = _moving_meanwhile(events)
    geometry = tuple(_geometry(ev, names, moving_meanwhile.get(i, frozenset())) for i, ev in enumerate(events))
    moving = [i for i, ev in enumerate(events) if ev.type == "movement" and ev.trajectory]
    rows = [-1] * len(events)
    for row, i in enumerate(moving):
        rows[i] = row
    ordered = sorted(range(len(events)), key=lambda i: (events[i].t0, depth[i], signatures[i], i))
    return Prepared(
        timeline, names,
        starts=tuple(i for i in ordered if events[i].type == "start"),
        others=tuple(i for i in ordered if events[i].type != "start"),
        signatures=signatures, causes=causes, geometry=geometry, rows=tuple(rows),
        paths=_resample([events[i] for i in moving]),
    )
