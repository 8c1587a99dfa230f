"""The pen state machine: every transition, possible or not, and tip hysteresis."""

from __future__ import annotations

import itertools

import pytest

from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.state import (
    VALID_TRANSITIONS,
    PenState,
    PenStateError,
    PenStateMachine,
    TipThresholds,
    route,
)

PAIRS = list(itertools.product(PenState, PenState))


def sample(p: float = 0.0, tip: bool = False, rng: bool = True, eraser: bool = False, b1: bool = False,
           b2: bool = False) -> PenSample:
    return PenSample(0.0, 0.5, 0.5, p, tip, rng, eraser, b1, b2, None, None, 2)


@pytest.mark.parametrize(("before", "after"), PAIRS, ids=[f"{a.name}->{b.name}" for a, b in PAIRS])
def test_every_transition(before: PenState, after: PenState) -> None:
    machine = PenStateMachine()
    machine.state = before
    if after in VALID_TRANSITIONS[before]:
        machine.apply(after)
        assert machine.state is after
    else:
        with pytest.raises(PenStateError) as info:
            machine.apply(after)
        assert (info.value.before, info.value.after) == (before, after)
        assert before.value in str(info.value) and after.value in str(info.value)
        assert machine.state is before  # an impossible transition changes nothing


@pytest.mark.parametrize(("start", "goal"), PAIRS, ids=[f"{a.name}->{b.name}" for a, b in PAIRS])
def test_route_reaches_every_state_through_valid_steps(start: PenState, goal: PenState) -> None:
    machine = PenStateMachine()
    machine.state = start
    for state in route(start, goal):
        machine.apply(state)
    assert machine.state is goal


@pytest.mark.parametrize(
    ("before", "after", "why"),
    [
        (PenState.TOUCHING, PenState.OUT_OF_RANGE, "must lift first"),
        (PenState.HOVERING, PenState.ERASER_HOVERING, "turning the pen needs leaving range"),
        (PenState.ERASING, PenState.TOUCHING, "eraser to tip while down"),
        (PenState.OUT_OF_RANGE, PenState.TOUCHING, "landing without hovering"),
    ],
    ids=["touch-to-out", "tip-to-eraser", "erasing-to-touching", "out-to-touch"],
)
def test_physically_impossible_transitions_raise(before: PenState, after: PenState, why: str) -> None:
    machine = PenStateMachine()
    machine.state = before
    with pytest.raises(PenStateError):
        machine.apply(after)


def test_a_sample_that_skips_states_is_followed_through_them() -> None:
    machine = PenStateMachine()
    passed = machine.follow(sample(p=0.5, tip=True))
    assert passed == [PenState.HOVERING, PenState.TOUCHING]
    passed = machine.follow(sample(rng=False))
    assert passed == [PenState.HOVERING, PenState.OUT_OF_RANGE]


@pytest.mark.parametrize(
    ("pressures", "states"),
    [
        ([0.03, 0.06, 0.02, 0.005], ["HOVERING", "TOUCHING", "TOUCHING", "HOVERING"]),
        ([0.051, 0.0101, 0.0099], ["TOUCHING", "TOUCHING", "HOVERING"]),
        ([0.05, 0.049], ["HOVERING", "HOVERING"]),
    ],
    ids=["down-above-5pc-up-below-1pc", "edges", "exactly-5pc-is-not-down"],
)
def test_tip_hysteresis(pressures: list[float], states: list[str]) -> None:
    machine = PenStateMachine(TipThresholds(down=0.05, up=0.01))
    got = []
    for p in pressures:
        machine.follow(sample(p=p, tip=p > 0))
        got.append(machine.state.name)
    assert got == states


def test_tablets_without_pressure_use_the_tip_switch() -> None:
    # the decoder reports p = 1.0 while the tip switch is down and 0.0 otherwise
    machine = PenStateMachine()
    machine.follow(sample(p=1.0, tip=True))
    assert machine.state is PenState.TOUCHING
    machine.follow(sample(p=0.0, tip=False))
    assert machine.state is PenState.HOVERING


def test_buttons_and_eraser_states() -> None:
    machine = PenStateMachine()
    machine.follow(sample(b1=True))
    assert machine.state is PenState.HOVERING_BUTTON
    machine.follow(sample(p=0.5, tip=True, b2=True))
    assert machine.state is PenState.TOUCHING_BUTTON
    machine.follow(sample(eraser=True))  # flipped to the eraser: through hover and out of range
    assert machine.state is PenState.ERASER_HOVERING
    machine.follow(sample(p=0.4, tip=True, eraser=True))
    assert machine.state is PenState.ERASING


@pytest.mark.parametrize(("down", "up"), [(0.01, 0.05), (0.05, 0.05), (1.5, 0.1), (0.05, -0.1)],
                         ids=["reversed", "equal", "above-one", "negative"])
def test_bad_thresholds_are_refused(down: float, up: float) -> None:
    with pytest.raises(ValueError, match="tip thresholds"):
        TipThresholds(down=down, up=up)
