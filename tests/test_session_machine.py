"""Issue 12, done-when: random sequences of strokes, taps, drags, dwells, mode changes, undo/redo/clear, seeks,
labels, speech and silences through a live session that journals and is ticked at random: nothing escapes
`handle`, and the journal replays to byte-identical outputs with and without ticks at 10, 30 and 120 Hz."""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, precondition, rule
from session_outputs import outputs
from test_session import box_points, circle_points, pen_header

from physink_tui.formats.journal.entries import CommandEntry, JournalEntry, PenEntry, SayEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session

SAMPLE = 0.01
where = st.floats(0.05, 0.95)
size = st.floats(0.02, 0.25)


def sample(t: float, x: float, y: float, tip: bool, eraser: bool = False) -> PenEntry:
    x, y = min(max(x, 0.0), 1.0), min(max(y, 0.0), 1.0)
    return PenEntry(round(t, 6), x, y, 0.6 if tip else 0.0, tip, True, eraser, False, False)


class SessionMachine(RuleBasedStateMachine):
    """One live session; every rule is something a user does (or time passing)."""

    def __init__(self) -> None:
        super().__init__()
        self.folder = Path(tempfile.mkdtemp(prefix="physink-machine-"))
        self.path = self.folder / "live.physink.jsonl"
        self.session = Session.from_header(pen_header())
        self.session.journal = JournalWriter.create(self.path, pen_header())
        self.t = 0.0

    # -- feeding -----------------------------------------------------------------------------------------------

    def feed(self, entries: list[JournalEntry], gap: float = 0.3) -> None:
        for entry in entries:
            self.session.handle(entry)
        self.t = entries[-1].t + gap

    def stroke(self, points: list[tuple[float, float]], eraser: bool = False, hold: float = 0.0) -> None:
        t = self.t
        entries = [sample(t, *points[0], tip=False, eraser=eraser)]
        for k in range(1, int(hold / SAMPLE) + 1):  # held still on the first point (a dwell)
            entries.append(sample(t + k * SAMPLE, *points[0], tip=True, eraser=eraser))
        t = entries[-1].t
        entries += [sample(t + (i + 1) * SAMPLE, x, y, True, eraser) for i, (x, y) in enumerate(points)]
        entries.append(sample(entries[-1].t + SAMPLE, *points[-1], tip=False, eraser=eraser))
        self.feed(entries)

    # -- what a user does ----------------------------------------------------------------------------------------

    @rule(x=where, y=where, w=size, h=size)
    def draw_box(self, x: float, y: float, w: float, h: float) -> None:
        self.stroke(box_points(x, y, min(x + w, 0.99), min(y + h, 0.99), n=8))

    @rule(x=where, y=where, r=st.floats(0.01, 0.12))
    def draw_circle(self, x: float, y: float, r: float) -> None:
        self.stroke(circle_points(x, y, r, n=24))

    @rule(x=where, y=where, dx=st.floats(-0.3, 0.3), dy=st.floats(-0.3, 0.3))
    def draw_line_or_drag(self, x: float, y: float, dx: float, dy: float) -> None:
        self.stroke([(min(max(x + dx * k / 12, 0), 1), min(max(y + dy * k / 12, 0), 1)) for k in range(13)])

    @rule(x=where, y=where, arm=st.floats(0.01, 0.04), gap=st.floats(0.05, 2.0))
    def draw_x(self, x: float, y: float, arm: float, gap: float) -> None:
        self.stroke([(x - arm + 2 * arm * k / 8, y - arm + 2 * arm * k / 8) for k in range(9)])
        self.t += gap - 0.3
        self.stroke([(x + arm - 2 * arm * k / 8, y - arm + 2 * arm * k / 8) for k in range(9)])

    @rule(x=where, y=where)
    def tap(self, x: float, y: float) -> None:
        self.feed([sample(self.t, x, y, False), sample(self.t + 0.02, x, y, True),
                   sample(self.t + 0.05, x, y, False)])

    @rule(x=where, y=where, dx=st.floats(-0.2, 0.2), dy=st.floats(-0.2, 0.2))
    def dwell_and_drag(self, x: float, y: float, dx: float, dy: float) -> None:
        self.stroke([(x + dx * k / 10, y + dy * k / 10) for k in range(11)], hold=0.5)

    @rule(x=where, y=where, dx=st.floats(-0.2, 0.2))
    def erase(self, x: float, y: float, dx: float) -> None:
        self.stroke([(x + dx * k / 6, y) for k in range(7)], eraser=True)

    @rule(mode=st.sampled_from(["sketch", "demo"]))
    def change_mode(self, mode: str) -> None:
        self.feed([CommandEntry(self.t, "mode", (mode,))], gap=0.1)

    @rule(name=st.sampled_from(["undo", "redo", "clear", "play", "pause", "stop"]))
    def command(self, name: str) -> None:
        self.feed([CommandEntry(self.t, name, ())], gap=0.1)

    @rule(args=st.sampled_from([(), (3,), (1, 2)]))
    def simulate(self, args: tuple[int, ...]) -> None:
        """SIMULATE with few rollouts (`Session.simulation_budget` stands in for a missing budget; the journal
        holds the one used)."""
        self.session.simulation_budget = 2
        self.feed([CommandEntry(self.t, "simulate", args)], gap=0.1)

    @rule(t=st.floats(0.0, 4.0))
    def seek(self, t: float) -> None:
        self.feed([CommandEntry(self.t, "seek", (t,))], gap=0.1)

    @rule(who=st.sampled_from(["last", "selected", "b1", "b2", "b3", "j1"]),
          text=st.sampled_from(["ball", "egg", "frying pan", "lever"]))
    def label(self, who: str, text: str) -> None:
        self.feed([CommandEntry(self.t, "label", (who, text))], gap=0.1)

    @rule(text=st.sampled_from(["label ball", "the ball hits the lever", "the egg lands in the frying pan", "um"]))
    def say(self, text: str) -> None:
        self.feed([SayEntry(self.t, text)], gap=0.1)

    @rule(seconds=st.floats(0.01, 4.0), pieces=st.integers(1, 40))
    def time_passes(self, seconds: float, pieces: int) -> None:
        """A live driver's clock: advances the session without input, in pieces of any size."""
        for k in range(1, pieces + 1):
            self.session.advance(self.t + seconds * k / pieces)
        self.t += seconds

    @rule(kind=st.sampled_from(["mode", "seek", "label", "pen", "hid", "unknown", "past"]))
    def malformed_input(self, kind: str) -> None:
        """Input a live source could get wrong: refused with a message, never acted on nor journaled."""
        from physink_tui.formats.journal.entries import HidEntry

        t = self.t
        entry = {"mode": CommandEntry(t, "mode", ()), "seek": CommandEntry(t, "seek", ("soon",)),
                 "label": CommandEntry(t, "label", ("b1",)), "pen": PenEntry(t, 1.5, 0.5, 0.0, False, True,
                                                                                False, False, False),
                 "hid": HidEntry(t, "tablet9", b"\x02\x00"), "unknown": CommandEntry(t, "explode", ()),
                 "past": CommandEntry(max(t - 5.0, 0.0) if t > 5.0 else -1.0, "undo", ())}[kind]
        told = len(self.session.messages)
        self.session.handle(entry)
        assert len(self.session.messages) == told + 1 and "refused" in self.session.messages[-1].text
        self.t += 0.1

    @precondition(lambda self: self.session.mode == "demo")
    @rule(x=where, y=where, dx=st.floats(-0.3, 0.3), dy=st.floats(-0.3, 0.3))
    def flick(self, x: float, y: float, dx: float, dy: float) -> None:
        self.stroke([(min(max(x + dx * k / 4, 0), 1), min(max(y + dy * k / 4, 0), 1)) for k in range(5)])

    # -- what must hold ------------------------------------------------------------------------------------------

    @invariant()
    def answers(self) -> None:
        view = self.session.view()
        assert not self.session.errors
        assert all(math.isfinite(c) for pose in view.poses.values() for c in pose)

    def teardown(self) -> None:
        session = self.session
        session.finish(self.t)
        expected = outputs(session)
        journal = read_journal(self.path)
        assert journal.entries[-1] == CommandEntry(self.t, "end", ())
        for ticks in (None, 10, 30, 120):
            again = replay(Session.from_header(journal.header), journal.entries, ticks)
            assert outputs(again) == expected, f"replayed with ticks={ticks}"
            told = [m.text for m in session.messages if not m.text.startswith("input refused")]
            assert [m.text for m in again.messages] == told  # refused input never reached the journal


SessionMachine.TestCase.settings = settings(max_examples=25, stateful_step_count=18, deadline=None,
                                            derandomize=True,
                                            suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
test_any_sequence_of_inputs_replays_to_the_same_outputs = SessionMachine.TestCase
