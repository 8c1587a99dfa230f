"""Issue 25, session 19's closed-loop rules on people's strokes (the $1 set: three people outside the project, a
stylus), not only on the pen models that designed them: `closed_loops.no_round_shape` refuses a circle or ellipse to
every person's star and to no person's circle, and `closed_loops.ends_cross` closes no one-stroke x or delete mark
(their first and last strokes cross at their middles, far from the ends)."""

from __future__ import annotations

import json
from collections import Counter
from functools import cache

import numpy as np
from shared_data import shared_path

from physink_tui.scene.recognition import closed_loops
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.shape_fits import fit_ellipse


@cache
def people() -> tuple[tuple[str, np.ndarray, float], ...]:
    """Each $1 stroke as (label, points at unit size about its centre, a pixel's noise in those units)."""
    out = []
    for line in shared_path("strokes", "dollar1-dev.jsonl").read_text(encoding="utf-8").splitlines():
        row = json.loads(line)
        pts = np.asarray([p[:2] for p in row["strokes"][0]], dtype=float)
        origin = pts.mean(axis=0)
        scale = float(np.abs(pts - origin).max())
        out.append((row["label"], (pts - origin) / scale, 1.0 / scale))
    return tuple(out)


def _counts(rule) -> tuple[Counter[str], Counter[str]]:  # type: ignore[no-untyped-def]
    fired, seen = Counter[str](), Counter[str]()
    for label, unit, noise in people():
        seen[label] += 1
        with np.errstate(all="ignore"):
            fired[label] += bool(rule(unit, noise))
    return fired, seen


def test_people_s_stars_are_no_round_shape_and_their_circles_are() -> None:
    """Measured: 90 of 90 stars refused, 0 of 90 circles (rectangles 1 of 90: a box is read by its sides anyway)."""
    def refused(unit: np.ndarray, noise: float) -> bool:
        loop = sg.resample(unit, 64)
        return closed_loops.no_round_shape(loop, noise, fit_ellipse(loop))

    fired, seen = _counts(refused)
    assert seen["star"] == seen["circle"] == 90
    assert fired["star"] == 90, fired
    assert fired["circle"] == 0, fired


def test_people_s_x_marks_and_delete_marks_do_not_close_by_their_crossing() -> None:
    """Measured: 0 of 90 x's, 0 of 90 delete marks (stars 17, triangles 10: their tails do cross at a corner)."""
    def crossed(unit: np.ndarray, noise: float) -> bool:
        return closed_loops.ends_cross(sg.resample(unit, 128), sg.bbox_diagonal(unit))

    fired, seen = _counts(crossed)
    assert seen["x"] == seen["delete_mark"] == 90
    assert fired["x"] == fired["delete_mark"] == 0, fired
    assert fired["star"] + fired["triangle"] > 0, fired  # the rule is alive on people's closings
