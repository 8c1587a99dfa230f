"""Draws an ideal pen path as a realistic timed stroke (a modelled hand and tablet); chooses no shape itself.

`strokes` builds the ideal path of each primitive at unit size; this module spoils it the way people
and digitisers do:

- corners drawn sharp, overshot (a small spike past the corner), rounded (a small fillet) or looped (a tiny
  loop taken the long way round);
- closed shapes that stop short of their start (a gap up to 15 % of the size) or run on past it, as often as
  people did in the $1 data (`CORNERED_CLOSURE`, `ROUND_CLOSURE`);
- hooks: a short sharp tail at the start and/or end of 20 % of strokes;
- a speed profile: slow at the ends and corners, where the pen may also rest a few tens of ms, fast in between,
  slower on tight curves (the two-thirds power law), at a random overall pace, sampled at a fixed rate of
  60-200 Hz so that the spacing of the samples varies along the stroke;
- tremor: smooth noise of 0.3-1 % of the size (a slow drift plus 4-11 Hz physiological tremor);
- digitiser faults: jitter spikes of one or two units on single samples, duplicated reports, pixel rounding.

All randomness comes from the ``random.Random`` passed in, so a seed gives the same stroke everywhere. No I/O and
no clock: times are computed, in seconds from ``t0``.
"""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

Point = tuple[float, float]
Sample = tuple[float, float, float]
"""(x, y, t): stroke units, and seconds from the start of the first stroke."""

CORNER_STYLES: Mapping[str, float] = {"sharp": 0.45, "overshoot": 0.25, "rounded": 0.2, "loop": 0.1}
"""How often each way of drawing a corner is chosen (weights)."""

HOOK_PROBABILITY = 0.2
STEP = 1 / 150  # densified path spacing, in unit sizes


@dataclass(frozen=True, slots=True)
class PenPath:
    """The ideal path of the pen before the hand's noise, at unit size.

    Attributes:
        points: the path in drawing order, in units of the shape's size (its largest extent is about 1);
            consecutive points may be far apart along straight runs.
        stops: indices into ``points`` where the pen slows right down (corners, hook turns); the two ends are
            always stops and are not listed.
    """

    points: tuple[Point, ...]
    stops: tuple[int, ...] = ()


def normalise(points: Sequence[Point]) -> list[Point]:
    """Scales and moves ``points`` so that their bounding box is centred on 0 and its larger side is 1.

    >>> normalise([(0, 0), (4, 2)])
    [(-0.5, -0.25), (0.5, 0.25)]
    """
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    extent = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    return [((x - cx) / extent, (y - cy) / extent) for x, y in points]


def _direction(a: Point, b: Point) -> tuple[Point, float]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    return ((dx / length, dy / length) if length else (1.0, 0.0)), length


def _rotate(d: Point, angle: float) -> Point:
    c, s = math.cos(angle), math.sin(angle)
    return (d[0] * c - d[1] * s, d[0] * s + d[1] * c)


def corner_path(vertices: Sequence[Point], rng: random.Random, styles: Mapping[str, float] = CORNER_STYLES) -> PenPath:
    """Joins ``vertices`` (unit size) by straight runs, drawing each interior corner in a style chosen by weight."""
    out: list[Point] = [tuple(vertices[0])]  # type: ignore[list-item]
    stops: list[int] = []
    names, weights = list(styles), list(styles.values())
    for i in range(1, len(vertices) - 1):
        v = vertices[i]
        d1, a_in = _direction(out[-1], v)
        d2, a_out = _direction(v, vertices[i + 1])
        if a_in < 1e-9 or a_out < 1e-9:
            continue
        short = min(a_in, a_out)
        turn = math.atan2(d1[0] * d2[1] - d1[1] * d2[0], d1[0] * d2[0] + d1[1] * d2[1])
        style = rng.choices(names, weights)[0] if abs(turn) > 0.3 else "sharp"
        if style == "overshoot":
            o = min(rng.uniform(0.01, 0.04), 0.3 * short)
            out.append((v[0] + d1[0] * o, v[1] + d1[1] * o))
            stops.append(len(out) - 1)
        elif style == "rounded":
            c = min(rng.uniform(0.015, 0.06), 0.35 * short)
            a, b = (v[0] - d1[0] * c, v[1] - d1[1] * c), (v[0] + d2[0] * c, v[1] + d2[1] * c)
            for k in range(9):
                u = k / 8
                out.append(
                    tuple((1 - u) ** 2 * p + 2 * u * (1 - u) * q + u**2 * r for p, q, r in zip(a, v, b, strict=True))
                )
            stops.append(len(out) - 5)
        elif style == "loop":
            rho = min(rng.uniform(0.01, 0.03), 0.25 * short)
            long_way = turn - math.copysign(2 * math.pi, turn)
            heading, (x, y) = math.atan2(d1[1], d1[0]), v
            out.append((x, y))
            stops.append(len(out) - 1)
            for _ in range(20):
                heading += long_way / 20
                x += rho * abs(long_way) / 20 * math.cos(heading)
                y += rho * abs(long_way) / 20 * math.sin(heading)
                out.append((x, y))
        else:
            out.append(tuple(v))  # type: ignore[arg-type]
            stops.append(len(out) - 1)
    out.append(tuple(vertices[-1]))  # type: ignore[arg-type]
    return PenPath(tuple(out), tuple(stops))


