"""Demonstrations kept from earlier versions of the scenarios, beside today's (issue 27): the eight of the
ball-and-platforms machine as first drawn (`bouncing_first`, before commit 0909bba) and the cup dispenser's full
demonstration (before dd04c71: demo mode ends 2 s after the pen lets go of the peg, so the timeline keeps the peg's
recoil). Recorded into tests/journals/restored/ by `make_journals`."""

from __future__ import annotations

from dataclasses import replace

from scenarios import bouncing_first
from scenarios.thesis import Scenario, cup_dispenser

FULL_SETTLE_S = 2.0
"""The cup dispenser's settling time before dd04c71."""


def cup_dispenser_full() -> Scenario:
    """The cup dispenser demonstrated to the end: the let-go peg springs back and knocks the platform's side."""
    return replace(cup_dispenser(), name="cup_dispenser_full", settle_s=FULL_SETTLE_S)


def restored_scenarios() -> tuple[Scenario, ...]:
    return (*bouncing_first.all_scenarios(), cup_dispenser_full())
