"""A line's long lead-in: the pen landing, sliding back along the line it then draws level or downhill; no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

LEAD_SHARE = 0.3
"""A lead-in run back along the line where the pen landed is at most this share of the stroke's path (the `sign` set's
ST5022 writers' lines: 12.7-27 % where `open_marks.BACK_HOOK_LANDED_SHARE`, 12.5 %, refuses them)."""
LEAD_TOTAL = 0.35
"""... and the lead-in and the piece cut where the pen lifted are together at most this share of it."""
LEAD_DEG = 38.0
"""... its chord (from where the pen turned to where it landed) within this angle of the line running on from there
(the ST writers' lead-ins 0-24 degrees, and 36 for writer001's downhill diagonal; drawn backwards, their lines turned
back where the pen lifted 13-36.6 degrees: `open_marks.retraced_ends` asks this of either end, issue 25, session 42).
30 until then (`open_marks.BACK_HOOK_DEG`). No mark of the design or fourth groups whose rest is a line by the line
test begins or ends with such a piece, drawn either way, within 72 degrees once its points lie near its chord
(`open_marks.RETRACE_NEAR`); a check's or barless radical's short arm, drawn first or last, is refused by its long
arm's rise (`LEAD_RISE_DEG`), not by this angle."""
LEAD_RISE_DEG = 20.0
"""... where the line drawn after it runs level or downhill: it rises above level by at most this angle (y down). A mark
drawn down into a point and up from it, a barless radical's tick and rise or a check's short arm and long one, rises
from its point by 45 degrees or more (`tests/penmodels/math_marks`: the rise leans 5-35 degrees off the upright, the
mark tilted up to 10), which is where the narrow run-back of a radical's tick and a line's lead-in could not be told
apart by angle, share or bow (issue 25, session 37, wt-hooks3); every `sign` lead-in so refused runs level (`left`,
`right`) or downhill (`diagonal_downLeft`)."""


def lead_in(end: np.ndarray, turn: np.ndarray, unit: np.ndarray, length: float) -> bool:
    """Whether ``end`` (the piece before where the pen turned, ``turn``, from the stroke's start; ``unit`` the way the
    line runs on from ``turn``; ``length`` the stroke's path) is a lead-in run back along a line drawn level or
    downhill (`LEAD_SHARE`, `LEAD_DEG`, `LEAD_RISE_DEG`)."""
    return rises_at_most(unit, LEAD_RISE_DEG) and turned_back(end, turn, unit, LEAD_SHARE * length, LEAD_DEG)


def turned_back(end: np.ndarray, turn: np.ndarray, unit: np.ndarray, most: float, deg: float) -> bool:
    """Whether ``end`` (an end piece of a stroke, from the stroke's end to where it turns, ``turn``) runs back along
    the line that goes on from ``turn`` the way of ``unit`` (a unit vector): its path no longer than ``most``, its
    chord (from ``turn`` to the stroke's end) within ``deg`` degrees of ``unit``. A lead-in (`lead_in`) and a hook
    (`open_marks.retraced_ends`) are both such pieces, told apart by their bounds."""
    if sg.path_length(end) > most:
        return False
    angle = sg.angle_deg(end[0] - turn, unit)
    return angle is None or angle <= deg


def rises_at_most(unit: np.ndarray, deg: float) -> bool:
    """Whether the way ``unit`` (a unit vector, y down) heads rises above level by at most ``deg`` degrees."""
    return -float(unit[1]) <= math.sin(math.radians(deg))
