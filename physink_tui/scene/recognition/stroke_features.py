"""Features of a resampled stroke that recognition judges by: corners' sharpness, lobes, closure,
loops, polygon sides; pure numpy, no decisions about kinds."""

from __future__ import annotations

import itertools
import math

import numpy as np
from shapely.geometry import MultiPoint

from physink_tui.scene.recognition import shape_turning
from physink_tui.scene.recognition import stroke_geometry as sg


def drop_end_stubs(work: np.ndarray, corners: list[int], length: float, fraction: float = 0.07) -> list[int]:
    """Forget corners that only cut a tiny first or last piece off the stroke (an unremoved hook)."""
    corners = list(corners)
    while len(corners) > 2 and sg.path_length(work[: corners[1] + 1]) < fraction * length:
        corners.pop(1)
    while len(corners) > 2 and sg.path_length(work[corners[-2]:]) < fraction * length:
        corners.pop(-2)
    return corners


NO_TURN_DEG = 1e-6
"""A step of a stroke's coarse turning under this (degrees) is straight on: the float rounding of a straight run's
headings (a mouse's or a lattice's points along one row: exactly 0 drawn one way, about 1e-15 mirrored)."""


def lobes(work: np.ndarray, min_deg: float = 35.0, noise: float = 0.0) -> list[float]:
    """Net turning (degrees) of each run of same-direction turning on a coarse copy of the stroke (coarser
    when the pen's ``noise`` is large), ignoring runs under ``min_deg``: a brace has five such lobes, a check
    mark one or two."""
    return turn_lobes(shape_turning.coarse_turning(work, noise), min_deg)


def turn_lobes(coarse: np.ndarray, min_deg: float = 35.0) -> list[float]:
    """`lobes` of a stroke whose coarse turning (`shape_turning.coarse_turning`, radians) is already known. A step
    turning by no more than `NO_TURN_DEG` either way joins the run it is in, whichever way that turns: it neither ends a
    run turning one way nor starts one (a zero once counted as turning left: it broke a run turning right into pieces
    each under ``min_deg``, so a stroke and its mirror image had different lobes)."""
    runs: list[float] = []
    for v in np.degrees(coarse).tolist():
        if runs and (abs(v) <= NO_TURN_DEG or abs(runs[-1]) <= NO_TURN_DEG or (v > 0) == (runs[-1] > 0)):
            runs[-1] += v
        else:
            runs.append(v)
    lobes: list[float] = []
    for r in (r for r in runs if abs(r) >= min_deg):
        if lobes and (r >= 0) == (lobes[-1] >= 0):
            lobes[-1] += r
        else:
            lobes.append(r)
    return lobes


def corner_turns(th: np.ndarray, corners: list[int], reach: int = 3) -> list[float]:
    """Net turning (degrees) right at each inner corner: a check mark's corner turns over 90 degrees,
    the top of a question mark's curl turns about 50 where the corner finder cut it."""
    n = len(th) + 2
    out = []
    for c in corners[1:-1]:
        lo, hi = max(c - reach, 1), min(c + reach, n - 2)
        out.append(abs(math.degrees(float(np.add.reduce(th[lo - 1:hi])))))
    return out or [0.0]


def bends(th: np.ndarray, corners: list[int], reach: int = 3) -> list[float]:
    """Net turning (degrees) along each segment, away from its corners."""
    n = len(th) + 2
    out = []
    for a, b in itertools.pairwise(corners):
        lo = a + reach if a > 0 else 0
        hi = b - reach if b < n - 1 else n - 2
        out.append(abs(math.degrees(float(np.add.reduce(th[lo:max(hi - 1, lo)])))))
    return out


def corner_share(th: np.ndarray, corners: list[int], reach: int = 3) -> float:
    """Share of the turning done at the corners rather than along the segments between them.

    Net turning is summed per window, so hand jitter cancels: a check mark whose long arm bows
    still turns mostly at its corner; a brace or a question mark turns mostly along its curls.
    """
    n = len(th) + 2
    at_corners, along = 0.0, 0.0
    inner = corners[1:-1]
    bounds = [0]
    for c in inner:
        lo, hi = max(c - reach, 1), min(c + reach, n - 2)
        at_corners += abs(float(np.add.reduce(th[lo - 1:hi])))
        bounds += [lo - 1, hi]
    bounds.append(n - 2)
    for a, b in zip(bounds[::2], bounds[1::2], strict=True):
        along += abs(float(np.add.reduce(th[a:b])))
    total = at_corners + along
    return at_corners / total if total else 0.0


def heading_home(work: np.ndarray, corners: list[int], max_deg: float = 50.0) -> bool:
    """Whether the last side points at the stroke's start (a polygon the pen lifted from too early)."""
    home = work[0] - work[-1]

    def angle(v: np.ndarray) -> float:
        between = sg.angle_deg(v, home)
        return 0.0 if between is None else between

    # the last side aims at the start, or the pen stopped at a corner and the gap runs along the first side's line
    # (the start lies on from the end the way the first side goes, or, drawn past the start, back from it)
    first = angle(work[corners[1]] - work[0])
    return angle(work[-1] - work[corners[-2]]) <= max_deg or first <= max_deg or first >= 180.0 - max_deg


