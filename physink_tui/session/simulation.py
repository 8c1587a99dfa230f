"""The session's SIMULATE: runs the parameter search on a document's demonstration serially, in the calling thread,
and sums up its outcome (`SearchResult`) and what to tell the user; `Searched` is a ``simulate`` whose search a
driver already ran (off the session's thread, `search_job`); executors, progress and cancellation are the drivers'
(``physink simulate``, a TUI worker)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

from physink_tui.errors import SimulationError
from physink_tui.formats.journal.entries import CommandEntry, JournalEntry
from physink_tui.scene.components import BACKGROUND, Scene
from physink_tui.session.history import Document
from physink_tui.sim.defaults import DEFAULT_BUDGET, DEFAULT_SEED
from physink_tui.sim.evaluate import Problem, Score, compare_rollout, evaluate_problem, make_problem, simulate
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.search import Search
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.up_to_demonstrated import RULE, afterwards


@dataclass(frozen=True, slots=True)
class SearchResult:
    """What SIMULATE found for one document (its scene and demonstrated timeline).

    Attributes:
        found: a candidate's simulation is qualitatively equivalent to the demonstration.
        qualitative_distance: the best candidate's qualitative distance to the demonstration (0 when found; inf
            when every candidate exploded).
        quantitative_distance: its quantitative distance, canvas units.
        rollouts: candidates simulated (<= budget: the search stops once found, or when it has nothing left).
        budget: the most rollouts the search could run (>= 1).
        seed: the search's random seed (>= 0).
        parameters: the best candidate (the seeded start when every candidate exploded).
        timeline: the best candidate's simulated timeline.
        reasons: what the best candidate does not reproduce (A = demonstration, B = simulation), first difference
            first; empty when found.
        exploded: candidates discarded because their physics blew up.
        afterwards: what the best candidate's simulation does after the last demonstrated event, left out of the
            comparison (`up_to_demonstrated.afterwards`), or None.
    """

    found: bool
    qualitative_distance: float
    quantitative_distance: float
    rollouts: int
    budget: int
    seed: int
    parameters: Parameters
    timeline: Timeline
    reasons: tuple[str, ...]
    exploded: int = 0
    afterwards: str | None = None


Evaluate = Callable[[Problem, Parameters], Score]
"""How one candidate is scored: `evaluate_problem` or a driver's wrapper round it (progress, cancellation, a memo)."""


@dataclass(frozen=True, slots=True)
class Searched:
    """``simulate SEED BUDGET`` with the result a driver's search found for it on ``scene`` and ``timeline``.

    A driver submits it instead of the command when it ran the search itself (`search_job`); the session journals
    the plain command (`entry`) and takes ``result`` as its own when its document at ``t`` is the one searched, so a
    replay, which searches again, comes to the same result; otherwise it searches as for the command.

    Attributes:
        t: seconds since the session start (the runner stamps it on arrival).
        seed, budget: what the journal's ``simulate`` line carries (budget: the rollouts the search ran, >= 1).
        scene, timeline: the document searched.
        result: what `run` gives for them with this seed and budget.
    """

    t: float
    seed: int
    budget: int
    scene: Scene
    timeline: Timeline
    result: SearchResult

    def entry(self) -> CommandEntry:
        """The command a journal holds."""
        return CommandEntry(self.t, "simulate", (self.seed, self.budget))

    def fits(self, document: Document, seed: int, budget: int) -> bool:
        """Whether ``result`` is what ``simulate seed budget`` gives on ``document``."""
        return (seed, budget) == (self.seed, self.budget) and self.searched(document.scene, document.timeline)

    def searched(self, scene: Scene, timeline: Timeline | None) -> bool:
        """Whether ``scene`` and ``timeline`` are the document searched (the same objects, or equal ones)."""
        return ((scene is self.scene or scene == self.scene)
                and (timeline is self.timeline or timeline == self.timeline))


SessionInput = JournalEntry | Searched
"""What a session takes: a journal entry, or a ``simulate`` whose search a driver ran (`Searched`)."""


