"""Circle or ellipse for a loop gone round more than once, told from its lap from the start and its lap to the end."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from physink_tui.scene.recognition import open_shapes
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import CIRCLE_RATIO, round_geometry, within
from physink_tui.scene.recognition.closed_loops import CLOSED_GAP, encloses
from physink_tui.scene.recognition.loop_ends import SMALL_LOOP
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse

ROUND_KINDS = ("circle", "ellipse")


def lap_fit(lap: np.ndarray, work: np.ndarray, diag: float, sigma: float, limit: float) -> EllipseFit | None:
    """The ellipse fitted to ``lap`` (once round from one end of ``work``), where the lap comes back within ``limit`` of
    where it began, encloses an area (`closed_loops.encloses`), is no hook's small loop (`loop_ends.SMALL_LOOP`) and its
    ellipse fits it as closely as a round stroke's (`open_shapes.round_error`): what `closed_loops.closed_loop` asks of
    the lap it keeps round. None where it does not."""
    if lap is work or float(np.hypot(*(lap[-1] - lap[0]))) > limit:
        return None
    if not encloses(lap) or sg.bbox_diagonal(lap) < SMALL_LOOP * diag:
        return None
    ellipse = fit_ellipse(lap)
    if ellipse is None or not ellipse[4] < open_shapes.round_error(ellipse, sigma):
        return None
    return ellipse if max(ellipse[1], ellipse[2]) > 0 else None


def aspect(ellipse: EllipseFit) -> float:
    """An ellipse's width over its length."""
    return min(ellipse[1], ellipse[2]) / max(ellipse[1], ellipse[2])


def both_lap_fits(work: np.ndarray, diag: float, sigma: float) -> tuple[EllipseFit, EllipseFit] | None:
    """The ellipses of a stroke gone round one way more than once (a circle drawn on past its start): of its lap from
    the start (`stroke_features.one_loop`, the lap `closed_loops.closed_loop` keeps) and of its lap to the end (once
    round from the end), where both come back round (`lap_fit`); None where either does not, or the stroke turns no
    more than once round."""
    th = sg.turning(work)
    if abs(float(th.sum())) <= 2.0 * math.pi:
        return None
    limit = max(CLOSED_GAP * diag, 4 * sigma)
    first = lap_fit(sf.one_loop(work, th), work, diag, sigma, limit)
    if first is None:
        return None
    back = work[::-1]
    last = lap_fit(sf.one_loop(back, -th[::-1]), back, diag, sigma, limit)
    return None if last is None else (first, last)


def round_kind_of_both_laps(laps: tuple[EllipseFit, EllipseFit] | None) -> str | None:
    """Circle or ellipse for a stroke gone round more than once, told from both its laps alike (``laps``:
    `both_lap_fits`) where they disagree on circle or ellipse (one at `beautify.CIRCLE_RATIO` or over, one under): then
    by their mean width over length. None where the laps agree, or either does not come back round: the reading is the
    start lap's. Drawn from its other end, the same stroke's laps swap and the answer stays (session 32: 8 circles of
    the design sets were a circle one way and an ellipse the other, their laps 0.71-0.86 wide for their length)."""
    if laps is None:
        return None
    first, last = aspect(laps[0]), aspect(laps[1])
    if (first >= CIRCLE_RATIO) == (last >= CIRCLE_RATIO):
        return None
    return "circle" if (first + last) / 2 >= CIRCLE_RATIO else "ellipse"


def round_from_both_laps(ranked: Recognition, work: np.ndarray, ellipse: EllipseFit | None, diag: float,
                         sigma: float, bounds: tuple[np.ndarray, np.ndarray] | None = None) -> Recognition:
    """``ranked`` (a round reading of the loop whose `fit_ellipse` is ``ellipse``) as a circle or an ellipse as
    `round_kind_of_both_laps` tells it, its shape that ellipse's (rounded off to a circle, or as drawn); or, where both
    laps are round enough for a circle but it was read an ellipse because the circle rounded off from the start lap
    reaches past the stroke's ``bounds`` (`ranking.rank`'s, from least to greatest x and y; given for an ellipse), a
    circle where the one rounded off from the lap to the end stays within them (`circle_within_either_lap`); else as it
    was."""
    if ranked.kind not in ROUND_KINDS or ellipse is None:
        return ranked
    laps = both_lap_fits(work, diag, sigma)
    kind = round_kind_of_both_laps(laps)
    if kind is None:
        circle = None if bounds is None else circle_within_either_lap(ranked, laps, ellipse, bounds)
        return ranked if circle is None else circle
    if kind == ranked.kind:
        return ranked
    geometry, _ = round_geometry(ellipse, circle_ratio=0.0 if kind == "circle" else math.inf)
    others = tuple(a for a in ranked.alternatives if a[0] != kind)
    return replace(ranked, kind=kind, geometry=geometry, alternatives=others)


def circle_within_either_lap(ranked: Recognition, laps: tuple[EllipseFit, EllipseFit] | None, ellipse: EllipseFit,
                             bounds: tuple[np.ndarray, np.ndarray]) -> Recognition | None:
    """A circle for an ellipse reading whose kept loop (fitted by ``ellipse``) and both laps (``laps``) are round enough
    for one (`beautify.CIRCLE_RATIO`), but whose circle rounded off from ``ellipse`` reaches past ``bounds``: the circle
    rounded off from the other lap, where that one stays within them. Asked of both laps alike, a stroke whose circle
    pokes out by a hair from one lap reads as drawn from its other end (session 33: hcira sinarest Subject3 circle10 and
    jd4386 User02 circle04, an ellipse one way, a circle the other). None where it does not apply."""
    if ranked.kind != "ellipse" or laps is None or aspect(ellipse) < CIRCLE_RATIO:
        return None
    if min(aspect(laps[0]), aspect(laps[1])) < CIRCLE_RATIO:
        return None
    kept, _ = round_geometry(ellipse, circle_ratio=0.0)
    if within(kept, *bounds):
        return None  # not read an ellipse for poking out
    for lap in laps:
        circle, _ = round_geometry(lap, circle_ratio=0.0)
        if within(circle, *bounds):
            others = tuple(a for a in ranked.alternatives if a[0] != "circle")
            return replace(ranked, kind="circle", geometry=circle, alternatives=others)
    return None
