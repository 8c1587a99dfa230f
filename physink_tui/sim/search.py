"""The parameter search (thesis 3.4.4) as a deterministic machine of candidate generations; it runs nothing itself.

A `Search` proposes a generation (`next_generation`), is told the generation's scores in candidate order (`tell`),
and so on until `done`; whoever drives it (``physink_tui.sim_run``) evaluates the candidates however it likes
(serially, in processes, on a cluster). The same seed and budget give the same candidates and the same `best`
whatever evaluated them. Generation 0 is the seed parameters (seeding.py) alone, in both strategies.

Strategies:

- ``"grid"``, the thesis's baseline: parameters adjusted one at a time over discrete values around the current best
  (coordinate sweeps); one generation is one parameter's values (the current value left out: it is known). A sweep
  over every parameter that improves nothing ends the search. The values (`grid_values`): an initial velocity's
  angle from -45° to +45° of the seeded one in 15° steps (thesis 3.4.4); a spring's natural length from l0/2 to 2·l0
  in l0/4 steps (thesis 3.4.4). Steps the thesis does not give, chosen here: an initial velocity's magnitude
  x0.5…x2 of the seeded one in x0.25 steps (like the natural length; 100 units/s steps up to 400 for a seeded
  speed of 0); mass and spring constant x¼, x½, x1, x2, x4 of the seeded one; friction 0 to 1 in 0.25 steps.
- ``"default"``: CMA-ES (pycma's ``CMAEvolutionStrategy``, ask/tell, its random numbers drawn from a generator
  seeded with ``seed``) over all continuous parameters at once, normalised around the seed: log mass and log k
  (step 1 = a factor e), friction (step 0.25, clipped to [0, 1]), natural length (step l0/4, at least 0), each
  initial velocity component (step half the seeded speed, at least `MIN_SPEED_SCALE`). Not done yet: leg by leg
  along the causal order, and early termination of a rollout that diverges.

The objective is `Score.objective` (qualitative distance weighted above quantitative); exploded candidates score
inf, are never best and are counted (`exploded`). Ties go to the earlier candidate.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from physink_tui.errors import SimulationError
from physink_tui.scene.components import Scene
from physink_tui.sim.evaluate import Score
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters
from physink_tui.sim.seeding import seed as seed_parameters
from physink_tui.timeline.events import Timeline

STRATEGIES = ("default", "grid")

ANGLE_STEPS = tuple(range(-45, 46, 15))
"""Degrees added to a seeded velocity's angle (thesis 3.4.4)."""
MAGNITUDE_FACTORS = (0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0)
"""Factors of a seeded speed (not in the thesis: the natural length's steps)."""
ZERO_SPEEDS = (0.0, 100.0, 200.0, 300.0, 400.0)
"""Speeds tried for a velocity seeded at 0 (units/s; not in the thesis)."""
LENGTH_FACTORS = (0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0)
"""Factors of a seeded natural length l0: l0/2 to 2·l0 in l0/4 steps (thesis 3.4.4)."""
SCALE_FACTORS = (0.25, 0.5, 1.0, 2.0, 4.0)
"""Factors of a seeded mass or spring constant (not in the thesis)."""
FRICTIONS = (0.0, 0.25, 0.5, 0.75, 1.0)
"""Frictions tried (not in the thesis)."""

CMA_SIGMA = 0.5
"""CMA-ES's initial step size in the normalised coordinates (half a step of each parameter's scale; measured on
the thesis scenes at budget 200: better than 1.0 and 0.25)."""
MIN_SPEED_SCALE = 100.0
"""Units/s: the smallest step of a velocity component in the normalised coordinates."""


@dataclass(frozen=True, slots=True)
class Coordinate:
    """One searched quantity: ``kind`` is "mass", "friction", "k", "rest_length", "angle", "speed" (grid) or
    "vx", "vy" (default), of component ``component``."""

    kind: str
    component: str


def _speed_angle(v: tuple[float, float]) -> tuple[float, float]:
    return math.hypot(*v), math.atan2(v[1], v[0])


