"""SIMULATE's rule that a simulation may bring a body to rest where the demonstration left it: the bounces of a
ball in the basket it landed in are part of its landing (issue "SIMULATE", thesis 3.4.6); the comparison itself is
equivalence.py's.
"""

from __future__ import annotations

from collections.abc import Mapping

from physink_tui.timeline.events import Event
from physink_tui.timeline.prepared import Prepared


def coming_to_rest(pa: Prepared, pb: Prepared, to_b: list[int], only_b: list[int]) -> set[int]:
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
            landings.append((ev_b[to_b[landing]].t0, names_of(ev_a[landing], pa.names)))
    excused: set[int] = set()
    if not landings:
        return excused
    for j in sorted(only_b, key=lambda j: (ev_b[j].t0, j)):
        ev = ev_b[j]
        if ev.type == "movement":
            if pb.causes[j] and all(c in excused for c in pb.causes[j]):
                excused.add(j)
        elif ev.type in ("contact", "end_contact"):
            pair = names_of(ev, pb.names)
            if any(ev.t0 >= t and pair == landed for t, landed in landings):
                excused.add(j)
    return excused


def continued(pb: Prepared, excused: set[int]) -> dict[int, int]:
    """For each excused movement of B (`coming_to_rest`), the movement it goes on with: the bounces of a body coming
    to rest are one contact with its landing, so they split no movement of the bodies in them (the cup a ball
    rattles in moves on as one movement). The movement of the same body that caused the excused event it follows,
    itself followed back while excused; movements with no such predecessor are left out."""
    out: dict[int, int] = {}
    events = pb.timeline.events
    for j in sorted(excused, key=lambda j: (events[j].t0, j)):
        ev = events[j]
        if ev.type != "movement" or not ev.components:
            continue
        before = [c for bounce in pb.causes[j] for c in pb.causes[bounce]
                  if events[c].type == "movement" and events[c].components[:1] == ev.components[:1]]
        if before:
            out[j] = out.get(before[0], before[0])
    return out


def names_of(ev: Event, names: Mapping[str, str]) -> frozenset[str]:
    return frozenset(names.get(c) or c for c in ev.components)