RUN_PAST_START = 0.45
"""The pen landed up to this share of the first side along it from the polygon's first corner, the corner its last
side ran through (`ran_through_first_corner`; `penmodels.triangle_habits`' start-short families land 0.1-0.45 along)."""


def ran_through_first_corner(work: np.ndarray, corners: list[int]) -> bool:
    """Whether the last side ran through the polygon's first corner and on past it, the pen having landed up to
    `RUN_PAST_START` along the first side: the first side's line, drawn back from the start, meets the last side's
    line within the last side as drawn, in its second half (the run past the corner no longer than the side up to it).
    Such an end, however far it ran, need not point home nor come back near the start, as `heading_home` and `closure`
    ask (quickdraw's triangles begun along a side and overshot at the close: tutorboard seed90210 #309)."""
    if len(corners) < 4:
        return False
    p, a = work[0], work[corners[-2]]
    met = sg.line_meet(p, work[corners[1]] - p, a, work[-1] - a)
    if met is None:
        return False
    _, t, u = met  # t along the first side from the start (0) to its corner (1), u the last from its corner to the end
    return -RUN_PAST_START / (1.0 - RUN_PAST_START) <= t <= 0.0 and 0.5 <= u <= 1.0


def closure(work: np.ndarray, diag: float) -> float:
    """How nearly the stroke returns to its start, over its size: the gap between its ends, or, for a
    stroke drawn past its start (or started before it), twice the closest approach of one end to
    the other end's first fifth (a shape closes through its ends, not through its middle)."""
    n = len(work)
    gap = float(np.hypot(*(work[-1] - work[0])))
    tail = work[int(n * 0.8):]
    head = work[: max(2, int(n * 0.2))]
    d1 = float(np.minimum.reduce(np.hypot(*(tail - work[0]).T)))
    d2 = float(np.minimum.reduce(np.hypot(*(head - work[-1]).T)))
    return min(gap, 2 * d1, 2 * d2) / diag


def retraced(work: np.ndarray, th: np.ndarray, diag: float) -> bool:
    """Whether what comes after the first time round runs back over it (a shape drawn twice),
    rather than on new ground (a star turns twice round on different sides)."""
    end = int(np.searchsorted(np.abs(np.add.accumulate(th)), 2 * math.pi)) + 2
    first, rest = work[:end], work[end:]
    if len(rest) < 4 or len(first) < 4:
        return False
    limit = 0.06 * diag
    # asked first, at no cost: no point of ``rest`` is nearer ``first`` than its bounding box, so where a tenth of
    # them or more are that far from the box (an order statistic at or below the quantile's), the quantile is too
    outside = np.maximum(np.maximum(first.min(axis=0) - rest, rest - first.max(axis=0)), 0.0)
    k = max(int(0.9 * (len(rest) - 1)) - 1, 0)
    if float(np.partition(np.hypot(outside[:, 0], outside[:, 1]), k)[k]) >= limit * (1 + 1e-9):
        return False
    d = np.hypot(rest[:, None, 0] - first[None, :, 0], rest[:, None, 1] - first[None, :, 1]).min(axis=1)
    # the quantile lies between the two order statistics it is interpolated from: where both are clearly on one
    # side of the limit (a hair's margin for the interpolation's rounding), so is it, without working it out
    at = 0.9 * (len(d) - 1)
    below, above = np.partition(d, (math.floor(at), math.ceil(at)))[[math.floor(at), math.ceil(at)]].tolist()
    if above < limit * (1 - 1e-9):
        return True
    if below >= limit * (1 + 1e-9):
        return False
    return float(np.quantile(d, 0.9)) < limit


def one_loop(work: np.ndarray, th: np.ndarray) -> np.ndarray:
    """The stroke once round: up to where it comes closest to its start while its turning is
    between 1.5 and 2.5 pi (robust to where exactly a corner completes the turn), resampled."""
    cum = np.abs(np.concatenate([[0.0, 0.0], np.add.accumulate(th)]))  # turning done on reaching each point
    window = np.flatnonzero((cum >= 1.5 * math.pi) & (cum <= 2.5 * math.pi))
    if not len(window):
        return work
    gaps = np.hypot(*(work[window] - work[0]).T)
    end = int(window[int(np.argmin(gaps))]) + 1
    return sg.resample(work[: max(end, 8)], len(work))


