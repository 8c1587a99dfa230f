"""Stroke geometry for recognition: cleaning, resampling, turning angles, corners; no classification.

Everything works on numpy arrays of shape (n, 2) in the stroke's own units, so recognition is the
same at any scale. Corners are found in the ShortStraw way (Wolin et al. 2008: short "straws"
between resampled points mark corners) with IStraw's refinements (Xiong & LaViola 2009: a corner
must turn the path by a real angle, and near-collinear corners are merged). Turning at the scale of the shape,
beyond the pen's tremor, is `shape_turning`'s.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import linalg_cores
from physink_tui.scene.recognition.diameter_bounds import diameter_bound

try:  # `np.interp`'s compiled core, which it calls on real points without a period once it has checked their type
    from numpy._core.multiarray import interp as _interp  # (tests/test_private_interp.py: still there, same numbers)
except ImportError:  # another numpy: the public function, the same numbers
    _interp = np.interp

MAX_WORKING_POINTS = 4000
"""Longer strokes are thinned by arc length first, so recognition time stays bounded."""


def drop_duplicates(pts: np.ndarray) -> np.ndarray:
    """Remove consecutive repeated points."""
    if len(pts) < 2:
        return pts
    keep = np.ones(len(pts), dtype=bool)
    keep[1:] = np.any(np.diff(pts, axis=0) != 0.0, axis=1)
    return pts[keep]


def path_length(pts: np.ndarray) -> float:
    if len(pts) < 2:
        return 0.0
    d = pts[1:] - pts[:-1]  # as np.diff, without its per-call overhead (this is called thousands of times a stroke)
    return float(np.add.reduce(np.hypot(d[:, 0], d[:, 1])))  # `.sum()`'s own sum, without its per-call overhead


def step_lengths(pts: np.ndarray) -> np.ndarray:
    """The length of each step between neighbouring points: ``np.hypot(*np.diff(pts, axis=0).T)`` to the bit, without
    ``np.diff``'s per-call overhead."""
    d = pts[1:] - pts[:-1]
    out: np.ndarray = np.hypot(d[:, 0], d[:, 1])
    return out


def along(pts: np.ndarray) -> np.ndarray:
    """The path's length from its start to each point: ``np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts,
    axis=0).T))])`` to the bit, without those calls' per-call overhead (this is asked thousands of times a stroke)."""
    if len(pts) == 0:
        return np.zeros(1)
    d = pts[1:] - pts[:-1]
    out = np.empty(len(pts))
    out[0] = 0.0
    np.add.accumulate(np.hypot(d[:, 0], d[:, 1]), out=out[1:])  # `np.cumsum`'s own sums
    return out


def succ(a: np.ndarray) -> np.ndarray:
    """Each element's (row's) successor round a closed outline, the first after the last: ``np.roll(a, -1, axis=0)``,
    the same array, without its per-call overhead."""
    return np.concatenate([a[1:], a[:1]])


def resample(pts: np.ndarray, n: int) -> np.ndarray:
    """``n`` points equally spaced along the path (first and last kept)."""
    d = pts[1:] - pts[:-1]
    cum = np.empty(len(pts))
    cum[0] = 0.0
    np.add.accumulate(np.hypot(d[:, 0], d[:, 1]), out=cum[1:])  # `np.cumsum`'s own sums
    total = cum[-1]
    if total == 0.0 or n < 2:
        return np.repeat(pts[:1], max(n, 1), axis=0)
    targets = spaced(float(total), n)
    out = np.empty((n, 2))
    out[:, 0] = _interp(targets, cum, pts[:, 0])  # (``np.interp``'s own numbers: float points, no period)
    out[:, 1] = _interp(targets, cum, pts[:, 1])
    return out


def spaced(total: float, n: int) -> np.ndarray:
    """``np.linspace(0.0, total, n)`` to the last bit (n >= 2), without its per-call overhead."""
    step = total / (n - 1)
    if step == 0.0:
        return np.linspace(0.0, total, n)
    out = np.arange(n, dtype=float)
    out *= step
    out[-1] = total
    return out