def with_defaults(entry: CommandEntry, budget: int = DEFAULT_BUDGET) -> CommandEntry:
    """``simulate [SEED [BUDGET]]`` with both numbers, the missing ones the defaults (``budget``: the budget's), as
    the session journals it: a replay then depends on no default. Other entries are returned unchanged."""
    if entry.name != "simulate" or len(entry.args) >= 2:
        return entry
    seed = entry.args[0] if entry.args else DEFAULT_SEED
    return replace(entry, args=(seed, budget))


def attempt(document: Document, canvas: tuple[float, float], seed: int,
            budget: int) -> tuple[SearchResult | None, str]:
    """``simulate SEED BUDGET`` on ``document``: the result (None when it could not run) and what to tell."""
    lacking = missing(document.scene, document.timeline)
    if lacking is not None or document.timeline is None:
        return None, lacking or ""
    try:
        result = run(document.scene, document.timeline, canvas, seed, budget)
    except SimulationError as exc:
        return None, f"simulate: {exc}"
    return result, summary(result)


def missing(scene: Scene, timeline: Timeline | None) -> str | None:
    """What must be done before SIMULATE can run on this document, as told to the user; None when it can."""
    if timeline is None or not timeline.events:
        return ("simulate: nothing has been demonstrated: in demo mode (mode demo), move the bodies the way the "
                "machine should behave, then simulate")
    gone = sorted({c for ev in timeline.events for c in ev.components} - set(scene.components) - {BACKGROUND})
    if gone:
        return (f"simulate: the demonstration moves {', '.join(gone)}, no longer in the sketch: demonstrate the "
                "machine again (or undo the erasing)")
    if not any(not scene.is_fixed(b.id) for b in scene.bodies()):
        return ("simulate: no body can move: draw a body that is not pinned or welded, demonstrate how it moves, "
                "then simulate")
    return None


def run(scene: Scene, timeline: Timeline, canvas: tuple[float, float], seed: int, budget: int,
        evaluate: Evaluate = evaluate_problem) -> SearchResult:
    """The default search for parameters reproducing ``timeline`` on ``scene``, every candidate evaluated in turn
    here (by ``evaluate``, which must score as `evaluate_problem` does): the same for the same document, seed and
    budget as ``physink simulate --seed S --budget N``.

    Raises:
        SimulationError: the demonstration cannot be searched (e.g. it names bodies the scene lacks).
    """
    search = Search(scene, timeline, canvas, seed=seed, budget=budget)
    problem = make_problem(scene, timeline, canvas, by_leg=search.by_leg)
    while not search.done:
        generation = search.next_generation()
        if not generation:
            break
        search.tell([evaluate(problem, p) for p in generation])
    best = search.best if search.best is not None else search.start
    rollout = simulate(problem, best)
    comparison = compare_rollout(problem, rollout, explain=True)
    found = search.best_score is not None and comparison.equivalent
    return SearchResult(
        found=found,
        qualitative_distance=comparison.qualitative_distance,
        quantitative_distance=comparison.quantitative_distance,
        rollouts=search.rollouts,
        budget=budget,
        seed=seed,
        parameters=best,
        timeline=rollout.timeline,
        reasons=() if found else tuple(comparison.reasons),
        exploded=search.exploded,
        afterwards=afterwards(comparison, rollout.timeline, problem.scene.names()),
    )


def summary(result: SearchResult) -> str:
    """The outcome in one message, naming the rule compared by (`up_to_demonstrated`: what ``physink equiv DEMO
    SIM --up-to-demonstrated`` says of the same two timelines)."""
    rollouts = f"{result.rollouts} rollout{'' if result.rollouts == 1 else 's'}"
    after = f"; {result.afterwards}" if result.afterwards else ""
    if result.found:
        return (f"simulation found in {rollouts} (equivalent {RULE}: qualitative distance "
                f"{result.qualitative_distance:g}, quantitative {result.quantitative_distance:.1f}){after}")
    text = f"no simulation reproduces the demonstration within {rollouts}"
    if result.rollouts == result.exploded:
        return text + ": every candidate's physics blew up"
    first = f"; first difference: {result.reasons[0]}" if result.reasons else ""
    return (f"{text} (best: not equivalent {RULE}, qualitative distance {result.qualitative_distance:g}, "
            f"quantitative {result.quantitative_distance:.1f}){first}")
