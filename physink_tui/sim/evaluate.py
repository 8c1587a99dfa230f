"""Scores one candidate: its rollout's simulated timeline against the demonstrated one (the equivalence metric);
no search, no I/O, no clock.

`Problem` is what every candidate of one search shares (scene, demonstrated timeline, canvas, rollout length); it is
a plain value, so an executor may ship it to worker processes. Within one process, the demonstrated timeline is
prepared once per problem and settled states are kept for the last few `Parameters.structure()` keys (a grid sweep
over an initial velocity forks every candidate from one settled state); both caches are keyed by the problem's
``key``, an opaque token given when the problem is made.
"""

from __future__ import annotations

import itertools
import math
from collections import OrderedDict
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from physink_tui.errors import SimulationError
from physink_tui.scene.components import Scene
from physink_tui.sim.legs import legs
from physink_tui.sim.parameters import Parameters, Structure
from physink_tui.sim.rollout import RolloutResult, Settled, Stop, rollout_from, settled_state
from physink_tui.timeline.equivalence import Comparison, Prepared, compare_prefixes, compare_prepared, prepare
from physink_tui.timeline.events import Event, Timeline

QUALITATIVE_WEIGHT = 1000.0
"""The objective is ``QUALITATIVE_WEIGHT * qualitative + quantitative``: one qualitative cost step (0.25, a region)
outweighs 250 canvas units of trajectory distance, so the quantitative distance only ranks candidates of equal
qualitative distance (unless trajectories are further apart than a quarter of the canvas, which ties are not)."""
MISS_WEIGHT = 4.0
"""How much more a unit of `Score.miss` counts than a unit of quantitative distance: among candidates that all
miss a demonstrated contact, reaching it matters more than following the pen's (not always physical) path."""
NEVER_MOVED = math.hypot(1600.0, 1000.0)
"""`Score.miss` of a demonstrated contact whose body never moved in the simulation."""
SETTLED_CACHE = 8
"""Settled states kept per process."""
MIN_SECONDS = 2.0
EXTRA_SECONDS = 2.0
MAX_SECONDS_CAP = 30.0
"""A rollout lasts at most the demonstration's length plus `EXTRA_SECONDS`, at least `MIN_SECONDS`, at most
`MAX_SECONDS_CAP` (what happens long after the demonstrated behaviour is not compared anyway)."""

_keys = itertools.count(1)


@dataclass(frozen=True, slots=True)
class Score:
    """How far one candidate's simulation is from the demonstration.

    Attributes:
        qualitative: the equivalence metric's qualitative distance (inf when exploded).
        quantitative: its quantitative distance, canvas units (inf when exploded).
        exploded: the rollout blew up (NaN or a huge speed) or the parameters were out of range: discarded.
        miss: canvas units by which the simulation missed the demonstrated contacts it does not reproduce (for
            each, how close the first body of the contact came to the demonstrated contact point; `miss_distance`):
            among candidates that all miss the ball-in-the-basket, the one that came nearest is the better.
        legs: when the problem asks for them (``Problem.by_leg``), the same for each leg of the demonstration
            (`legs.legs`: the demonstration up to the end of each leg against the whole simulation, what the
            simulation does after its last event matched with the leg not counted).
    """

    qualitative: float
    quantitative: float
    exploded: bool = False
    miss: float = 0.0
    legs: tuple[Score, ...] = ()

    @property
    def objective(self) -> float:
        """What the search minimises: `QUALITATIVE_WEIGHT` * qualitative + quantitative + miss; inf when exploded."""
        if self.exploded:
            return math.inf
        return QUALITATIVE_WEIGHT * self.qualitative + self.quantitative + MISS_WEIGHT * self.miss


EXPLODED_SCORE = Score(math.inf, math.inf, True)


@dataclass(frozen=True, slots=True)
class Problem:
    """What every candidate of one search shares.

    Attributes:
        scene: the sketched scene (without parameters applied).
        timeline: the demonstrated timeline.
        canvas: (width, height) in canvas units.
        max_seconds: the longest rollout (`rollout_seconds` of the timeline by default).
        by_leg: score each leg too (`Score.legs`), for the leg-by-leg search.
        key: an opaque token naming this problem in a process's caches (given at creation, kept when pickled).
    """

    scene: Scene
    timeline: Timeline
    canvas: tuple[float, float]
    max_seconds: float
    by_leg: bool = False
    key: int = field(default_factory=lambda: next(_keys))


