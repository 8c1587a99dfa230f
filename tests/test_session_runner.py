"""The session runner: stamps at arrival, time at a fixed rate never past unhandled input, views at most 30 a
second, the end journaled at the stop time, the session's exceptions surfaced; with a fake clock moved by hand."""

from __future__ import annotations

import itertools
import threading
import time
from dataclasses import dataclass, field

import pytest

from physink_tui.formats.journal.entries import CommandEntry, JournalEntry, JournalHeader, PenEntry, SayEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.session.runner import SessionRunner

HANG_S = 60.0
"""Hang guard: the longest a test waits for the worker (only a stuck one gets there)."""


class FakeClock:
    """A monotonic clock that moves only when told to."""

    def __init__(self, start: float = 0.0) -> None:
        self.now = start

    def __call__(self) -> float:
        return self.now


@dataclass
class FakeSession:
    """Records every call; its view is (entries handled, t); raises on the entry ``fail_on`` names."""

    t: float = 0.0
    calls: list[tuple] = field(default_factory=list)
    handled: list[JournalEntry] = field(default_factory=list)
    fail_on: str | None = None

    def handle(self, entry: JournalEntry) -> None:
        assert entry.t >= self.t, "entries must come in time order"
        self.t = entry.t
        if isinstance(entry, CommandEntry) and entry.name == self.fail_on:
            raise ZeroDivisionError("a bug in the session")
        self.calls.append(("handle", entry))
        self.handled.append(entry)

    def advance(self, t: float) -> None:
        self.calls.append(("advance", t))
        self.t = max(self.t, t)

    def view(self) -> tuple[int, float]:
        return (len(self.handled), self.t)

    def finish(self, t: float | None = None) -> None:
        self.calls.append(("finish", t))

    def advances(self) -> list[float]:
        return [c[1] for c in self.calls if c[0] == "advance"]


def pen(x: float = 0.5, t: float = 99.0) -> PenEntry:
    return PenEntry(t, x, 0.5, 0.5, True, True, False, False, False)


def make(clock: FakeClock | None = None, **kwargs) -> tuple[FakeSession, FakeClock, SessionRunner]:
    clock = clock or FakeClock()
    session = FakeSession()
    return session, clock, SessionRunner(session, clock=clock, **kwargs)


def test_entries_are_stamped_when_they_arrive_in_order_and_never_restamped() -> None:
    session, clock, runner = make()
    clock.now += 0.5
    first = runner.submit(pen(0.1, t=42.0))  # the entry's own time is ignored
    clock.now += 0.25
    second = runner.command("mode", "demo")
    third = runner.say("label ball")  # the same instant: stamps may tie, never go back
    clock.now += 1.0
    runner.step()
    assert [e.t for e in (first, second, third)] == [0.5, 0.75, 0.75]
    assert session.handled == [first, second, third]
    assert second == CommandEntry(0.75, "mode", ("demo",)) and third == SayEntry(0.75, "label ball")
    assert session.calls[-1] == ("advance", 1.75)  # the entries keep their stamps; time moves on after them


def test_stamps_continue_from_the_session_time() -> None:
    clock = FakeClock(1000.0)
    session = FakeSession(t=3.0)
    runner = SessionRunner(session, clock=clock)
    clock.now += 0.5
    assert runner.submit(pen()).t == 3.5


def test_advance_never_passes_an_entry_it_has_not_handled() -> None:
    session, clock, runner = make()
    stamps = []
    for i in range(400):
        clock.now += 0.0013
        if i % 3:
            stamps.append(runner.submit(pen(i / 400)).t)
        if i % 7 == 0:
            runner.step()
    runner.stop()
    handled: set[float] = set()
    for call in session.calls:
        if call[0] == "handle":
            handled.add(call[1].t)
        elif call[0] in ("advance", "finish"):
            assert {s for s in stamps if s <= call[1]} <= handled, f"{call[0]}({call[1]}) before an entry stamped so"
    assert [e.t for e in session.handled] == stamps


