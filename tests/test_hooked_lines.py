"""Issue 25, session 37: a Tablet PC pen's line whose end runs back narrowly along it for up to 30 % of the path
(`hooked_lines.NARROW_DEG`, `NARROW_SHARE`), or curls round onto it where the pen lifted, standing up to 60 degrees
off (`hooked_lines.CURL_DEG`, `CURL_BOW`), reads as a line, where it read as a two-piece polyline (the back-hook rule
of session 36 cut only hooks within 30 degrees, up to 12.5-15 % of the path); people's checks, whose short arm stands
as far off but straight, stay polylines.

The `sign` set's strokes (the ST5022 writers: design material) and the design sources' ticks are read from the
public-set caches (`benchmarks/public_sets.py`; no licence lets the project hold them) and skip without them."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import open_marks
from physink_tui.scene.recognition.recognize import recognize_stroke

SIGN = "public-sets/sign.jsonl"
AT = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
NARROW_LEADS = (
    "writer001/sessionB/diagonal_downLeft-1-24.json",  # run back 17 % of the path where the pen landed, 0 degrees
    "writer001/sessionB/right-1-12.json",  # 23 %, 4 degrees
    "writer005/sessionC/right-1-11.json",  # 27 %, 3 degrees, and a hook where the pen lifted
    "writer007/sessionB/right-1-13.json",  # 21 %, 11 degrees
)
CURLED_HOOKS = (
    "writer003/sessionD/diagonal_upRight-1-16.json",  # curled where the pen lifted, 12 % of the path, 35 degrees
    "writer003/sessionD/diagonal_upRight-1-5.json",  # 7 %, 56 degrees
    "writer004/sessionB/diagonal_downLeft-1-10.json",  # 7 %, 47 degrees
    "writer008/sessionB/right-1-22.json",  # 5 %, 40 degrees
)
"""ST5022 writers' lines (tuning material) read as polylines at main 21789a8."""


@pytest.mark.parametrize("file", NARROW_LEADS + CURLED_HOOKS)
def test_a_line_run_back_narrowly_or_curled_at_an_end_is_a_line(file: str) -> None:
    row = cached_rows(SIGN).get(AT + file)
    assert row is not None, f"{file} is not in the cached sign set"
    assert recognize_stroke(*_stroke(row)).kind == "line"


STRAIGHT_ARMS = (
    "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TrainingData/Tick.xml#65",
    "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TrainingData/Tick.xml#41",
    "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TrainingData/Tick.xml#17",
)
"""Design ticks whose long arm is a line once the short arm (8-11 % of the path, 61-73 degrees off it, bowing 0.03 of
its chord or less) is cut: marks, not lines."""


@pytest.mark.parametrize("file", STRAIGHT_ARMS, ids=[f.rsplit(":", 1)[-1] for f in STRAIGHT_ARMS])
def test_a_ticks_straight_short_arm_is_no_curl(file: str) -> None:
    row = cached_rows("public-sets/ahmadosama.jsonl").get(file)
    assert row is not None, f"{file} is not in ahmadosama"
    assert recognize_stroke(*_stroke(row)).kind != "line"


def _line_with(end: np.ndarray) -> np.ndarray:
    """A line 200 px along x, points 2 px apart, led into by ``end`` (points ending at the origin)."""
    xs = np.arange(0.0, 200.0 + 1e-9, 2.0)
    return np.vstack([end[:-1], np.column_stack([xs, np.zeros_like(xs)])])


def _lead(length: float, degrees: float) -> np.ndarray:
    a = math.radians(degrees)
    steps = np.arange(length, -1e-9, -2.0)[:, None]
    return steps * [math.cos(a), math.sin(a)]


def _curl(radius: float, sweep_deg: float) -> np.ndarray:
    """A circular curl ``radius`` px round turning ``sweep_deg`` onto the line at the origin (from its free end)."""
    t = np.linspace(0.0, math.radians(sweep_deg), 16)
    return np.column_stack([radius * np.sin(t), radius - radius * np.cos(t)])[::-1]


@pytest.mark.parametrize(("end", "lifted", "cut"), [
    (_lead(60.0, 8.0), False, True),  # run back 60 px (23 % of the path) within 8 degrees: the pen sliding back
    (_lead(100.0, 6.0), False, False),  # 100 px: over `NARROW_SHARE` of the path
    (_lead(50.0, 20.0), False, False),  # a fifth of the path at 20 degrees: a narrow v's short leg
    (_curl(12.0, 90.0), True, True),  # a curl onto the line where the pen lifted, its chord 45 degrees off
    (_curl(12.0, 90.0), False, False),  # ... where it landed: a barless radical's rounded tick is drawn so
    (_lead(18.0, 45.0), True, False),  # a straight short arm as far off: a tick
])
def test_a_narrow_lead_or_a_curl_is_cut_and_an_arm_is_not(end: np.ndarray, lifted: bool, cut: bool) -> None:
    pts = _line_with(end)
    kept = open_marks.retraced_ends(pts[::-1].copy() if lifted else pts, 1.0)
    assert (kept is not None) == cut
    if cut:
        assert kept is not None and float(np.ptp(kept[:, 1])) < 1e-9
