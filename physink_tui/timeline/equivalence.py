"""Qualitative equivalence of two causal timelines (thesis 2.4, 3.4.4): distances and reasons; no I/O, no search.

Two timelines are *equivalent* when the same events happen in both, with the same causes and the same
qualitative geometry (the sides that touch, the regions a moving body passes through). Exact trajectories,
timings and contact points do not matter for that; they only make the quantitative distance, how *close* two
timelines are, which the parameter search (`physink_tui.sim`, not here) uses to choose among equivalent ones.

Components are matched by name: the label ``names`` gives, else the id, so two separately drawn projects whose
bodies carry the same labels compare as one scene, and a simulation of a scene (same ids) compares with its
demonstration. Two components of one timeline with the same label are treated as one body.

How events are matched: each event gets a *signature* (its type, the moving component, the set of the other
components). Start events are paired with start events in time order. The other events of each timeline are put
in order by (t0, causal depth, signature, creation order) -- depth so that a cause comes before what it causes
at the same instant, the signature so that simultaneous events are ordered alike whatever their ids -- and the
two signature sequences are aligned (`difflib.SequenceMatcher`, after stripping the common prefix and suffix).
Events left over on both sides with equal signatures are then paired in time order: concurrent, causally
unrelated events (two balls falling side by side) may happen in either order; the order that matters is
causality, which is compared next.

The qualitative distance adds up a cost (the ``*_COST`` constants) for each unmatched event, each side of a
matched contact that differs, each region of a matched movement passed in one timeline only, and each cause edge
between matched events present in one timeline only. The quantitative distance is the mean, over matched
movements and contacts, of the mean distance between the two trajectories resampled at the same fractions of
their durations (speed does not count) and of the distance between the two contact points, in canvas units.

>>> a = Timeline((Event("e1", "start"), Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0)))
>>> compare(a, a).equivalent
True
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from difflib import SequenceMatcher
from itertools import chain
from operator import attrgetter

import numpy as np

from physink_tui.timeline.events import REGIONS, Event, Timeline, event_label
from physink_tui.timeline.graph import topological_generations

UNMATCHED_EVENT_COST = 1.0
"""An event of one timeline with no counterpart in the other: the coarsest difference (figure 2-12, another
platform hit or one bounce more), so the unit of the qualitative distance."""
SIDE_COST = 0.5
"""Each body of a matched contact whose side differs (figure 2-13): half an event, so a contact with both sides
wrong weighs as much as a missing event, and it still counts (> 0) on its own. A body landing *inside* a container
in both timelines may touch it with any of its own sides first (the ball that lands in the basket, thesis 3.4.6):
only the container's side counts then."""
REGION_COST = 0.25
"""Each region (above, below, left, right) of one other body that a matched movement passes in one timeline only
while the other timeline passes the opposite region in its place (figure 2-14: above platform B in one, below it in
the other): above instead of below costs two regions, half an event. A region passed in one timeline only with
nothing opposed to it (a corner strip brushed, a body passed near in one timeline only) is the trajectory's shape,
which the quantitative distance measures: a simulated parabola is never exactly the path the pen drew (thesis
figure 3-22)."""
CAUSE_COST = 0.5
"""Each cause edge between matched events found in one timeline only: the same events in another causal order.
Edges to unmatched events are not counted again; the unmatched event already costs `UNMATCHED_EVENT_COST`."""
OPPOSITE = {"above": "below", "below": "above", "left": "right", "right": "left"}
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


@dataclass(frozen=True, slots=True)
class Comparison:
    """The result of comparing timeline A with timeline B.

    Attributes:
        equivalent: whether ``qualitative_distance`` is 0.
        qualitative_distance: sum of the costs (the module's ``*_COST`` constants) of every mismatch; >= 0.
        quantitative_distance: mean over the matched movements (mean distance between the resampled
            trajectories) and matched contacts (distance between the contact points), canvas units; 0 when
            nothing matched has positions. Unmatched events add nothing here.
        reasons: one sentence per mismatch (empty when asked not to explain): first the events found in A only,
            then those in B only, then the differences of matched events, each group in comparison order.
        matches: ``(event id in A, event id in B)`` per matched pair, in A's comparison order (starts first).
        only_a, only_b: ids of the events without a counterpart, in comparison order.
    """

    equivalent: bool
    qualitative_distance: float
    quantitative_distance: float
    reasons: tuple[str, ...]
    matches: tuple[tuple[str, str], ...]
    only_a: tuple[str, ...]
    only_b: tuple[str, ...]


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


