"""A replay paced in real time stamps its recorded times however late its inputs are taken (`ReplayClock`): a
capture played into a consumer that stalls, and the clock held at each input until it is in."""

from __future__ import annotations

import queue
import threading
import time
from pathlib import Path

import pytest

from physink_tui.input.captures.capture import Capture
from physink_tui.input.replay_clock import ReplayClock
from physink_tui.input.scripted_sources import CaptureReplaySource
from physink_tui.input.sources import RawReport, SourceEnded

CAPTURE = Path(__file__).parent / "recorded_hid" / "uclogic-v1-strokes.hid"
HANG_GUARD = 60.0


class Stalling(queue.Queue):
    """Takes each report when it comes (reading the clock, as a runner stamps it), then stalls the replay's thread
    as a loaded machine would: far longer than the reports' spacing at the replay's speed."""

    def __init__(self, clock: ReplayClock, stall: float) -> None:
        super().__init__()
        self.clock, self.stall = clock, stall
        self.stamps: list[float] = []
        self.ended = threading.Event()

    def put(self, item, block=True, timeout=None) -> None:
        if isinstance(item, SourceEnded):
            self.ended.set()
            return
        assert isinstance(item, RawReport)
        self.stamps.append(self.clock())
        time.sleep(self.stall)


def test_each_report_is_stamped_with_its_own_time_however_long_the_consumer_stalls() -> None:
    capture = Capture.from_file(CAPTURE)
    events = capture.events_for(0)[:30]
    capture = Capture(capture.devices, tuple(events))
    clock = ReplayClock(speed=50.0)
    taken = Stalling(clock, stall=0.02)  # 1 s of input at 50x, each report 20 ms late on the one before
    source = CaptureReplaySource(capture, realtime=True, speed=50.0, clock=clock)
    source.start(taken)
    assert taken.ended.wait(HANG_GUARD)
    source.stop()
    origin = taken.stamps[0]
    assert [s - origin for s in taken.stamps] == pytest.approx([e.t - events[0].t for e in events], abs=1e-9)


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
    with pytest.raises(ValueError, match="speed"):
        ReplayClock(speed=0.0)
