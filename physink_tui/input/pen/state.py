"""The pen as an explicit state machine: states, the valid transitions, tip hysteresis; no gestures.

The states follow the pen states Microsoft's pen guidelines define and hid-tools' tablet tests use
(out of range, in range, in range with a button, in contact, erasing ...). `PenStateMachine.apply()`
raises on an impossible transition and names it; `route()` finds the shortest valid path between
two states, which is how real tablets that skip a state (a pen that lands between two reports, a
tablet that never reports leaving) are followed without losing a transition.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from enum import Enum

from physink_tui.errors import PhysinkError
from physink_tui.input.pen.sample import PenSample


class PenState(Enum):
    """Where the pen is and what it does."""

    OUT_OF_RANGE = "out of range"
    HOVERING = "hovering"
    HOVERING_BUTTON = "hovering with a button pressed"
    TOUCHING = "touching"
    TOUCHING_BUTTON = "touching with a button pressed"
    ERASER_HOVERING = "eraser hovering"
    ERASING = "erasing"

    @property
    def in_contact(self) -> bool:
        return self in (PenState.TOUCHING, PenState.TOUCHING_BUTTON, PenState.ERASING)

    @property
    def in_range(self) -> bool:
        return self is not PenState.OUT_OF_RANGE

    @property
    def eraser(self) -> bool:
        return self in (PenState.ERASER_HOVERING, PenState.ERASING)


S = PenState

VALID_TRANSITIONS: dict[PenState, frozenset[PenState]] = {
    S.OUT_OF_RANGE: frozenset({S.OUT_OF_RANGE, S.HOVERING, S.HOVERING_BUTTON, S.ERASER_HOVERING}),
    S.HOVERING: frozenset({S.HOVERING, S.OUT_OF_RANGE, S.HOVERING_BUTTON, S.TOUCHING}),
    S.HOVERING_BUTTON: frozenset({S.HOVERING_BUTTON, S.OUT_OF_RANGE, S.HOVERING, S.TOUCHING_BUTTON}),
    S.TOUCHING: frozenset({S.TOUCHING, S.HOVERING, S.TOUCHING_BUTTON}),
    S.TOUCHING_BUTTON: frozenset({S.TOUCHING_BUTTON, S.TOUCHING, S.HOVERING_BUTTON}),
    S.ERASER_HOVERING: frozenset({S.ERASER_HOVERING, S.OUT_OF_RANGE, S.ERASING}),
    S.ERASING: frozenset({S.ERASING, S.ERASER_HOVERING}),
}
"""From each state, the states one report may lead to. The pen must lift before it leaves range,
and it turns from tip to eraser only out of range (the user flips it over)."""


class PenStateError(PhysinkError):
    """An impossible pen transition.

    Attributes:
        before: the state the pen was in.
        after: the state asked for.
    """

    def __init__(self, before: PenState, after: PenState) -> None:
        self.before, self.after = before, after
        allowed = ", ".join(sorted(s.value for s in VALID_TRANSITIONS[before]))
        super().__init__(f"impossible pen transition {before.value!r} -> {after.value!r} (allowed: {allowed})")


def route(start: PenState, goal: PenState) -> list[PenState]:
    """The shortest list of states after ``start`` that ends at ``goal`` through valid transitions.

    >>> [s.name for s in route(PenState.OUT_OF_RANGE, PenState.TOUCHING)]
    ['HOVERING', 'TOUCHING']
    >>> route(PenState.HOVERING, PenState.HOVERING)
    []
    """
    if start is goal:
        return []
    previous: dict[PenState, PenState] = {start: start}
    todo = deque([start])
    while todo:
        state = todo.popleft()
        for nxt in sorted(VALID_TRANSITIONS[state], key=lambda s: list(PenState).index(s)):
            if nxt not in previous:
                previous[nxt] = state
                if nxt is goal:
                    path = [goal]
                    while previous[path[-1]] is not start:
                        path.append(previous[path[-1]])
                    return path[::-1]
                todo.append(nxt)
    raise PenStateError(start, goal)  # every state reaches every other; kept for safety


@dataclass(frozen=True, slots=True)
class TipThresholds:
    """Tip hysteresis on normalised pressure, as libinput does it.

    Attributes:
        down: contact begins when pressure rises above this (0..1; libinput: 5 % of the range).
        up: contact ends when pressure falls below this (0..1, below ``down``; libinput: 1 %).
    """

    down: float = 0.05
    up: float = 0.01

    def __post_init__(self) -> None:
        if not 0.0 <= self.up < self.down <= 1.0:
            raise ValueError(f"tip thresholds need 0 <= up < down <= 1, got up={self.up!r} down={self.down!r}")


class PenStateMachine:
    """Follows one pen through `PenState`s from its samples.

    >>> m = PenStateMachine()
    >>> m.apply(PenState.HOVERING); m.state.name
    'HOVERING'
    >>> m.apply(PenState.ERASING)
    Traceback (most recent call last):
    ...
    physink_tui.input.pen.state.PenStateError: impossible pen transition 'hovering' -> 'erasing' ...
    """

    def __init__(self, thresholds: TipThresholds | None = None) -> None:
        self.thresholds = thresholds or TipThresholds()
        self.state = PenState.OUT_OF_RANGE

    def apply(self, new: PenState) -> None:
        """Move to ``new``; raise `PenStateError` naming the transition when it is impossible."""
        if new not in VALID_TRANSITIONS[self.state]:
            raise PenStateError(self.state, new)
        self.state = new

    def target(self, sample: PenSample) -> PenState:
        """The state a sample shows, with tip hysteresis applied against the current state."""
        if not sample.range and not sample.tip:
            return PenState.OUT_OF_RANGE
        touching_now = self.state.in_contact
        p = sample.p
        contact = p >= self.thresholds.up if touching_now else p > self.thresholds.down
        if sample.eraser:
            return PenState.ERASING if contact else PenState.ERASER_HOVERING
        button = sample.b1 or sample.b2
        if contact:
            return PenState.TOUCHING_BUTTON if button else PenState.TOUCHING
        return PenState.HOVERING_BUTTON if button else PenState.HOVERING

    def follow(self, sample: PenSample) -> list[PenState]:
        """Advance to the state ``sample`` shows through valid transitions; return the states passed."""
        goal = self.target(sample)
        path = route(self.state, goal)
        for state in path:
            self.apply(state)
        return path