def test_advance_never_passes_unhandled_entries_submitted_from_many_threads() -> None:
    session = FakeSession()
    runner = SessionRunner(session, tick_rate=1000.0)
    runner.start()

    def source(n: int) -> None:
        for i in range(300):
            runner.submit(pen((n + i) % 10 / 10))
            if i % 50 == 0:
                time.sleep(0.001)

    threads = [threading.Thread(target=source, args=(n,)) for n in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    runner.stop()
    handled = 0
    stamps = [e.t for e in session.handled]
    assert len(stamps) == 1200 and stamps == sorted(stamps)
    for call in session.calls:
        if call[0] == "handle":
            handled += 1
        elif call[0] == "advance":
            assert all(s > call[1] for s in stamps[handled:]), "advanced past an entry not handled yet"


def test_advance_comes_at_the_fixed_rate() -> None:
    session, clock, runner = make(tick_rate=120.0)
    for _ in range(1000):
        clock.now += 0.001
        runner.step()
    times = session.advances()
    assert 120 <= len(times) <= 121  # ticks 0 to 120 over one second
    gaps = [b - a for a, b in itertools.pairwise(times)]
    assert all(1 / 120 - 0.0011 < g < 1 / 120 + 0.0011 for g in gaps), gaps


def test_views_are_published_at_most_30_times_a_second_and_after_the_last_input() -> None:
    session, clock, runner = make()
    published: list[tuple[float, tuple[int, float]]] = []
    runner.subscribe(lambda view: published.append((clock.now, view)))
    assert runner.latest_view() is None
    for i in range(1000):
        clock.now += 0.001
        if i % 5 == 0 and i < 990:
            runner.submit(pen(i / 1000))
        runner.step()
    times = [t for t, _ in published]
    assert all(b - a >= 1 / 30 - 1e-9 for a, b in itertools.pairwise(times))
    assert 28 <= len(published) <= 30
    assert runner.latest_view() == published[-1][1]
    assert published[-1][1][0] == len(session.handled) == 198  # the last view shows every input


def test_a_command_is_shown_at_once_without_waiting_for_the_next_view_slot() -> None:
    _, clock, runner = make(tick_rate=1.0)
    runner.step()  # t=0: the first view
    clock.now += 0.005
    runner.submit(pen())
    runner.step()  # a pen sample waits for the next slot (1/30 s after the last view)
    assert runner.latest_view() == (0, 0.0)
    clock.now += 0.005
    runner.submit(CommandEntry(0.0, "mode", ("demo",)))
    runner.step()  # a key's reaction does not
    assert runner.latest_view() == (2, 0.01)


def test_a_view_follows_the_last_input_even_between_ticks() -> None:
    session, clock, runner = make(tick_rate=1.0)
    runner.step()  # t=0: tick 0 and the first view
    assert runner.latest_view() == (0, 0.0)
    clock.now += 0.01
    runner.submit(pen())
    runner.step()  # too soon for another view
    assert runner.latest_view() == (0, 0.0)
    clock.now += 0.03
    runner.step()  # no tick is due (1 Hz), but the input is not shown yet
    assert runner.latest_view() == (1, 0.01)
    assert session.advances() == [0.0]


def test_stop_handles_what_arrived_then_finishes_at_the_stop_time() -> None:
    session, clock, runner = make()
    views = []
    runner.subscribe(views.append)
    clock.now += 1.0
    runner.submit(pen())
    clock.now += 1.5
    runner.stop()
    assert [c[0] for c in session.calls] == ["handle", "finish"]
    assert session.calls[-1] == ("finish", 2.5)
    assert views == [(1, 1.0)]  # the last view, after the end
    clock.now += 1.0
    assert runner.submit(pen()) is None  # after the stop nothing is taken: never handled, never journaled
    assert runner.now() == 2.5
    runner.stop()  # idempotent
    assert session.calls[-1] == ("finish", 2.5) and len(session.calls) == 2


def test_an_exception_from_the_session_is_recorded_and_raised_by_stop() -> None:
    errors = []
    session, clock, runner = make(on_error=errors.append)
    session.fail_on = "undo"
    clock.now += 0.2
    runner.command("undo")
    runner.submit(pen())
    runner.step()
    assert isinstance(runner.error, ZeroDivisionError) and errors == [runner.error]
    clock.now += 0.3
    assert runner.submit(pen()) is None  # a failed runner refuses input
    runner.step()  # and calls the session no more
    with pytest.raises(ZeroDivisionError, match="a bug in the session"):
        runner.stop()
    assert session.calls == [("finish", 0.2)]  # only the end, at the failure, so the journal is closed


def test_the_worker_thread_runs_the_session_and_stop_joins_it() -> None:
    session = FakeSession()
    runner = SessionRunner(session)
    runner.start()
    assert runner.running
    with pytest.raises(RuntimeError):
        runner.step()  # the worker is the session's only caller
    stamped = [runner.submit(pen(i / 10)) for i in range(10)]
    deadline = time.monotonic() + HANG_S
    while (runner.latest_view() or (0,))[0] < 10:
        assert time.monotonic() < deadline, "no view with the ten inputs"
        time.sleep(0.005)
    runner.stop()
    assert not runner.running
    assert session.handled == stamped
    assert session.calls[-1][0] == "finish" and session.calls[-1][1] >= stamped[-1].t
    assert session.advances(), "time moved on by itself"


def test_an_exception_on_the_worker_thread_is_raised_by_stop() -> None:
    errors = []
    session = FakeSession(fail_on="clear")
    runner = SessionRunner(session, on_error=errors.append)
    runner.start()
    runner.command("clear")
    deadline = time.monotonic() + HANG_S
    while runner.running:
        assert time.monotonic() < deadline, "the worker went on after the error"
        time.sleep(0.005)
    assert errors and isinstance(errors[0], ZeroDivisionError)
    with pytest.raises(ZeroDivisionError):
        runner.stop()
    assert session.calls[-1][0] == "finish"


def test_a_real_session_journals_every_entry_with_its_stamp_and_the_end(tmp_path) -> None:
    from physink_tui.session.session import Session

    header = JournalHeader(16.0, 10.0, (), {}, 0.05, 0.01)
    session = Session.from_header(header)
    session.journal = JournalWriter.create(tmp_path / "live.physink.jsonl", header)
    clock = FakeClock()
    runner = SessionRunner(session, clock=clock)
    submitted = []

    def stroke(points: list[tuple[float, float]]) -> None:
        for i, (x, y) in enumerate(points):
            down = 0 < i < len(points) - 1
            clock.now += 0.01
            submitted.append(runner.submit(PenEntry(0.0, x, y, 0.6 if down else 0.0, down, True, False, False,
                                                    False)))
            runner.step()

    stroke([(0.2 + 0.6 * i / 40, 0.8) for i in range(41)])  # a line
    clock.now += 0.5
    submitted.append(runner.command("mode", "demo"))
    stroke([(0.5, 0.3 + 0.2 * i / 30) for i in range(31)])
    clock.now += 0.2
    submitted.append(runner.say("label ball"))
    submitted.append(runner.command("undo"))
    runner.step()
    clock.now += 0.4
    runner.stop()
    journal = read_journal(tmp_path / "live.physink.jsonl")
    assert list(journal.entries[:-1]) == submitted
    assert journal.entries[-1] == CommandEntry(clock.now, "end")


def test_a_live_session_on_the_real_clock_and_thread_replays_to_the_same_files(tmp_path) -> None:
    """The runner as the TUI and kiosk will use it: its own thread, the monotonic clock, input from another
    thread while time passes; the journal it leaves replays (with and without ticks) to the same files."""
    import itertools
    import threading
    import time

    from session_outputs import outputs

    from physink_tui.session.replay_driver import replay
    from physink_tui.session.session import Session

    header = JournalHeader(1600.0, 1000.0, (), {}, 0.05, 0.01)
    session = Session.from_header(header)
    session.journal = JournalWriter.create(tmp_path / "live.physink.jsonl", header)
    runner = SessionRunner(session)
    views = []
    runner.subscribe(views.append)
    runner.start()

    def hand() -> None:  # a box, demo mode, the box pushed and let go, a label
        corners = [(0.3, 0.3), (0.5, 0.3), (0.5, 0.45), (0.3, 0.45), (0.3, 0.3)]
        path = [(ax + (bx - ax) * k / 10, ay + (by - ay) * k / 10)
                for (ax, ay), (bx, by) in itertools.pairwise(corners) for k in range(10)]
        for points in ([*path, corners[0]], [(0.4, 0.37 + 0.01 * k) for k in range(20)]):
            runner.submit(PenEntry(0.0, *points[0], 0.0, False, True, False, False, False))
            for x, y in points:
                runner.submit(PenEntry(0.0, x, y, 0.6, True, True, False, False, False))
                time.sleep(0.004)
            runner.submit(PenEntry(0.0, *points[-1], 0.0, False, True, False, False, False))
            if runner.command("mode", "demo") is None:
                return
            time.sleep(0.05)
        runner.say("label block")

    worker = threading.Thread(target=hand)
    worker.start()
    worker.join(timeout=HANG_S)
    assert not worker.is_alive()
    time.sleep(0.3)  # the pushed box slides on while nothing is input (however far it gets, the replay agrees)
    runner.stop()
    assert not session.errors and views and views[-1].mode == "sketch"
    journal = read_journal(tmp_path / "live.physink.jsonl")
    assert journal.entries[-1].name == "end"
    expected = outputs(session)
    assert "timeline.json" in expected and session.scene.labels()
    for ticks in (None, 30, 120):
        assert outputs(replay(Session.from_header(journal.header), journal.entries, ticks)) == expected


def test_an_utterance_is_stamped_when_it_began_unless_something_later_was_stamped() -> None:
    from physink_tui.session.inbox import StampingInbox

    now = [10.0]
    inbox = StampingInbox(lambda: now[0])
    now[0] = 12.0
    said = inbox.put(SayEntry(0.0, "label ball"), at=1.5)
    assert said is not None and said.t == 1.5
    later = inbox.put(CommandEntry(0.0, "play", ()))
    assert later is not None and later.t == 2.0
    again = inbox.put(SayEntry(0.0, "the ball falls"), at=1.8)  # began before the play command was stamped
    assert again is not None and again.t == 2.0
    future = inbox.put(SayEntry(0.0, "label cup"), at=5.0)  # never stamped ahead of the clock
    assert future is not None and future.t == 2.0
