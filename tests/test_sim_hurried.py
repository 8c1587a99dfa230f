"""SIMULATE on demonstrations our own virtual pen did not make: the pinball, the egg cracker and the
ball-and-platforms machine sketched and demonstrated by the hurried hand of tests/penmodels (corner slow-downs,
overshoots, hooks), each seed a different drawing and demonstration."""

from __future__ import annotations

from dataclasses import replace
from functools import cache

import pytest
from penmodels.journal import header, hurried_drawing
from scenarios.bouncing import below_b
from scenarios.thesis import egg_cracker, pinball

from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import compare_rollout, make_problem, simulate
from physink_tui.sim.search import Search
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import SerialExecutor

SOLVED_SEEDS = (2, 3)
"""Hurried pinballs SIMULATE reproduces (seeds 1 and 4 end at 0.5 and 3.5 within 200 rollouts: the ball's
contact with paddle a is explained by the paddle's own movement there, and ball two reaches paddle c)."""


@cache
def hurried_pinball(seed: int) -> Session:
    """The pinball drawn and then demonstrated (the two balls dragged) by the hurried pen seeded ``seed``."""
    return hurried(pinball, seed)


def hurried(make_scenario, seed: int) -> Session:
    """A thesis scenario drawn and then demonstrated by the hurried pen seeded ``seed``."""
    scenario = make_scenario()
    steps = list(scenario.steps)
    steps[-1] = replace(steps[-1], commands=(*steps[-1].commands, ("mode", ("demo",))))
    entries, _ = hurried_drawing((*steps, *scenario.demo), seed)
    entries.append(CommandEntry(round(entries[-1].t + scenario.settle_s, 6), "mode", ("sketch",)))
    return Session.from_header(header()).run(entries)


@pytest.mark.parametrize("seed", SOLVED_SEEDS)
def test_a_hurried_pinball_demonstration_is_reproduced(seed: int) -> None:
    session = hurried_pinball(seed)
    timeline = session.timeline
    contacts = [ev for ev in timeline.events if ev.type == "contact"]
    assert len(contacts) >= 2, "the hurried demonstration hits the paddles"
    search = Search(session.scene, timeline, session.canvas, seed=0, budget=60)
    problem = make_problem(session.scene, timeline, session.canvas)
    run_search(search, problem, SerialExecutor())
    assert search.found_at is not None, search.best_score
    comparison = compare_rollout(problem, simulate(problem, search.best), explain=True)
    assert comparison.equivalent and not comparison.reasons


@pytest.mark.parametrize("seed", (1, 5))
def test_a_hurried_hand_pushing_the_egg_through_the_paddles_touches_each_once(seed: int) -> None:
    # seeds whose hurried demonstration knocks the egg through (others miss the egg with the knife); without the
    # recorder's same-push rule, seed 5's egg catches up with the right paddle it pushed and touches it twice
    session = hurried(egg_cracker, seed)
    names = session.scene.names()
    touched = [frozenset(names[c] for c in ev.components) for ev in session.timeline.events if ev.type == "contact"]
    assert [touched.count(frozenset({"egg", paddle})) for paddle in ("left paddle", "right paddle", "pan")] == [1, 1, 1]


@pytest.mark.parametrize("seed", (1, 2, 3))
def test_a_hurried_drop_above_a_and_below_b_into_the_basket_is_reproduced(seed: int) -> None:
    # figure 3-22 drawn and demonstrated by the hurried hand (its platforms and basket where its strokes put them);
    # the hurried corners of the other bouncing demonstrations miss the platforms, so only this path is a fair test
    session = hurried(below_b, seed)
    names = session.scene.names()
    first = next(ev for ev in session.timeline.events if ev.type == "movement")
    regions = {names[body]: set(where) for body, where in first.regions}
    assert "above" in regions["platform a"] and "below" in regions["platform b"], regions
    search = Search(session.scene, session.timeline, session.canvas, seed=0, budget=60)
    problem = make_problem(session.scene, session.timeline, session.canvas)
    run_search(search, problem, SerialExecutor())
    assert search.found_at is not None, search.best_score
