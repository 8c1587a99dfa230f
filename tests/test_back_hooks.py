"""Issue 25, session 36: a straight line drawn with a Tablet PC pen that hooked back where it landed or lifted (up to
12.5 % of the path where it landed, 15 % where it lifted, the hook's chord within `open_marks.BACK_HOOK_DEG` of the
line) reads as a line, by the stroke alone (and through a whole session since session 39, when a longer piece where
the pen landed before a level or downhill line became a lead-in cut: `lead_ins.lead_in`), where it read as a
two-piece polyline (`open_marks.retraced_ends` cut only a piece lying along the line); a mark's short arm, standing
farther off, stays a polyline.

The `sign` set's strokes (the ST5022 writers: design material) and the design sources' checks are read from the
public-set caches (`benchmarks/public_sets.py`; no licence lets the project hold them) and skip without them."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drawn_strokes import drawn_person_stroke
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import open_marks
from physink_tui.scene.recognition.recognize import recognize_stroke

SIGN = "public-sets/sign.jsonl"
AT = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
HOOKED_LINES = (
    "writer001/sessionB/left-1-18.json",  # hooked back at both ends, 11 % and 13 % of its path (12-13 degrees)
    "writer001/sessionC/diagonal_downLeft-1-11.json",  # hooked where the pen landed
    "writer003/sessionB/diagonal_upRight-1-3.json",  # 12 % where the pen landed
    "writer003/sessionC/right-1-11.json",
    "writer003/sessionD/left-1-21.json",
    "writer005/sessionB/right-1-21.json",  # both ends, 11 % and 9 %
    "writer008/sessionC/right-1-19.json",
    "writer1011/sessionA/diagonal_downLeft-1-0.json",
)
"""ST5022 writers' lines (tuning material) read as polylines at main 02d2055."""


@pytest.mark.parametrize("file", HOOKED_LINES)
def test_a_line_hooked_back_where_the_pen_landed_or_lifted_is_a_line(file: str) -> None:
    row = cached_rows(SIGN).get(AT + file)
    assert row is not None, f"{file} is not in the cached sign set"
    assert recognize_stroke(*_stroke(row)).kind == "line"


SHORT_ARMS = {
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user1/check05.xml"): "polyline",
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user1/check06.xml"): "polyline",
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/check03.xml"): "polyline",
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user1/check08.xml"): "polyline",
}
"""The design sources' checks whose long arm is straight and whose short arm (14-24 % of the path) stands off it the
least (38-55 degrees by the short arm's chord): marks, not lines."""


