"""A line whose pen turned back along it where it lifted reads as a line exactly where, drawn backwards, that turn is a
long lead-in (`lead_ins.lead_in`, asked by `open_marks.retraced_ends` of the stroke as drawn and reversed; issue 25,
session 42: the `sign` set's ST5022 writers' level lines and rising diagonals): so a lead-in and a line read the same
drawn from either end, and a mark drawn backwards (a check, a barless radical from the top of its rise) is refused as
it is drawn forwards, its long arm rising from the point. Lead-ins stand off the line by up to 38 degrees
(`lead_ins.LEAD_DEG`; 30 before session 42) whichever end they are at.

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/`, as `test_open_marks.py` reads the
public sets) and skip without it, saying so.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from sign_rows import assert_body_through_a_session, assert_read_as, sign_id, sign_row
from test_open_marks import _stroke, cached_rows
from test_people_strokes import people_rows

from physink_tui.scene.recognition import open_marks
from physink_tui.scene.recognition.recognize import recognize_stroke

LIFTED = [
    "writer008/sessionB/right-1-17.json",  # turned back 15 % of the path, 13 degrees off: over `BACK_HOOK_SHARE`
    "writer1010/sessionC/left-1-24.json",  # 11 %, 31 degrees
    "writer005/sessionC/left-1-13.json",  # 12 %, 30.1 degrees
    "writer008/sessionD/left-1-5.json",  # 10 %, 34 degrees
    "writer003/sessionD/diagonal_upRight-1-16.json",  # 12 %, 35 degrees, rising 37 degrees
    "writer005/sessionC/left-1-7.json",  # 10 %, 36.6 degrees
]
"""ST5022 writers' lines (tuning writers) turned back where the pen lifted, read as polylines at main f64c966: drawn
backwards each begins with a lead-in before a line drawn level or downhill."""
LANDED = [
    "writer001/sessionA/diagonal_downLeft-1-15.json",  # a lead-in of 10 % of the path 36 degrees off, downhill
]
"""An ST5022 writer's lead-in standing off more than the 30 degrees of main f64c966."""
TURNED = LIFTED + LANDED


def _backwards(points: list[list[float]], times: list[float] | None) -> tuple[list[list[float]], list[float] | None]:
    """The stroke drawn from its other end: its points reversed, its times counted from the same start."""
    return points[::-1], None if times is None else [times[-1] - t for t in times[::-1]]


@pytest.mark.parametrize("file", TURNED, ids=[sign_id(f) for f in TURNED])
def test_a_writers_line_turned_back_at_an_end_is_a_line(file: str) -> None:
    assert_read_as(sign_row(file), "line")


@pytest.mark.parametrize("file", TURNED, ids=[sign_id(f) for f in TURNED])
def test_a_writers_turned_line_reads_the_same_drawn_backwards(file: str) -> None:
    back = _backwards(*_stroke(sign_row(file)))
    assert recognize_stroke(*back, learned=False).kind == "line"
    assert recognize_stroke(*back).kind == "line"


THROUGH_A_SESSION = [LIFTED[1], LIFTED[4]]


@pytest.mark.parametrize("file", THROUGH_A_SESSION, ids=[sign_id(f) for f in THROUGH_A_SESSION])
def test_a_writers_turned_line_is_a_line_body_through_a_session(file: str, tmp_path) -> None:
    """The person's stroke drawn 300 px across by the careful virtual pen through the thesis device, journal ->
    replay -> project: a line body."""
    assert_body_through_a_session(sign_row(file), "line", tmp_path)


DOWNHILL = [
    "writer1010/sessionA/diagonal_downLeft-1-3.json",  # turned back up 17 % of the path, 21 degrees off the line
    "writer1010/sessionD/diagonal_downLeft-1-13.json",  # 24 %, 10 degrees: nearly run back along itself
]
"""writer1010's long diagonals drawn down to the left, turned back up where the pen lifted: drawn backwards the turn is
a short first arm before a rise, as a check's or a barless radical's is, so neither way is it cut."""
CHECKS_DRAWN_BACKWARDS = [
    "pixelfac/hcira-project-23@80d4cc7:src/dataset/user06/check3.xml",  # backwards, its short arm 40 degrees off
    "pixelfac/hcira-project-23@80d4cc7:src/dataset/user06/check7.xml",  # 33
    "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/check03.xml",  # 39
]
"""hcira checks that read as lines drawn backwards while session 41's `lifted_turns` cut turns on lines drawn downhill
(reverted: `tests/test_marks_people.py` asks a check to read the same from either end)."""


