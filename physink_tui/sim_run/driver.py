"""Drives a `Search` with an `Executor`: one generation at a time, results told in candidate order, progress
reported through a callback ``(rollouts done, budget, best score or None)``; it neither chooses candidates nor
says where they run."""

from __future__ import annotations

import dataclasses
import uuid
from collections.abc import Callable, Sequence

from physink_tui.sim.evaluate import Problem, Score, evaluate_problem, make_problem
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.search import Search
from physink_tui.sim_run import executors
from physink_tui.sim_run.executors import Executor, SharingExecutor

Progress = Callable[[int, int, Score | None], None]


class Evaluate:
    """``evaluate_problem(problem, candidate)`` as a picklable callable; where workers are forked it pickles as the
    problem's key only (the problem is `executors.share`d before the pool starts)."""

    def __init__(self, problem: Problem) -> None:
        self.problem = problem
        if executors.FORK:
            executors.share(("problem", problem.key), problem)

    def __call__(self, parameters: Parameters) -> Score:
        return evaluate_problem(self.problem, parameters)

    def __reduce__(self) -> tuple:
        if executors.FORK:
            return (_shared_evaluate, (self.problem.key,))
        return (Evaluate, (self.problem,))


def _shared_evaluate(key: int) -> Evaluate:
    e = Evaluate.__new__(Evaluate)
    e.problem = executors.shared(("problem", key))
    return e


def _evaluator(problem: Problem, executor: Executor) -> Callable[[Sequence[Parameters]], list[Score]]:
    """How a generation is scored: with the problem sent once per search (a `SharingExecutor`, under a key unique
    across processes, since its workers outlive this search and may serve other clients: `Problem.key` only counts
    within one process), or as an `Evaluate`."""
    if isinstance(executor, SharingExecutor):
        shipped = dataclasses.replace(problem, key=uuid.uuid4().int)
        return lambda generation: executor.map_shared(evaluate_problem, shipped, generation)
    fn = Evaluate(problem)
    return lambda generation: executor.map(fn, generation)


def run_search(search: Search, problem: Problem, executor: Executor, progress: Progress | None = None) -> Search:
    """Runs ``search`` to its end (KeyboardInterrupt propagates; ``search.best`` then holds the best so far).
    A search that reads each leg's score gets a problem that scores them."""
    if search.by_leg and not problem.by_leg:
        problem = make_problem(problem.scene, problem.timeline, problem.canvas, problem.max_seconds, by_leg=True)
    try:
        evaluate = _evaluator(problem, executor)
        if progress is not None:
            progress(search.rollouts, search.budget, search.best_score)
        while not search.done:
            generation = search.next_generation()
            if not generation:
                break
            search.tell(evaluate(generation))
            if progress is not None:
                progress(search.rollouts, search.budget, search.best_score)
    finally:
        executors.unshare(("problem", problem.key))
    return search
