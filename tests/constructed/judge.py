"""A constructed case searched as ``physink simulate`` searches it: the default search, then the verdict on its
best candidate; no generation, no timing (callers time what they run)."""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.session.session import Session
from physink_tui.sim.defaults import DEFAULT_BUDGET, DEFAULT_SEED
from physink_tui.sim.evaluate import compare_rollout, make_problem, simulate
from physink_tui.sim.search import Search
from physink_tui.sim.verdict import refusal_or_verdict
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import Executor


@dataclass(frozen=True, slots=True)
class Outcome:
    """What a search of a case gave: found (qualitative 0), at which rollout, rollouts run, the verdict."""

    found: bool
    found_at: int | None
    rollouts: int
    qualitative: float
    verdict: str


def judge(session: Session, executor: Executor, *, seed: int = DEFAULT_SEED, budget: int = DEFAULT_BUDGET,
          strategy: str = "default") -> Outcome:
    """Search the session's demonstration and give its outcome, the verdict as ``physink simulate`` words it."""
    search = Search(session.scene, session.timeline, session.canvas, strategy=strategy, seed=seed, budget=budget)
    problem = make_problem(session.scene, session.timeline, session.canvas)
    run_search(search, problem, executor)
    best = search.best if search.best is not None else search.start
    result = simulate(problem, best)
    comparison = compare_rollout(problem, result, explain=True)
    found = search.best_score is not None and not search.best_score.exploded and comparison.equivalent
    text = refusal_or_verdict(search, problem, result, comparison, found=found)
    return Outcome(found, search.found_at, search.rollouts, comparison.qualitative_distance, text)