@dataclass(frozen=True, slots=True)
class Closure:
    """How people end a closed shape: stop short of the start (a gap), run on past it, or meet it.

    Attributes:
        gap_share: share of shapes that stop short; ``max_gap`` is the largest gap, in units of the size.
        overshoot_share: share that run on; ``max_overshoot`` is the most, as a fraction of the perimeter.
        The rest close within 0.5 % of the size.
    """

    gap_share: float
    max_gap: float
    overshoot_share: float
    max_overshoot: float


CORNERED_CLOSURE = Closure(gap_share=0.7, max_gap=0.15, overshoot_share=0.2, max_overshoot=0.04)
"""Boxes and polygons: people stop short (the $1 rectangles' ends are 9 % of the size apart at the median, 14 %
at the 90th percentile) far more often than they run on (2.5 % of the perimeter at most)."""
ROUND_CLOSURE = Closure(gap_share=0.4, max_gap=0.15, overshoot_share=0.5, max_overshoot=0.2)
"""Circles and ellipses: half run on past the start (the $1 circles by up to 20 % of the perimeter)."""


def closure_delta(rng: random.Random, perimeter: float, closure: Closure) -> float:
    """How much further than once round a closed shape the pen goes, in unit lengths (negative: a gap)."""
    u = rng.random()
    if u < closure.gap_share:
        return -rng.uniform(0.005, closure.max_gap)
    if u < closure.gap_share + closure.overshoot_share:
        return rng.uniform(0.005, closure.max_overshoot * perimeter)
    return rng.uniform(-0.005, 0.005)


def closed_traversal(vertices: Sequence[Point], edge: int, fraction: float, delta: float) -> list[Point]:
    """Vertices met going once round the closed polygon ``vertices`` from a point on one edge, plus ``delta``.

    The pen starts ``fraction`` of the way along edge ``edge`` (from vertex ``edge`` to the next; 0 is a corner)
    and stops after the perimeter plus ``delta`` (negative: short of the start).

    >>> closed_traversal([(0, 0), (1, 0), (1, 1), (0, 1)], 0, 0.5, 0.0)
    [(0.5, 0.0), (1, 0), (1, 1), (0, 1), (0, 0), (0.5, 0.0)]
    """
    n = len(vertices)
    a, b = vertices[edge % n], vertices[(edge + 1) % n]
    start = (a[0] + (b[0] - a[0]) * fraction, a[1] + (b[1] - a[1]) * fraction)
    chain = [start] + [vertices[(edge + 1 + i) % n] for i in range(2 * n + 1)]
    perimeter = sum(math.dist(vertices[i], vertices[(i + 1) % n]) for i in range(n))
    left = max(perimeter + delta, 0.5 * perimeter)
    out = [start]
    for p, q in itertools.pairwise(chain):
        step = math.dist(p, q)
        if step >= left - 1e-12:
            u = left / step if step else 0.0
            out.append((p[0] + (q[0] - p[0]) * u, p[1] + (q[1] - p[1]) * u))
            break
        out.append(q)
        left -= step
    return out


