"""SIMULATE's default strategy: leg by leg along the demonstration's causal order, CMA-ES on each leg's
parameters; it runs nothing itself.

Before the legs: the seed's flight-time family (`FAMILY_STEPS`: every start body still reaching its first
demonstrated contact, faster or slower), then the best of it with its start velocities turned and scaled together
(`SCAN_ANGLES`, `SCAN_SPEEDS`); each time the candidate furthest along the legs becomes the centre. When the family's
best already reproduces every leg the aims address (`aimed_legs`: up to the start body meeting a movable body, the
ball landing on the cup), the aims and the scan are skipped: they move only the throw, which then already does what
they aim at, and their rollouts (70 on the cup dispenser) go to the legs.

The demonstration is cut into legs (`legs.legs`: each ends with a contact). The search always works on the first leg the
best parameters so far do not reproduce: it optimises only the parameters the demonstration up to the end of that leg
can depend on (`Leg.components`: the start bodies' initial velocities, the masses and frictions of the bodies in it, its
springs), from those best parameters, against that leg's score (`Score.legs[k]`: the qualitative distance of the
demonstration up to there, weighted above the quantitative and the miss distance). The parameters of earlier legs stay
free, at the point earlier stages found, so a later leg may still move them a little; the prefix score keeps the earlier
legs reproduced. A later leg's first run adjusts only the components its own events name (`Leg.own`: the platform, cup,
peg and springs of the cup meeting the peg, not the ball's throw that set them moving), fewer coordinates for CMA-ES; a
restart adjusts every component up to the leg's end. As soon as a candidate reproduces the leg, the search moves on from
it to the next leg it does not reproduce (one candidate may solve several legs). A run that stalls (its best not better
for `STALL_GENERATIONS` generations, or CMA-ES stops) restarts from the best with a step size twice as large (as
IPOP-CMA-ES does); past `MAX_SIGMA` the leg is given up and the next one taken, the unsolved leg's mismatch still
counted in every later prefix. When every leg has been tried and some given up, another round starts from the best so
far (fresh random numbers, the given-up legs tried again), until the budget is spent.

CMA-ES is pycma's ``CMAEvolutionStrategy`` (ask/tell) in `coordinates.Normalisation`'s unscaled coordinates, its
random numbers drawn from a generator seeded with (seed, round, leg, restart), so a search is the same for the same seed
whatever evaluates it. One free coordinate (pycma needs two) is searched by a seeded Gaussian sampler around the
run's best, whose width shrinks each generation.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Sequence
from enum import StrEnum
from typing import Any

import numpy as np

from physink_tui.sim.aim import Aimed, AimSpace
from physink_tui.sim.coordinates import Normalisation, coordinates
from physink_tui.sim.evaluate import Score
from physink_tui.sim.legs import Leg
from physink_tui.sim.parameters import Parameters, SpringParameters

CMA_SIGMA = 0.5
"""CMA-ES's initial step size in the normalised coordinates (half a step of each parameter's scale); doubled at
each restart. (Measured on the ten ball scenes, 3 seeds, budget 400: starting a leg that follows a reproduced one
with steps of 0.05 or 0.15, growing 4x or 3x per restart, solved 19 and 17 of 30 searches against 20 for this.)"""
MAX_SIGMA = 4.0
"""A leg is given up once a restart would need a step size above this."""
STALL_GENERATIONS = 6
"""Generations without a better leg score after which a run restarts."""
FAMILY_STEPS = (2 ** (1 / 4), 2 ** (1 / 16), 2 ** (1 / 64))
FAMILY_SPAN = (range(-12, 5), range(-3, 4), range(-3, 4))
FAMILY_ROUNDS = len(FAMILY_STEPS)
"""The flight-time family (`seeding.seed_family`) is searched first, by zooming: factors 2^(k/4) of the seeded
flight time for k = -12..4 (0.125 to 2.0), then 2^(j/16) and 2^(j/64) around the best so far for j = -3..3: every
start body still reaches its first demonstrated contact, faster or slower (28 rollouts at most). (Measured, seeds
0-3, budget 400: reaching down to 1/8 rather than 0.3 of the demonstrated time solves figure 2-13's bounce off
the bottom of B at every seed, in 83-112 rollouts, against one seed of four; no other scene changed.)"""
SCAN_ANGLES = tuple(range(-45, 46, 15))
SCAN_SPEEDS = (0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0)
"""After the family, the best one's start velocities turned by -45°…45° in 15° steps and scaled x0.5…x2 in
x0.25 steps, all start bodies alike (the thesis grid's velocity steps: 48 rollouts), the best of which leads."""
SPRING_K = (2.0, 4.0, 8.0)
SPRING_REST = (1.0, 1.25, 1.5)
"""After the scan, the best so far with its springs' constants scaled by `SPRING_K` and natural lengths by
`SPRING_REST`, all springs alike (9 rollouts, only in scenes with springs): a spring drawn at its natural length
under a body struck hard lets it strike the body it is fixed to (the trampoline its base), which the demonstration
seldom shows and which CMA-ES, moving the throw and the spring together from the seeded k = 20, rarely undoes.
(Measured on the spring machines' tuning range 0-15, seed 0, budget 200, once spring-borne bodies collide: see
docs/BENCHMARKS.md.)"""
AIM_GENERATION = 16
"""Aimed candidates (`aim.aimed`) handed out per generation, so that a search reproducing the demonstration stops
within 16 rollouts of the candidate that does."""
AIM_RUN_SIGMA = 1.0
"""CMA-ES's initial step size in `aim.AimSpace` (a quarter of the edge or fan, a flight-time factor of e^0.35)."""
AIM_RUN_ROUND = 1_000_000
"""The round number in the aim run's random key (rounds of leg runs count from 0)."""
AIM_RUN_ROLLOUTS = 60
"""The most rollouts of the run that corrects the best aimed candidate (it stops sooner when it stalls)."""
LINE_SAMPLES = 8
"""Candidates per generation of the one-coordinate sampler."""
EXPLODED_PENALTY = 1.0e6
"""Added to twice the worst finite objective of a generation, as an exploded candidate's value for CMA-ES."""


class Phase(StrEnum):
    """What the search is doing: which generation it asked for last."""

    START = "start"
    """The seeded parameters alone (generation 0)."""
    FAMILY = "family"
    """The seed's flight-time family (`FAMILY_STEPS`)."""
    AIM = "aim"
    """Launches aimed at the demonstrated contacts' surfaces (`chain.chain_aimed`, `aim.aimed`), `AIM_GENERATION` at a
    time."""
    AIM_RUN = "aim run"
    """CMA-ES in `aim.AimSpace` round the best aimed candidate (at most `AIM_RUN_ROLLOUTS`)."""
    SCAN = "scan"
    """The best so far with its start velocities turned and scaled (`SCAN_ANGLES`, `SCAN_SPEEDS`)."""
    SPRINGS = "springs"
    """The best so far with stiffer and longer springs (`SPRING_K`, `SPRING_REST`)."""
    RUN = "run"
    """CMA-ES (or the one-coordinate sampler) on a leg."""


def leg_score(score: Score, leg: int) -> Score:
    """The score of the demonstration up to the end of leg ``leg`` (the whole score when legs were not scored)."""
    return score.legs[leg] if leg < len(score.legs) else score


class LegByLeg:
    """The default strategy (see the module docstring).

    Args:
        start: the seeded parameters (the scales of the normalised coordinates come from them).
        legs: the demonstration's legs.
        seed: the random seed.
        family: the seed with its start bodies' flight time scaled by a factor (`seeding.seed_family`), searched
            first; None to skip it.
        aims: launches aimed at the demonstrated contacts' surfaces (`chain.chain_aimed`, `aim.aimed`), tried after
            the family; or a function giving them, called only when the family has not found the answer.
    """

    def __init__(self, start: Parameters, legs: Sequence[Leg], *, seed: int,
                 family: Callable[[float], Parameters] | None = None,
                 aims: Sequence[Aimed] | Callable[[], Sequence[Aimed]] = (), aimed_legs: int = 0) -> None:
        self.start = start
        self.family = family
        self.aimed_legs = aimed_legs
        self._aims: list[Aimed] = [] if callable(aims) else list(aims)
        self._aims_source = aims if callable(aims) else None  # made when first needed (after the family)
        self._aimed: list[Aimed] = []  # the last generation's aims
        self._best_aim: Aimed | None = None
        self._aim_run_rollouts = 0
        self._family_round = 0 if family is not None else FAMILY_ROUNDS
        self._family_best = 1.0
        self._factors: list[float] = []
        self.legs = tuple(legs) or (None,)
        self.seed = seed
        self.leg = 0
        self.restarts = 0
        self.centre = start
        self.centre_score: Score | None = None
        self.finished = False
        self._phase = Phase.START  # what the last generation was
        self._given_up = -1
        self._round = 0
        self._runs_this_round = 0
        self._run: _Run | None = None

    @property
    def phase(self) -> Phase:
        """What the last generation asked for was."""
        return self._phase

    # -- the strategy interface (search.Search) ---------------------------------------------------------------------

    def generation(self, best: Parameters | None) -> list[Parameters]:
        if self._family_round < FAMILY_ROUNDS and self.family is not None:
            self._phase = Phase.FAMILY
            self._factors = [self._family_best * FAMILY_STEPS[self._family_round] ** j
                             for j in FAMILY_SPAN[self._family_round] if j != 0]
            return [self.family(f) for f in self._factors]
        if self._phase is Phase.FAMILY and self._delivered():
            self._aims, self._aims_source = [], None  # the family already carries the start body where aims would
            self._phase = Phase.SCAN  # nor is its throw to be turned: on to the springs, then the legs
        if self._aims_source is not None and self._phase in (Phase.FAMILY, Phase.AIM):
            self._aims, self._aims_source = list(self._aims_source()), None
        if self._aims and self._phase in (Phase.FAMILY, Phase.AIM):
            self._phase = Phase.AIM
            self._aimed, self._aims = self._aims[:AIM_GENERATION], self._aims[AIM_GENERATION:]
            return [a.parameters for a in self._aimed]
        if self._phase in (Phase.AIM, Phase.AIM_RUN) and self._best_aim is not None:
            if self._run is None and self._phase is Phase.AIM:
                self._begin_aim_run()
            if self._run is not None and self._aim_run_rollouts < AIM_RUN_ROLLOUTS:
                self._phase = Phase.AIM_RUN
                return self._run.ask()
            self._run = None
        if self._phase in (Phase.FAMILY, Phase.AIM, Phase.AIM_RUN) or (self._phase is Phase.START
                                                                       and self.centre.velocities):
            self._phase = Phase.SCAN
            return _turned_and_scaled(self.centre)
        if self._phase is Phase.SCAN and self.centre.springs:
            self._phase = Phase.SPRINGS
            return _stiffened(self.centre)
        self._phase = Phase.RUN
        while not self.finished:
            if self._run is None and not self._begin():
                continue
            assert self._run is not None
            return self._run.ask()
        return []

    def told(self, generation: list[Parameters], scores: list[Score]) -> None:
        if self.centre_score is None:  # the start, alone (generation 0 of the search)
            self.centre_score = scores[0]
            return
        if self._phase in (Phase.FAMILY, Phase.SCAN, Phase.SPRINGS, Phase.AIM):  # the one furthest along leads
            if self._phase is Phase.FAMILY:
                self._family_round += 1
            for k, (p, s) in enumerate(zip(generation, scores, strict=True)):
                if not s.exploded and self._progress(s) < self._progress(self.centre_score):
                    self.centre, self.centre_score = p, s
                    if self._phase is Phase.FAMILY:
                        self._family_best = self._factors[k]
                    if self._phase is Phase.AIM:
                        self._best_aim = self._aimed[k]
            return
        if self._phase is Phase.AIM_RUN:
            run = self._run
            assert run is not None
            self._aim_run_rollouts += len(generation)
            stopped = run.tell(generation, scores, [self._key(s) for s in scores])
            if run.best is not None and self._progress(run.best[2]) < self._progress(self.centre_score):
                self._adopt(run.best)
            if stopped or run.stalled or (run.best is not None and run.best[2].qualitative == 0):
                self._run = None
                self._best_aim = None  # corrected once; on to the scan
            return
        run = self._run
        assert run is not None
        stopped = run.tell(generation, scores, [self._key(s) for s in scores])
        if run.best is not None and leg_score(run.best[2], self.leg).qualitative == 0:
            self._adopt(run.best)
            self.restarts = 0
            self._run = None  # on to the first leg the new best does not reproduce
        elif stopped or run.stalled:
            if run.best is not None and run.best[0] < self._key(self.centre_score):
                self._adopt(run.best)
            self.restarts += 1
            if self._sigma() > MAX_SIGMA:
                self._given_up = self.leg
                self.restarts = 0
            self._run = None

    # -- legs -------------------------------------------------------------------------------------------------------

    def _progress(self, s: Score) -> tuple[int, float, float]:
        """How far along the legs a score is: more leading legs reproduced first, then the first unreproduced
        leg's objective, then the whole objective (smaller is further)."""
        solved = next((k for k in range(len(self.legs)) if leg_score(s, k).qualitative > 0), len(self.legs))
        return (-solved, leg_score(s, solved).objective if solved < len(self.legs) else 0.0, s.objective)

    def _components(self, leg: Leg) -> frozenset[str]:
        """What a run on ``leg`` adjusts: at first, after a reproduced leg, the components the leg's own events name
        (`Leg.own`) when the machine has springs; on a restart, or without springs, every component up to its end
        (`Leg.components`). On the egg cracker (no springs) the narrowed run crept ~100 rollouts before a restart."""
        if (self.restarts == 0 and self.leg > 0 and leg.own and self.centre.springs
                and coordinates(self.centre, ("vx", "vy"), leg.own)):
            return leg.own
        return leg.components

    def _delivered(self) -> bool:
        """Whether the centre reproduces every leg the aims and the scan address (`aimed_legs`)."""
        assert self.centre_score is not None
        return 0 < self.aimed_legs <= -self._progress(self.centre_score)[0]

    def _key(self, s: Score) -> tuple[float, float]:
        return (leg_score(s, self.leg).objective, s.objective)

    def _sigma(self) -> float:
        """The step size of the next run on the current leg."""
        return CMA_SIGMA * 2.0 ** self.restarts

    def _adopt(self, best: tuple[tuple[float, float], Parameters, Score]) -> None:
        self.centre, self.centre_score = best[1], best[2]

    def _begin_aim_run(self) -> None:
        """A CMA-ES run in `AimSpace` round the best aimed candidate, on the first leg the centre does not
        reproduce (the aimed candidate corrected by rollouts)."""
        assert self.centre_score is not None and self._best_aim is not None
        self.leg = next((k for k in range(len(self.legs)) if leg_score(self.centre_score, k).qualitative > 0),
                        len(self.legs))
        if self.leg >= len(self.legs):
            self._best_aim = None
            return
        self._run = _Run(AimSpace(self.centre, self._best_aim), AIM_RUN_SIGMA, (self.seed, AIM_RUN_ROUND, self.leg, 0))

    def _begin(self) -> bool:
        """Starts a run on the first leg after the last given up that the centre does not reproduce; False when
        there is nothing to adjust for it (then that leg is given up) and ``finished`` when no leg is left."""
        assert self.centre_score is not None
        self.leg = next((k for k in range(self._given_up + 1, len(self.legs))
                         if leg_score(self.centre_score, k).qualitative > 0), len(self.legs))
        if self.leg >= len(self.legs):
            if self.centre_score.qualitative == 0 or not self._runs_this_round:
                self.finished = True  # reproduced, or nothing left that a run could adjust
            else:  # every leg tried and some given up: another round from the best so far, until the budget
                self._round += 1
                self._given_up = -1
                self._runs_this_round = 0
            return False
        leg = self.legs[self.leg]
        coords = coordinates(self.centre, ("vx", "vy"), None if leg is None else self._components(leg))
        if not coords:
            self._given_up = self.leg
            return False
        rng_key = (self.seed, self._round, self.leg, self.restarts)
        self._runs_this_round += 1
        self._run = _Run(Normalisation(coords, self.centre, self.start), self._sigma(), rng_key)
        return True


def _turned_and_scaled(p: Parameters) -> list[Parameters]:
    """``p`` with every start body's initial velocity turned by `SCAN_ANGLES` and scaled by `SCAN_SPEEDS` together
    (the thesis grid's velocity steps, one combination for all start bodies), ``p`` itself left out."""
    out = []
    for degrees in SCAN_ANGLES:
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        for factor in SCAN_SPEEDS:
            if degrees == 0 and factor == 1.0:
                continue
            out.append(p.with_velocities({b: (factor * (vx * c - vy * s), factor * (vx * s + vy * c))
                                          for b, (vx, vy) in p.velocities.items()}))
    return out


def _stiffened(p: Parameters) -> list[Parameters]:
    """``p`` with every spring's constant scaled by `SPRING_K` and natural length by `SPRING_REST`, all alike."""
    return [Parameters(p.bodies, {sid: SpringParameters(sp.k * k, sp.rest_length * rest)
                                  for sid, sp in p.springs.items()}, p.velocities)
            for k in SPRING_K for rest in SPRING_REST]


class _Run:
    """One CMA-ES run (or one-coordinate sampler) on one leg, from one centre."""

    def __init__(self, norm: Normalisation | AimSpace, sigma: float, rng_key: tuple[int, ...]) -> None:
        self.norm = norm
        self.sigma = sigma
        self.rng_key = rng_key
        self.generations = 0
        self.since_better = 0
        self.best: tuple[tuple[float, float], Parameters, Score] | None = None
        self._best_z = 0.0
        self._asked: list[np.ndarray] = []
        self._es = self._optimiser(len(norm.coords)) if len(norm.coords) > 1 else None

    @property
    def stalled(self) -> bool:
        return self.since_better >= STALL_GENERATIONS

    def _optimiser(self, n: int) -> Any:  # a cma.CMAEvolutionStrategy (cma has no type information)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # pycma warns about matplotlib, which it does not need here
            import cma
            rng = np.random.default_rng(list(self.rng_key))
            options = {"seed": (self.rng_key[0] % 2_147_483_646) + 1, "verbose": -9,
                       "randn": lambda *shape: rng.standard_normal(shape)}
            return cma.CMAEvolutionStrategy([0.0] * n, self.sigma, options)

    def ask(self) -> list[Parameters]:
        if self._es is not None:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                self._asked = list(self._es.ask())
        else:
            rng = np.random.default_rng([*self.rng_key, self.generations])
            width = self.sigma * 0.8 ** self.generations
            self._asked = [np.array([self._best_z + width * float(x)]) for x in rng.standard_normal(LINE_SAMPLES)]
        return [self.norm.decode(z) for z in self._asked]

    def tell(self, generation: list[Parameters], scores: list[Score], keys: list[tuple[float, float]]) -> bool:
        """The generation's scores and keys (leg objective, whole objective); True when CMA-ES has stopped (a
        generation cut short by the budget is not told: the search is over then)."""
        self.generations += 1
        improved = False
        for z, p, s, key in zip(self._asked, generation, scores, keys, strict=False):
            if self.best is None or key < self.best[0]:
                self.best, self._best_z, improved = (key, p, s), float(z[0]), True
        self.since_better = 0 if improved else self.since_better + 1
        if self._es is None:
            return False
        if len(generation) < len(self._asked):
            return True
        values = [key[0] for key in keys]
        finite = [v for v in values if math.isfinite(v)]
        worst = max(finite, default=1.0e9)
        told = [v if math.isfinite(v) else 2 * abs(worst) + EXPLODED_PENALTY for v in values]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            self._es.tell(self._asked, told)
            return bool(self._es.stop())
