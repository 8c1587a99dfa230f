"""SIMULATE on ball-and-platform machines made by construction (tests/constructed), a handful of each kind (the
full table is benchmarks/bench_constructed.py's): a possible case's witness reproduces its demonstration and the
default search finds an equivalent within the default budget; an impossible case is refused, the verdict naming
the contact the construction made impossible."""

from __future__ import annotations

import pytest
from constructed.impossible import impossible
from constructed.judge import judge
from constructed.levers import lever
from constructed.possible import possible

from physink_tui.sim.defaults import DEFAULT_BUDGET
from physink_tui.sim.evaluate import evaluate, rollout_seconds
from physink_tui.sim_run.executors import SerialExecutor
from physink_tui.timeline.events import event_label

POSSIBLE = (3, 16, 17)
"""From the tuning range (0-999): three platform contacts (virtual pen), two (the hurried hand), two on one
platform (virtual pen)."""
IMPOSSIBLE = (0, 8)
"""From the tuning range: touching the bottom of a level platform and then its top (0), and its top then its
bottom (8)."""


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


def test_a_lever_machine_is_witnessed_and_found() -> None:
    case = lever(3)  # the tuning range's: the ball tips the lever and drops into the basket
    s = case.session()
    names = s.scene.names()
    bar = next(b.id for b in s.scene.bodies() if names[b.id] == "lever")
    assert not s.scene.is_fixed(bar)
    assert any(ev.type == "movement" and ev.components[0] == bar for ev in s.timeline.events), "the lever turns"
    score = evaluate(s.scene, s.timeline, s.canvas, case.witness_parameters(), rollout_seconds(s.timeline))
    assert score.qualitative == 0 and not score.exploded
    outcome = judge(s, SerialExecutor())
    assert outcome.found, outcome.verdict


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


def test_a_slice_searched_on_a_dask_cluster_gives_the_local_outcomes() -> None:
    import distributed

    from physink_tui.sim_run.dask_executor import DaskExecutor

    cases = (possible(3).session(), impossible(0).session())
    local = [judge(s, SerialExecutor()) for s in cases]
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=40) as cluster, DaskExecutor(cluster=cluster) as executor:
        remote = [judge(s, executor) for s in cases]
    assert remote == local
    assert [o.found for o in local] == [True, False]