@pytest.mark.parametrize(("name", "file"), list(SHORT_ARMS), ids=[f.rsplit("/", 1)[-1] for _, f in SHORT_ARMS])
def test_a_checks_short_arm_is_no_hook(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    assert recognize_stroke(*_stroke(row)).kind == SHORT_ARMS[(name, file)]


def _hooked(share: float, degrees: float, both: bool = False, length: float = 200.0) -> np.ndarray:
    """A line ``length`` px long along x, with a hook at its start ``share`` of the path long, turned back ``degrees``
    off the line (and one at its end, to the other side, where ``both``), points 2 px apart."""
    hook = share * length / (1 - share * (2 if both else 1))
    a = math.radians(degrees)
    xs = np.arange(0.0, length + 1e-9, 2.0)
    line = np.column_stack([xs, np.zeros_like(xs)])
    steps = np.arange(hook, 0.0, -2.0)[:, None]
    head = steps * [math.cos(a), math.sin(a)]
    pts = np.vstack([head, line])
    if both:
        pts = np.vstack([pts, [length, 0.0] + steps[::-1] * [-math.cos(a), -math.sin(a)]])
    return pts


@pytest.mark.parametrize(("share", "degrees", "both", "cut", "rising"), [
    (0.10, 28.0, False, True, False),  # a hook turned back 28 degrees, a tenth of the path (10 px off the line)
    (0.10, 28.0, False, True, True),  # the same before a rise
    (0.12, 25.0, True, True, False),  # hooks at both ends, 12 % each: 24 % in all
    (0.08, 45.0, False, False, False),  # a tick's short arm standing off 45 degrees
    (0.08, 45.0, False, False, True),
    (0.20, 15.0, False, False, True),  # a fifth of the path before a rise: a mark's arm, however narrow
    (0.135, 20.0, False, False, True),  # where the pen landed, over `BACK_HOOK_LANDED_SHARE`: a barless radical's tick
])
def test_a_hook_turned_back_is_cut_and_an_arm_is_not(share: float, degrees: float, both: bool, cut: bool,
                                                     rising: bool) -> None:
    """Drawn along a level line, or before (and after) a line rising as a radical's or a check's long arm does
    (``rising``: `_rising`); the last two before a level line are lead-ins since session 39 (below)."""
    pts = _hooked(share, degrees, both)
    kept = open_marks.retraced_ends(_rising(pts) if rising else pts, 1.0)
    assert (kept is not None) == cut
    if cut:
        assert kept is not None and float(np.ptp((_rising(kept, back=True) if rising else kept)[:, 1])) < 1e-9


@pytest.mark.parametrize(("share", "degrees"), [(0.20, 15.0), (0.135, 20.0)])
def test_a_long_narrow_lead_in_before_a_level_line_is_cut(share: float, degrees: float) -> None:
    """The same pieces where the pen landed before a line drawn level: a lead-in (`lead_ins.lead_in`, issue 25,
    session 39), kept before a rise at main df2c518 and still (`test_a_hook_turned_back_is_cut_and_an_arm_is_not`)."""
    kept = open_marks.retraced_ends(_hooked(share, degrees), 1.0)
    assert kept is not None and float(np.ptp(kept[:, 1])) < 1e-9


def _rising(pts: np.ndarray, back: bool = False) -> np.ndarray:
    """``pts`` (a line along x, y down) turned to rise 60 degrees above level, as a barless radical's rise does (or,
    with ``back``, turned back to level)."""
    a = math.radians(-60.0 if back else 60.0)
    c, s = math.cos(a), math.sin(a)
    return np.column_stack([pts[:, 0] * c + pts[:, 1] * s, -pts[:, 0] * s + pts[:, 1] * c])


def test_a_hook_where_the_pen_lifted_may_be_longer_than_where_it_landed() -> None:
    """A hook 13.5 % of the path, 20 degrees off the line: kept where the pen landed (a radical's tick is drawn first),
    cut where it lifted (`open_marks.BACK_HOOK_LANDED_SHARE`, `BACK_HOOK_SHARE`)."""
    pts = _rising(_hooked(0.135, 20.0))  # before a rise (before a level line it is a lead-in, cut: `lead_ins`)
    assert open_marks.retraced_ends(pts, 1.0) is None
    kept = open_marks.retraced_ends(pts[::-1].copy(), 1.0)
    assert kept is not None and float(np.ptp(_rising(kept, back=True)[:, 1])) < 1e-9


def test_a_persons_hooked_line_is_a_line_body_through_a_session(tmp_path) -> None:
    """writer001's left line hooked back at both ends (`HOOKED_LINES`' first), drawn 300 px long by the careful
    virtual pen through the thesis device: a polyline body of more than two points at main 02d2055, and a strict xfail
    until main df2c518 (the virtual pen's wobble lengthens the landed hook from 10.5 % of the path to 13.6 %, over
    `open_marks.BACK_HOOK_LANDED_SHARE`); a line since session 39: the line is drawn level, where a landed piece up to
    30 % of the path is a lead-in (`lead_ins.lead_in`)."""
    row = cached_rows(SIGN).get(AT + HOOKED_LINES[0])
    assert row is not None
    shapes, told = drawn_person_stroke(np.asarray(_stroke(row)[0], dtype=float), tmp_path)
    assert shapes == ["line"], told
