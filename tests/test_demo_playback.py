"""Demo mode through the session: playback (play, pause, stop, seek), what the user is told on bad input,
phrases that label events, and no tunnelling when a body is dragged at absurd speed."""

from __future__ import annotations

from dataclasses import replace

import pytest
from test_session import circle_points, pen_header, pen_stroke

from physink_tui.cli import main
from physink_tui.formats.journal.entries import CommandEntry, PenEntry, SayEntry
from physink_tui.input.journal_compose import write_journal
from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Scene
from physink_tui.session.history import Document
from physink_tui.session.session import Session
from physink_tui.timeline.tape import Tape

W, H = 1600, 1000


def square(w: float, h: float) -> tuple[tuple[float, float], ...]:
    return ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))


def machine() -> Scene:
    """A ball (b1) left of a wall welded to the background (b2), a free block (b3) far right."""
    scene = Scene()
    scene = scene.add(Body("b1", "circle", (), 40.0, (300.0, 500.0), 0.0, MATERIALS["round"], "ball"))
    scene = scene.add(Body("b2", "box", square(20, 600), 0.0, (800.0, 500.0), 0.0, MATERIALS["box"], "wall"))
    scene = scene.add(Joint("j1", "weld", "b2", BACKGROUND, (800.0, 500.0)))
    scene = scene.add(Body("b3", "box", square(100, 100), 0.0, (1200.0, 500.0), 0.0, MATERIALS["box"], "block"))
    return scene


def session_for(scene: Scene) -> Session:
    return Session.from_header(pen_header(), Document(scene))


def feed(session: Session, entries) -> Session:
    for entry in sorted(entries, key=lambda e: e.t):
        session.handle(entry)
    return session


def demonstrated() -> Session:
    """The ball dragged up and back down over 1 s, then released (the wall and block untouched)."""
    session = session_for(machine())
    path = [(300 / W, (500 - 3 * k) / H) for k in range(50)] + [(300 / W, (350 + 3 * k) / H) for k in range(50)]
    return feed(session, [CommandEntry(0.5, "mode", ("demo",)), *pen_stroke(1.0, path),
                          PenEntry(4.0, 0.9, 0.9, 0.0, False, False, False, False, False)])


def test_demo_mode_with_nothing_drawn_says_so() -> None:
    session = feed(session_for(Scene()), [CommandEntry(0.1, "mode", ("demo",))])
    assert session.messages[-1].text == "demo mode with nothing drawn: draw the machine first"


def test_grabbing_a_fixed_body_says_it_cannot_move_and_records_nothing() -> None:
    session = session_for(machine())
    feed(session, [CommandEntry(0.1, "mode", ("demo",)), *pen_stroke(0.5, [(800 / W, 0.5), (800 / W, 0.6)])])
    assert session.messages[-1].text == "wall (b2) is fixed: it cannot be moved in the demonstration"
    assert session.timeline is None


def test_seeking_past_the_end_is_refused_and_names_the_timeline_length() -> None:
    session = demonstrated()
    clock, duration = session.view().clock, session.view().duration
    feed(session, [CommandEntry(5.0, "seek", (duration + 5,))])
    assert session.messages[-1].text == (f"seek {duration + 5:g}: the timeline runs from 0 to {duration:.2f} s; "
                                         f"stayed at {clock:.2f} s")
    assert session.view().clock == clock
    feed(session, [CommandEntry(5.1, "seek", (-1.0,))])
    assert "input refused" in session.messages[-1].text and "a number in [0," in session.messages[-1].text


def test_seek_shows_the_recorded_state_and_play_pause_stop_move_timeline_time() -> None:
    session = demonstrated()
    tape = Tape(session.timeline)
    feed(session, [CommandEntry(5.0, "seek", (0.5,))])
    assert session.view().clock == 0.5
    assert session.view().poses["b1"][:2] == pytest.approx(tape.pose("b1", 0.5)[:2], abs=1e-6)
    feed(session, [CommandEntry(5.5, "play", ()), CommandEntry(5.75, "pause", ())])
    assert session.view().clock == pytest.approx(0.75, abs=0.01)  # a quarter second of input, a quarter of timeline
    assert session.view().poses["b1"][1] == pytest.approx(tape.pose("b1", session.view().clock)[1], abs=1.0)
    paused = session.view().clock
    feed(session, [CommandEntry(7.0, "seek", (paused,))])  # time passes; paused, nothing moves
    assert session.view().clock == paused
    feed(session, [CommandEntry(8.0, "stop", ())])
    view = session.view()
    assert view.clock == 0 and view.poses["b1"][:2] == pytest.approx(tape.pose("b1", 0.0)[:2], abs=1e-6)
    events = session.timeline.events
    feed(session, [CommandEntry(8.5, "play", ()), CommandEntry(12.0, "pause", ())])
    view = session.view()
    assert view.clock == pytest.approx(view.duration, abs=0.01)  # played to the end and stopped there
    assert session.timeline.events == events  # playing back records nothing new


