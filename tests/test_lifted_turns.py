"""Lines whose pen turned back sharply along them where it lifted read as lines (issue 25, session 41: the `sign` set's
ST5022 writers, writer1010's long diagonals above all): the lifted end turns back along the line for up to a quarter
of the path, its chord within 40 degrees of the line run backwards, the landing end clean (`lifted_turns.lifted_turn`,
asked by `open_shapes.line` after `open_marks.retraced_ends` and `end_curls.curled_ends`, which refuse them: the turn
skews the stroke's chord past `open_marks.RETRACE_NEAR`, or is longer than `open_marks.BACK_HOOK_SHARE`, or stands off
more than `open_marks.BACK_HOOK_DEG`, and it is no round curl). A mark's short arm drawn last stands off farther, one
drawn first turns into a rising long arm, and a v's second arm is longer: those stay polylines.

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/`, as `test_open_marks.py` reads the
public sets) and skip without it, saying so.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from sign_rows import assert_body_through_a_session, assert_read_as, sign_id, sign_row
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import lifted_turns
from physink_tui.scene.recognition.recognize import recognize_stroke

TURNED = [
    "writer1010/sessionA/diagonal_downLeft-1-1.json",  # turned back up 16 % of the path, 32 degrees off the line
    "writer1010/sessionA/diagonal_downLeft-1-3.json",
    "writer1010/sessionC/diagonal_downLeft-1-7.json",  # 22 %, 37 degrees; the rest bowed by the hand's swing
    "writer1010/sessionD/diagonal_downLeft-1-11.json",
    "writer1010/sessionD/diagonal_downLeft-1-12.json",
    "writer1010/sessionD/diagonal_downLeft-1-13.json",  # 24 %, 10 degrees: nearly run back along itself
    "writer1010/sessionD/diagonal_downLeft-1-15.json",
    "writer1010/sessionC/left-1-24.json",  # 11 %, 31 degrees
    "writer003/sessionD/diagonal_upRight-1-16.json",  # 12 %, 35 degrees
    "writer008/sessionB/right-1-17.json",  # 15 %, 13 degrees, a hair over `open_marks.BACK_HOOK_SHARE`
    "writer008/sessionD/left-1-5.json",
    "writer005/sessionC/left-1-13.json",
]
"""ST5022 writers' lines (tuning writers) read as polylines at main 261f2a7."""


@pytest.mark.parametrize("file", TURNED, ids=[sign_id(f) for f in TURNED])
def test_a_writers_line_turned_back_where_the_pen_lifted_is_a_line(file: str) -> None:
    assert_read_as(sign_row(file), "line")


THROUGH_A_SESSION = [TURNED[4], TURNED[7]]


@pytest.mark.parametrize("file", THROUGH_A_SESSION, ids=[sign_id(f) for f in THROUGH_A_SESSION])
def test_a_writers_turned_line_is_a_line_body_through_a_session(file: str, tmp_path) -> None:
    """The person's stroke drawn 300 px across by the careful virtual pen through the thesis device, journal ->
    replay -> project: a line body."""
    assert_body_through_a_session(sign_row(file), "line", tmp_path)


BRACKETS = "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s06/"
ARMS_DRAWN_LAST = {
    ("public-sets/hcira.jsonl", BRACKETS + "left_square_bracket1.xml"): "polyline",
    ("public-sets/hcira.jsonl", BRACKETS + "right_square_bracket1.xml"): "polyline",
    ("public-sets/itt-more.jsonl",
     "ITT23/assignment-06-gesture-recognition-sina-sch@8c0dbdb:dataset/right_curly_brace04.xml"): "curve",
}
"""The design sources' marks whose piece past the line's end where the pen lifted turns back the least with the landing
end clean and the rest a line: two square brackets' last arms, 17-21 % of the path at 66-74 degrees, and a brace's
curl, 9 % at 64 degrees. Read as at main 261f2a7."""


@pytest.mark.parametrize(("name", "file"), sorted(ARMS_DRAWN_LAST),
                         ids=[f.rsplit("/", 1)[-1] for _, f in sorted(ARMS_DRAWN_LAST)])
def test_a_marks_arm_drawn_last_is_no_turn(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    assert recognize_stroke(*_stroke(row)).kind == ARMS_DRAWN_LAST[(name, file)]


def _turned(share: float, degrees: float, heading: float = 225.0, landed: bool = False,
            first: tuple[float, float] | None = None) -> np.ndarray:
    """A line 240 px long heading ``heading`` degrees (y down: 225 runs down to the left), points 2 px apart, with a
    straight piece ``share`` of the path where the pen lifted turned back ``degrees`` off the line run backwards (or,
    with ``landed``, where it landed, the pen setting off back along the line and turning into it), and, with
    ``first`` (a share, degrees), a straight piece where the pen landed standing off the line so."""
    h = math.radians(heading)
    u = np.array([math.cos(h), math.sin(h)])

    def turned_by(v: np.ndarray, deg: float) -> np.ndarray:
        a = math.radians(deg)
        return np.array([v[0] * math.cos(a) - v[1] * math.sin(a), v[0] * math.sin(a) + v[1] * math.cos(a)])

    line = np.arange(0.0, 240.0 + 1e-9, 2.0)[:, None] * u
    steps = np.arange(2.0, share * 240.0 / (1 - share) + 1e-9, 2.0)[:, None]
    if landed:
        pts = np.vstack([steps[::-1] * turned_by(u, degrees), line])
    else:
        pts = np.vstack([line, line[-1] + steps * turned_by(-u, degrees)])
    if first is not None:
        arm = np.arange(first[0] * 240.0, 0.0, -2.0)[:, None] * turned_by(u, first[1])
        pts = np.vstack([arm, pts])
    return pts + np.array([600.0, 400.0])


@pytest.mark.parametrize(("share", "degrees", "heading"), [
    (0.20, 25.0, 225.0),  # a long diagonal drawn down to the left, turned back up a fifth of its path
    (0.24, 10.0, 225.0),  # nearly run back along itself
    (0.20, 38.0, 0.0),  # a level line drawn to the right
    (0.20, 25.0, -60.0),  # a line rising to the right
])
def test_a_line_turned_back_where_the_pen_lifted_is_a_line(share: float, degrees: float, heading: float) -> None:
    pts = _turned(share, degrees, heading)
    assert lifted_turns.lifted_turn(pts) is not None
    assert recognize_stroke(pts.tolist(), learned=False).kind == "line"
    assert recognize_stroke(pts.tolist()).kind == "line"


@pytest.mark.parametrize(("share", "degrees", "heading", "landed", "first"), [
    (0.20, 50.0, 225.0, False, None),  # a tick or check drawn from its long arm's end: its short arm stands off
    (0.30, 25.0, 225.0, False, None),  # a lopsided v: its second arm is no turn where the pen lifted
    (0.20, 25.0, -60.0, True, None),  # a check drawn short arm first, turning into its rising long arm
    (0.15, 25.0, 225.0, False, (0.10, 60.0)),  # an arm where the pen landed too: a zig-zag's, an N's
])
def test_a_marks_arm_stays_a_polyline(share: float, degrees: float, heading: float, landed: bool,
                                      first: tuple[float, float] | None) -> None:
    pts = _turned(share, degrees, heading, landed, first)
    assert lifted_turns.lifted_turn(pts) is None
    assert recognize_stroke(pts.tolist(), learned=False).kind == "polyline"
    assert recognize_stroke(pts.tolist()).kind == "polyline"
