"""A line whose pen turned back sharply along it where it lifted, without that turn; no I/O."""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

TURN_MIDDLE = (0.3, 0.7)
"""The line's way is the chord between these shares of the path (`end_curls.CURL_MIDDLE`: a turn lies outside them)."""
TURN_SHARE = 0.25
"""What the pen turned back where it lifted is at most this share of the path (the ST writers' 5-24 %)."""
TURN_DEG = 40.0
"""... its chord, from where it turned to the stroke's end, within this angle of the line run backwards from there (the
ST writers' 10-37 degrees, one at 42 left a polyline). A mark's short arm drawn last stands off farther: the design and
fourth groups' square brackets 66-90 degrees, braces 64 and more; the pen models' ticks drawn from the long arm's end
(`tests/penmodels/hurried_marks.hooked_tick`, seeds 0-29, 1000-1029, 2000-2599) 41 and more, their checks 58
(`stroke_geometry.ARM_ANGLE_DEG`: an arm stands 45 degrees or more off its line). A barless radical drawn backwards,
its tick last, turns back as narrowly (17-40 degrees): the rule rests on the order people draw in, as
`open_marks.BACK_HOOK_LANDED_SHARE` does (issue 25, session 41: docs/BENCHMARKS.md)."""
LANDED_FLICK = 0.05
"""The end where the pen landed reaches back past the line's start by at most this share of the path
(`end_curls.CURL_TINY`: a flick): a check's or a tick's short arm drawn first is longer."""


def lifted_turn(raw: np.ndarray) -> np.ndarray | None:
    """``raw`` between its points farthest back and farthest on along its middle's way (`TURN_MIDDLE`), where what lies
    past the farthest on, up to where the pen lifted, turned back along the line (`TURN_SHARE`, `TURN_DEG`) and what
    lies before the farthest back is a flick at most (`LANDED_FLICK`); None otherwise.

    The `sign` set's ST5022 writers end lines so (issue 25, session 41): a long diagonal whose lifted end turns back
    along it for 5-24 % of the path, the landing end clean. `open_marks.retraced_ends` measures off the stroke's chord,
    start to end, which so long a turn skews past `open_marks.RETRACE_NEAR`, and caps a hook at
    `open_marks.BACK_HOOK_SHARE` within `open_marks.BACK_HOOK_DEG`; `end_curls.curled_ends` asks for a round curl. Only
    the end where the pen lifted is cut: where it landed, a check's or tick's short arm turns as sharply into its
    rising long arm (the design sets' checks: 17-30 % of the path at 33-50 degrees); where it lifted, no mark of the
    design or fourth groups with its landing end clean and the rest a line turns back within 60 degrees (square
    brackets' last arms 66 and more, braces' curls 64)."""
    at = sg.along(raw)
    length = float(at[-1])
    if not length > 0:
        return None
    x0, y0, x1, y1 = (float(np.interp(share * length, at, raw[:, k])) for share in TURN_MIDDLE for k in (0, 1))
    way = np.array([x1 - x0, y1 - y0])
    norm = float(np.hypot(*way))
    if norm == 0.0:
        return None
    on = raw @ (way / norm)
    lo, hi = int(np.argmin(on)), int(np.argmax(on))
    if hi == len(raw) - 1 or lo >= hi or at[lo] > LANDED_FLICK * length or at[hi] < (1.0 - TURN_SHARE) * length:
        return None
    angle = sg.angle_deg(raw[-1] - raw[hi], raw[lo] - raw[hi])
    if angle is None or angle > TURN_DEG:
        return None
    kept = raw[lo:hi + 1]
    return kept if len(kept) >= 2 else None