def grid_values(kind: str, seeded: float) -> tuple[float, ...]:
    """The thesis grid's values of one parameter seeded at ``seeded`` (an angle in radians for "angle")."""
    if kind == "angle":
        return tuple(seeded + math.radians(d) for d in ANGLE_STEPS)
    if kind == "speed":
        return ZERO_SPEEDS if seeded == 0 else tuple(seeded * f for f in MAGNITUDE_FACTORS)
    if kind == "rest_length":
        return tuple(seeded * f for f in LENGTH_FACTORS)
    if kind in ("mass", "k"):
        return tuple(seeded * f for f in SCALE_FACTORS)
    if kind == "friction":
        return FRICTIONS
    raise SimulationError(f"no grid for {kind!r}")


def _get(p: Parameters, c: Coordinate) -> float:
    if c.kind == "mass":
        return p.bodies[c.component].mass
    if c.kind == "friction":
        return p.bodies[c.component].friction
    if c.kind == "k":
        return p.springs[c.component].k
    if c.kind == "rest_length":
        return p.springs[c.component].rest_length
    v = p.velocities[c.component]
    speed, angle = _speed_angle(v)
    return {"angle": angle, "speed": speed, "vx": v[0], "vy": v[1]}[c.kind]


def _set(p: Parameters, c: Coordinate, value: float) -> Parameters:
    bodies, springs, velocities = dict(p.bodies), dict(p.springs), dict(p.velocities)
    if c.kind in ("mass", "friction"):
        b = bodies[c.component]
        bodies[c.component] = BodyParameters(value, b.friction) if c.kind == "mass" else BodyParameters(b.mass, value)
    elif c.kind in ("k", "rest_length"):
        s = springs[c.component]
        springs[c.component] = SpringParameters(value, s.rest_length) if c.kind == "k" else \
            SpringParameters(s.k, value)
    else:
        vx, vy = velocities[c.component]
        speed, angle = _speed_angle((vx, vy))
        if c.kind == "angle":
            vx, vy = speed * math.cos(value), speed * math.sin(value)
        elif c.kind == "speed":
            if speed == 0:
                angle = 0.0  # a velocity seeded at 0 has no direction: start along +x (the angle sweep turns it)
            vx, vy = value * math.cos(angle), value * math.sin(angle)
        elif c.kind == "vx":
            vx = value
        else:
            vy = value
        velocities[c.component] = (vx, vy)
    return Parameters(bodies, springs, velocities)


def _coordinates(p: Parameters, velocity_kinds: tuple[str, str]) -> list[Coordinate]:
    out = [Coordinate(kind, body) for body in p.start_bodies for kind in velocity_kinds]
    out += [Coordinate(kind, body) for body in sorted(p.bodies) for kind in ("mass", "friction")]
    out += [Coordinate(kind, spring) for spring in sorted(p.springs) for kind in ("rest_length", "k")]
    return out


