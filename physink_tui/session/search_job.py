"""SIMULATE for a driver, off the session's thread: one search on a snapshot of the document, reporting progress
after every rollout and stoppable, whose result the session takes as its own (`simulation.Searched`); no threads
of its own and no UI (the TUI runs it in a worker and draws the progress).

Stopping keeps the best so far in a form a replay reproduces: a search stopped after k rollouts is the search of
budget k (`Search` truncates its last generation to the budget, so the first k candidates are the same whatever
the budget), and its result is computed as `simulation.run` with budget k computes it, the k scores already known
taken from a memo rather than simulated again. The journal then says ``simulate SEED k``.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable
from dataclasses import dataclass

from physink_tui.scene.components import Scene
from physink_tui.session import simulation
from physink_tui.session.simulation import Searched
from physink_tui.sim.evaluate import Problem, Score, evaluate_problem
from physink_tui.sim.parameters import Parameters
from physink_tui.timeline.events import Timeline


@dataclass(frozen=True, slots=True)
class Progress:
    """How far a search has come.

    Attributes:
        rollouts: candidates simulated so far (0..budget).
        budget: the most the search will simulate (>= 1).
        qualitative, quantitative: the best candidate's distances so far (inf before one that did not explode).
    """

    rollouts: int
    budget: int
    qualitative: float = math.inf
    quantitative: float = math.inf


class _Stopped(Exception):
    """`SearchJob.stop` was called: the evaluator stops the search before its next rollout."""


class SearchJob:
    """One search of ``timeline`` on ``scene`` with ``seed`` and at most ``budget`` rollouts.

    Call `run` on a thread of the driver's; `stop` from any thread ends it after the rollout under way.

    Args:
        scene, timeline: the document searched (what `simulation.missing` accepts).
        canvas: the session's canvas.
        seed: the search's seed (>= 0); budget: at most this many rollouts (>= 1).
        on_progress: called on the running thread before the first rollout and after each.
        evaluate: scores a candidate (tests slow it down or count it); `evaluate_problem` by default.
    """

    def __init__(self, scene: Scene, timeline: Timeline, canvas: tuple[float, float], seed: int, budget: int, *,
                 on_progress: Callable[[Progress], object] | None = None,
                 evaluate: simulation.Evaluate = evaluate_problem) -> None:
        if budget < 1:
            raise ValueError(f"budget is {budget!r}; expected at least 1 rollout")
        self.scene, self.timeline, self.canvas = scene, timeline, canvas
        self.seed, self.budget = seed, budget
        self._on_progress = on_progress
        self._evaluate = evaluate
        self._stop = threading.Event()
        self._memo: list[tuple[Parameters, Score]] = []
        self._best: Score | None = None

    def stop(self) -> None:
        """End the search after the rollout under way; `run` then returns the best so far (any thread)."""
        self._stop.set()

    @property
    def stopped(self) -> bool:
        return self._stop.is_set()

    @property
    def rollouts(self) -> int:
        """Candidates simulated so far."""
        return len(self._memo)

    def run(self) -> Searched | None:
        """Search to the end, or until stopped: the ``simulate SEED k`` a session takes (k: the rollouts run), or
        None when stopped before the first rollout finished.

        Raises:
            SimulationError: the demonstration cannot be searched (as `simulation.run`).
        """
        self._report()
        try:
            result = simulation.run(self.scene, self.timeline, self.canvas, self.seed, self.budget, self._scored)
        except _Stopped:
            if not self._memo:
                return None
            result = simulation.run(self.scene, self.timeline, self.canvas, self.seed, len(self._memo),
                                    _Remembered(self._memo))
        return Searched(0.0, self.seed, result.budget, self.scene, self.timeline, result)

    def _scored(self, problem: Problem, candidate: Parameters) -> Score:
        if self._stop.is_set():
            raise _Stopped
        score = self._evaluate(problem, candidate)
        self._memo.append((candidate, score))
        if not score.exploded and (self._best is None or score.objective < self._best.objective):
            self._best = score
        self._report()
        return score

    def _report(self) -> None:
        if self._on_progress is None:
            return
        best = self._best
        self._on_progress(Progress(len(self._memo), self.budget, best.qualitative if best else math.inf,
                                   best.quantitative if best else math.inf))


class _Remembered:
    """Scores candidates from a stopped search's memo, in order (simulating again any candidate that differs, so
    the result is `simulation.run`'s whatever the search does)."""

    def __init__(self, memo: list[tuple[Parameters, Score]]) -> None:
        self._memo = memo
        self._next = 0

    def __call__(self, problem: Problem, candidate: Parameters) -> Score:
        index, self._next = self._next, self._next + 1
        if index < len(self._memo) and self._memo[index][0] == candidate:
            return self._memo[index][1]
        return evaluate_problem(problem, candidate)
