"""A replay paced in real time stamps its recorded times however late its inputs are taken (`ReplayClock`): the TUI's
journal feed into a consumer that stalls, the clock held at each entry until it is in."""

from __future__ import annotations

import threading
import time

import pytest

from physink_tui.formats.journal.entries import PenEntry
from physink_tui.input.replay_clock import ReplayClock
from physink_tui.tui.live import JournalFeed

HANG_GUARD = 60.0


def test_each_entry_is_stamped_with_its_own_time_however_long_the_consumer_stalls() -> None:
    entries = [PenEntry(0.01 * k, 0.5, 0.5, 0.6, True, True, False, False, False) for k in range(30)]
    clock = ReplayClock()
    stamps: list[float] = []

    def stalling_submit(entry) -> None:  # reads the clock as a runner stamps, then stalls as a loaded machine would
        stamps.append(clock())
        time.sleep(0.03)  # three times the entries' spacing at the feed's speed

    done = threading.Event()
    JournalFeed(entries, stalling_submit, speed=1.0, on_done=done.set, clock=clock).start()
    assert done.wait(HANG_GUARD)
    assert [s - stamps[0] for s in stamps] == pytest.approx([e.t for e in entries], abs=1e-9)


def test_the_clock_waits_at_the_held_time_and_runs_on_once_released() -> None:
    clock = ReplayClock()
    held = clock() + 0.001
    clock.hold_at(held)
    stop = threading.Event()
    assert not clock.wait_until(held + 0.05, stop)  # the base clock runs past the hold
    assert clock() == held
    clock.hold_at(held - 1.0)  # a hold never moves back
    assert clock() == held
    clock.release()
    assert clock() > held