def smooth(pts: np.ndarray, passes: int = 2) -> np.ndarray:
    """A light [1, 2, 1] / 4 filter along the path, ends kept: takes out per-sample jitter and grid
    steps of coarse devices while corners (judged over several points) stay sharp."""
    if len(pts) < 3 or passes < 1:
        return pts.copy()
    out = pts.astype(np.result_type(pts.dtype, 0.25))  # a copy, in floats (as the filter's quarters are)
    inner = np.empty_like(out[1:-1])
    for _ in range(passes):  # ``(out[:-2] + 2 * out[1:-1] + out[2:]) / 4``, the same operations in one buffer, made
        np.multiply(out[1:-1], 2, out=inner)  # whole before it is written back
        np.add(out[:-2], inner, out=inner)
        np.add(inner, out[2:], out=inner)
        np.divide(inner, 4, out=inner)
        out[1:-1] = inner
    return out


def turning(pts: np.ndarray) -> np.ndarray:
    """Signed turning angle at each interior vertex (radians, wrapped to -pi..pi); a step straight back turns the way
    the stroke turns round it (`_turn_back`), so a stroke and its mirror image turn by opposite angles."""
    d = pts[1:] - pts[:-1]
    heading = np.arctan2(d[:, 1], d[:, 0])
    th: np.ndarray = heading[1:] - heading[:-1]
    th += np.pi  # ``(dth + pi) % (2 pi) - pi`` to the bit, in place
    np.remainder(th, 2 * np.pi, out=th)
    th -= np.pi
    if len(th) and np.minimum.reduce(th) == -np.pi:  # (`.min()`'s own reduction, without its per-call overhead)
        _turn_back(th)
    return th


def _turn_back(th: np.ndarray) -> None:
    """Give each exact turn back (wrapped to -pi whichever way a mirror image turns) the sign of the turns next to it,
    else of the stroke's other turns, in place: -pi only where nothing else turns (a line drawn back over itself)."""
    back = th == -np.pi
    rest = np.where(back, 0.0, th)
    total = float(rest.sum())
    for k in np.flatnonzero(back):
        way = float(rest[max(int(k) - 1, 0)] + (rest[k + 1] if k + 1 < len(th) else 0.0)) or total
        if way > 0.0:
            th[k] = np.pi


def line_meet(p: np.ndarray, r: np.ndarray, q: np.ndarray, s: np.ndarray,
              min_sine: float = 1e-9) -> tuple[np.ndarray, float, float] | None:
    """Where the line ``p + t r`` meets the line ``q + u s``: ``(point, t, u)``, each parameter in [0, 1] within the
    segment its line spans from ``p`` to ``p + r`` (``q`` to ``q + s``); None where the lines are parallel, the sine of
    the angle between them ``min_sine`` or less (or a direction has no length).

    >>> line_meet(np.array([0.0, 0.0]), np.array([2.0, 0.0]), np.array([1.0, -1.0]), np.array([0.0, 4.0]))
    (array([1., 0.]), 0.5, 0.25)
    """
    den = float(r[0] * s[1] - r[1] * s[0])
    if abs(den) <= min_sine * math.hypot(float(r[0]), float(r[1])) * math.hypot(float(s[0]), float(s[1])):
        return None
    w = q - p
    t = float(w[0] * s[1] - w[1] * s[0]) / den
    return p + t * r, t, float(w[0] * r[1] - w[1] * r[0]) / den


_DIRECTIONS = np.array([[math.cos(a), math.sin(a)] for a in np.linspace(0.0, math.pi, 32, endpoint=False)])


def bbox_diagonal(pts: np.ndarray) -> float:
    """The points' diameter (their largest extent in any direction, within 0.2 %): the diagonal of
    an upright box, and a size that rotating the stroke does not change."""
    if len(pts) < 2:
        return 0.0
    proj = pts @ _DIRECTIONS.T
    return float(np.maximum.reduce(proj.max(axis=0) - proj.min(axis=0)))  # (`.max()`'s own reduction, as below)


