"""Issue 12: one session for every driver — undo/redo in demo mode, time as input (ticked or not, the same
physics), mode changes ending an adjustment, views, and nothing an input does escaping `handle`."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest
from session_outputs import outputs
from test_session import box_points, circle_points, pen_header, pen_stroke

from physink_tui.cli import main
from physink_tui.formats.journal.entries import CommandEntry, PenEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session


def platform_and_ball() -> list:
    entries = pen_stroke(0.0, box_points(0.1, 0.6, 0.5, 0.66))  # b1, a free platform
    entries += pen_stroke(1.0, circle_points(0.7, 0.3, 0.05))  # b2, a ball
    return entries


def hover(t: float, x: float, y: float) -> PenEntry:
    return PenEntry(t, x, y, 0.0, False, True, False, False, False)


def drag(t0: float, start: tuple[float, float], end: tuple[float, float], n: int = 20, dt: float = 0.01) -> list:
    """Pen down on ``start``, straight to ``end`` in ``n`` samples, lift there (canvas fractions)."""
    (x0, y0), (x1, y1) = start, end
    return pen_stroke(t0, [(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n) for k in range(n + 1)], dt=dt)


def live(entries, path, ticks: float | None = None) -> Session:
    """A live session journaling to ``path``, optionally ticked like a driver."""
    session = Session.from_header(pen_header())
    session.journal = JournalWriter.create(path, pen_header())
    return replay(session, sorted(entries, key=lambda e: e.t), ticks)


def replayed(path, ticks: float | None = None) -> Session:
    journal = read_journal(path)
    return replay(Session.from_header(journal.header), journal.entries, ticks)


def test_undo_demo_redo_then_a_drag_moves_the_redone_body_and_the_journal_replays(tmp_path) -> None:
    entries = platform_and_ball()
    entries += [CommandEntry(2.0, "undo"), CommandEntry(2.1, "mode", ("demo",)), CommandEntry(2.2, "redo")]
    entries += drag(2.5, (0.7, 0.3), (0.7, 0.45))
    session = live(entries, tmp_path / "s.physink.jsonl")
    assert not session.errors
    assert sorted(session.scene.components) == ["b1", "b2"]
    movement = [e for e in session.timeline.events if e.type == "movement"]
    assert movement and movement[0].components[0] == "b2"  # the redone ball is in the demonstration's world
    again = replayed(tmp_path / "s.physink.jsonl")
    assert outputs(again) == outputs(session)


def test_undo_in_demo_mode_takes_back_the_demonstration(tmp_path) -> None:
    entries = [*platform_and_ball(), CommandEntry(2.0, "mode", ("demo",))]
    entries += drag(2.5, (0.7, 0.3), (0.7, 0.45))
    entries += [CommandEntry(6.0, "undo")]
    session = Session.from_header(pen_header())
    for entry in sorted(entries, key=lambda e: e.t):
        session.handle(entry)
    assert session.timeline is None and session.mode == "demo"  # demonstrating again, from the document
    assert session.view().clock == 0
    assert session.view().poses["b2"][:2] == pytest.approx(session.scene.components["b2"].position)
    session.handle(CommandEntry(6.5, "redo"))
    assert any(e.type == "movement" for e in session.timeline.events) and session.mode == "demo"


@pytest.mark.parametrize("hz", [10, 30, 120])
def test_a_flick_then_silence_ends_the_same_whether_the_clock_ticks_or_not(tmp_path, hz: float) -> None:
    entries = [*platform_and_ball(), CommandEntry(2.0, "mode", ("demo",))]
    entries += drag(2.5, (0.7, 0.3), (0.9, 0.3), n=5)  # a fast flick to the right, let go mid-flight
    entries += [hover(8.0, 0.05, 0.05), CommandEntry(8.1, "mode", ("sketch",))]
    plain = live(entries, tmp_path / "plain.physink.jsonl")
    ticked = live(entries, tmp_path / "ticked.physink.jsonl", ticks=hz)
    assert outputs(ticked) == outputs(plain)
    (movement,) = [e for e in plain.timeline.events if e.type == "movement"]
    assert movement.t1 > 2.0  # the ball coasts until it comes to rest, not until a cap on steps per input
    assert outputs(replayed(tmp_path / "ticked.physink.jsonl")) == outputs(plain)


def test_changing_mode_during_an_adjustment_puts_the_body_down(tmp_path) -> None:
    entries = platform_and_ball()
    entries.append(hover(2.0, 0.7, 0.3))
    entries += [PenEntry(2.0 + 0.01 * k, 0.7, 0.3, 0.5, True, True, False, False, False) for k in range(1, 51)]
    entries += [PenEntry(2.5 + 0.01 * k, 0.7, 0.3 + 0.002 * k, 0.5, True, True, False, False, False)
                for k in range(1, 41)]
    entries.append(CommandEntry(3.0, "mode", ("demo",)))  # the pen is still down
    session = Session.from_header(pen_header())
    for entry in sorted(entries, key=lambda e: e.t):
        session.handle(entry)
        if entry.t == 2.9:
            assert session.mode == "adjust"
    assert session.mode == "demo"
    ball = session.scene.components["b2"]
    assert ball.position[1] > 0.3 * 1000 + 40  # moved down with the pen and put down there
    session.handle(CommandEntry(3.5, "undo"))  # the adjustment was one action
    assert session.scene.components["b2"].position[1] == pytest.approx(300, abs=2)


def test_a_view_is_an_immutable_snapshot_of_ink_pending_strokes_and_poses() -> None:
    session = Session.from_header(pen_header())
    stroke = pen_stroke(0.0, box_points(0.1, 0.6, 0.5, 0.66))
    for entry in stroke[:20]:
        session.handle(entry)
    view = session.view()
    assert view.mode == "sketch" and len(view.ink) == 1 and len(view.ink[0]) == 19
    with pytest.raises(dataclasses.FrozenInstanceError):
        view.mode = "demo"  # type: ignore[misc]
    with pytest.raises(TypeError):
        view.poses["b1"] = (0, 0, 0)  # type: ignore[index]
    for entry in stroke[20:]:
        session.handle(entry)
    for entry in pen_stroke(1.0, [(0.8, 0.1 + 0.005 * k) for k in range(10)]):  # a short line: half an X?
        session.handle(entry)
    view = session.view()
    assert view.ink == () and len(view.pending) == 1 and list(view.poses) == ["b1"]
    assert view.can_undo and not view.can_redo and view.revision > 0
    session.advance(3.0)  # no second arm came: the line is taken on its own
    assert session.view().pending == () and session.view().revision > view.revision


def test_commands_that_make_no_sense_in_the_mode_are_told_not_raised() -> None:
    session = Session.from_header(pen_header())
    for k, entry in enumerate([CommandEntry(0.1, "seek", (2.0,)), CommandEntry(0.2, "play"),
                               CommandEntry(0.3, "undo"), CommandEntry(0.4, "redo"),
                               CommandEntry(0.5, "label", ("selected", "ball")), CommandEntry(0.6, "simulate")]):
        session.handle(entry)
        assert len(session.messages) == k + 1
    assert not session.errors


def test_a_loaded_project_becomes_the_document_and_replays_from_the_journal_alone(tmp_path) -> None:
    drawn = live([*platform_and_ball(), CommandEntry(2.0, "label", ("b2", "ball"))], tmp_path / "a.physink.jsonl")
    project = json.loads(outputs(drawn)["project.json"])
    entries = [CommandEntry(0.5, "load", ("machine.physink.json",), project=project),
               CommandEntry(2.0, "undo"), CommandEntry(2.5, "redo"), *drag(3.0, (0.3, 0.63), (0.3, 0.5))]
    session = live(entries, tmp_path / "b.physink.jsonl")
    assert session.scene.labels() == {"b2": "ball"} and sorted(session.scene.components) == ["b1", "b2", "b3"]
    assert session.messages[0].text == "loaded machine.physink.json: 2 components" and not session.errors
    assert outputs(replayed(tmp_path / "b.physink.jsonl")) == outputs(session)


def test_an_entry_the_journal_cannot_hold_is_refused_before_it_acts(tmp_path) -> None:
    session = Session.from_header(pen_header())
    session.journal = JournalWriter.create(tmp_path / "s.physink.jsonl", pen_header())
    session.handle(CommandEntry(1.0, "mode", ("demo",)))
    session.handle(PenEntry(0.5, 0.5, 0.5, 0.0, False, True, False, False, False))  # time going backwards
    assert session.mode == "demo" and "input refused" in session.messages[-1].text
    session.handle(CommandEntry(2.0, "mode", ("sketch",)))  # the journal goes on
    session.finish()
    names = [getattr(e, "name", None) for e in read_journal(tmp_path / "s.physink.jsonl").entries]
    assert names == ["mode", "mode", "end"]


def test_physink_replay_with_ticks_writes_the_same_files_and_lists_the_dwell(tmp_path, capsys) -> None:
    entries = [*platform_and_ball(), hover(2.0, 0.7, 0.3)]
    entries += [PenEntry(2.0 + 0.01 * k, 0.7, 0.3, 0.5, True, True, False, False, False) for k in range(1, 51)]
    entries += drag(2.6, (0.7, 0.3), (0.6, 0.4))[1:]
    entries += [CommandEntry(4.0, "mode", ("demo",)), *drag(4.5, (0.6, 0.4), (0.8, 0.4), n=5)]
    live(entries, tmp_path / "s.physink.jsonl")
    folders = {}
    for ticks in (None, "30", "120"):
        folders[ticks] = tmp_path / f"out-{ticks}"
        extra = ["--ticks", ticks] if ticks else []
        assert main(["replay", str(tmp_path / "s.physink.jsonl"), "--out", str(folders[ticks]), *extra]) == 0
    names = sorted(p.name for p in folders[None].iterdir())
    assert names == ["gestures.jsonl", "project.json", "timeline.json", "timeline.txt"]
    for ticks in ("30", "120"):
        for name in names:
            assert (folders[ticks] / name).read_bytes() == (folders[None] / name).read_bytes(), (ticks, name)
    assert '"gesture":"dwell"' in (folders[None] / "gestures.jsonl").read_text()
    assert main(["replay", str(tmp_path / "s.physink.jsonl"), "--out", str(tmp_path / "x"), "--ticks", "0"]) == 2


def test_views_taken_during_a_demonstration_change_nothing_it_records() -> None:
    """A live driver looks at the session 30 times a second, a replay never: the egg cracker's timeline is the
    same either way, and grabbing the egg while it still moves continues its movement (no re-demonstration)."""
    journal = read_journal(Path(__file__).parent / "journals" / "egg_cracker.physink.jsonl")
    watched = Session.from_header(journal.header)
    next_view = 0.0
    for entry in journal.entries:
        watched.handle(entry)
        if entry.t >= next_view:
            watched.view()
            next_view = entry.t + 1 / 30
    watched.finish()
    alone = replay(Session.from_header(journal.header), journal.entries)
    assert outputs(watched) == outputs(alone)
    assert not [m for m in watched.messages if "re-demonstrating" in m.text]