def _geometry(ev: Event, names: Mapping[str, str]) -> Geometry:
    if ev.sides:
        return tuple(sorted((names.get(c) or c, side) for c, side in ev.sides))
    if ev.regions:
        crossed: dict[str, set[str]] = {}
        for c, regions in ev.regions:
            crossed.setdefault(names.get(c) or c, set()).update(regions)
        return tuple(sorted((n, tuple(r for r in REGIONS if r in rs)) for n, rs in crossed.items() if rs))
    return ()


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
    geometry = tuple(_geometry(ev, names) for ev in events)
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


def _align(sa: Sequence[str], sb: Sequence[str]) -> list[tuple[int, int]]:
    """Matched positions of two signature sequences, increasing in both."""
    n, m = len(sa), len(sb)
    lo = 0
    while lo < n and lo < m and sa[lo] == sb[lo]:
        lo += 1
    hi = 0
    while hi < n - lo and hi < m - lo and sa[n - 1 - hi] == sb[m - 1 - hi]:
        hi += 1
    pairs = [(k, k) for k in range(lo)]
    if lo < n - hi and lo < m - hi:
        matcher = SequenceMatcher(None, sa[lo:n - hi], sb[lo:m - hi], autojunk=False)
        for i, j, size in matcher.get_matching_blocks():
            pairs.extend((lo + i + k, lo + j + k) for k in range(size))
    pairs.extend((n - hi + k, m - hi + k) for k in range(hi))
    return pairs


def _match(pa: Prepared, pb: Prepared) -> list[tuple[int, int]]:
    """Matched event indices (A, B): starts in order, then the aligned others, then leftovers by signature.

    The alignment always runs with the smaller signature sequence first, so the matching -- and hence every
    distance -- is the same whichever timeline is A.
    """
    pairs = list(zip(pa.starts, pb.starts, strict=False))
    sa = [pa.signatures[i] for i in pa.others]
    sb = [pb.signatures[i] for i in pb.others]
    if sa == sb:
        return pairs + list(zip(pa.others, pb.others, strict=True))
    aligned = _align(sa, sb) if sa < sb else [(i, j) for j, i in _align(sb, sa)]
    used_a, used_b = {i for i, _ in aligned}, {j for _, j in aligned}
    left: dict[str, list[int]] = {}
    for j, s in enumerate(sb):
        if j not in used_b:
            left.setdefault(s, []).append(j)
    for i, s in enumerate(sa):
        waiting = left.get(s) if i not in used_a else None
        if waiting:
            aligned.append((i, waiting.pop(0)))
    aligned.sort()
    return pairs + [(pa.others[i], pb.others[j]) for i, j in aligned]


def _words(items: list[str]) -> str:
    return " and ".join(items) if len(items) <= 2 else ", ".join(items[:-1]) + " and " + items[-1]


def _t(t: float) -> str:
    return f"t={t:.2f}"


class _Explainer:
    """Writes the reasons; only made when they are asked for."""

    def __init__(self, pa: Prepared, pb: Prepared) -> None:
        self.pa, self.pb = pa, pb
        self.lines: list[str] = []

    def label(self, ia: int, ib: int) -> str:
        ea, eb = self.pa.timeline.events[ia], self.pb.timeline.events[ib]
        la, lb = event_label(ea, self.pa.names), event_label(eb, self.pb.names)
        name = la if la == lb else f"{la} / {lb}"
        ta, tb = _t(ea.t0), _t(eb.t0)
        return f"{name} ({ta})" if ta == tb else f"{name} ({ta} in A, {tb} in B)"

    def only(self, p: Prepared, i: int, side: str) -> None:
        ev = p.timeline.events[i]
        self.lines.append(f'"{event_label(ev, p.names)}" only in {side} ({_t(ev.t0)})')

    def causes(self, p: Prepared, i: int) -> str:
        evs = [p.timeline.events[c] for c in p.causes[i]]
        return " and ".join(f'"{event_label(ev, p.names)}" ({_t(ev.t0)})' for ev in evs) or "nothing"