def add_hooks(path: PenPath, rng: random.Random, probability: float = HOOK_PROBABILITY) -> PenPath:
    """With ``probability``, a short sharp tail (2-7 % of the size, turning 110-165 deg) at one or both ends."""
    if rng.random() >= probability or len(path.points) < 2:
        return path
    ends = rng.choices(("start", "end", "both"), (0.45, 0.35, 0.2))[0]
    points, stops = list(path.points), list(path.stops)
    if ends in ("start", "both"):
        d0 = _end_direction(points)
        e = _rotate(d0, -math.copysign(math.radians(rng.uniform(110, 165)), rng.random() - 0.5))
        length = rng.uniform(0.02, 0.07)
        points.insert(0, (points[0][0] - e[0] * length, points[0][1] - e[1] * length))
        stops = [1] + [s + 1 for s in stops]
    if ends in ("end", "both"):
        back = _end_direction(points[::-1])
        dn = (-back[0], -back[1])
        e = _rotate(dn, math.copysign(math.radians(rng.uniform(110, 165)), rng.random() - 0.5))
        length = rng.uniform(0.02, 0.07)
        stops.append(len(points) - 1)
        points.append((points[-1][0] + e[0] * length, points[-1][1] + e[1] * length))
    return PenPath(tuple(points), tuple(stops))


def _end_direction(points: Sequence[Point], reach: float = 0.03) -> Point:
    """Direction of travel from the first point to the first point at least ``reach`` away."""
    for p in points[1:]:
        if math.dist(points[0], p) >= reach:
            return _direction(points[0], p)[0]
    return _direction(points[0], points[-1])[0]


def _densify(path: PenPath) -> tuple[np.ndarray, list[int]]:
    """Points no further apart than `STEP`, without repeats, and where the stops went."""
    stops = set(path.stops)
    out: list[Point] = [path.points[0]]
    new_stops: list[int] = []
    for i in range(1, len(path.points)):
        p, q = out[-1], path.points[i]
        n = math.ceil(math.dist(p, q) / STEP)
        if n == 0:
            if i in stops:
                new_stops.append(len(out) - 1)
            continue
        out += [(p[0] + (q[0] - p[0]) * k / n, p[1] + (q[1] - p[1]) * k / n) for k in range(1, n + 1)]
        if i in stops:
            new_stops.append(len(out) - 1)
    return np.asarray(out, dtype=float), sorted(set(new_stops) - {0, len(out) - 1})


def draw(path: PenPath, rng: random.Random, *, rate_hz: float | None = None, pace: float | None = None) -> list[Sample]:
    """Moves a modelled hand along ``path`` (unit size): speed profile, rests, fixed-rate sampling and tremor.

    Args:
        rate_hz: sampling rate, else 60-200 Hz at random.
        pace: duration multiplier, else 0.6 (fast) .. 1.6 (slow) at random.

    Returns:
        Samples in unit-size coordinates, times in seconds from 0.
    """
    xy, stops = _densify(path)
    if len(xy) < 2:
        return [(float(xy[0, 0]), float(xy[0, 1]), 0.0)]
    ds = np.hypot(*np.diff(xy, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(ds)])
    length = s[-1]
    stop_s = np.concatenate([[0.0, length], s[stops]])
    near = np.min(np.abs(s[:, None] - stop_s[None, :]), axis=1)
    v_stop = 0.12 + 0.88 * (1 - np.exp(-near / 0.05))
    # Two-thirds power law: speed grows with the cube root of the radius of curvature (measured over ~0.02).
    w = 3
    i = np.arange(len(xy))
    a, b = xy - xy[np.maximum(i - w, 0)], xy[np.minimum(i + w, len(xy) - 1)] - xy
    turn = np.abs(np.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], np.sum(a * b, axis=1)))
    span = np.hypot(*a.T) + np.hypot(*b.T)
    radius = np.where(turn > 1e-9, span / np.maximum(turn, 1e-9), 1.0)
    v = v_stop * np.clip(radius, 0.03, 1.0) ** (1 / 3)
    t = np.concatenate([[0.0], np.cumsum(ds / ((v[:-1] + v[1:]) / 2))])
    pace = pace if pace is not None else rng.uniform(0.6, 1.6)
    t *= pace * (0.1 + 0.25 * length + 0.2 * len(stops)) / t[-1]
    # Rests: the pen lingers a moment where it lands, at some corners and before it lifts.
    rests = {0: rng.uniform(0.0, 0.06), len(xy) - 1: rng.uniform(0.0, 0.04)}
    rests.update({k: rng.uniform(0.0, 0.05) for k in stops if rng.random() < 0.5})
    knot_t, knot_i, shift = [], [], 0.0
    for k in range(len(xy)):
        knot_t.append(t[k] + shift)
        knot_i.append(k)
        if rests.get(k, 0.0) > 1e-4:
            shift += rests[k]
            knot_t.append(t[k] + shift)
            knot_i.append(k)
    kt, kxy = np.asarray(knot_t), xy[knot_i]
    rate = rate_hz if rate_hz is not None else rng.uniform(60.0, 200.0)
    ts = np.arange(int(kt[-1] * rate) + 1) / rate
    if kt[-1] - ts[-1] > 0.25 / rate:
        ts = np.append(ts, kt[-1])
    x, y = np.interp(ts, kt, kxy[:, 0]), np.interp(ts, kt, kxy[:, 1])
    dx, dy = _tremor(rng, ts)
    return [(float(p), float(q), float(r)) for p, q, r in zip(x + dx, y + dy, ts, strict=True)]


