"""Cuts a demonstrated timeline into causal legs for the leg-by-leg search; no stepping, no search.

A *leg* ends with a contact or an end-contact: the first leg is the start, the first movements and the first
contact they bring about; each next leg adds the movements that contact causes and the next contact. Events are
taken in the equivalence metric's comparison order (time, then causal depth), so a cause always comes before what it
causes and every prefix is a timeline of its own. The last leg is the whole demonstration.

A leg's *components* are those named by the events up to its end (a movement names its body and what is tied to
it): the parameters of those components -- masses, frictions, springs, the initial velocities of start bodies --
are what the prefix can depend on, so the search adjusts only them while it solves that leg.
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.timeline.events import Timeline
from physink_tui.timeline.prepared import prepare


@dataclass(frozen=True, slots=True)
class Leg:
    """The demonstration up to the end of one leg.

    Attributes:
        events: the ids of the events up to and including the leg's last event.
        components: the component ids those events name.
        last: the id of its last event (a contact or end-contact; the last leg may end with a movement).
    """

    events: frozenset[str]
    components: frozenset[str]
    last: str
    own: frozenset[str] = frozenset()
    """The component ids the leg's own events name (not those of earlier legs): what the leg brings in."""


def legs(timeline: Timeline) -> tuple[Leg, ...]:
    """The legs of ``timeline`` in causal order, the last one the whole timeline (empty for an empty timeline)."""
    prepared = prepare(timeline)
    order = [*prepared.starts, *prepared.others]
    events = timeline.events
    out: list[Leg] = []
    taken: list[int] = []
    since = 0
    for position, i in enumerate(order):
        taken.append(i)
        ends_leg = events[i].type in ("contact", "end_contact") or position == len(order) - 1
        if ends_leg:
            out.append(_leg(timeline, taken, since, events[i].id))
            since = len(taken)
    return tuple(out)


def _leg(timeline: Timeline, taken: list[int], since: int, last: str) -> Leg:
    events = [timeline.events[i] for i in taken]
    return Leg(frozenset(ev.id for ev in events), frozenset(c for ev in events for c in ev.components), last,
               frozenset(c for ev in events[since:] for c in ev.components))
