"""Demo mode (first slice of issue 6): grabbing a body, the others reacting, and the causal events recorded."""

from __future__ import annotations

from test_session import box_points, circle_points, pen_header, pen_stroke

from physink_tui.cli import main
from physink_tui.formats.journal.entries import CommandEntry, PenEntry
from physink_tui.input.journal_compose import write_journal
from physink_tui.session.session import Session
from physink_tui.timeline.graph import check_acyclic, descendants
from physink_tui.timeline.narrate import timeline_text


def push_ball_into_box() -> Session:
    entries = pen_stroke(0.0, box_points(0.55, 0.4, 0.65, 0.6))             # a free block (b1)
    entries += pen_stroke(1.0, circle_points(0.2, 0.5, 0.05))                # a ball (b2)
    entries.append(CommandEntry(2.0, "mode", ("demo",)))
    t = 2.5
    entries.append(PenEntry(t, 0.2, 0.5, 0.0, False, True, False, False, False))
    entries += [PenEntry(t + 0.01 * k, 0.2 + 0.004 * k, 0.5, 0.6, True, True, False, False, False)
                for k in range(1, 101)]                                       # push it right into the block
    entries.append(PenEntry(t + 1.02, 0.6, 0.5, 0.0, False, True, False, False, False))
    entries += [PenEntry(t + 1.1 + 0.1 * k, 0.9, 0.9, 0.0, False, False, False, False, False) for k in range(30)]
    entries.append(CommandEntry(t + 5.0, "mode", ("sketch",)))
    session = Session.from_header(pen_header())
    return session.run(sorted(entries, key=lambda e: e.t))


def test_pushing_a_ball_into_a_block_records_start_movement_contact_movement() -> None:
    session = push_ball_into_box()
    timeline = session.timeline
    assert timeline is not None
    check_acyclic(timeline)
    kinds = [(e.type, e.components) for e in timeline.events]
    assert kinds[0] == ("start", ())
    assert kinds[1] == ("movement", ("b2",))
    contact = next(e for e in timeline.events if e.type == "contact")
    assert set(contact.components) == {"b1", "b2"} and kinds[1] != contact
    assert timeline.events[1].id in contact.causes
    block_moves = [e for e in timeline.events if e.type == "movement" and e.components == ("b1",)]
    assert block_moves and contact.id in block_moves[0].causes
    assert dict(contact.sides)["b1"] == "left"
    assert block_moves[0].id in descendants(timeline, timeline.events[0].id)
    assert "CAUSES" in timeline_text(timeline, {"b2": "ball", "b1": "block"})


def test_the_sketch_is_unchanged_by_a_demonstration() -> None:
    session = push_ball_into_box()
    x, y = session.scene.components["b1"].position  # where it was drawn (to a pixel), not where it was pushed
    assert abs(x - 0.6 * 1600) < 1.0 and abs(y - 0.5 * 1000) < 1.0


def test_released_bodies_come_to_rest_and_replay_writes_the_timeline(tmp_path, capsys) -> None:
    session = push_ball_into_box()
    assert all(e.t1 < 4.5 for e in session.timeline.events)  # everything stopped before demo mode ended
    entries = pen_stroke(0.0, box_points(0.55, 0.4, 0.65, 0.6)) + pen_stroke(1.0, circle_points(0.2, 0.5, 0.05))
    entries.append(CommandEntry(2.0, "mode", ("demo",)))
    entries.append(PenEntry(2.5, 0.2, 0.5, 0.0, False, True, False, False, False))
    entries += [PenEntry(2.5 + 0.01 * k, 0.2 + 0.004 * k, 0.5, 0.6, True, True, False, False, False)
                for k in range(1, 101)]
    entries.append(PenEntry(3.52, 0.6, 0.5, 0.0, False, True, False, False, False))
    entries.append(CommandEntry(7.0, "mode", ("sketch",)))
    path = tmp_path / "demo.physink.jsonl"
    write_journal(path, pen_header(), sorted(entries, key=lambda e: e.t))
    for name in ("a", "b"):
        assert main(["replay", str(path), "--out", str(tmp_path / name)]) == 0
    capsys.readouterr()
    text = (tmp_path / "a" / "timeline.txt").read_text()
    assert text.startswith("Movement of b2 CAUSES") and "Contact between" in text
    for file in ("timeline.json", "timeline.txt", "project.json"):
        assert (tmp_path / "a" / file).read_bytes() == (tmp_path / "b" / file).read_bytes()


def block_demo_journal(path):
    """A block labelled "block" and a ball pushed into it in demo mode, as a journal at ``path``."""
    entries = pen_stroke(0.0, box_points(0.55, 0.4, 0.65, 0.6)) + pen_stroke(1.0, circle_points(0.2, 0.5, 0.05))
    entries += [CommandEntry(1.5, "label", ("b1", "block")), CommandEntry(2.0, "mode", ("demo",)),
                PenEntry(2.5, 0.2, 0.5, 0.0, False, True, False, False, False)]
    entries += [PenEntry(2.5 + 0.01 * k, 0.2 + 0.004 * k, 0.5, 0.6, True, True, False, False, False)
                for k in range(1, 101)]
    entries += [PenEntry(3.52, 0.6, 0.5, 0.0, False, True, False, False, False), CommandEntry(7.0, "mode", ("sketch",))]
    write_journal(path, pen_header(), sorted(entries, key=lambda e: e.t))
    return path


def test_physink_timeline_prints_a_project_timeline_in_every_format(tmp_path, capsys) -> None:
    path = block_demo_journal(tmp_path / "demo.physink.jsonl")
    assert main(["replay", str(path), "--out", str(tmp_path / "out")]) == 0
    project = str(tmp_path / "out" / "project.json")
    capsys.readouterr()
    assert main(["timeline", project]) == 0
    text = capsys.readouterr().out
    assert "Movement of b2 CAUSES" in text and "Contact between b2 and block" in text
    assert main(["timeline", project, "--format", "dot"]) == 0
    assert capsys.readouterr().out.startswith("digraph")
    assert main(["timeline", project, "--format", "json"]) == 0
    assert '"type": "contact"' in capsys.readouterr().out


def test_physink_timeline_of_a_project_without_one_is_one_line(tmp_path, capsys) -> None:
    path = tmp_path / "j.physink.jsonl"
    write_journal(path, pen_header(), pen_stroke(0.0, box_points(0.1, 0.1, 0.3, 0.3)))
    assert main(["replay", str(path), "--out", str(tmp_path / "o")]) == 0
    capsys.readouterr()
    assert main(["timeline", str(tmp_path / "o" / "project.json")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "no timeline" in err[0]