def _geometry_cost(ga: Geometry, gb: Geometry, contact: bool,
                   say: _Explainer | None, ia: int, ib: int) -> float:
    da, db = dict(ga), dict(gb)
    cost = 0.0
    landed_in = contact and any(side == "inside" and db.get(name) == "inside" for name, side in da.items())
    for name in sorted(da.keys() | db.keys()):
        a, b = da.get(name), db.get(name)
        if a == b or (landed_in and "inside" not in (a, b)):
            continue  # what lands in a container may touch it with any side first (thesis 3.4.6)
        if contact:
            cost += SIDE_COST
            if say is not None:
                sa, sb = a or "not recorded", b or "not recorded"
                say.lines.append(f"{say.label(ia, ib)}: {name}'s side is {sa} in A, {sb} in B")
        else:
            ra = set(a) if isinstance(a, tuple) else set()
            rb = set(b) if isinstance(b, tuple) else set()
            opposed = _opposed(ra, rb) + _opposed(rb, ra)
            if not opposed:
                continue
            cost += REGION_COST * opposed
            if say is not None:
                words = [_words([r for r in REGIONS if r in rs]) or "no region" for rs in (ra, rb)]
                say.lines.append(f"{say.label(ia, ib)}: relative to {name} it passes {words[0]} in A, "
                                 f"{words[1]} in B")
    return cost


def _opposed(ra: set[str], rb: set[str]) -> int:
    """Regions passed in A only whose opposite is passed in B only: A went by on the other side."""
    return sum(1 for r in ra - rb if OPPOSITE[r] in rb - ra)


def _coming_to_rest(pa: Prepared, pb: Prepared, to_b: list[int], only_b: list[int]) -> set[int]:
    """The events of B (a simulation of the demonstration A) that only bring a body to rest where A left it.

    A body's demonstrated behaviour ends with a movement that causes nothing (a leaf), caused by its landing: a
    contact of the body with another. When that landing is matched in B, B's unmatched events from the landing on
    that are contacts or end-contacts of the same two bodies (the bounces of a ball in the basket it landed in),
    and the movements caused only by such events, are part of the same landing.
    """
    ev_a, ev_b = pa.timeline.events, pb.timeline.events
    caused = {c for cs in pa.causes for c in cs}
    landings: list[tuple[float, frozenset[str]]] = []
    for ia, ev in enumerate(ev_a):
        if ev.type != "movement" or ia in caused or to_b[ia] < 0 or len(pa.causes[ia]) != 1:
            continue
        landing = pa.causes[ia][0]
        if ev_a[landing].type == "contact" and to_b[landing] >= 0:
            landings.append((ev_b[to_b[landing]].t0, _names(ev_a[landing], pa.names)))
    excused: set[int] = set()
    if not landings:
        return excused
    for j in sorted(only_b, key=lambda j: (ev_b[j].t0, j)):
        ev = ev_b[j]
        if ev.type == "movement":
            if pb.causes[j] and all(c in excused for c in pb.causes[j]):
                excused.add(j)
        elif ev.type in ("contact", "end_contact"):
            pair = _names(ev, pb.names)
            if any(ev.t0 >= t and pair == landed for t, landed in landings):
                excused.add(j)
    return excused


def _names(ev: Event, names: Mapping[str, str]) -> frozenset[str]:
    return frozenset(names.get(c) or c for c in ev.components)


