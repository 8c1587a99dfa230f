"""SIMULATE's search: the thesis grid's steps, CMA-ES from a wrong start, determinism across executors, exploded
candidates, the budget."""

from __future__ import annotations

import math

import pytest

from physink_tui.errors import SimulationError
from physink_tui.sim.evaluate import EXPLODED_SCORE, QUALITATIVE_WEIGHT, Score, evaluate, evaluate_problem, make_problem
from physink_tui.sim.grid import ANGLE_STEPS, grid_values
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters
from physink_tui.sim.search import Search
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import ProcessExecutor, SerialExecutor
from tests.sim_scenes import CANVAS, ball_floor_wall, demonstration, parameters

WRONG_START = parameters((100.0, 0.0))
"""Too slow: the ball stops before the wall (qualitatively wrong)."""


def problem():
    return make_problem(ball_floor_wall(), demonstration(), CANVAS)


def test_demonstration_hits_the_wall() -> None:
    assert any(ev.type == "contact" and set(ev.components) == {"b1", "b3"} for ev in demonstration().events)


def test_grid_values_are_the_thesis_steps() -> None:
    assert ANGLE_STEPS == (-45, -30, -15, 0, 15, 30, 45)
    angles = grid_values("angle", 0.3)
    assert [round(math.degrees(a - 0.3)) for a in angles] == [-45, -30, -15, 0, 15, 30, 45]
    assert grid_values("rest_length", 40.0) == (20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
    assert grid_values("friction", 1.0) == (0.0, 0.25, 0.5, 0.75, 1.0)
    assert grid_values("mass", 8.0) == (2.0, 4.0, 8.0, 16.0, 32.0)
    assert grid_values("speed", 100.0) == (50.0, 75.0, 100.0, 125.0, 150.0, 175.0, 200.0)
    assert grid_values("speed", 0.0)[0] == 0.0


def test_evaluate_scores_and_discards_out_of_range_parameters() -> None:
    right = evaluate(ball_floor_wall(), demonstration(), CANVAS, parameters((400.0, 0.0)), 4.0)
    assert right == Score(0.0, 0.0, False)
    wrong = evaluate(ball_floor_wall(), demonstration(), CANVAS, WRONG_START, 6.0)
    assert wrong.qualitative > 0 and not wrong.exploded
    bad = Parameters({"b1": BodyParameters(-1.0, 1.0)}, {}, {"b1": (1.0, 0.0)})
    assert evaluate(ball_floor_wall(), demonstration(), CANVAS, bad, 6.0) == EXPLODED_SCORE
    assert EXPLODED_SCORE.objective == math.inf
    assert Score(1.0, 5.0).objective == QUALITATIVE_WEIGHT + 5.0


@pytest.mark.parametrize("strategy", ["default", "grid"])
def test_search_finds_the_known_answer_from_a_wrong_start(strategy: str) -> None:
    p = problem()
    start = evaluate_problem(p, WRONG_START)
    search = Search(p.scene, p.timeline, CANVAS, strategy=strategy, seed=1, budget=60, start=WRONG_START)
    run_search(search, p, SerialExecutor())
    assert search.rollouts <= 60 and 0 <= search.rollouts - search.found_at < 48  # stops once found
    assert search.best_score.objective < start.objective
    assert search.best_score.qualitative == 0.0


def test_same_result_whatever_the_executor() -> None:
    p = problem()
    results = []
    for executor in (SerialExecutor(), ProcessExecutor(2)):
        search = Search(p.scene, p.timeline, CANVAS, seed=7, budget=17, start=WRONG_START)
        with executor:
            run_search(search, p, executor)
        results.append((search.rollouts, search.best, search.best_score))
    assert results[0] == results[1]
    assert results[0][0] <= 17


class Fake:
    """A pure objective over the candidates (no rollouts): distance of b1's velocity from (300, 50); every
    candidate with vy > 60 explodes; none is ever qualitatively equivalent (so the search uses its budget)."""

    def __call__(self, p: Parameters) -> Score:
        vx, vy = p.velocities["b1"]
        if vy > 60:
            return EXPLODED_SCORE
        d = math.hypot(vx - 300, vy - 50)
        return Score(1.0 + float(d > 30), d)


def drive(search: Search) -> int:
    fn = Fake()
    asked = 0
    while not search.done:
        generation = search.next_generation()
        if not generation:
            break
        asked += len(generation)
        search.tell([fn(c) for c in generation])
    return asked


def test_exploded_candidates_are_counted_and_never_best() -> None:
    search = Search(ball_floor_wall(), demonstration(), CANVAS, seed=3, budget=60, start=parameters((250.0, 0.0)))
    asked = drive(search)
    assert asked == search.rollouts == 60
    assert search.exploded > 0
    assert not search.best_score.exploded and search.best.velocities["b1"][1] <= 60


def test_same_seed_same_search_other_seed_other_candidates() -> None:
    def run(seed: int):
        s = Search(ball_floor_wall(), demonstration(), CANVAS, seed=seed, budget=90, start=parameters((250.0, 0.0)))
        drive(s)
        return s.best, s.best_score, s.exploded

    assert run(5) == run(5)
    assert run(5) != run(6)


def test_the_grid_tries_every_combination_in_odometer_order_until_the_budget() -> None:
    start = Parameters({"b1": BodyParameters(10.0, 1.0)}, {"s1": SpringParameters(20.0, 40.0)}, {"b1": (100.0, 0.0)})
    search = Search(ball_floor_wall(), demonstration(), CANVAS, strategy="grid", budget=1000, start=start)
    seen = []
    while not search.done:
        generation = search.next_generation()
        if not generation:
            break
        seen.extend(generation)
        search.tell([Score(1.0, 1.0)] * len(generation))  # nothing ever better than the start
    assert search.rollouts == len(seen) == 1000 and search.best == start
    grid = seen[1:]
    assert len(set(map(repr, grid))) == len(grid)  # no combination twice
    # the first coordinate (b1's velocity angle, 7 values) changes fastest, then its speed (7 values)
    angles = [round(math.degrees(math.atan2(p.velocities["b1"][1], p.velocities["b1"][0]))) for p in grid[:8]]
    assert angles == [-45, -30, -15, 0, 15, 30, 45, -45]
    speeds = [round(math.hypot(*p.velocities["b1"])) for p in grid[:15]]
    assert speeds == [50] * 7 + [75] * 7 + [100]
    assert {p.bodies["b1"].mass for p in grid[:49]} == {2.5}  # the mass changes after all 49 velocities
    assert grid[49].bodies["b1"].mass == 5.0


def test_the_grid_stops_at_the_first_equivalent_candidate() -> None:
    search = Search(ball_floor_wall(), demonstration(), CANVAS, strategy="grid", budget=1000,
                    start=parameters((250.0, 0.0)))
    found = drive_until(search, lambda p: p.velocities["b1"][0] > 300)
    assert search.done and search.best_score.qualitative == 0 and search.found_at == found


def drive_until(search: Search, right) -> int:
    """Drives ``search`` with candidates ``right`` picks scoring 0; the rollout that found the first one."""
    found = 0
    while not search.done:
        generation = search.next_generation()
        scores = []
        for p in generation:
            scores.append(Score(0.0 if right(p) else 1.0, 1.0))
            if right(p) and not found:
                found = search.rollouts + len(scores)
        search.tell(scores)
    return found


def test_budget_cuts_the_last_generation_and_bad_arguments_are_refused() -> None:
    search = Search(ball_floor_wall(), demonstration(), CANVAS, seed=1, budget=5, start=parameters((250.0, 0.0)))
    assert drive(search) == 5
    with pytest.raises(SimulationError):
        search.next_generation()
    with pytest.raises(SimulationError):
        Search(ball_floor_wall(), demonstration(), CANVAS, budget=0)
    with pytest.raises(SimulationError):
        Search(ball_floor_wall(), demonstration(), CANVAS, strategy="random", budget=3)
    s = Search(ball_floor_wall(), demonstration(), CANVAS, budget=3)
    s.next_generation()
    with pytest.raises(SimulationError):
        s.next_generation()
    with pytest.raises(SimulationError):
        s.tell([])
