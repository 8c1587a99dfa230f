"""Judges whether a hand-drawn stroke could be one arm of an X and whether two strokes make one; no I/O, no clock.

The recogniser names each stroke on its own, and a person's X arm is rarely a clean line: it bows, it ends in a
hook where the pen landed or lifted, and the two arms cross wherever the hand put them. So this module looks at a
stroke's extent and its middle rather than at its kind: the middle three fifths (free of end hooks) must be nearly
straight, and the whole stroke must stay close to that straight axis. Two such arms make an X when they cross
(or nearly cross) away from their ends at a clear angle. Geometry only: deciding what an X means is interpret's.

>>> a = [(0.0, 0.0), (10.0, 10.5), (20.0, 20.0), (21.0, 17.0)]       # a diagonal with a hook at its end
>>> b = [(0.0, 20.0), (9.0, 10.0), (20.0, 1.0)]
>>> pair_x(a, b).kind, [round(v) for v in pair_x(a, b).geometry.center]
('x', [10, 10])
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from physink_tui.scene.recognition.primitives import Line, Recognition, XSymbol
from physink_tui.scene.recognition.recognize import recognize_strokes

CORE = (0.2, 0.8)
"""The part of a stroke (shares of its path length) that must be straight: its ends may hook."""
CORE_BOW = 0.12
"""The straight part strays from its own axis by at most this share of its length (a hand's bow)."""
CORE_INK = 1.25
"""...and holds at most this much ink per unit of chord (no loops, no zigzag)."""
SPREAD = 0.35
"""The whole stroke, hooks included, stays within this share of its extent from the axis."""
INK = 2.0
"""The whole stroke holds at most this much ink per unit of extent along the axis."""
MIN_ANGLE = 40.0
"""Degrees between the arms of an X, at least."""
MIDDLE = 0.4
"""The arms cross within this share of each arm's length from its middle (0.5 would allow an L or a T)."""
LENGTH_RATIO = 3.0
"""The longer arm is at most this many times the shorter."""
RESAMPLE = 41
SMOOTHING = 5


def x_arm(points: Sequence[Sequence[float]], max_length: float = math.inf) -> Line | None:
    """The straight line a stroke stands for if it could be one arm of an X, else None.

    Args:
        points: the stroke's (x, y) points (extra columns are ignored).
        max_length: longer strokes (along their axis) are not arms.

    >>> arm = x_arm([(0, 0), (5, 0.4), (10, 0), (9, 2)])    # a bowed stroke with a hook
    >>> [round(v) for v in (*arm.start, *arm.end)]
    [0, 0, 10, 0]
    >>> x_arm([(0, 0), (5, 5), (10, 0)]) is None            # a caret is not an arm
    True
    """
    path = _resample(points)
    if path is None:
        return None
    lo, hi = (round(share * (RESAMPLE - 1)) for share in CORE)
    core = path[lo:hi + 1]
    centre = core.mean(axis=0)
    _, _, vt = np.linalg.svd(core - centre)
    d = vt[0]
    along, across = (path - centre) @ d, (path - centre) @ np.array([-d[1], d[0]])
    core_along, core_across = along[lo:hi + 1], across[lo:hi + 1]
    smooth = _smooth(path)  # ink is judged without the pen's jitter, which adds length to a small stroke
    core_chord = float(np.hypot(*(smooth[hi] - smooth[lo])))
    core_ink = _ink(smooth[lo:hi + 1])
    extent = float(along.max() - along.min())
    ink = _ink(smooth)
    if core_chord == 0.0 or extent == 0.0 or extent > max_length:
        return None
    core_length = float(core_along.max() - core_along.min())
    if float(np.abs(core_across).max()) > CORE_BOW * core_length or core_ink > CORE_INK * core_chord:
        return None
    if float(np.abs(across).max()) > SPREAD * extent or ink > INK * extent:
        return None
    if along[-1] < along[0]:  # keep the direction the pen moved
        d, along = -d, -along
    start, end = centre + float(along.min()) * d, centre + float(along.max()) * d
    return Line(_point(start), _point(end))


def pair_x(first: Sequence[Sequence[float]], second: Sequence[Sequence[float]],
           max_length: float = math.inf, noise: float = 1.0,
           times: tuple[Sequence[float] | None, Sequence[float] | None] = (None, None)) -> Recognition | None:
    """The X two consecutive strokes make, or None.

    The recogniser's own answer is taken when it finds an X; otherwise two arms (`x_arm`) that cross away from
    their ends at `MIN_ANGLE` degrees or more, neither more than `LENGTH_RATIO` times the other, make one. The first
    arm must be at most ``max_length`` long; the second at most `LENGTH_RATIO` times the first. ``noise`` is the
    pen's jitter in the strokes' units and ``times`` each stroke's point times in seconds, or None
    (`recognize.recognize_stroke`: the pen's times, as sketch mode gives it for a lone stroke).
    """
    a = x_arm(first, max_length)
    if a is None:
        return None
    b = x_arm(second, LENGTH_RATIO * math.dist(a.start, a.end))
    if b is None:
        return None
    recognised = _recognised_x(first, second, noise, times)
    if recognised is not None:
        return recognised
    crossing = _crossing(a, b)
    if crossing is None:
        return None
    centre, confidence = crossing
    return Recognition("x", confidence, XSymbol(centre, a, b), (("line", 0.5),))


def _recognised_x(first: Sequence[Sequence[float]], second: Sequence[Sequence[float]], noise: float,
                  times: tuple[Sequence[float] | None, Sequence[float] | None]) -> Recognition | None:
    """The recogniser's X (`recognize.recognize_strokes`), each stroke read with its own times; None when the
    recogniser finds no X."""
    found = recognize_strokes((first, second), noise=noise, times=times)
    return found if found.kind == "x" else None


def _crossing(a: Line, b: Line) -> tuple[tuple[float, float], float] | None:
    """Where two arms cross and how X-like they are (0.5-1), or None when they do not make an X."""
    p, r = np.array(a.start), np.array(a.end) - np.array(a.start)
    q, s = np.array(b.start), np.array(b.end) - np.array(b.start)
    la, lb = float(np.hypot(*r)), float(np.hypot(*s))
    denom = float(r[0] * s[1] - r[1] * s[0])
    if la == 0.0 or lb == 0.0 or denom == 0.0 or max(la, lb) > LENGTH_RATIO * min(la, lb):
        return None
    angle = math.degrees(math.asin(min(1.0, abs(denom) / (la * lb))))
    if angle < MIN_ANGLE:
        return None
    t = float((q - p)[0] * s[1] - (q - p)[1] * s[0]) / denom
    u = float((q - p)[0] * r[1] - (q - p)[1] * r[0]) / denom
    off = max(abs(t - 0.5), abs(u - 0.5))
    if off > MIDDLE:
        return None
    centre = p + t * r
    confidence = 0.5 + 0.5 * min(1.0, (angle - MIN_ANGLE) / 45.0) * (1.0 - off / 0.5)
    return _point(centre), confidence


def _resample(points: Sequence[Sequence[float]]) -> np.ndarray | None:
    """`RESAMPLE` points evenly spaced along the stroke, or None for a stroke without length or finite points."""
    try:
        pts = np.asarray([p[:2] for p in points], dtype=float)
    except (TypeError, ValueError):
        return None
    if pts.ndim != 2 or len(pts) < 2 or not np.isfinite(pts).all():
        return None
    steps = np.hypot(*np.diff(pts, axis=0).T)
    walked = np.concatenate(([0.0], np.cumsum(steps)))
    if walked[-1] == 0.0:
        return None
    at = np.linspace(0.0, walked[-1], RESAMPLE)
    return np.column_stack((np.interp(at, walked, pts[:, 0]), np.interp(at, walked, pts[:, 1])))


def _smooth(path: np.ndarray) -> np.ndarray:
    """A moving average over `SMOOTHING` points (ends kept where they are)."""
    k = SMOOTHING
    padded = np.concatenate((np.repeat(path[:1], k // 2, axis=0), path, np.repeat(path[-1:], k // 2, axis=0)))
    kernel = np.ones(k) / k
    return np.column_stack([np.convolve(padded[:, i], kernel, mode="valid") for i in (0, 1)])


def _ink(path: np.ndarray) -> float:
    return float(np.hypot(*np.diff(path, axis=0).T).sum())


def _point(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))