def rollout_seconds(timeline: Timeline) -> float:
    """The rollout length for a demonstration (see `MIN_SECONDS`)."""
    end = max((max(ev.t0, ev.t1 if ev.t1 is not None else ev.t0) for ev in timeline.events), default=0.0)
    return min(max(end + EXTRA_SECONDS, MIN_SECONDS), MAX_SECONDS_CAP)


def make_problem(scene: Scene, timeline: Timeline, canvas: tuple[float, float],
                 max_seconds: float | None = None, *, by_leg: bool = False) -> Problem:
    """A problem with a fresh key and, by default, `rollout_seconds` of the timeline."""
    seconds = rollout_seconds(timeline) if max_seconds is None else max_seconds
    return Problem(scene, timeline, (float(canvas[0]), float(canvas[1])), seconds, by_leg)


_prepared: dict[int, tuple[Prepared, tuple[frozenset[str], ...]]] = {}
_settled: OrderedDict[tuple[int, Structure], Settled] = OrderedDict()


def _demonstration(problem: Problem) -> tuple[Prepared, tuple[frozenset[str], ...]]:
    """The demonstration prepared for comparing, and the event ids of each of its legs (when the problem asks)."""
    p = _prepared.get(problem.key)
    if p is None:
        _prepared.clear()  # one search at a time per process
        by_leg = tuple(leg.events for leg in legs(problem.timeline)) if problem.by_leg else ()
        p = _prepared[problem.key] = (prepare(problem.timeline, problem.scene.names()), by_leg)
    return p


def simulate(problem: Problem, parameters: Parameters) -> RolloutResult:
    """The rollout of ``parameters`` (settled state cached by structure within this process)."""
    key = (problem.key, parameters.structure())
    state = _settled.get(key)
    if state is None:
        state = settled_state(problem.scene, problem.canvas, parameters)
        _settled[key] = state
        while len(_settled) > SETTLED_CACHE:
            _settled.popitem(last=False)
    else:
        _settled.move_to_end(key)
    return rollout_from(problem.scene, state, problem.canvas, parameters, max_seconds=problem.max_seconds)


def compare_rollout(problem: Problem, result: RolloutResult, *, explain: bool = False) -> Comparison:
    """The demonstration (A) against a rollout's simulated timeline (B)."""
    return compare_prepared(_demonstration(problem)[0], prepare(result.timeline, problem.scene.names()),
                            explain=explain, simulation=True)


def evaluate_problem(problem: Problem, parameters: Parameters) -> Score:
    """`evaluate` for a prepared problem; picklable as ``functools.partial(evaluate_problem, problem)``."""
    try:
        result = simulate(problem, parameters)
    except SimulationError:
        return EXPLODED_SCORE
    if result.stopped_because == Stop.EXPLODED:
        return EXPLODED_SCORE
    demonstrated, by_leg = _demonstration(problem)
    simulated = prepare(result.timeline, problem.scene.names())
    whole, prefixes = compare_prefixes(demonstrated, simulated, by_leg, simulation=True)
    sides = side_misses(problem.scene, problem.timeline, result.timeline, whole.matches)
    scores = tuple(Score(d.qualitative_distance, d.quantitative_distance, False,
                         _miss(problem, result, d.only_a) + sum(m for e, m in sides.items() if e in leg))
                   for d, leg in zip(prefixes, by_leg, strict=True))
    return Score(whole.qualitative_distance, whole.quantitative_distance, False,
                 _miss(problem, result, whole.only_a) + sum(sides.values()), scores)


def _miss(problem: Problem, result: RolloutResult, only_demonstrated: Sequence[str]) -> float:
    return miss_distance(problem.timeline, result.timeline, only_demonstrated) if only_demonstrated else 0.0


def _frames(timeline: Timeline, body: str) -> tuple[np.ndarray, np.ndarray]:
    """A body's recorded frames (its own movements' and those it is carried along in), by time: times, centres."""
    frames = sorted((q.t, q.x, q.y) for ev in timeline.events if ev.type == "movement"
                    for track in ([ev.trajectory] if ev.components and ev.components[0] == body else [])
                    + [f for b, f in ev.tracks if b == body] for q in track)
    a = np.asarray(frames, dtype=float).reshape(-1, 3)
    return a[:, 0], a[:, 1:]