def _tremor(rng: random.Random, ts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Smooth 2-D wobble of 0.3-1 % of the size: a slow drift (0.5-2 Hz) and three 4-11 Hz components."""
    amplitude = rng.uniform(0.003, 0.01)
    out = []
    for _axis in range(2):
        freqs = [rng.uniform(0.5, 2.0)] + [rng.uniform(4.0, 11.0) for _ in range(3)]
        weights = [rng.uniform(0.5, 1.0)] + [rng.uniform(0.1, 0.5) for _ in range(3)]
        total = sum(weights)
        out.append(
            sum(
                amplitude * wk / total * np.sin(2 * math.pi * fk * ts + rng.uniform(0, 2 * math.pi))
                for fk, wk in zip(freqs, weights, strict=True)
            )
        )
    return out[0], out[1]


def place(
    samples: Sequence[Sample], *, size: float, angle: float, center: Point, mirror: bool = False, t0: float = 0.0
) -> list[Sample]:
    """Unit-size samples scaled to ``size``, mirrored (x -> -x) if asked, rotated by ``angle``, moved to ``center``."""
    c, s = math.cos(angle), math.sin(angle)
    out = []
    for x, y, t in samples:
        x = -x if mirror else x
        out.append((center[0] + size * (x * c - y * s), center[1] + size * (x * s + y * c), t + t0))
    return out


def digitise(
    samples: Sequence[Sample],
    rng: random.Random,
    *,
    size: float,
    quantum: float | None = None,
    spike_probability: float = 0.25,
    duplicate_probability: float = 0.5,
) -> list[Sample]:
    """A tablet's faults on placed samples: jitter spikes, duplicated reports and rounding to ``quantum`` units.

    A spike moves one sample by 1-2 units (at most 2 % of ``size``); a stroke with duplicates repeats about
    one report in 25, with the same time or half-way to the next.
    """
    out = list(samples)
    if len(out) > 4 and rng.random() < spike_probability:
        for _ in range(rng.randint(1, 2)):
            k = rng.randrange(1, len(out) - 1)
            magnitude, heading = min(rng.uniform(1.0, 2.0), 0.02 * size), rng.uniform(0, 2 * math.pi)
            x, y, t = out[k]
            out[k] = (x + magnitude * math.cos(heading), y + magnitude * math.sin(heading), t)
    if rng.random() < duplicate_probability:
        doubled: list[Sample] = []
        for k, sample in enumerate(out):
            doubled.append(sample)
            if rng.random() < 0.04:
                later = out[k + 1][2] if k + 1 < len(out) else sample[2]
                t = sample[2] if rng.random() < 0.5 else (sample[2] + later) / 2
                doubled.append((sample[0], sample[1], t))
        out = doubled
    if quantum:
        out = [(round(x / quantum) * quantum, round(y / quantum) * quantum, t) for x, y, t in out]
    return out
