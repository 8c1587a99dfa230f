"""The session over journals: strokes become a scene, labels, taps, undo/redo, clear, eraser, determinism."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import pytest

from physink_tui.cli import main
from physink_tui.demo_data import drawing_capture
from physink_tui.formats.journal.entries import CommandEntry, JournalHeader, PenEntry, SayEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.input.journal_compose import capture_entries, header_for_capture, write_journal
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.scene.components import BACKGROUND, Body, Joint, Rope
from physink_tui.session.session import Session

MAPPING = TabletMapping(canvas_width=1600, canvas_height=1000, tablet_width=1.6, tablet_height=1.0)


def egg_cracker_journal(path: Path, extra=()) -> Path:
    capture = drawing_capture()
    write_journal(path, header_for_capture(capture, MAPPING), capture_entries(capture), list(extra))
    return path


def pen_header() -> JournalHeader:
    return JournalHeader(1600, 1000, (), {}, 0.05, 0.01)


def pen_stroke(t0: float, points: list[tuple[float, float]], eraser: bool = False, dt: float = 0.01) -> list[PenEntry]:
    """A stroke as mouse/scripted `pen` lines (canvas fractions): hover, touch along the points, lift."""
    out = [PenEntry(t0, *points[0], 0.0, False, True, eraser, False, False)]
    for i, (x, y) in enumerate(points, 1):
        out.append(PenEntry(t0 + i * dt, x, y, 0.6, True, True, eraser, False, False))
    out.append(PenEntry(t0 + (len(points) + 1) * dt, *points[-1], 0.0, False, True, eraser, False, False))
    return out


def box_points(x0: float, y0: float, x1: float, y1: float, n: int = 15) -> list[tuple[float, float]]:
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    pts = []
    for (ax, ay), (bx, by) in itertools.pairwise(corners):
        pts += [(ax + (bx - ax) * k / n, ay + (by - ay) * k / n) for k in range(n)]
    return [*pts, corners[0]]


def circle_points(cx: float, cy: float, r: float, n: int = 40) -> list[tuple[float, float]]:
    angles = [2 * math.pi * k / n for k in range(n + 1)]
    return [(cx + r / 1.6 * math.cos(a), cy + r * math.sin(a)) for a in angles]


def run(entries, header=None) -> Session:
    return Session.from_header(header or pen_header()).run(sorted(entries, key=lambda e: e.t))


def test_the_egg_cracker_drawing_becomes_its_machine(tmp_path) -> None:
    journal = read_journal(egg_cracker_journal(tmp_path / "egg.physink.jsonl", [SayEntry(5.3, "label ball")]))
    session = Session.from_header(journal.header).run(journal.entries)
    scene = session.scene
    bodies = {b.id: b for b in scene.bodies()}
    joints = [c for c in scene.components.values() if isinstance(c, Joint)]
    assert [b.shape for b in bodies.values()] == ["polyline", "circle", "box", "circle", "polyline"]
    ramp, ball, lever = bodies["b1"], bodies["b2"], bodies["b3"]
    assert ball.label == "ball"
    assert {(j.kind, j.a, j.b) for j in joints} == {("weld", ramp.id, BACKGROUND), ("pivot", lever.id, BACKGROUND),
                                                    ("weld", "b5", BACKGROUND)}
    assert scene.is_fixed(ramp.id) and not scene.is_fixed(ball.id)


def test_replaying_the_same_journal_twice_gives_identical_project_files(tmp_path, capsys) -> None:
    journal = egg_cracker_journal(tmp_path / "egg.physink.jsonl")
    for name in ("a", "b"):
        assert main(["replay", str(journal), "--out", str(tmp_path / name)]) == 0
    capsys.readouterr()
    first = (tmp_path / "a" / "project.json").read_bytes()
    assert first == (tmp_path / "b" / "project.json").read_bytes()
    assert b'"physink-project"' in first


def test_undo_redo_and_clear() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.3, 0.3)) + pen_stroke(1.0, circle_points(0.6, 0.5, 0.08))
    entries += [CommandEntry(2.0, "undo"), CommandEntry(2.1, "redo"), CommandEntry(2.2, "clear"),
                CommandEntry(2.3, "undo"), CommandEntry(2.4, "undo")]
    session = Session.from_header(pen_header())
    states = []
    for e in sorted(entries, key=lambda e: e.t):
        session.handle(e)
        if isinstance(e, CommandEntry):
            states.append(sorted(session.scene.components))
    assert states == [["b1"], ["b1", "b2"], [], ["b1", "b2"], ["b1"]]


def test_labels_by_command_and_speech_and_what_the_user_is_told() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.3, 0.3)) + pen_stroke(1.0, circle_points(0.6, 0.5, 0.08))
    entries += [SayEntry(1.8, "label ball"), CommandEntry(2.0, "label", ("b1", "shelf")),
                CommandEntry(2.1, "label", ("b9", "ghost"))]
    # a tap on the box selects it; the next label goes to it
    entries += [PenEntry(3.0, 0.2, 0.2, 0.0, False, True, False, False, False),
                PenEntry(3.01, 0.2, 0.2, 0.5, True, True, False, False, False),
                PenEntry(3.05, 0.2, 0.2, 0.0, False, True, False, False, False),
                SayEntry(3.2, "label crate")]
    session = run(entries)
    assert session.scene.components["b2"].label == "ball"
    assert session.scene.components["b1"].label == "crate"
    told = " | ".join(m.text for m in session.messages)
    assert "no component 'b9'" in told and "b1, b2" in told and "selected" in told


def test_label_with_nothing_to_label_is_told() -> None:
    session = run([SayEntry(0.5, "label ball")])
    assert not session.scene.components and "tap or hover over it first" in session.messages[-1].text


def test_an_eraser_stroke_removes_the_body_it_crosses() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.3, 0.3))
    entries += pen_stroke(1.0, [(0.15 + 0.01 * k, 0.2) for k in range(12)], eraser=True)
    session = run(entries)
    assert not session.scene.components


def test_two_short_lines_in_a_row_make_an_x_and_a_lone_one_waits_then_is_a_line() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.5, 0.5))
    entries += pen_stroke(1.0, [(0.28 + 0.004 * k, 0.28 + 0.004 * k) for k in range(11)])
    entries += pen_stroke(1.5, [(0.32 - 0.004 * k, 0.28 + 0.004 * k) for k in range(11)])
    entries += pen_stroke(3.0, [(0.8 + 0.004 * k, 0.8) for k in range(11)])  # alone, far away
    session = run(entries)
    kinds = [type(c).__name__ for c in session.scene.components.values()]
    assert kinds == ["Body", "Joint", "Body"]
    weld = session.scene.components["j1"]
    assert (weld.kind, weld.a, weld.b) == ("weld", "b1", BACKGROUND)


def test_save_is_journaled_and_changes_nothing() -> None:
    """``save PATH``: the driver (the TUI) writes the file, so a replay writes none and the session tells nothing."""
    session = run([CommandEntry(0.1, "save", ("machine.physink.json",))])
    assert session.messages == [] and not session.scene.components and not session.history.can_undo


@pytest.mark.parametrize("command", ["play", "pause", "stop", "seek"])
def test_playback_while_sketching_says_it_needs_demo_mode(command: str) -> None:
    args = (1.0,) if command == "seek" else ()
    session = run([CommandEntry(0.1, command, args)])
    assert session.messages[-1].text.startswith(f"{command}: playback works in demo mode")


def test_a_curve_from_a_peg_is_a_rope_attached_to_it() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.15, 0.15))
    entries += pen_stroke(1.0, [(0.125 + 0.3 * u, 0.125 + 0.3 * u * u) for u in (k / 30 for k in range(31))])
    session = run(entries)
    rope = next(c for c in session.scene.components.values() if isinstance(c, Rope))
    assert rope.start_body == "b1" and rope.end_body is None
    assert isinstance(session.scene.components["b1"], Body)


def test_dwell_then_drag_moves_a_body_and_leaves_the_others() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.6, 0.3, 0.7))            # a platform
    entries += pen_stroke(1.0, circle_points(0.6, 0.3, 0.05))            # a ball
    # dwell on the ball's centre for half a second, then drag it over the platform
    t = 2.0
    entries.append(PenEntry(t, 0.6, 0.3, 0.0, False, True, False, False, False))
    hold = [PenEntry(t + 0.01 * k, 0.6, 0.3, 0.5, True, True, False, False, False) for k in range(1, 51)]
    drag = [PenEntry(t + 0.5 + 0.01 * k, 0.6 - 0.004 * k, 0.3 + 0.002 * k, 0.5, True, True, False, False, False)
            for k in range(1, 101)]
    entries += hold + drag
    entries.append(PenEntry(t + 1.6, 0.2, 0.5, 0.0, False, True, False, False, False))
    session = run(entries)
    ball, platform = session.scene.components["b2"], session.scene.components["b1"]
    assert ball.position[0] == pytest.approx(0.2 * 1600, abs=40)
    assert ball.position[1] == pytest.approx(0.5 * 1000, abs=40)
    assert platform.position == pytest.approx(((0.1 + 0.3) / 2 * 1600, (0.6 + 0.7) / 2 * 1000), abs=1.0)
    assert "moving b2" in " | ".join(m.text for m in session.messages)
    session.handle(CommandEntry(t + 2.0, "undo"))
    assert session.scene.components["b2"].position == pytest.approx((0.6 * 1600, 0.3 * 1000), abs=2.0)


def test_dragging_a_ball_into_a_platform_ends_flush_not_inside() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.6, 0.5, 0.7))
    entries += pen_stroke(1.0, circle_points(0.8, 0.3, 0.05))
    t = 2.0
    entries.append(PenEntry(t, 0.8, 0.3, 0.0, False, True, False, False, False))
    entries += [PenEntry(t + 0.01 * k, 0.8, 0.3, 0.5, True, True, False, False, False) for k in range(1, 51)]
    # pull it down into the middle of the platform
    entries += [PenEntry(t + 0.5 + 0.01 * k, 0.8 - 0.005 * k, 0.3 + 0.0035 * k, 0.5, True, True, False, False, False)
                for k in range(1, 101)]
    entries.append(PenEntry(t + 1.6, 0.3, 0.65, 0.0, False, True, False, False, False))
    session = run(entries)
    ball = session.scene.components["b2"]
    radius = ball.radius
    top_of_platform = 0.6 * 1000
    assert ball.position[1] <= top_of_platform - radius + 3  # resting on top, not sunk into it


def test_a_body_drawn_into_another_is_pushed_clear() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.5, 0.5, 0.7))                # a block
    entries += pen_stroke(1.0, circle_points(0.3, 0.47, 0.06))                # a ball drawn half into it
    session = run(entries)
    ball = session.scene.components["b2"]
    block_top = 0.5 * 1000
    assert ball.position[1] + ball.radius <= block_top + 3
    assert session.scene.components["b1"].position == pytest.approx((0.3 * 1600, 0.6 * 1000), abs=1.0)
    assert "pushed it clear" in session.messages[-1].text


def test_a_pin_in_a_welded_body_then_a_body_drawn_over_it_does_not_break_the_world() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.5, 0.4, 0.7))
    entries += pen_stroke(1.0, [(0.23 + 0.004 * k, 0.58 + 0.004 * k) for k in range(11)])
    entries += pen_stroke(1.5, [(0.27 - 0.004 * k, 0.58 + 0.004 * k) for k in range(11)])
    entries += pen_stroke(3.5, circle_points(0.3, 0.65, 0.015))               # a pin in the welded block
    entries += pen_stroke(5.0, box_points(0.3, 0.45, 0.5, 0.55))              # a box drawn half into it
    session = run(entries)                                                     # must not raise
    kinds = sorted((c.kind, c.a, c.b) for c in session.scene.components.values() if isinstance(c, Joint))
    assert kinds == [("pivot", "b1", BACKGROUND), ("weld", "b1", BACKGROUND)]
    assert "pushed it clear" in session.messages[-1].text


def test_a_live_session_journals_what_it_consumes_and_the_journal_replays_to_the_same_scene(tmp_path) -> None:
    from physink_tui.formats.journal.writer import JournalWriter

    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.3, 0.3)) + pen_stroke(1.0, circle_points(0.6, 0.5, 0.08))
    entries += [SayEntry(1.9, "label ball"), CommandEntry(2.0, "undo"), CommandEntry(2.1, "redo")]
    path = tmp_path / "live.physink.jsonl"
    live = Session.from_header(pen_header())
    live.journal = JournalWriter.create(path, pen_header())
    live.run(entries)
    journal = read_journal(path)
    assert list(journal.entries) == [*entries, CommandEntry(2.1, "end")]  # what it consumed, then its end
    again = Session.from_header(journal.header).run(journal.entries)
    assert again.scene == live.scene and again.scene.components["b2"].label == "ball"


def test_erasing_is_undone_with_its_joints() -> None:
    entries = pen_stroke(0.0, box_points(0.1, 0.1, 0.5, 0.5))
    entries += pen_stroke(1.0, circle_points(0.3, 0.3, 0.02))                   # a pin
    entries += pen_stroke(2.0, [(0.3, 0.05 + 0.05 * k) for k in range(11)])     # a line through the block
    session = run(entries)
    assert not session.scene.components
    session.handle(CommandEntry(4.0, "undo"))
    assert sorted(session.scene.components) == ["b1", "j1"]


def test_a_small_circle_outside_every_body_becomes_one_and_the_user_is_told() -> None:
    session = run(pen_stroke(0.0, circle_points(0.5, 0.5, 0.012)))
    assert session.scene.components["b1"].shape == "circle"
    assert "outside every body" in session.messages[-1].text


def test_grabbed_near_an_edge_a_body_turns_as_it_is_dragged() -> None:
    entries = pen_stroke(0.0, box_points(0.3, 0.45, 0.7, 0.5))                 # a plank
    t = 1.0
    entries.append(PenEntry(t, 0.68, 0.475, 0.0, False, True, False, False, False))
    entries += [PenEntry(t + 0.01 * k, 0.68, 0.475, 0.5, True, True, False, False, False) for k in range(1, 51)]
    entries += [PenEntry(t + 0.5 + 0.01 * k, 0.68, 0.475 + 0.003 * k, 0.5, True, True, False, False, False)
                for k in range(1, 101)]                                          # pull its end downwards
    entries.append(PenEntry(t + 1.6, 0.68, 0.775, 0.0, False, True, False, False, False))
    session = run(entries)
    assert abs(session.scene.components["b1"].angle) > 0.2


def test_sketching_gives_the_recogniser_the_pens_times_from_the_journal(monkeypatch) -> None:
    """The learned ranker reads how the pen slowed at corners (issue 25); in a session the times are the journal's,
    so a replay decides the same."""
    from physink_tui.session.modes import sketch

    seen: list[tuple[int, list[float] | None]] = []
    real = sketch.recognize_stroke

    def spy(points, times=None, **kw):
        seen.append((len(points), None if times is None else list(times)))
        return real(points, times, **kw)

    monkeypatch.setattr(sketch, "recognize_stroke", spy)
    points = box_points(0.2, 0.2, 0.5, 0.6)
    session = run(pen_stroke(1.0, points, dt=0.02))
    assert [b.shape for b in session.scene.bodies()] == ["box"]
    (n, times), = seen
    assert times is not None and len(times) == n
    assert times[0] >= 1.0 and times == sorted(times) and times[-1] - times[0] > 0.9 * 0.02 * (len(points) - 1)