def miss_distance(demonstrated: Timeline, simulated: Timeline, only_demonstrated: Sequence[str]) -> float:
    """For each demonstrated contact (of ``only_demonstrated`` event ids) the simulation does not reproduce: the
    closest the contact's mover (`mover`) came to the demonstrated contact point in any simulated movement (the
    canvas diagonal of 1600 x 1000 if it never moved), summed."""
    paths: dict[str, list[tuple[float, float]]] = {}
    for ev in simulated.events:
        if ev.type == "movement" and ev.components and ev.trajectory:
            paths.setdefault(ev.components[0], []).extend((q.x, q.y) for q in ev.trajectory)
    total = 0.0
    for event_id in only_demonstrated:
        ev = demonstrated.event(event_id)
        if ev.type != "contact" or ev.point is None or not ev.components:
            continue
        points = paths.get(mover(demonstrated, ev))
        if not points:
            total += NEVER_MOVED
            continue
        xy = np.asarray(points)
        total += float(np.sqrt(((xy - np.asarray(ev.point)) ** 2).sum(axis=1)).min())
    return total


def side_misses(scene: Scene, demonstrated: Timeline, simulated: Timeline,
                matches: Sequence[tuple[str, str]]) -> dict[str, float]:
    """For each matched contact between two movable bodies whose sides differ (the cup meets the peg's top, not its
    side; none where one lands inside the other): how far, in canvas units, the second body's centre lay from the
    first's at the simulated contact from where it lay at the demonstrated one, by demonstrated event id. A contact on
    the wrong side scores no `miss_distance` (it is matched), so without this a search sees no way towards the right
    side; the two bodies' placement at contact is the way (the cup lower beside the peg). A contact with a fixed body
    is left out: there the start body's throw decides the side, which the aims and the velocity scan look after, and
    the term changed which throws the search followed (measured: one held-back ball-and-platforms case lost)."""
    out: dict[str, float] = {}
    for a_id, b_id in matches:
        ea, eb = demonstrated.event(a_id), simulated.event(b_id)
        if ea.type != "contact" or len(ea.components) != 2 or set(ea.components) != set(eb.components):
            continue
        if any(scene.is_fixed(c) for c in ea.components):
            continue
        sa, sb = dict(ea.sides), dict(eb.sides)
        if sa == sb or "inside" in (*sa.values(), *sb.values()):
            continue
        first, second = ea.components
        offsets = [np.subtract(_centre(scene, tl, second, ev.t0), _centre(scene, tl, first, ev.t0))
                   for tl, ev in ((demonstrated, ea), (simulated, eb))]
        out[a_id] = float(np.hypot(*(offsets[0] - offsets[1])))
    return out


def _centre(scene: Scene, timeline: Timeline, body: str, t: float) -> tuple[float, float]:
    """Where ``body``'s centre is at ``t`` in ``timeline``: its recorded frame nearest in time (a movement's own or
    a body carried along by it), else where it is drawn."""
    times, centres = _frames(timeline, body)
    if not len(times):
        component = scene.components.get(body)
        return getattr(component, "position", (0.0, 0.0))
    k = int(np.abs(times - t).argmin())
    return (float(centres[k, 0]), float(centres[k, 1]))


def mover(timeline: Timeline, contact: Event) -> str:
    """The body of ``contact`` that brought it about: of the movements causing it, the one moving fastest in its
    last frame (a peg sprung into a cup that sinks on its platform), else the contact's first body."""
    fastest, body = -1.0, contact.components[0]
    for cause in contact.causes:
        ev = timeline.event(cause)
        if ev.type == "movement" and ev.trajectory and ev.components and ev.components[0] in contact.components:
            last = ev.trajectory[-1]
            if math.hypot(last.vx, last.vy) > fastest:
                fastest, body = math.hypot(last.vx, last.vy), ev.components[0]
    return body


def evaluate(scene: Scene, timeline: Timeline, canvas: tuple[float, float], parameters: Parameters,
             max_seconds: float) -> Score:
    """Roll ``parameters`` out on ``scene`` for at most ``max_seconds`` and compare the simulated timeline with the
    demonstrated ``timeline``. Parameters out of range and exploded rollouts give `EXPLODED_SCORE`."""
    return evaluate_problem(make_problem(scene, timeline, canvas, max_seconds), parameters)
