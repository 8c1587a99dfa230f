"""SIMULATE on ball-and-platform machines made by construction (tests/constructed), a handful of each kind (the
full table is benchmarks/bench_constructed.py's): a possible case's witness reproduces its demonstration and the
default search finds an equivalent within the default budget; an impossible case is refused, the verdict naming
the contact the construction made impossible."""

from __future__ import annotations

import pytest
from constructed.impossible import impossible
from constructed.judge import judge
from constructed.possible import possible

from physink_tui.sim.defaults import DEFAULT_BUDGET
from physink_tui.sim.evaluate import evaluate, rollout_seconds
from physink_tui.sim_run.executors import SerialExecutor
from physink_tui.timeline.events import event_label

POSSIBLE = (0, 3, 6, 16, 17)
"""From the tuning range (0-999): two and three platform contacts, the hurried hand with one and two."""
IMPOSSIBLE = (0, 2, 3)


@pytest.mark.parametrize("seed", POSSIBLE)
def test_a_possible_case_is_witnessed_and_found(seed: int) -> None:
    case = possible(seed)
    s = case.session()
    score = evaluate(s.scene, s.timeline, s.canvas, case.witness_parameters(), rollout_seconds(s.timeline))
    assert score.qualitative == 0 and not score.exploded, "the witness reproduces the demonstration"
    names = s.scene.names()
    shown = [names[c] for ev in s.timeline.events if ev.type == "contact" for c in ev.components
             if names[c].startswith("platform")]
    assert shown == list(case.platform_contacts), "the pen demonstrated the witness's platform contacts"
    outcome = judge(s, SerialExecutor())
    assert outcome.found and outcome.rollouts <= DEFAULT_BUDGET, outcome.verdict


@pytest.mark.parametrize("seed", IMPOSSIBLE)
def test_an_impossible_case_is_refused_naming_the_impossible_contact(seed: int) -> None:
    case = impossible(seed)
    s = case.session()
    names = s.scene.names()
    event = case.impossible_event()
    assert dict(event.sides)[next(c for c in event.components if names[c] == case.platform)] == case.sides[1]
    outcome = judge(s, SerialExecutor())
    assert not outcome.found and outcome.qualitative > 0
    assert f'"{event_label(event, names)}" (t={event.t0:.2f} s' in outcome.verdict, outcome.verdict
