"""Lines a quick wrist bowed one way, lying slanted or level, read as lines (issue 25, session 37: the `sign` set's
ST5022 writers): bowed 5-12 % of their chord, deepest anywhere but in an end's hook, bent at one end or both, as a
parenthesis may be shaped, but lying far off the upright as no parenthesis does, and no circle fits the bow
(`bowed_lines.slanted_flick`, asked by `open_marks.swung_line`), by the rules and with the learned ranker. The same
stroke stood upright stays a bow, and people's quarter arcs (the set's unscored curve gestures) never read as lines.

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/sign.jsonl`, as `test_open_marks.py`
reads the public sets) and skip without it, saying so.
"""

from __future__ import annotations

import math

import pytest
from sign_rows import SIGN, assert_read_as, sign_id, sign_row
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

BOWED = [
    "writer001/sessionA/diagonal_downLeft-1-2.json",  # deepest 0.32 of its chord from its start, straight after
    "writer002/sessionC/diagonal_upRight-1-2.json",  # deepest 0.24 from its start
    "writer001/sessionC/left-1-2.json",  # level, bent where the pen landed
    "writer001/sessionA/diagonal_upRight-1-11.json",  # bent at both ends (11 and 11 degrees)
    "writer007/sessionB/left-1-11.json",  # level, bent at both ends
    "writer004/sessionB/diagonal_downLeft-1-21.json",
    "writer001/sessionA/diagonal_downLeft-1-0.json",  # bowed 0.10 of its chord
    "writer001/sessionB/diagonal_upRight-1-17.json",  # bowed 0.093
]
"""ST5022 writers' lines (tuning writers) read as arcs at main 21789a8."""


def _upright(points: list[list[float]]) -> list[list[float]]:
    """``points`` turned about their start so that their chord stands on the page's vertical."""
    (x0, y0), (x1, y1) = points[0], points[-1]
    turn = math.pi / 2 - math.atan2(y1 - y0, x1 - x0)
    c, s = math.cos(turn), math.sin(turn)
    return [[x0 + (x - x0) * c - (y - y0) * s, y0 + (x - x0) * s + (y - y0) * c] for x, y in points]


@pytest.mark.parametrize("file", BOWED, ids=[sign_id(f) for f in BOWED])
def test_a_writers_slanted_bowed_line_is_a_line_and_stood_upright_a_bow(file: str) -> None:
    row = sign_row(file)
    assert_read_as(row, "line")
    points, times = _stroke(row)
    # stood upright, the same bow is a parenthesis' shape: no line (as at main 21789a8)
    assert recognize_stroke(_upright(points), times, learned=False).kind in ("arc", "curve")


LINE_LABELS = ("left", "right", "diagonal_downLeft", "diagonal_upRight")
ST_LINES_FLOOR = 3732
"""The ST5022 writers' 3,800 strokes of the four line labels read as lines, by the rules and shipped: 3,732 since
session 42's lead-ins asked of either end within 38 degrees (`tests/test_lifted_lead_ins.py`); 3,725 since
session 40's `end_curls.curled_ends` (`tests/test_end_curls.py`); 3,707 since session 39's `lead_ins.lead_in`
(`tests/test_lead_ins.py`); 3,690 since session 38's `open_marks.hooked_bow`
(`tests/test_hooked_bows.py`, 3,684 alone) and `bowed_lines.end_bent` (`tests/test_curled_lines.py`, 3,679 alone);
3,673 when written, 3,597 at main 21789a8, before `bowed_lines.slanted_flick`; 3,512 at 02d2055, before
`open_marks.flicked`, whose test file kept a floor of 3,548 here until this one rose past it)."""


def test_the_st5022_writers_lines_are_lines() -> None:
    rows = [r for r in cached_rows(SIGN).values()
            if r["label"] in LINE_LABELS and "ST5022" in r["device"] and len(r["strokes"]) == 1]
    assert len(rows) == 3800
    for learned in (False, True):
        read = [recognize_stroke(*_stroke(r), learned=learned).kind for r in rows]
        assert sum(k == "line" for k in read) >= ST_LINES_FLOOR, learned


def test_the_st5022_writers_quarter_arcs_are_no_lines() -> None:
    """The ST5022 writers' 3,800 curve gestures (quarter arcs, bowing 0.37-1.32 of their chord): none is read as a
    line (none was at main 21789a8)."""
    rows = [r for r in cached_rows(SIGN).values()
            if r["label"].startswith("curve_") and "ST5022" in r["device"] and len(r["strokes"]) == 1]
    assert len(rows) == 3800
    lines = [r["file"] for r in rows if recognize_stroke(*_stroke(r)).kind == "line"]
    assert not lines, lines