class Search:
    """A search for parameters that reproduce ``timeline`` on ``scene`` (see the module docstring).

    Args:
        scene, timeline, canvas: the demonstration (seeded by `seeding.seed`).
        strategy: "default" (CMA-ES) or "grid" (the thesis's).
        seed: the random seed (the grid uses none; it is kept for the record).
        budget: at most this many rollouts (>= 1).
        start: the parameters to start from (default: the thesis's seed).

    Use: ``while not s.done: s.tell([evaluate(p) for p in s.next_generation()])``.
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
        self._pending: list[Parameters] | None = None
        self._finished = False
        if strategy == "grid":
            self._coords = _coordinates(self.start, ("angle", "speed"))
            self._coord_index = 0
            self._improved_in_sweep = False
            self._grids = {c: grid_values(c.kind, _get(self.start, c)) for c in self._coords}
        else:
            self._coords = _coordinates(self.start, ("vx", "vy"))
            self._scales = [self._scale(c) for c in self._coords]
            self._es = None

    # -- state ------------------------------------------------------------------------------------------------------

    @property
    def done(self) -> bool:
        """No more generations: the budget is spent, or the strategy has nothing left to try."""
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
        elif self.strategy == "grid":
            generation = self._grid_generation()
        else:
            generation = self._cma_generation()
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
        improved = False
        for p, s in zip(generation, results, strict=True):
            self.rollouts += 1
            self.exploded += s.exploded
            if not s.exploded and (self.best_score is None or s.objective < self.best_score.objective):
                self.best, self.best_score, improved = p, s, True
        self.generations += 1
        if self.best_score is not None and self.best_score.qualitative == 0 and self.best_score.quantitative == 0:
            self._finished = True  # nothing can be better
        if self.generations == 1:
            if not self._coords:
                self._finished = True  # nothing to adjust
            return
        if self.strategy == "grid":
            self._grid_told(improved)
        else:
            self._cma_told(generation, results)

    # -- grid -------------------------------------------------------------------------------------------------------

    def _current(self) -> Parameters:
        return self.best if self.best is not None else self.start

    def _grid_generation(self) -> list[Parameters]:
        while True:
            c = self._coords[self._coord_index]
            current = self._current()
            now = _get(current, c)
            candidates = [_set(current, c, v) for v in self._grids[c] if not math.isclose(v, now, abs_tol=1e-9)]
            if candidates:
                return candidates
            if self._advance():
                return []

    def _advance(self) -> bool:
        """Next coordinate; True when a whole sweep improved nothing (the search is over)."""
        self._coord_index += 1
        if self._coord_index == len(self._coords):
            self._coord_index = 0
            if not self._improved_in_sweep:
                self._finished = True
                return True
            self._improved_in_sweep = False
        return False

    def _grid_told(self, improved: bool) -> None:
        self._improved_in_sweep = self._improved_in_sweep or improved
        self._advance()

    # -- CMA-ES -----------------------------------------------------------------------------------------------------

    def _scale(self, c: Coordinate) -> float:
        if c.kind in ("mass", "k"):
            return 1.0
        if c.kind == "friction":
            return 0.25
        if c.kind == "rest_length":
            return max(_get(self.start, c) / 4, 1.0)
        speed, _ = _speed_angle(self.start.velocities[c.component])
        return max(speed / 2, MIN_SPEED_SCALE)

    def _decode(self, z: np.ndarray) -> Parameters:
        p = self.start
        for c, scale, zi in zip(self._coords, self._scales, z, strict=True):
            base = _get(self.start, c)
            if c.kind in ("mass", "k"):
                value = base * math.exp(float(zi) * scale)
            elif c.kind == "friction":
                value = min(max(base + float(zi) * scale, 0.0), 1.0)
            elif c.kind == "rest_length":
                value = max(base + float(zi) * scale, 0.0)
            else:
                value = base + float(zi) * scale
            p = _set(p, c, value)
        return p

    def _cma(self):
        if self._es is None:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                import cma
            rng = np.random.default_rng(self.seed)
            options = {"seed": (self.seed % 2_147_483_646) + 1, "verbose": -9,
                       "randn": lambda *shape: rng.standard_normal(shape)}
            if len(self._coords) == 1:
                raise SimulationError("one parameter")  # handled by the caller
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                self._es = cma.CMAEvolutionStrategy([0.0] * len(self._coords), CMA_SIGMA, options)
        return self._es

    def _cma_generation(self) -> list[Parameters]:
        if len(self._coords) == 1:
            return self._line_generation()
        es = self._cma()
        self._asked = es.ask()
        return [self._decode(z) for z in self._asked]

    def _line_generation(self) -> list[Parameters]:
        """One parameter (pycma needs two): a seeded Gaussian sample around the best, shrinking each generation."""
        rng = np.random.default_rng([self.seed, self.generations])
        c = self._coords[0]
        best = self._current()
        width = CMA_SIGMA * 0.8 ** self.generations
        z0 = self._encode_one(best, c)
        self._asked = [np.array([z0 + width * float(x)]) for x in rng.standard_normal(8)]
        return [self._decode(z) for z in self._asked]

    def _encode_one(self, p: Parameters, c: Coordinate) -> float:
        base, scale, value = _get(self.start, c), self._scales[0], _get(p, c)
        if c.kind in ("mass", "k"):
            return math.log(value / base) / scale
        return (value - base) / scale

    def _cma_told(self, generation: list[Parameters], results: Sequence[Score]) -> None:
        if self._es is None or len(generation) < len(self._asked):
            return  # the one-parameter sampler, or a generation cut short by the budget (then the search is done)
        finite = [s.objective for s in results if math.isfinite(s.objective)]
        worst = max(finite, default=1.0e9)
        values = [s.objective if math.isfinite(s.objective) else 2 * abs(worst) + 1.0e6 for s in results]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            self._es.tell(self._asked, values)
            if self._es.stop():
                self._finished = True
