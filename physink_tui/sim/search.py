"""The parameter search (thesis 3.4.4) as a deterministic machine of candidate generations; it runs nothing itself.

A `Search` proposes a generation (`next_generation`), is told the generation's scores in candidate order (`tell`),
and so on until `done`; whoever drives it (``physink_tui.sim_run``) evaluates the candidates however it likes
(serially, in processes, on a cluster). The same seed and budget give the same candidates and the same `best`
whatever evaluated them. Generation 0 is the seed parameters (seeding.py) alone, in every strategy.

Strategies: ``"default"``, leg by leg along the causal order with CMA-ES (leg_search.py); ``"grid"``, the thesis's
grid of every combination (grid.py), kept as the baseline. Both stop as soon as a candidate is qualitatively
equivalent to the demonstration (the thesis halts once the qualitative score crosses a threshold), else at the
budget or when the strategy has nothing left to try.

The objective is `Score.objective` (qualitative distance weighted above quantitative); exploded candidates score
inf, are never best and are counted (`exploded`). Ties go to the earlier candidate. Beside the best, the search
keeps the candidate that reproduces the most leading legs of the demonstration (`furthest`, by `progress`): when
nothing is found, the first event that candidate misses is the first one no candidate reproduces (the verdict's).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from physink_tui.errors import SimulationError
from physink_tui.scene.components import Scene
from physink_tui.sim.aim import Aimed, aimed
from physink_tui.sim.chain import aimed_legs, chain_aimed
from physink_tui.sim.evaluate import Score
from physink_tui.sim.grid import ThesisGrid
from physink_tui.sim.leg_search import LegByLeg
from physink_tui.sim.legs import legs
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.seeding import seed as seed_parameters
from physink_tui.sim.seeding import seed_family
from physink_tui.timeline.events import Timeline

STRATEGIES = ("default", "grid")


class Strategy(Protocol):
    """What a search strategy does between generations."""

    @property
    def finished(self) -> bool:
        """Nothing is left to try (the search stops before the budget is spent)."""

    def generation(self, best: Parameters | None) -> list[Parameters]: ...

    def told(self, generation: list[Parameters], scores: list[Score]) -> None: ...


def progress(score: Score) -> tuple[int, float]:
    """How far along the demonstration's legs a score reaches (smaller is further): more leading legs reproduced,
    then the first unreproduced leg's objective; a score without legs counts as one leg."""
    legs_ = score.legs or (score,)
    solved = next((k for k, s in enumerate(legs_) if s.qualitative > 0), len(legs_))
    return (-solved, legs_[solved].objective if solved < len(legs_) else 0.0)


class Search:
    """A search for parameters that reproduce ``timeline`` on ``scene`` (see the module docstring).

    Args:
        scene, timeline, canvas: the demonstration (seeded by `seeding.seed`).
        strategy: "default" (leg by leg) or "grid" (the thesis's).
        seed: the random seed (the grid uses none; it is kept for the record).
        budget: at most this many rollouts (>= 1).
        start: the parameters to start from (default: the thesis's seed).

    Use: ``while not s.done: s.tell([evaluate(p) for p in s.next_generation()])``, with a problem made with
    ``by_leg=s.by_leg`` (the default strategy reads each leg's score).
    """

    def __init__(self, scene: Scene, timeline: Timeline, canvas: tuple[float, float], *,
                 strategy: str = "default", seed: int = 0, budget: int, start: Parameters | None = None) -> None:
        if strategy not in STRATEGIES:
            raise SimulationError(f"unknown strategy {strategy!r}; expected one of {', '.join(STRATEGIES)}")
        if budget < 1:
            raise SimulationError(f"budget is {budget}; expected at least 1 rollout")
        self.strategy = strategy
        self.seed = seed
        self.budget = budget
        self.start = seed_parameters(scene, timeline, canvas) if start is None else start
        self.rollouts = 0
        self.exploded = 0
        self.generations = 0
        self.best: Parameters | None = None
        self.best_score: Score | None = None
        self.found_at: int | None = None
        self.furthest: Parameters | None = None
        self.furthest_score: Score | None = None
        self._pending: list[Parameters] | None = None
        self._finished = False
        self._strategy: Strategy
        if strategy == "grid":
            self._strategy = ThesisGrid(self.start)
        else:
            def family(factor: float) -> Parameters:
                return seed_family(scene, timeline, canvas, (factor,))[0]

            seeded = start is None and bool(self.start.velocities)
            def aims() -> list[Aimed]:  # aimed only when the family has not found the answer
                return [*chain_aimed(scene, timeline, self.start), *aimed(scene, timeline, self.start)]

            legs_ = legs(timeline)
            self._strategy = LegByLeg(self.start, legs_, seed=seed, family=family if seeded else None,
                                      aims=aims if seeded else (), aimed_legs=aimed_legs(scene, timeline, legs_))

    @property
    def by_leg(self) -> bool:
        """Whether the strategy reads each leg's score (`Score.legs`; `evaluate.make_problem(by_leg=...)`)."""
        return isinstance(self._strategy, LegByLeg)

    @property
    def done(self) -> bool:
        """No more generations: a candidate reproduces the demonstration, the budget is spent, or the strategy
        has nothing left to try."""
        return self._finished or self.rollouts >= self.budget

    def next_generation(self) -> list[Parameters]:
        """The next candidates to evaluate; `tell` their scores before asking again. Empty (and `done`) when the
        strategy turns out to have nothing left to try."""
        if self._pending is not None:
            raise SimulationError("tell the scores of the last generation before asking for another")
        if self.done:
            raise SimulationError("the search is done")
        if self.generations == 0:
            generation = [self.start]
        elif self._strategy.finished:
            generation = []
        else:
            generation = self._strategy.generation(self.best)
        generation = generation[: self.budget - self.rollouts]
        if not generation:
            self._finished = True  # the strategy has nothing left to try
            return []
        self._pending = generation
        return list(generation)

    def tell(self, results: Sequence[Score]) -> None:
        """The scores of the last generation, in candidate order."""
        if self._pending is None:
            raise SimulationError("no generation to tell about")
        if len(results) != len(self._pending):
            raise SimulationError(f"{len(results)} scores for {len(self._pending)} candidates")
        generation, self._pending = self._pending, None
        for p, s in zip(generation, results, strict=True):
            self.rollouts += 1
            self.exploded += s.exploded
            if not s.exploded and (self.furthest_score is None or progress(s) < progress(self.furthest_score)):
                self.furthest, self.furthest_score = p, s
            if not s.exploded and (self.best_score is None or s.objective < self.best_score.objective):
                self.best, self.best_score = p, s
                if s.qualitative == 0 and self.found_at is None:
                    self.found_at = self.rollouts
        self.generations += 1
        if self.best_score is not None and self.best_score.qualitative == 0:
            self._finished = True  # reproduced: the thesis's early halt
        self._strategy.told(generation, list(results))
        if self._strategy.finished:
            self._finished = True
