"""Drives a `Search` with an `Executor`: one generation at a time, results told in candidate order, progress
reported through a callback ``(rollouts done, budget, best score or None)``."""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from physink_tui.sim.evaluate import Problem, Score, evaluate_problem
from physink_tui.sim.search import Search
from physink_tui.sim_run.executors import Executor

Progress = Callable[[int, int, Score | None], None]


def run_search(search: Search, problem: Problem, executor: Executor, progress: Progress | None = None) -> Search:
    """Runs ``search`` to its end (KeyboardInterrupt propagates; ``search.best`` then holds the best so far)."""
    fn = partial(evaluate_problem, problem)
    if progress is not None:
        progress(search.rollouts, search.budget, search.best_score)
    while not search.done:
        generation = search.next_generation()
        if not generation:
            break
        search.tell(executor.map(fn, generation))
        if progress is not None:
            progress(search.rollouts, search.budget, search.best_score)
    return search
