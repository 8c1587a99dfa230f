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
matched contact that differs (not the own side of a body landing inside a container in both), each region of a
matched movement passed in one timeline only while the other passes the opposite one, and each cause edge between
matched events present in one timeline only. With ``simulation=True`` (B simulates the demonstration A), B's
unmatched events after its last matched one and its bounces coming to rest are left out (`compare`), and such a
bounce splits no movement of the bodies in it. The quantitative distance is the mean, over matched movements and
contacts, of the mean distance between the two trajectories resampled at the same fractions of their durations
(speed does not count) and of the distance between the two contact points, in canvas units.

>>> a = Timeline((Event("e1", "start"), Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0)))
>>> compare(a, a).equivalent
True
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from difflib import SequenceMatcher

import numpy as np

from physink_tui.timeline.events import REGIONS, Event, Timeline, event_label
from physink_tui.timeline.prepared import SAMPLES, Geometry, Prepared, prepare
from physink_tui.timeline.resting import coming_to_rest, continued

__all__ = ["CAUSE_COST", "REGION_COST", "SAMPLES", "SIDE_COST", "UNMATCHED_EVENT_COST", "Comparison",
           "PrefixDistance", "Prepared", "compare", "compare_prefixes", "compare_prepared", "prepare"]

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
figure 3-22). Regions count against the scenery a body passes: not relative to a body that another movement moves
at the same time (the paddle swinging as the ball goes by; `prepared.py`)."""
CAUSE_COST = 0.5
"""Each cause edge between matched events found in one timeline only: the same events in another causal order.
Edges to unmatched events are not counted again; the unmatched event already costs `UNMATCHED_EVENT_COST`."""
OPPOSITE = {"above": "below", "below": "above", "left": "right", "right": "left"}
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
        after_b: with ``simulation=True``, B's events left out of the comparison, in comparison order: what the
            simulation does after its last event matched with the demonstration, and its bounces coming to rest
            (`afterwards` says it in words); empty otherwise.
    """

    equivalent: bool
    qualitative_distance: float
    quantitative_distance: float
    reasons: tuple[str, ...]
    matches: tuple[tuple[str, str], ...]
    only_a: tuple[str, ...]
    only_b: tuple[str, ...]
    after_b: tuple[str, ...] = ()


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


@dataclass(slots=True)
class _Ledger:
    """Every cost of one comparison with what it is charged to: an event of A (by index) or, for an event of B
    only, its time in B; and each matched pair's trajectory or contact-point distance, by A's event."""

    a_costs: list[tuple[int, float]]
    b_costs: list[tuple[Event, float]]  # an event of B only, its cost
    distances: list[tuple[int, float]]
    b_time: dict[int, float]  # A's matched events: the time of their counterpart in B


def _compare(pa: Prepared, pb: Prepared, say: _Explainer | None, simulation: bool) -> tuple[Comparison, _Ledger]:
    pairs = _match(pa, pb)
    ev_a, ev_b = pa.timeline.events, pb.timeline.events
    to_b = [-1] * len(ev_a)
    to_a = [-1] * len(ev_b)
    for ia, ib in pairs:
        to_b[ia], to_a[ib] = ib, ia
    only_a = [i for i in (*pa.starts, *pa.others) if to_b[i] < 0]
    only_b = [j for j in (*pb.starts, *pb.others) if to_a[j] < 0]
    goes_on: dict[int, int] = {}  # B's movements split off by a bounce coming to rest -> the one they go on with
    after_b: list[int] = []
    if simulation and only_b:
        resting = coming_to_rest(pa, pb, to_b, only_b)
        goes_on = continued(pb, resting)
        until = max((ev_b[ib].t0 for _, ib in pairs if ev_b[ib].type != "start"), default=-1.0)
        kept = [j for j in only_b if j not in resting and _before(ev_b[j], until)]
        after_b = [j for j in only_b if j not in kept]
        only_b = kept
    ledger = _Ledger([(i, UNMATCHED_EVENT_COST) for i in only_a],
                     [(ev_b[j], UNMATCHED_EVENT_COST) for j in only_b], [],
                     {ia: ev_b[ib].t0 for ia, ib in pairs})
    if say is not None:
        for i in only_a:
            say.only(pa, i, "A")
        for j in only_b:
            say.only(pb, j, "B")
    rows_a, rows_b, row_owner = [], [], []
    for ia, ib in pairs:
        ea = ev_a[ia]
        ga, gb = pa.geometry[ia], pb.geometry[ib]
        if ga != gb:
            cost = _geometry_cost(ga, gb, ea.type == "contact", say, ia, ib)
            if cost:
                ledger.a_costs.append((ia, cost))
        ca, cb = pa.causes[ia], pb.causes[ib]
        if goes_on:
            cb = tuple(dict.fromkeys(goes_on.get(c, c) for c in cb))
        if len(ca) == 1 and len(cb) == 1 and to_b[ca[0]] == cb[0]:
            pass  # the usual case, one cause each and they match: no sets to build
        elif (mapped := {to_b[c] for c in ca if to_b[c] >= 0}) != (own := {c for c in cb if to_a[c] >= 0}):
            ledger.a_costs.append((ia, CAUSE_COST * len(mapped ^ own)))
            if say is not None:
                say.lines.append(f"{say.label(ia, ib)} is caused by {say.causes(pa, ia)} in A but by "
                                 f"{say.causes(pb, ib)} in B")
        if pa.rows[ia] >= 0 and pb.rows[ib] >= 0:
            rows_a.append(pa.rows[ia])
            rows_b.append(pb.rows[ib])
            row_owner.append(ia)
        elif (pta := ea.point) is not None and (ptb := ev_b[ib].point) is not None:
            ledger.distances.append((ia, ((pta[0] - ptb[0]) ** 2 + (pta[1] - ptb[1]) ** 2) ** 0.5))
    if rows_a:
        gap = pa.paths[rows_a] - pb.paths[rows_b]
        per_row = np.sqrt((gap * gap).sum(axis=2)).mean(axis=1)
        ledger.distances.extend(zip(row_owner, per_row.tolist(), strict=True))
    qualitative = sum(c for _, c in ledger.a_costs) + sum(c for _, c in ledger.b_costs)
    quantitative = sum(d for _, d in ledger.distances) / len(ledger.distances) if ledger.distances else 0.0
    comparison = Comparison(
        equivalent=qualitative == 0.0,
        qualitative_distance=qualitative,
        quantitative_distance=quantitative,
        reasons=() if say is None else tuple(say.lines),
        matches=tuple((ev_a[ia].id, ev_b[ib].id) for ia, ib in pairs),
        only_a=tuple(ev_a[i].id for i in only_a),
        only_b=tuple(ev_b[j].id for j in only_b),
        after_b=tuple(ev_b[j].id for j in after_b),
    )
    return comparison, ledger


