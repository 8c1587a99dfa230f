"""Circle or ellipse for a loop gone round more than once, told from its lap from the start and its lap to the end."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from physink_tui.scene.recognition import open_shapes
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import CIRCLE_RATIO, round_geometry
from physink_tui.scene.recognition.closed_loops import CLOSED_GAP, encloses
from physink_tui.scene.recognition.loop_ends import SMALL_LOOP
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse

ROUND_KINDS = ("circle", "ellipse")


def lap_aspect(lap: np.ndarray, work: np.ndarray, diag: float, sigma: float, limit: float) -> float | None:
    """The width over the length of the ellipse fitted to ``lap`` (once round from one end of ``work``), where the lap
    comes back within ``limit`` of where it began, encloses an area (`closed_loops.encloses`), is no hook's small loop
    (`loop_ends.SMALL_LOOP`) and its ellipse fits it as closely as a round stroke's (`open_shapes.round_error`): what
    `closed_loops.closed_loop` asks of the lap it keeps round. None where it does not."""
    if lap is work or float(np.hypot(*(lap[-1] - lap[0]))) > limit:
        return None
    if not encloses(lap) or sg.bbox_diagonal(lap) < SMALL_LOOP * diag:
        return None
    ellipse = fit_ellipse(lap)
    if ellipse is None or not ellipse[4] < open_shapes.round_error(ellipse, sigma):
        return None
    _, rx, ry, _, _ = ellipse
    return min(rx, ry) / max(rx, ry) if max(rx, ry) > 0 else None


def round_kind_of_both_laps(work: np.ndarray, diag: float, sigma: float) -> str | None:
    """Circle or ellipse for a stroke gone round one way more than once (a circle drawn on past its start), told from
    both its laps alike: its lap from the start (`stroke_features.one_loop`, the lap `closed_loops.closed_loop` keeps)
    and its lap to the end (once round from the end), where both come back round (`lap_aspect`) and they disagree on
    circle or ellipse (one at `beautify.CIRCLE_RATIO` or over, one under): then by their mean width over length. None
    where the laps agree, or either does not come back round: the reading is the start lap's. Drawn from its other end,
    the same stroke's laps swap and the answer stays (session 32: 8 circles of the design sets were a circle one way and
    an ellipse the other, their laps 0.71-0.86 wide for their length)."""
    th = sg.turning(work)
    if abs(float(th.sum())) <= 2.0 * math.pi:
        return None
    limit = max(CLOSED_GAP * diag, 4 * sigma)
    first = lap_aspect(sf.one_loop(work, th), work, diag, sigma, limit)
    if first is None:
        return None
    back = work[::-1]
    last = lap_aspect(sf.one_loop(back, -th[::-1]), back, diag, sigma, limit)
    if last is None or (first >= CIRCLE_RATIO) == (last >= CIRCLE_RATIO):
        return None
    return "circle" if (first + last) / 2 >= CIRCLE_RATIO else "ellipse"


def round_from_both_laps(ranked: Recognition, work: np.ndarray, ellipse: EllipseFit | None, diag: float,
                         sigma: float) -> Recognition:
    """``ranked`` (a round reading of the loop whose `fit_ellipse` is ``ellipse``) as a circle or an ellipse as
    `round_kind_of_both_laps` tells it, its shape that ellipse's (rounded off to a circle, or as drawn); else as it
    was."""
    if ranked.kind not in ROUND_KINDS or ellipse is None:
        return ranked
    kind = round_kind_of_both_laps(work, diag, sigma)
    if kind is None or kind == ranked.kind:
        return ranked
    geometry, _ = round_geometry(ellipse, circle_ratio=0.0 if kind == "circle" else math.inf)
    others = tuple(a for a in ranked.alternatives if a[0] != kind)
    return replace(ranked, kind=kind, geometry=geometry, alternatives=others)
