"""Lines whose end the pen curled read as lines (issue 25, session 40: the `sign` set's ST5022 writers): the pen lands
and swings round into the line, or swings round off it where it lifts, a tight round curl of at most 18 % of the path
heading 125 degrees or more off the line (`end_curls.curled_ends`, asked by `open_shapes.line`); a tick's or check's
short arm, however round its corner, stays a polyline (it heads at most 123 degrees off the long arm where it is as
round, or is longer or turns gently).

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/`, as `test_open_marks.py` reads the
public sets) and skip without it, saying so.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from sign_rows import assert_body_through_a_session, assert_read_as, sign_id, sign_row
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import end_curls
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_math_marks import read

CURLED = [
    "writer004/sessionA/diagonal_downLeft-1-12.json",  # landed heading right, swung round and down: 17 % of the path
    "writer004/sessionA/diagonal_downLeft-1-16.json",
    "writer004/sessionC/diagonal_downLeft-1-11.json",
    "writer007/sessionD/diagonal_downLeft-1-16.json",  # landed heading up, swung over the top
    "writer007/sessionD/diagonal_downLeft-1-24.json",
    "writer007/sessionA/diagonal_upRight-1-23.json",  # landed right of the line's foot, swung round under it
    "writer007/sessionD/diagonal_upRight-1-1.json",
    "writer006/sessionA/diagonal_upRight-1-5.json",
    "writer003/sessionD/diagonal_downLeft-1-23.json",  # curled back where the pen lifted
    "writer003/sessionD/diagonal_upRight-1-5.json",
    "writer003/sessionD/right-1-20.json",
    "writer008/sessionB/left-1-6.json",
    "writer008/sessionC/left-1-13.json",
    "writer1010/sessionC/left-1-14.json",
]
"""ST5022 writers' lines (tuning writers) read as polylines at main bd4d4df."""


@pytest.mark.parametrize("file", CURLED, ids=[sign_id(f) for f in CURLED])
def test_a_writers_line_curled_at_an_end_is_a_line(file: str) -> None:
    assert_read_as(sign_row(file), "line")


THROUGH_A_SESSION = [CURLED[1], CURLED[6]]


@pytest.mark.parametrize("file", THROUGH_A_SESSION,
                         ids=[sign_id(f) for f in THROUGH_A_SESSION])
def test_a_writers_curled_line_is_a_line_body_through_a_session(file: str, tmp_path) -> None:
    """The person's stroke drawn 300 px across by the careful virtual pen through the thesis device, journal ->
    replay -> project: a line body."""
    assert_body_through_a_session(sign_row(file), "line", tmp_path)


TICKS = "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TrainingData/Tick.xml#"
ROUND_ARMS = {
    ("public-sets/ahmadosama.jsonl", TICKS + "28"),
    ("public-sets/ahmadosama.jsonl", TICKS + "26"),
    ("public-sets/ahmadosama.jsonl", TICKS + "23"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/check07.xml"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/check08.xml"),
    ("public-sets/hcira.jsonl", "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/check6.xml"),
    ("public-sets/hcira.jsonl", "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s06/check2.xml"),
}
"""The design sources' ticks and checks whose short arm, with its rounded corner, is most like a curl: round (its bow a
fifth of its chord or more, or within 0.05 of it) and short (14-25 % of the path), heading 102-141 degrees off the long
arm: marks, not lines."""


@pytest.mark.parametrize(("name", "file"), sorted(ROUND_ARMS),
                         ids=[f.rsplit("/", 1)[-1] for _, f in sorted(ROUND_ARMS)])
def test_a_ticks_round_short_arm_is_no_curl(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    assert recognize_stroke(*_stroke(row), learned=False).kind == "polyline"


def _curled(turn_deg: float, share: float, length: float = 200.0) -> np.ndarray:
    """A line ``length`` px long along x (points 2 px apart), begun with a round curl (a circle's arc) ``share`` of the
    path long that swings round ``turn_deg`` degrees into it: the pen landed heading that far off the line."""
    theta = math.radians(turn_deg)
    r = share * length / (1 - share) / theta
    phi = np.linspace(-theta, 0.0, max(3, int(r * theta / 2)))
    arc = np.column_stack([r * np.sin(phi), -r + r * np.cos(phi)])
    xs = np.arange(2.0, length + 1e-9, 2.0)
    return np.vstack([arc, np.column_stack([xs, np.zeros_like(xs)])]) + 300.0


def _armed(off_deg: float, share: float, length: float = 200.0) -> np.ndarray:
    """The same line begun with a straight arm ``share`` of the path long, heading ``off_deg`` off the line."""
    arm = share * length / (1 - share)
    a = math.radians(off_deg)
    steps = np.arange(arm, 0.0, -2.0)[:, None]
    head = steps * [-math.cos(a), math.sin(a)]
    xs = np.arange(0.0, length + 1e-9, 2.0)
    return np.vstack([head, np.column_stack([xs, np.zeros_like(xs)])]) + 300.0


@pytest.mark.parametrize(("turn", "share", "cut"), [
    (160.0, 0.12, True),  # a tight curl swung round 160 degrees, 12 % of the path (as judged, smoothed: 140, 9 %)
    (170.0, 0.1, True),
    (100.0, 0.1, False),  # swung round too little: a tick's arm heads so far off
    (170.0, 0.25, False),  # a long hook: a J, no line
])
def test_a_tight_round_curl_is_cut(turn: float, share: float, cut: bool) -> None:
    pts = _curled(turn, share)
    kept = end_curls.curled_ends(pts)
    assert (kept is not None) == cut
    if cut:
        assert kept is not None and float(np.ptp(kept[:, 1])) < 10.0  # the line (and the curl's last 30 degrees)
        assert recognize_stroke(pts.tolist()).kind == "line"


@pytest.mark.parametrize("off", [100.0, 130.0, 160.0])
def test_a_straight_short_arm_is_no_curl(off: float) -> None:
    assert end_curls.curled_ends(_armed(off, 0.12)) is None


@pytest.mark.parametrize("timed", [True, False])
def test_a_radicals_hooked_tick_is_no_curl(timed: bool) -> None:
    """The careful pen's barless radical of tuning seed 14 begins with a small hook into its tick: round, short and
    swung far off the rise, as a curl is, but its first step heads back along the rise (`end_curls.CURL_END_DEG`)."""
    assert read("barless-radical", "careful", 14, timed) == "polyline"