def thickness(pts: np.ndarray) -> float:
    """Extent of the points across their principal axis (rotation-independent; 0 for a straight line)."""
    centred = pts - np.add.reduce(pts, axis=0) / len(pts)  # `pts.mean(axis=0)` to the bit, without its overhead
    across = centred @ linalg_cores.svd_vt(centred)[-1]
    return float(np.maximum.reduce(across) - np.minimum.reduce(across))


def chord_deviation(pts: np.ndarray) -> float:
    """Largest distance of a run of points from the chord between its ends, over the chord length."""
    rel = pts - pts[0]
    d = rel[-1]  # the chord
    chord = float(np.hypot(d[0], d[1]))
    if chord == 0.0:
        return math.inf
    dev = np.abs(rel[:, 0] * (d[1] / chord) - rel[:, 1] * (d[0] / chord))
    return float(np.maximum.reduce(dev)) / chord


def find_corners(pts: np.ndarray, min_turn_deg: float = 45.0, window: int = 3, *, every_dip: bool = False,
                 th: np.ndarray | None = None) -> list[int]:
    """Corner indices of a resampled stroke (equal spacing), endpoints included.

    A candidate is a local minimum of the straw ``|p[i+w] - p[i-w]|`` below 95 % of the median
    straw (ShortStraw): the lowest of each run of short straws, and with ``every_dip`` each other dip in the run at
    least ``window`` points from a lower one that turns the path by `DIP_TURN_DEG` (an arrow's head or a zig-zag's
    small teeth, whose sides are shorter than the straw, make one run of short straws with a dip at each sharp corner;
    a brace's tip, one run too, turns less where it leaves and rejoins the stroke). It is kept only if the path turns
    by at least ``min_turn_deg`` across it (so gentle curves make no corners), and corners closer than ``window``
    points merge. ``th``: the `turning` of ``pts``, where already measured.
    """
    n = len(pts)
    w = window
    if n < 2 * w + 3:
        return [0, n - 1]
    straws = np.full(n, np.inf)
    straws[w:n - w] = np.hypot(*(pts[2 * w:] - pts[:n - 2 * w]).T)
    threshold = median(straws[w:n - w]) * 0.95
    short = straws.tolist()  # the same numbers as Python floats: the walk below compares them one at a time
    candidates: list[tuple[int, float]] = []  # a corner's index and the least it must turn (degrees)
    i = w
    while i < n - w:
        if short[i] < threshold:
            j = i
            best = i
            while j < n - w and short[j] < threshold:
                if short[j] < short[best]:
                    best = j
                j += 1
            candidates.append((best, min_turn_deg))
            if every_dip:
                candidates += [(d, max(min_turn_deg, DIP_TURN_DEG)) for d in _dips(straws, i, j, w) if d != best]
            i = j
        else:
            i += 1
    th = turning(pts) if th is None else th  # th[k] is the turn at vertex k + 1
    corners = [0]
    reach = max(w, 2)
    for c, least in sorted(candidates):
        lo, hi = max(c - reach, 1), min(c + reach, n - 2)
        if c - corners[-1] < w:
            continue  # too close to the last corner kept, however far it turns
        turn = abs(float(np.add.reduce(th[lo - 1:hi])))
        if math.degrees(turn) >= least:
            corners.append(c)
    if n - 1 - corners[-1] < w and len(corners) > 1:
        corners.pop()
    corners.append(n - 1)
    return _merge_collinear(pts, corners)


DIP_TURN_DEG = 90.0
"""How far the path must turn at a dip in a run of short straws that is not the run's lowest to be a corner too."""


def _dips(straws: np.ndarray, lo: int, hi: int, w: int) -> list[int]:
    """The local minima of ``straws[lo:hi]`` (a run of short straws), lowest first kept, none within ``w`` points of a
    lower one kept before it; in path order."""
    run = straws[lo:hi]
    dips = [lo + k for k in range(len(run))
            if (k == 0 or run[k] <= run[k - 1]) and (k == len(run) - 1 or run[k] <= run[k + 1])]
    kept: list[int] = []
    for d in sorted(dips, key=lambda d: (straws[d], d)):
        if all(abs(d - k) >= w for k in kept):
            kept.append(d)
    return sorted(kept)


