"""Lines begun with a long lead-in read as lines (issue 25, session 39: the `sign` set's ST5022 writers): the pen
lands, slides back along the line for 12.7-27 % of the path, within 30 degrees of it (38 since session 42:
`tests/test_lifted_lead_ins.py`, which asks it of either end), and draws the line level or downhill
(`lead_ins.lead_in`, asked by `open_marks.retraced_ends`); a mark drawn down into a point and rising from it, as a
barless radical or a check is, keeps its short first arm however narrowly it stands off the rise.

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/`, as `test_open_marks.py` reads the
public sets) and skip without it, saying so.
"""

from __future__ import annotations

import numpy as np
import pytest
from sign_rows import assert_body_through_a_session, assert_read_as, sign_id, sign_row

from physink_tui.scene.recognition import lead_ins, open_marks
from physink_tui.scene.recognition.recognize import recognize_stroke

LEAD_INS = [
    "writer001/sessionB/diagonal_downLeft-1-24.json",  # run back 17 % straight along it
    "writer001/sessionB/right-1-12.json",  # 23 %
    "writer004/sessionC/diagonal_downLeft-1-15.json",
    "writer005/sessionB/diagonal_downLeft-1-5.json",
    "writer005/sessionB/left-1-21.json",
    "writer005/sessionB/right-1-5.json",  # curled in from the left, 15 %
    "writer005/sessionC/right-1-11.json",  # 27 %, and a loop where it lifted
    "writer006/sessionA/right-1-13.json",
    "writer007/sessionA/diagonal_downLeft-1-12.json",
    "writer007/sessionA/diagonal_downLeft-1-16.json",
    "writer007/sessionA/diagonal_downLeft-1-23.json",  # flicked up into the top, 16 %, 20 degrees off
    "writer007/sessionB/diagonal_downLeft-1-0.json",
    "writer007/sessionB/diagonal_downLeft-1-23.json",
    "writer007/sessionB/right-1-13.json",
    "writer007/sessionD/diagonal_downLeft-1-19.json",
    "writer007/sessionD/left-1-8.json",
    "writer007/sessionD/right-1-5.json",
]
"""ST5022 writers' lines (tuning writers) read as polylines at main df2c518."""


@pytest.mark.parametrize("file", LEAD_INS, ids=[sign_id(f) for f in LEAD_INS])
def test_a_writers_line_with_a_long_lead_in_is_a_line(file: str) -> None:
    assert_read_as(sign_row(file), "line")


THROUGH_A_SESSION = [LEAD_INS[0], LEAD_INS[10]]


@pytest.mark.parametrize("file", THROUGH_A_SESSION,
                         ids=[sign_id(f) for f in THROUGH_A_SESSION])
def test_a_writers_line_with_a_long_lead_in_is_a_line_body_through_a_session(file: str, tmp_path) -> None:
    """The person's stroke drawn 300 px across by the careful virtual pen through the thesis device, journal ->
    replay -> project: a line body."""
    assert_body_through_a_session(sign_row(file), "line", tmp_path)


def _v(rise_deg: float, off_deg: float, arm: float = 40.0, long: float = 200.0) -> np.ndarray:
    """A stroke (y down) drawn down a short first arm into a point and out along a long one heading ``rise_deg`` above
    level, the first arm's start standing ``off_deg`` off the long one's way from the point."""
    way = np.array([np.cos(np.radians(rise_deg)), -np.sin(np.radians(rise_deg))])
    a = np.radians(off_deg)
    start = arm * np.array([way[0] * np.cos(a) - way[1] * np.sin(a), way[0] * np.sin(a) + way[1] * np.cos(a)])
    first = np.linspace(start, [0.0, 0.0], 12)
    return np.vstack([first, np.linspace([0.0, 0.0], long * way, 49)[1:]]) + 500.0


def test_a_lead_in_before_a_level_or_downhill_line_is_cut() -> None:
    for rise in (0.0, -45.0, 15.0):
        kept = open_marks.retraced_ends(_v(rise, 15.0), 1.0)
        assert kept is not None and len(kept) == 49, rise


def test_a_narrow_tick_before_a_rise_is_kept() -> None:
    """A barless radical's or a check's short arm standing 15 degrees off its rise is no lead-in."""
    for rise in (45.0, 60.0, 80.0):
        assert open_marks.retraced_ends(_v(rise, 15.0), 1.0) is None, rise
        assert recognize_stroke(_v(rise, 15.0).tolist(), None).kind != "line", rise


def test_a_lead_in_standing_far_off_or_long_is_kept() -> None:
    assert open_marks.retraced_ends(_v(0.0, 40.0), 1.0) is None  # a check's short arm's angle
    assert open_marks.retraced_ends(_v(0.0, 10.0, arm=120.0), 1.0) is None  # 37 % of the path: an arm


def test_rises_at_most() -> None:
    assert lead_ins.rises_at_most(np.array([1.0, 0.0]), lead_ins.LEAD_RISE_DEG)
    assert lead_ins.rises_at_most(np.array([-0.6, 0.8]), lead_ins.LEAD_RISE_DEG)  # downhill
    assert not lead_ins.rises_at_most(np.array([0.6, -0.8]), lead_ins.LEAD_RISE_DEG)