def test_a_phrase_labels_the_nearest_event_and_an_unknown_object_is_told_the_labels() -> None:
    session = demonstrated()
    feed(session, [SayEntry(4.5, "the ball rises"), SayEntry(4.6, "the ball lands in the skillet")])
    first, second = session.messages[-2:]
    movement = next(e for e in session.timeline.events if e.type == "movement")
    assert first.text == f"{movement.id} is now narrated 'the ball rises'" and movement.label == "the ball rises"
    assert "no component is called 'skillet'" in second.text and "ball, block, wall" in second.text


def test_a_body_dragged_at_absurd_speed_does_not_pass_through_a_wall() -> None:
    session = session_for(machine())
    jump = [PenEntry(1.0, 300 / W, 0.5, 0.0, False, True, False, False, False),
            PenEntry(1.01, 300 / W, 0.5, 0.6, True, True, False, False, False)]
    jump += [PenEntry(1.02 + 0.01 * k, 1500 / W, 0.5, 0.6, True, True, False, False, False) for k in range(100)]
    feed(session, [CommandEntry(0.5, "mode", ("demo",)), *jump])
    assert session.view().poses["b1"][0] < 800 - 10 - 40 + 2  # held against the wall's left face, not through it
    contact = next(e for e in session.timeline.events if e.type == "contact")
    assert set(contact.components) == {"b1", "b2"} and dict(contact.sides) == {"b1": "right", "b2": "left"}


def test_demonstrating_again_continues_the_timeline() -> None:
    session = demonstrated()
    feed(session, [CommandEntry(5.0, "mode", ("sketch",))])
    first = session.timeline
    path = [(1200 / W, (500 - 3 * k) / H) for k in range(40)]
    feed(session, [CommandEntry(5.5, "mode", ("demo",)), *pen_stroke(6.0, path),
                   CommandEntry(9.0, "mode", ("sketch",))])
    timeline = session.timeline
    assert timeline.events[: len(first)] == first.events  # the ball's movement is kept
    block = [e for e in timeline.events if e.components[:1] == ("b3",)]
    assert block and block[0].causes == (timeline.events[0].id,)  # the same start event drives it


def vocabulary_journal(tmp_path, vocabulary: str = "", name: str = "plain") -> str:
    """The ball demonstrated, then "the ball careens" said: a verb the default vocabulary lacks."""
    entries = [*pen_stroke(0.0, circle_points(0.2, 0.5, 0.05)), SayEntry(0.6, "label ball"),
               CommandEntry(1.0, "mode", ("demo",))]
    entries += pen_stroke(1.5, [(0.2 + 0.002 * k, 0.5) for k in range(60)])
    entries += [SayEntry(3.0, "the ball careens"), CommandEntry(4.0, "mode", ("sketch",))]
    path = tmp_path / f"{name}.physink.jsonl"
    write_journal(path, replace(pen_header(), vocabulary=vocabulary), entries)
    return str(path)


def test_the_vocabulary_is_extended_by_a_file_kept_in_the_journal_header(tmp_path, capsys) -> None:
    assert main(["replay", vocabulary_journal(tmp_path), "--out", str(tmp_path / "plain")]) == 0
    told = capsys.readouterr().out
    assert "careens" in told and "verb" in told  # told why the phrase was not understood
    assert "careens" not in (tmp_path / "plain" / "timeline.txt").read_text()
    assert main(["replay", vocabulary_journal(tmp_path, "# words of my machine\nverb careens\n", "header"),
                 "--out", str(tmp_path / "header")]) == 0
    assert "the ball careens" in (tmp_path / "header" / "timeline.txt").read_text()
    words = tmp_path / "words.txt"
    words.write_text("verb careens\n")
    assert main(["replay", vocabulary_journal(tmp_path, name="flag"), "--out", str(tmp_path / "flag"),
                 "--vocabulary", str(words)]) == 0
    assert "the ball careens" in (tmp_path / "flag" / "timeline.txt").read_text()
    words.write_text("verb careens\nnoun skillet\n")
    capsys.readouterr()
    assert main(["replay", vocabulary_journal(tmp_path, name="bad"), "--out", str(tmp_path / "bad"),
                 "--vocabulary", str(words)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{words}:2:" in err[0] and "noun skillet" in err[0]
