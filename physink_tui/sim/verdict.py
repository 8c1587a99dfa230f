"""SIMULATE's verdict in words: reproduced, or the first demonstrated event no candidate reproduces and why (thesis
2.4.2: "the system will inform the user"); no search, no I/O.

The first event is found leg by leg (`legs.legs`, causal order): the first leg the best candidate does not
reproduce, then the first of that leg's own events the simulation lacks. Why, in words:

- a movement nothing causes (no start, no contact: a body rising from rest by itself): no physics sets a body at
  rest moving with nothing touching it;
- a contact the simulation never makes: how close the body came to where the contact was demonstrated, and, for a
  pair that touches again in the demonstration (the ball bouncing on platform B twice), how often it touched;
- otherwise the metric's own reason for that leg (another side, another region, another cause, an event more).

A reproduced demonstration's verdict adds where the simulation's contacts lie far from the drawn ones
(`where.differences_in_place`: the metric compares sides, not places).
"""

from __future__ import annotations

from physink_tui.sim.evaluate import Problem, compare_rollout, miss_distance, simulate
from physink_tui.sim.legs import legs
from physink_tui.sim.rollout import RolloutResult
from physink_tui.sim.search import Search
from physink_tui.sim.where import differences_in_place
from physink_tui.timeline.equivalence import Comparison, compare_prefixes, prepare
from physink_tui.timeline.events import Event, Timeline, event_label
from physink_tui.timeline.up_to_demonstrated import RULE, afterwards

REPRODUCED = f"every demonstrated event is reproduced (equivalent {RULE})"


def refusal_or_verdict(search: Search, problem: Problem, best: RolloutResult, comparison: Comparison, *,
                       found: bool) -> str:
    """The verdict of a finished search whose best candidate rolled out as ``best`` and compares as
    ``comparison``: when nothing was found, told from the candidate that got furthest along the demonstration's
    legs (`Search.furthest`), so that the event it names is the first one no candidate reproduces."""
    rollouts = search.rollouts - search.exploded if search.best is not None else 0
    if found or search.furthest is None or search.furthest is search.best:
        return verdict(problem, best.timeline, comparison, found=found, rollouts=rollouts, flagged=best.flagged)
    furthest = simulate(problem, search.furthest)
    return verdict(problem, furthest.timeline, compare_rollout(problem, furthest, explain=True), found=False,
                   rollouts=rollouts, flagged=furthest.flagged)


def verdict(problem: Problem, simulated: Timeline, comparison: Comparison, *, found: bool, rollouts: int,
            flagged: tuple[str, ...] = ()) -> str:
    """The verdict for the best candidate, whose rollout gave ``simulated`` and compares as ``comparison`` (with
    reasons); ``rollouts`` is how many candidates the search tried."""
    if found:
        after = afterwards(comparison, simulated, problem.scene.names())
        text = REPRODUCED + (f"; {after}" if after else "")
        elsewhere = differences_in_place(problem.scene, problem.timeline, simulated, comparison)
        if elsewhere:
            text += "; where it differs from the drawing: " + "; ".join(elsewhere)
    elif rollouts == 0 or not simulated.events:
        text = "no candidate could be simulated without the physics blowing up"
    else:
        text = _first_difference(problem, simulated, comparison, rollouts)
    if flagged:
        text += ". Flagged: " + "; ".join(flagged)
    return text


def _first_difference(problem: Problem, simulated: Timeline, comparison: Comparison, rollouts: int) -> str:
    names = problem.scene.names()
    demonstrated = problem.timeline
    cut = legs(demonstrated)
    _, prefixes = compare_prefixes(prepare(demonstrated, names), prepare(simulated, names),
                                   [leg.events for leg in cut], simulation=True)
    before: frozenset[str] = frozenset()
    for leg, distance in zip(cut, prefixes, strict=True):
        if distance.qualitative_distance > 0:
            missing = [e for e in distance.only_a if e not in before]
            if missing:
                event = demonstrated.event(missing[0])
                why = _why_missing(problem, simulated, event, names)
                return (f'no simulation in {rollouts} rollouts reproduces "{event_label(event, names)}" '
                        f"(t={event.t0:.2f} s in the demonstration): {why}")
            event = demonstrated.event(leg.last)  # every event there, some otherwise: the metric says how
            why = "; ".join(comparison.reasons[:3]) or "the simulation does it otherwise"
            return (f"no simulation in {rollouts} rollouts reproduces the demonstration up to "
                    f'"{event_label(event, names)}" (t={event.t0:.2f} s): {why}')
        before = leg.events
    return "not reproduced: " + "; ".join(comparison.reasons[:3])


def _why_missing(problem: Problem, simulated: Timeline, event: Event, names: dict[str, str]) -> str:
    def name(c: str) -> str:
        return names.get(c) or c

    if event.type == "movement" and not event.causes and event.components:
        return (f"nothing sets the {name(event.components[0])} moving there (no start, no contact), and no "
                "physics starts a body at rest moving by itself")
    if event.type == "contact" and len(event.components) == 2:
        a, b = (name(c) for c in event.components)
        near = miss_distance(demonstrated=problem.timeline, simulated=simulated, only_demonstrated=(event.id,))
        pair = set(event.components)
        shown = sum(1 for e in problem.timeline.events if e.type == "contact" and set(e.components) == pair
                    and e.t0 <= event.t0)
        made = sum(1 for e in simulated.events if e.type == "contact" and set(e.components) == pair)
        if made == 0 or shown == 1:
            return f"the {a} never reaches the {b} (the best candidate comes within {near:.0f} canvas units of it)"
        return (f"the {a} touches the {b} {_times(made)} in the best candidate; this is the {_ordinal(shown)} touch "
                f"demonstrated (the candidate comes within {near:.0f} canvas units of where it was)")
    return "the best candidate never does it"


def _times(n: int) -> str:
    return {1: "once", 2: "twice"}.get(n, f"{n} times")


def _ordinal(n: int) -> str:
    return {2: "second", 3: "third", 4: "fourth"}.get(n, f"{n}th")
