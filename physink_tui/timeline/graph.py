"""Graph algorithms on a `Timeline` as free functions (networkx vocabulary): edges run cause -> effect.

Results that are sets follow networkx (`ancestors`, `descendants` exclude the event itself); results with an
order are deterministic: ties are broken by creation order.
"""

from __future__ import annotations

from physink_tui.timeline.events import Timeline, TimelineError


class CausalCycleError(TimelineError):
    """The timeline's causes form a cycle, which the thesis forbids (events cannot cause themselves).

    Attributes:
        cycle: the event ids along the cycle in causal order; the last one causes the first.
    """

    def __init__(self, cycle: tuple[str, ...]) -> None:
        self.cycle = cycle
        path = " -> ".join(repr(e) for e in (*cycle, cycle[0]))
        super().__init__(f"the timeline has a causal cycle {path}; expected a directed acyclic graph", cycle[0])


def ancestors(timeline: Timeline, event_id: str) -> set[str]:
    """Every event that causes ``event_id`` directly or indirectly (not the event itself)."""
    seen: set[str] = set()
    stack = list(timeline.event(event_id).causes)
    while stack:
        e = stack.pop()
        if e not in seen:
            seen.add(e)
            stack.extend(timeline.event(e).causes)
    seen.discard(event_id)
    return seen


def descendants(timeline: Timeline, event_id: str) -> set[str]:
    """Every event ``event_id`` causes directly or indirectly (not the event itself)."""
    seen: set[str] = set()
    stack = list(timeline.children(event_id))
    while stack:
        e = stack.pop()
        if e not in seen:
            seen.add(e)
            stack.extend(timeline.children(e))
    seen.discard(event_id)
    return seen


def find_cycle(timeline: Timeline) -> tuple[str, ...] | None:
    """One causal cycle as event ids in causal order (the first found in creation order), or None."""
    white, grey, black = 0, 1, 2
    colour = dict.fromkeys(timeline.ids(), white)
    for root in timeline.ids():
        if colour[root] != white:
            continue
        path: list[str] = [root]
        iters = [iter(timeline.children(root))]
        colour[root] = grey
        while iters:
            child = next(iters[-1], None)
            if child is None:
                colour[path.pop()] = black
                iters.pop()
            elif colour[child] == grey:
                return tuple(path[path.index(child):])
            elif colour[child] == white:
                colour[child] = grey
                path.append(child)
                iters.append(iter(timeline.children(child)))
    return None


def check_acyclic(timeline: Timeline) -> None:
    """Raise `CausalCycleError` naming a cycle when the timeline is not a DAG."""
    cycle = find_cycle(timeline)
    if cycle is not None:
        raise CausalCycleError(cycle)


def topological_generations(timeline: Timeline) -> list[list[str]]:
    """Events in layers: the first holds events with no cause, each next one events whose causes all came before.

    Within a layer ids are in creation order. Raises `CausalCycleError` when the timeline has a cycle.
    """
    pending = {ev.id: len(set(ev.causes)) for ev in timeline.events}
    layer = [ev.id for ev in timeline.events if pending[ev.id] == 0]
    generations: list[list[str]] = []
    placed = 0
    while layer:
        generations.append(layer)
        placed += len(layer)
        ready: set[str] = set()
        for e in layer:
            for child in timeline.children(e):
                pending[child] -= 1
                if pending[child] == 0:
                    ready.add(child)
        layer = sorted(ready, key=timeline.position)
    if placed != len(timeline):
        check_acyclic(timeline)
    return generations