def turn_concentration(th: np.ndarray) -> float:
    """Share of all turning done in the sharpest fifth of the stroke (boxes ~0.9, circles ~0.3)."""
    a = np.abs(th)
    total = float(np.add.reduce(a))
    if total == 0.0:
        return 0.0
    k = max(1, len(a) // 5)
    return float(np.add.reduce(np.sort(a)[-k:])) / total


def corner_roundness(work: np.ndarray, corners: list[int], share: float = 0.8, *, th: np.ndarray | None = None,
                     ) -> list[float]:
    """How round each inner corner is: the length of path, centred on the corner, over which the stroke does
    ``share`` of the turning it does between the midpoints of its neighbouring sides, over the shorter of those
    two sides. A drawn corner turns within a tenth or two of its sides; a brace's or a question mark's bend
    takes as long as a side. ``th``: `stroke_geometry.turning` of ``work`` where already known."""
    return roundness_along(walk(work, th), corners, share)


def walk(work: np.ndarray, th: np.ndarray | None = None) -> tuple[list[float], list[float]]:
    """The turning done before each point of ``work`` but the first (``th``: `stroke_geometry.turning` of ``work``
    where already known) and the path drawn to each point, from the start: what `corner_roundness` walks along, as plain
    floats (each corner's walk looks at a few of them one at a time)."""
    if th is None:
        th = sg.turning(work)  # th[k] is the turn at point k + 1
    cum_turn = [0.0, *np.add.accumulate(th).tolist()]  # cum_turn[k]: turning done before point k + 1
    d = work[1:] - work[:-1]
    cum_len = [0.0, *np.add.accumulate(np.hypot(d[:, 0], d[:, 1])).tolist()]
    return cum_turn, cum_len


def roundness_along(walked: tuple[list[float], list[float]], corners: list[int], share: float = 0.8) -> list[float]:
    """`corner_roundness` of the stroke whose `walk` is ``walked``."""
    cum_turn, cum_len = walked
    n = len(cum_len)
    out = []
    for a, c, b in zip(corners, corners[1:], corners[2:], strict=False):
        lo, hi = (a + c) // 2, (c + b) // 2
        total = abs(cum_turn[max(hi - 1, 0)] - cum_turn[max(lo - 1, 0)])
        shorter = min(cum_len[c] - cum_len[a], cum_len[b] - cum_len[c])
        if total == 0.0 or shorter <= 0.0:
            out.append(0.0)
            continue
        need = share * total
        r = max(hi - lo, 1) - 1  # the widest reach, unless the turning is held within a shorter one
        for k in range(r + 1):
            if abs(cum_turn[min(c + k, n - 2)] - cum_turn[max(c - 1 - k, 0)]) >= need:
                r = k
                break
        arc = cum_len[min(c + r, n - 1)] - cum_len[max(c - r, 0)]
        out.append(arc / shorter)
    return out


def figure_eight(vertices: np.ndarray, share: float = 0.5) -> bool:
    """Whether a closed outline crosses over itself into lobes turning opposite ways (it winds round no net turn)
    and those lobes cancel: its signed area is under ``share`` of its hull's. A delete mark whose ends meet is
    such a bow tie; a triangle with a small loop at a corner winds once less but keeps most of its area."""
    v = np.asarray(vertices, dtype=float)
    if len(v) < 4:
        return False
    sides = sg.succ(v) - v
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    turns = (sg.succ(heading) - heading + math.pi) % (2 * math.pi) - math.pi
    if round(float(turns.sum()) / (2 * math.pi)) != 0:
        return False
    return abs(_signed_area(v)) < share * _hull_area(v)


def _signed_area(v: np.ndarray) -> float:
    x, y = v[:, 0], v[:, 1]
    return 0.5 * float((x * sg.succ(y) - sg.succ(x) * y).sum())


def _hull_area(v: np.ndarray) -> float:
    """Area of the convex hull (0 for fewer than three points or points in a line)."""
    return float(MultiPoint(v).convex_hull.area)


def closing_sides(work: np.ndarray, corners: list[int], straight: float, end_bow: float,
                  gap_sides: float) -> np.ndarray | None:
    """The sides of the outline ``work`` draws between its ``corners`` (indices, its ends among them), closed through
    the gap between its ends (the last side), or None: unless every side drawn is straight (bowed under ``straight``
    of its chord, the first and last under ``end_bow``: the hand swings as it lands and lifts) and the gap is at most
    ``gap_sides`` of the longest side drawn."""
    bows = [sg.chord_deviation(work[a:b + 1]) for a, b in itertools.pairwise(corners)]
    if max(bows[1:-1]) >= straight or max(bows[0], bows[-1]) >= end_bow:
        return None
    ring = np.vstack([work[corners], work[corners[:1]]])
    sides = np.diff(ring, axis=0)
    lengths = np.hypot(sides[:, 0], sides[:, 1])
    if not lengths[:-1].max() > 0 or lengths[-1] > gap_sides * lengths[:-1].max():
        return None
    return sides


def ring_turns(sides: np.ndarray) -> np.ndarray:
    """The turn (radians, signed) at the start of each of a closed ring's ``sides``' successors: at corner k + 1."""
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    return np.asarray((np.diff(np.append(heading, heading[0])) + math.pi) % (2 * math.pi) - math.pi)