def _before(ev: Event, until: float) -> bool:
    """Whether an event of B counts before B's last matched event at ``until``: earlier, or at that instant a
    contact (the movements a contact causes start with it and belong to what follows)."""
    return ev.t0 < until or (ev.t0 == until and ev.type != "movement")


def compare_prepared(pa: Prepared, pb: Prepared, *, explain: bool = True, simulation: bool = False) -> Comparison:
    """`compare` for prepared timelines; ``explain=False`` skips writing the reasons (the distances are the same)."""
    return _compare(pa, pb, _Explainer(pa, pb) if explain else None, simulation)[0]


@dataclass(frozen=True, slots=True)
class PrefixDistance:
    """How far B is from the beginning of A (`compare_prefixes`).

    Attributes:
        qualitative_distance, quantitative_distance: as `Comparison`'s, over the prefix's events and B's
            unmatched events up to the last one matched with the prefix.
        only_a: ids of the prefix's events without a counterpart in B.
    """

    qualitative_distance: float
    quantitative_distance: float
    only_a: tuple[str, ...]


def compare_prefixes(pa: Prepared, pb: Prepared, prefixes: Sequence[frozenset[str]], *,
                     simulation: bool = False) -> tuple[Comparison, tuple[PrefixDistance, ...]]:
    """The whole comparison (without reasons) and, for each prefix of A (a set of A's event ids closed under
    causes, e.g. a leg of the search), the distances that prefix accounts for.

    One matching serves every prefix: a prefix is charged the costs of its own events (unmatched, other
    geometry, other causes) and the events of B only that happen before the last event of B matched with the
    prefix (at that instant, contacts only: the movements a matched contact causes belong to the next leg); what
    B does later, or in a concurrent chain that A has later too, is not the prefix's business.
    """
    whole, ledger = _compare(pa, pb, None, simulation)
    index = {ev.id: i for i, ev in enumerate(pa.timeline.events)}
    out = []
    for prefix in prefixes:
        inside = {index[e] for e in prefix}
        until = max((t for i, t in ledger.b_time.items() if i in inside and pa.timeline.events[i].type != "start"),
                    default=-1.0)
        qualitative = sum(c for i, c in ledger.a_costs if i in inside)
        qualitative += sum(c for ev, c in ledger.b_costs if _before(ev, until))

        distances = [d for i, d in ledger.distances if i in inside]
        quantitative = sum(distances) / len(distances) if distances else 0.0
        only_a = tuple(e for e in whole.only_a if e in prefix)
        out.append(PrefixDistance(qualitative, quantitative, only_a))
    return whole, tuple(out)


def compare(a: Timeline, b: Timeline, names_a: Mapping[str, str] | None = None,
            names_b: Mapping[str, str] | None = None, *, explain: bool = True,
            simulation: bool = False) -> Comparison:
    """How far timeline ``b`` is from timeline ``a``, qualitatively and quantitatively, and why.

    Args:
        a, b: the timelines (e.g. the demonstrated and a simulated one).
        names_a, names_b: component id -> label for each (default: none; components are then matched by id).
        explain: write the reasons (False for a search loop that needs only the distances).
        simulation: ``b`` simulates the demonstration ``a``: the comparison covers the demonstrated behaviour, so
            what B does after its last event matched with A (the demonstration has played out) is no difference,
            and neither are the bounces of a body coming to rest where it landed once its own demonstrated
            behaviour has ended (`resting.coming_to_rest`), nor do they split the movements of the bodies in them
            (`resting.continued`: the cup a ball rattles in moves on); a bounce more before that still counts
            (figure 2-12).

    The qualitative distance is symmetric unless ``simulation``: ``compare(a, b)`` and ``compare(b, a)`` give the
    same distances.
    Raises `graph.CausalCycleError` when a timeline has a cycle.
    """
    return compare_prepared(prepare(a, names_a), prepare(b, names_b), explain=explain, simulation=simulation)
