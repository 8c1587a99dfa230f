"""Drives a `Search` with an `Executor`: one generation at a time, results told in candidate order, progress
reported through a callback ``(rollouts done, budget, best score or None)``."""

from __future__ import annotations

from collections.abc import Callable

from physink_tui.sim.evaluate import Problem, Score, evaluate_problem, make_problem
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.search import Search
from physink_tui.sim_run import executors
from physink_tui.sim_run.executors import Executor

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


def run_search(search: Search, problem: Problem, executor: Executor, progress: Progress | None = None) -> Search:
    """Runs ``search`` to its end (KeyboardInterrupt propagates; ``search.best`` then holds the best so far).
    A search that reads each leg's score gets a problem that scores them."""
    if search.by_leg and not problem.by_leg:
        problem = make_problem(problem.scene, problem.timeline, problem.canvas, problem.max_seconds, by_leg=True)
    fn = Evaluate(problem)
    try:
        if progress is not None:
            progress(search.rollouts, search.budget, search.best_score)
        while not search.done:
            generation = search.next_generation()
            if not generation:
                break
            search.tell(executor.map(fn, generation))
            if progress is not None:
                progress(search.rollouts, search.budget, search.best_score)
    finally:
        executors.unshare(("problem", problem.key))
    return search
