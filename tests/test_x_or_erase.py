"""Issue 25: X or erase is decided by what follows a stroke through a body, not by its size. An X drawn on a
platform welds it at any size up to the platform's own, its arms 0.1-0.8 s apart; a lone stroke through a body
erases it once the X window has passed. Drawn by both pen models, journaled, replayed, read back as a project."""

from __future__ import annotations

import math
import random
import re

import pytest
from xerase_drawings import (
    DIAGONAL,
    PENS,
    PLATFORM_CENTRE,
    journal,
    platform_length,
    replayed_project,
    x_segments,
)

from physink_tui.formats.journal.entries import CommandEntry, PenEntry
from physink_tui.formats.session_outputs import session_output_texts
from physink_tui.scene.components import BACKGROUND, Body, Joint
from physink_tui.session.modes.sketch import X_WAIT
from physink_tui.session.session import Session

ARMS = (0.02, 0.05, 0.09, 0.12, 0.15)
"""X arm lengths, shares of the canvas diagonal (today's limit for an X arm was 0.08)."""
GAPS = (0.1, 0.25, 0.5, 0.8)
"""Seconds from the first arm's pen lifting to the second's landing."""
THICKNESS = (8.0, 16.0, 40.0)


def _welded_platform(project, told: str, case: str) -> None:
    scene = project.scene
    bodies = scene.bodies()
    joints = [(c.kind, c.a, c.b) for c in scene.components.values() if isinstance(c, Joint)]
    assert [b.id for b in bodies] == ["b1"], f"{case}: {[(b.id, b.shape) for b in bodies]}\n{told}"
    assert joints == [("weld", "b1", BACKGROUND)], f"{case}: {joints}\n{told}"
    assert re.search(r"told +X → \w+ b1 fixed$", told, re.MULTILINE), f"{case}: the outcome is told\n{told}"


@pytest.mark.parametrize("pen", PENS)
@pytest.mark.parametrize("arm", ARMS)
def test_an_x_on_a_platform_welds_it_whatever_its_size_and_pace(pen: str, arm: float, tmp_path) -> None:
    length_px = arm * DIAGONAL
    for k, (gap, thickness) in enumerate((g, t) for g in GAPS for t in THICKNESS):
        rng = random.Random(f"{pen}:{arm}:{k}")
        length = platform_length(length_px)
        along = rng.uniform(-0.25, 0.25) * (length - length_px)
        centre = (PLATFORM_CENTRE[0] + along, PLATFORM_CENTRE[1] + rng.uniform(-0.2, 0.2) * thickness)
        first, second = x_segments(rng, centre, length_px)
        header, entries = journal(pen, k, thickness, length, [first, second], gap)
        folder = tmp_path / f"{k}"
        folder.mkdir()
        project, told = replayed_project(header, entries, folder)
        _welded_platform(project, told, f"{pen} arm {arm:.0%} gap {gap} s thickness {thickness} px")


@pytest.mark.parametrize("pen", PENS)
@pytest.mark.parametrize("thickness", THICKNESS)
def test_a_lone_stroke_through_a_platform_erases_it_after_the_x_window(pen: str, thickness: float,
                                                                        tmp_path) -> None:
    for k, share in enumerate((0.05, 0.1, 0.15)):
        rng = random.Random(f"lone:{pen}:{thickness}:{k}")
        half = max(share * DIAGONAL, 3 * thickness) / 2
        heading = rng.uniform(-1.2, 1.2) + 1.5708  # across the platform, within about 70 degrees of upright
        cx = PLATFORM_CENTRE[0] + rng.uniform(-100, 100)
        d = (half * math.cos(heading), half * math.sin(heading))
        stroke = ((cx - d[0], PLATFORM_CENTRE[1] - d[1]), (cx + d[0], PLATFORM_CENTRE[1] + d[1]))
        header, entries = journal(pen, k, thickness, platform_length(0.15 * DIAGONAL), [stroke], 0.5)
        case = f"{pen} stroke {share:.0%} thickness {thickness} px"

        session = Session.from_header(header)
        ended = _entries_until_the_stroke_ends(session, entries)
        assert [b.id for b in session.scene.bodies()] == ["b1"] and session.view().pending, case
        waiting = PenEntry(round(ended + X_WAIT - 0.05, 6), 0.95, 0.95, 0.0, False, False, False, False, False)
        session.handle(waiting)
        assert [b.id for b in session.scene.bodies()] == ["b1"], f"{case}: still within the X window"

        folder = tmp_path / f"{k}"
        folder.mkdir()
        project, told = replayed_project(header, entries, folder)
        assert not project.scene.components, f"{case}: {list(project.scene.components)}\n{told}"
        assert re.search(r"told +erased \w+ b1 — u to undo$", told, re.MULTILINE), f"{case}\n{told}"


def _entries_until_the_stroke_ends(session: Session, entries) -> float:
    """Feeds entries until the second stroke (the one across the platform) has ended; returns when it did."""
    strokes = 0
    for entry in entries:
        held = session.stroke_pending
        session.handle(entry)
        if not held and session.stroke_pending:
            strokes += 1
            return entry.t
    raise AssertionError(f"the stroke across the platform never ended ({strokes} strokes waited)")


def test_each_stroke_tells_what_it_made() -> None:
    """The session's messages name every stroke's outcome: bodies, the weld, the erase."""
    rng = random.Random(7)
    first, second = x_segments(rng, PLATFORM_CENTRE, 0.1 * DIAGONAL)
    header, entries = journal("hurried", 7, 16.0, platform_length(0.1 * DIAGONAL), [first, second], 0.3)
    session = Session.from_header(header).run(entries)
    outcomes = [m.text for m in session.messages if m.kind == "outcome"]
    assert outcomes == ["box → body b1", "X → platform b1 fixed"], [m.text for m in session.messages]
    session.handle(PenEntry(session.t + 0.1, 0.95, 0.95, 0.0, False, True, False, False, False))
    session.handle(CommandEntry(session.t + 0.2, "undo", ()))
    assert not [c for c in session.scene.components.values() if isinstance(c, Joint)]
    assert isinstance(session.scene.components["b1"], Body)




@pytest.mark.parametrize("pen", PENS)
def test_the_x_window_is_read_from_the_journals_times(pen: str, tmp_path) -> None:
    """The same two arms 1.3 s apart make an X; 1.8 s apart the first has erased the platform by the time the
    second lands. The live session and the replay of its journal agree on both, to the byte."""
    rng = random.Random(f"window:{pen}")
    arm = 0.1 * DIAGONAL
    first, second = x_segments(rng, PLATFORM_CENTRE, arm)
    outcomes = {}
    for gap in (1.3, 1.8):
        header, entries = journal(pen, 5, 12.0, platform_length(arm), [first, second], gap)
        live = Session.from_header(header).run(entries)
        folder = tmp_path / f"{gap}"
        folder.mkdir()
        _, told = replayed_project(header, entries, folder)
        assert (folder / "out" / "project.json").read_text() == session_output_texts(
            live.scene, live.timeline, live.canvas, live.vocabulary_lines())["project.json"]
        outcomes[gap] = [m.text for m in live.messages if m.kind == "outcome"]
        assert all(f"told          {text}" in told for text in outcomes[gap]), (outcomes[gap], told)
    assert outcomes[1.3][-1] == "X → platform b1 fixed", outcomes
    assert outcomes[1.8][1] == "erased platform b1 — u to undo", outcomes