def _merge_collinear(pts: np.ndarray, corners: list[int], ratio: float = 0.975) -> list[int]:
    """Drop corners whose neighbours are almost in line with them (path length vs chord)."""
    if len(corners) <= 2:
        return corners
    d = pts[1:] - pts[:-1]
    seg = np.hypot(d[:, 0], d[:, 1])  # a run's `path_length` is the sum of its stretch of these, summed alike
    measured: dict[tuple[int, int], float] = {}  # each pair of corners' straightness, measured once
    changed = True
    while changed and len(corners) > 2:
        changed = False
        best, best_k = 0.0, -1
        for k in range(1, len(corners) - 1):
            a, b = corners[k - 1], corners[k + 1]
            if (a, b) not in measured:
                chord = float(np.hypot(*(pts[b] - pts[a])))
                run = float(np.add.reduce(seg[a:b]))
                measured[a, b] = chord / run if run else 1.0
            straightness = measured[a, b]
            if straightness > ratio and straightness > best:
                best, best_k = straightness, k
        if best_k > 0:
            corners.pop(best_k)
            changed = True
    return corners


def remove_hooks(pts: np.ndarray, max_fraction: float = 0.1, min_turn_deg: float = 70.0) -> np.ndarray:
    """Cut a short sharply bent tail at either end (the pen landing or lifting), PaleoSketch style.

    A tail counts as a hook when it is at most ``max_fraction`` of the path and the path turns by
    at least ``min_turn_deg`` where it joins the rest, unless it is a short straight arm (`end_arm`): at one end, of
    a stroke with no other corner (a tick); at both ends, of a straight run with no point (a square bracket).
    """
    n = len(pts)
    if n < 12:
        return pts
    gap = float(np.hypot(*(pts[-1] - pts[0])))
    if not gap >= 0.05 * diameter_bound(pts) and gap < 0.05 * bbox_diagonal(pts):  # (the bound settles most)
        return pts  # a closed shape: what looks like a hook may be its last short side
    th = np.degrees(turning(pts))
    k = max(2, int(n * max_fraction))
    start, end = 0, n
    idx = _hook_end(th[:k], min_turn_deg)
    if idx is not None and abs(float(np.sum(th[idx + 1:idx + 1 + k]))) < min_turn_deg / 2:
        start = idx + 1
    idx = _hook_end(th[::-1][:k], min_turn_deg)
    if idx is not None and abs(float(np.sum(th[::-1][idx + 1:idx + 1 + k]))) < min_turn_deg / 2:
        end = n - idx - 1
    length = path_length(pts)
    if start > 0 and end < n:  # arms at both ends stand off one straight run with no point (a square bracket)
        spine = pts[start:end]
        middle = spine[len(spine) // 5: len(spine) - len(spine) // 5]
        if (sharpest_turn(middle, POINT_SPAN * length) < POINT_TURN_DEG and end_arm(pts[:start + 1], spine, length)
                and end_arm(pts[end - 1:][::-1], spine[::-1], length)):
            start, end = 0, n
    if start > 0 and end_arm(pts[:start + 1], pts[start:], length):
        start = 0
    if end < n and end_arm(pts[end - 1:][::-1], pts[:end][::-1], length):
        end = n
    if end - start < n // 2:
        return pts
    return pts[start:end]


ARM_SHARE = 0.06
ARM_STRAIGHT = 0.2
ARM_ANGLE_DEG = (45.0, 135.0)
"""An end piece `remove_hooks` would cut is a mark's short arm, kept, when it is straight (strays from its chord by
less than `ARM_STRAIGHT` of it, a quarter circle's bow), at least `ARM_SHARE` of the path, leaves the rest at an angle
within `ARM_ANGLE_DEG` (a hook doubles back along the stroke or curls; an arm stands off it), and the rest is one run
with no corner: a tick or check drawn with a short first arm is two straight arms, not a line with a landing hook
(a mouse lands without one). The landing hooks of the design sources' lines double back (under 40 degrees) or are
under 5 % of the path; a brace's curl leaves a rest with its tip, a corner, or a point the corner finder missed
(`POINT_TURN_DEG` within `POINT_SPAN` in the rest's middle three fifths, as for the bracket's spine in `remove_hooks`:
issue 25, sixth pass, in docs/BENCHMARKS.md)."""


POINT_SPAN = 0.04
POINT_TURN_DEG = 20.0
"""A run has no point (a brace's tip) when, in its middle three fifths, it turns less than `POINT_TURN_DEG` degrees
within any `POINT_SPAN` of the stroke's path (the label contradictions' brace-point test, the same numbers)."""


def hooks_cut(pts: np.ndarray, n: int) -> np.ndarray:
    """``pts`` on ``n`` points equally spaced, smoothed, a hook at either end cut (`remove_hooks`), and on ``n`` points
    again: an open stroke as a mark's rule judges it (`round_brackets.kept_bracket`, `angular_braces.kept_brace`)."""
    return resample(remove_hooks(smooth(resample(pts, n))), n)


def sharpest_turn(run: np.ndarray, span: float) -> float:
    """The most the run turns (degrees, net) within any stretch of ``span`` along it (points equally spaced)."""
    if len(run) < 3:
        return 0.0
    step = path_length(run) / (len(run) - 1)
    w = max(1, round(span / step)) if step > 0 else 1
    done = np.concatenate([[0.0], np.add.accumulate(np.degrees(turning(run)))])
    if w >= len(done):
        return abs(float(done[-1]))
    return float(np.maximum.reduce(np.abs(done[w:] - done[:-w])))


def angle_deg(u: np.ndarray, v: np.ndarray) -> float | None:
    """The angle (degrees, 0-180) between the vectors ``u`` and ``v``, or None where either has no length."""
    norms = float(np.hypot(*u) * np.hypot(*v))
    if norms == 0.0:
        return None
    return math.degrees(math.acos(max(-1.0, min(1.0, float(u @ v) / norms))))


def end_arm(piece: np.ndarray, rest: np.ndarray, length: float) -> bool:
    """Whether ``piece`` (from the stroke's end to where it joins ``rest``, which runs on from the join) is an arm."""
    if len(piece) < 2 or length == 0.0 or path_length(piece) < ARM_SHARE * length:
        return False
    if len(piece) > 2 and chord_deviation(piece) >= ARM_STRAIGHT:
        return False
    ahead = resample(rest, 50)
    u, v = piece[0] - piece[-1], ahead[10] - ahead[0]  # the arm and the first fifth of the rest, from the join
    angle = angle_deg(u, v)
    if angle is None:
        return False
    if not (ARM_ANGLE_DEG[0] <= angle <= ARM_ANGLE_DEG[1] and len(find_corners(rest)) == 2):
        return False
    middle = rest[len(rest) // 5: len(rest) - len(rest) // 5]  # no point there either (a brace's soft tip)
    return sharpest_turn(middle, POINT_SPAN * length) < POINT_TURN_DEG


def _hook_end(th_head: np.ndarray, min_turn_deg: float) -> int | None:
    """Index of the vertex where a hook at the start of ``th_head`` (degrees) has done its turning:
    the first point where the cumulative turn is within 15 % of its extreme, if that is large."""
    cum = np.abs(np.add.accumulate(th_head))
    peak = float(np.maximum.reduce(cum)) if len(cum) else 0.0
    if peak < min_turn_deg:
        return None
    return int((cum >= 0.85 * peak).argmax())


def median(values: np.ndarray) -> float:
    """``np.median`` of a 1-D array, to the last bit, without its per-call overhead (NaN when any value is)."""
    n = len(values)
    if n == 0 or np.logical_or.reduce(np.isnan(values)):  # (`.any()`'s own reduction)
        return float(np.median(values))
    h = n // 2
    if n % 2:
        return float(np.partition(values, h)[h])
    part = np.partition(values, (h - 1, h))
    return float((part[h - 1] + part[h]) / 2)