def compare_prepared(pa: Prepared, pb: Prepared, *, explain: bool = True, simulation: bool = False,
                     prefix: bool = False) -> Comparison:
    """`compare` for prepared timelines; ``explain=False`` skips writing the reasons (the distances are the same)."""
    pairs = _match(pa, pb)
    ev_a, ev_b = pa.timeline.events, pb.timeline.events
    to_b = [-1] * len(ev_a)
    to_a = [-1] * len(ev_b)
    for ia, ib in pairs:
        to_b[ia], to_a[ib] = ib, ia
    say = _Explainer(pa, pb) if explain else None
    only_a = [i for i in (*pa.starts, *pa.others) if to_b[i] < 0]
    only_b = [j for j in (*pb.starts, *pb.others) if to_a[j] < 0]
    if simulation and only_b:
        resting = _coming_to_rest(pa, pb, to_b, only_b)
        only_b = [j for j in only_b if j not in resting]
    if prefix and only_b:
        last = max((ev_b[ib].t0 for ia, ib in pairs if ev_b[ib].type != "start"), default=-1.0)
        only_b = [j for j in only_b if ev_b[j].t0 <= last]
    qualitative = UNMATCHED_EVENT_COST * (len(only_a) + len(only_b))
    if say is not None:
        for i in only_a:
            say.only(pa, i, "A")
        for j in only_b:
            say.only(pb, j, "B")

    rows_a, rows_b, points = [], [], 0.0
    n_points = 0
    for ia, ib in pairs:
        ea = ev_a[ia]
        ga, gb = pa.geometry[ia], pb.geometry[ib]
        if ga != gb:
            qualitative += _geometry_cost(ga, gb, ea.type == "contact", say, ia, ib)
        ca, cb = pa.causes[ia], pb.causes[ib]
        if len(ca) == 1 and len(cb) == 1 and to_b[ca[0]] == cb[0]:
            pass  # the usual case, one cause each and they match: no sets to build
        elif (mapped := {to_b[c] for c in ca if to_b[c] >= 0}) != (own := {c for c in cb if to_a[c] >= 0}):
            qualitative += CAUSE_COST * len(mapped ^ own)
            if say is not None:
                say.lines.append(f"{say.label(ia, ib)} is caused by {say.causes(pa, ia)} in A but by "
                                 f"{say.causes(pb, ib)} in B")
        if pa.rows[ia] >= 0 and pb.rows[ib] >= 0:
            rows_a.append(pa.rows[ia])
            rows_b.append(pb.rows[ib])
        elif ea.point is not None and ev_b[ib].point is not None:
            pta, ptb = ea.point, ev_b[ib].point
            points += ((pta[0] - ptb[0]) ** 2 + (pta[1] - ptb[1]) ** 2) ** 0.5
            n_points += 1
    total = points
    if rows_a:
        gap = pa.paths[rows_a] - pb.paths[rows_b]
        total += float(np.sqrt((gap * gap).sum(axis=2)).mean(axis=1).sum())
    count = len(rows_a) + n_points
    quantitative = total / count if count else 0.0

    return Comparison(
        equivalent=qualitative == 0.0,
        qualitative_distance=qualitative,
        quantitative_distance=quantitative,
        reasons=() if say is None else tuple(say.lines),
        matches=tuple((ev_a[ia].id, ev_b[ib].id) for ia, ib in pairs),
        only_a=tuple(ev_a[i].id for i in only_a),
        only_b=tuple(ev_b[j].id for j in only_b),
    )


def compare(a: Timeline, b: Timeline, names_a: Mapping[str, str] | None = None,
            names_b: Mapping[str, str] | None = None, *, explain: bool = True,
            simulation: bool = False, prefix: bool = False) -> Comparison:
    """How far timeline ``b`` is from timeline ``a``, qualitatively and quantitatively, and why.

    Args:
        a, b: the timelines (e.g. the demonstrated and a simulated one).
        names_a, names_b: component id -> label for each (default: none; components are then matched by id).
        explain: write the reasons (False for a search loop that needs only the distances).
        simulation: ``b`` simulates the demonstration ``a``: what B does after a body's demonstrated behaviour
            has ended, only to bring it to rest where it landed, is no difference (`_coming_to_rest`).
        prefix: ``a`` is the beginning of a behaviour that ``b`` goes on beyond (the search compares a simulation
            leg by leg): B's unmatched events later than its last event matched with A are no difference.

    The qualitative distance is symmetric unless ``simulation``: ``compare(a, b)`` and ``compare(b, a)`` give the
    same distances.
    Raises `graph.CausalCycleError` when a timeline has a cycle.
    """
    return compare_prepared(prepare(a, names_a), prepare(b, names_b), explain=explain, simulation=simulation,
                            prefix=prefix)
