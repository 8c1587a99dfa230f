"""The one rule by which a simulation is equivalent to a demonstration, in the words every driver uses (SIMULATE's
message in the TUI, ``result.json``, ``physink equiv --up-to-demonstrated``); no comparison of its own, no I/O.

A simulation goes on after the demonstration ends: the ball the user put in the basket bounces in it twice more,
the cup it pushed off rolls away. `equivalence.compare` with ``simulation=True`` compares the two *up to the last
demonstrated event* (what the simulation does after its last event matched with the demonstration, and its
bounces coming to rest, are left out: `Comparison.after_b`); `verdict` names that rule and `afterwards` says what
was left out, so the user sees why a search that found an equivalent simulation and a comparison of the whole
timelines can disagree.
"""

from __future__ import annotations

from collections.abc import Mapping

from physink_tui.timeline.equivalence import Comparison
from physink_tui.timeline.events import Timeline

RULE = "up to the last demonstrated event"
"""The rule's name: the simulation is compared with the demonstration up to the demonstration's last event."""


def verdict(comparison: Comparison) -> str:
    """``equivalent up to the last demonstrated event`` or ``not equivalent up to ...``.

    >>> from physink_tui.timeline.equivalence import Comparison
    >>> verdict(Comparison(True, 0.0, 3.5, (), (), (), ()))
    'equivalent up to the last demonstrated event'
    """
    return f"{'equivalent' if comparison.equivalent else 'not equivalent'} {RULE}"


def _times(n: int) -> str:
    return {1: "once", 2: "twice"}.get(n, f"{n} times")


def afterwards(comparison: Comparison, simulated: Timeline, names: Mapping[str, str]) -> str | None:
    """What the simulation does after the demonstration, left out of the comparison, in words; None when nothing.

    ``afterwards the simulation goes on: the ball bounces on the basket twice more; the cup moves on``: contacts
    by pair (the body that moved into the other named first; *bounces on* when the pair touched within the
    demonstrated part too, else *touches*), then the bodies that only move on.

    >>> from physink_tui.timeline.equivalence import Comparison
    >>> from physink_tui.timeline.events import Event, Timeline
    >>> sim = Timeline((Event("e1", "start"), Event("e2", "movement", ("b1",), ("e1",), 0, 1),
    ...                 Event("e3", "contact", ("b1", "b2"), ("e2",), 1, 1),
    ...                 Event("e4", "movement", ("b1",), ("e3",), 1, 2),
    ...                 Event("e5", "contact", ("b1", "b2"), ("e4",), 2, 2),
    ...                 Event("e6", "movement", ("b1",), ("e5",), 2, 3),
    ...                 Event("e7", "contact", ("b1", "b2"), ("e6",), 3, 3)))
    >>> done = Comparison(True, 0.0, 1.0, (), (("e1", "e1"), ("e2", "e2"), ("e3", "e3")), (), (),
    ...                   ("e4", "e5", "e6", "e7"))
    >>> afterwards(done, sim, {"b1": "ball", "b2": "basket"})
    'afterwards the simulation goes on: the ball bounces on the basket twice more'
    """
    left = [simulated.event(e) for e in comparison.after_b if e in simulated]
    if not left:
        return None
    matched = {b for _, b in comparison.matches}
    touched_before = {frozenset(ev.components) for ev in simulated.events
                      if ev.id in matched and ev.type == "contact"}

    def name(c: str) -> str:  # "the ball"; an unlabelled body by its id, "b2"
        return f"the {names[c]}" if names.get(c) and names[c] != c else c

    pairs: dict[tuple[str, str], int] = {}
    for ev in left:
        if ev.type == "contact" and len(ev.components) == 2:
            key = (ev.components[0], ev.components[1])
            same = next((k for k in pairs if set(k) == set(key)), key)
            pairs[same] = pairs.get(same, 0) + 1
    parts = []
    for (a, b), n in pairs.items():
        if frozenset((a, b)) in touched_before:
            parts.append(f"{name(a)} bounces on {name(b)} {_times(n)} more")
        else:
            parts.append(f"{name(a)} touches {name(b)}" + ("" if n == 1 else f" {_times(n)}"))
    in_contacts = {c for pair in pairs for c in pair}
    ended: dict[tuple[str, str], int] = {}
    for ev in left:
        if ev.type == "end_contact" and len(ev.components) == 2:
            key = next((k for k in ended if set(k) == set(ev.components)), (ev.components[0], ev.components[1]))
            ended[key] = ended.get(key, 0) + 1
    parts += [f"{name(a)} comes away from {name(b)}" + ("" if n == 1 else f" {_times(n)}")
              for (a, b), n in ended.items()]
    movers = dict.fromkeys(ev.components[0] for ev in left if ev.type == "movement" and ev.components)
    parts += [f"{name(body)} moves on" for body in movers if body not in in_contacts]
    return "afterwards the simulation goes on: " + "; ".join(parts)
