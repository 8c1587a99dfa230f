"""The frame pacer: every view drawn while the UI keeps up; while views reach it late, one every interval, the
others passed over for a catch-up."""

from __future__ import annotations

import pytest

from physink_tui.tui.pacing import FramePacer


def test_views_taken_in_time_are_all_drawn() -> None:
    pacer = FramePacer(late=0.025, slow_interval=0.05)
    assert all(pacer.draw_now(posted=k / 60, now=k / 60 + 0.01) for k in range(100))
    assert pacer.passed == 0


def test_late_views_are_drawn_one_an_interval_and_the_passed_one_caught_up() -> None:
    pacer = FramePacer(late=0.025, slow_interval=0.05)
    assert pacer.draw_now(posted=0.0, now=0.04)  # late, but nothing drawn for longer than the interval
    assert not pacer.draw_now(posted=0.03, now=0.07)  # late, 30 ms after the last frame
    assert pacer.catch_up_in(0.07) == pytest.approx(0.02)
    pacer.drew(0.09)
    assert not pacer.draw_now(posted=0.08, now=0.12)
    assert pacer.draw_now(posted=0.10, now=0.145)  # late, and the interval is up
    assert pacer.draw_now(posted=0.146, now=0.15)  # in time again: drawn at once
    assert pacer.passed == 2


def test_bad_settings_are_named() -> None:
    with pytest.raises(ValueError, match="late and slow_interval must be > 0"):
        FramePacer(late=0.0)