@pytest.mark.parametrize("file", DOWNHILL, ids=[sign_id(f) for f in DOWNHILL])
def test_a_line_drawn_downhill_keeps_its_lifted_turn_either_way(file: str) -> None:
    """The rule cuts neither way, and the stroke reads alike either way (today a polyline both ways, a miss its label
    calls a line, left in docs/BENCHMARKS.md: the rule must not take it one way only)."""
    points, times = _stroke(sign_row(file))
    raw = np.asarray(points, dtype=float)
    assert open_marks.retraced_ends(raw, 1.0) is None
    assert open_marks.retraced_ends(raw[::-1].copy(), 1.0) is None
    assert recognize_stroke(points, times).kind == recognize_stroke(*_backwards(points, times)).kind


@pytest.mark.parametrize("file", CHECKS_DRAWN_BACKWARDS, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1]
                                                               for f in CHECKS_DRAWN_BACKWARDS])
def test_a_narrow_check_is_a_polyline_drawn_either_way(file: str) -> None:
    row = cached_rows("public-sets/hcira.jsonl").get(file)
    assert row is not None, f"{file} is not in hcira"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == "polyline"
    assert recognize_stroke(*_backwards(points, times)).kind == "polyline"


def test_dollar1_s03s_slow_x_is_a_polyline_drawn_either_way() -> None:
    """s03's slow x10, a narrow first arm and a long diagonal (``tests/test_reversed_people.py``'s `DOLLAR1_ALIKE`):
    its arm stands farther off the chord than a line's lead-in (`open_marks.RETRACE_NEAR`), drawn either way."""
    row = next(r for r in people_rows() if r["file"] == "s03/slow/x10.xml")
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == "polyline"
    assert recognize_stroke(*_backwards(points, times)).kind == "polyline"


def _turned(share: float, degrees: float, heading: float) -> np.ndarray:
    """A line 240 px long heading ``heading`` degrees (y down: 0 runs level to the right, -60 rises to the right, 135
    falls to the left), points 2 px apart, with a straight piece ``share`` of the path where the pen lifted turned back
    ``degrees`` off the line run backwards."""
    h = math.radians(heading)
    u = np.array([math.cos(h), math.sin(h)])
    a = math.radians(degrees)
    back = np.array([-u[0] * math.cos(a) + u[1] * math.sin(a), -u[0] * math.sin(a) - u[1] * math.cos(a)])
    line = np.arange(0.0, 240.0 + 1e-9, 2.0)[:, None] * u
    steps = np.arange(2.0, share * 240.0 / (1 - share) + 1e-9, 2.0)[:, None]
    return np.vstack([line, line[-1] + steps * back]) + np.array([600.0, 400.0])


@pytest.mark.parametrize(("share", "degrees", "heading"), [
    (0.25, 10.0, 180.0),  # a level line drawn to the left, nearly run back along itself
    (0.12, 35.0, 0.0),  # a level line drawn to the right
    (0.15, 30.0, -40.0),  # a line rising to the right
    (0.12, 36.0, 200.0),  # a line drawn to the left, rising 20 degrees
])
def test_a_line_turned_back_where_the_pen_lifted_is_cut_as_it_is_drawn_backwards(share: float, degrees: float,
                                                                                  heading: float) -> None:
    pts = _turned(share, degrees, heading)
    ahead, back = open_marks.retraced_ends(pts, 1.0), open_marks.retraced_ends(pts[::-1].copy(), 1.0)
    assert ahead is not None and back is not None
    assert np.array_equal(ahead, back[::-1])
    for drawn in (pts, pts[::-1]):
        assert recognize_stroke(drawn.tolist(), learned=False).kind == "line"
        assert recognize_stroke(drawn.tolist()).kind == "line"


@pytest.mark.parametrize(("share", "degrees", "heading"), [
    (0.20, 33.0, 135.0),  # a narrow check drawn from its long arm's end, down to the left: its rise, drawn first
    (0.20, 33.0, 45.0),  # the same, mirrored
    (0.20, 45.0, 0.0),  # a short arm standing off past `lead_ins.LEAD_DEG`, a tick's drawn last
    (0.33, 20.0, 0.0),  # a lopsided v's second arm, past `lead_ins.LEAD_SHARE`
])
def test_a_marks_arm_stays_a_polyline_drawn_either_way(share: float, degrees: float, heading: float) -> None:
    pts = _turned(share, degrees, heading)
    for drawn in (pts, pts[::-1]):
        assert open_marks.retraced_ends(drawn.copy(), 1.0) is None
        assert recognize_stroke(drawn.tolist(), learned=False).kind == "polyline"
        assert recognize_stroke(drawn.tolist()).kind == "polyline"

