"""Training-only copies of people's strokes, changed as other hands and devices change them, for the learned ranker.

`train_ranker.py --augment K` adds K copies of every training stroke whose label the ranker's family can read right
(`ranker.KINDS`) to the strokes a model is fitted on, never to the strokes it is scored on: the copies are not people
and no figure counts them. Each copy is turned a little and stretched (rotation within `ROTATE` degrees, aspect within
`ASPECT`), then changed in one way a hand does — corners rounded, corners cut, an overshoot or hook at an end, or none
— then, half the time, drawn again as a mouse or a trackpad draws it: resampled at another density, snapped to a pixel
grid, with a pixel of jitter, or (``events_share`` of those, none by default) sampled by 8-25 events evenly in time as
a trackpad gives a fast stroke (`SPARSE_EVENTS`); and its pen times, where it has them, sped up or slowed down
unevenly. Every draw comes from a generator seeded by the sha256 of the seed, the stroke's file and label and the
copy's number: the same rows give the same copies on any machine.
"""

from __future__ import annotations

import hashlib
import math

import numpy as np
from stroke_sets import Row

ROTATE = 20.0
"""The largest turn of a copy, degrees (either way)."""
ASPECT = 1.33
"""The largest stretch of one axis against the other (either way)."""
SHAPES = ("none", "round", "cut", "overshoot", "hook")
"""The one change of a hand each copy gets, drawn uniformly."""
EVENTS_SHARE = 0.0
"""The share of copies drawn again by a device that are sampled by a few events evenly in time (`_events`): none by
default (the sixth pass's copies, drawn from the same numbers); `train_ranker.py --events-share` sets it."""
SPARSE_EVENTS = (8, 25)
"""The fewest and most events of a copy sampled evenly in time: a stroke of 0.2-0.5 s at an event every 15-30 ms
(`bench_device_stress.fast`'s range)."""


def rng_for(seed: int, row: Row, copy: int) -> np.random.Generator:
    """A generator fixed by the seed, the row's file and label and the copy's number."""
    digest = hashlib.sha256(f"{seed}\0{row['file']}\0{row['label']}\0{copy}".encode()).digest()
    return np.random.default_rng(int.from_bytes(digest[:8], "little"))


def augmented_rows(rows: list[Row], copies: int, seed: int, kinds: tuple[str, ...], events_share: float = EVENTS_SHARE,
                   ) -> tuple[list[Row], list[int]]:
    """``copies`` changed copies of each row whose label accepts one of ``kinds``, and for each the index of the row
    it was made from; a copy keeps its row's fields (source, person, device, label, accepts) but its stroke, and its
    file names the copy. ``events_share`` of the copies drawn again by a device are sampled by a few events (`_events`).
    """
    out, origin = [], []
    for i, row in enumerate(rows):
        if not set(row["accepts"]) & set(kinds):
            continue
        for c in range(copies):
            stroke = augment(row["strokes"][0], rng_for(seed, row, c), events_share)
            out.append({**row, "strokes": [stroke], "file": f"{row['file']}#copy{c}-seed{seed}"})
            origin.append(i)
    return out, origin


def augment(stroke: list, rng: np.random.Generator, events_share: float = EVENTS_SHARE) -> list[list[float]]:
    """One changed copy of ``stroke`` (points ``[x, y]`` or ``[x, y, t_ms]``), in the same form; ``events_share`` of
    the copies drawn again by a device are sampled by a few events evenly in time (`_events`)."""
    pts = np.array([p[:2] for p in stroke], dtype=float)
    times = (np.array([p[2] for p in stroke], dtype=float)
             if all(len(p) > 2 and p[2] is not None for p in stroke) else None)
    centre = pts.mean(axis=0)
    pts = pts - centre
    angle = math.radians(rng.uniform(-ROTATE, ROTATE))
    c, s = math.cos(angle), math.sin(angle)
    pts = pts @ np.array([[c, s], [-s, c]])
    stretch = math.sqrt(math.exp(rng.uniform(-math.log(ASPECT), math.log(ASPECT))))
    pts = pts * np.array([stretch, 1.0 / stretch])
    diag = float(np.hypot(*np.ptp(pts, axis=0))) if len(pts) > 1 else 0.0
    if diag > 0 and len(pts) >= 4:
        shape = SHAPES[int(rng.integers(len(SHAPES)))]
        pts, times = _shape(shape, pts, times, diag, rng)
        if rng.random() < 0.5:
            drawn = _events if events_share > 0 and rng.random() < events_share else _device
            pts, times = drawn(pts, times, diag, rng)
    if times is not None and len(times) > 1:
        times = _speed(times, rng)
    pts = pts + centre
    if times is None:
        return [[float(x), float(y)] for x, y in pts]
    return [[float(x), float(y), float(t)] for (x, y), t in zip(pts, times, strict=True)]


def _arc(pts: np.ndarray) -> np.ndarray:
    seg = np.hypot(*np.diff(pts, axis=0).T)
    return np.concatenate(([0.0], np.cumsum(seg)))


def _resample(pts: np.ndarray, times: np.ndarray | None, n: int) -> tuple[np.ndarray, np.ndarray | None]:
    """``n`` points evenly spaced along the path (times interpolated along it)."""
    s = _arc(pts)
    if s[-1] <= 0:
        return pts, times
    u = np.linspace(0.0, s[-1], n)
    out = np.column_stack([np.interp(u, s, pts[:, 0]), np.interp(u, s, pts[:, 1])])
    return out, (np.interp(u, s, times) if times is not None else None)


def _shape(shape: str, pts: np.ndarray, times: np.ndarray | None, diag: float, rng: np.random.Generator,
           ) -> tuple[np.ndarray, np.ndarray | None]:
    if shape == "round":  # corners rounded: a Gaussian blur along the path, ends kept
        n = max(len(pts), 64)
        pts, times = _resample(pts, times, n)
        sigma = rng.uniform(0.01, 0.035) * n
        k = np.arange(-int(3 * sigma) - 1, int(3 * sigma) + 2)
        w = np.exp(-0.5 * (k / sigma) ** 2)
        w /= w.sum()
        pad = np.pad(pts, ((len(k) // 2, len(k) // 2), (0, 0)), mode="edge")
        smooth = np.column_stack([np.convolve(pad[:, j], w, mode="valid") for j in range(2)])
        smooth[0], smooth[-1] = pts[0], pts[-1]
        return smooth, times
    if shape == "cut":  # corners cut: the path simplified, each corner cut once (Chaikin), resampled back
        n = len(pts)
        keep = _simplify(pts, rng.uniform(0.015, 0.04) * diag)
        poly, ptimes = pts[keep], (times[keep] if times is not None else None)
        u = rng.uniform(0.1, 0.3)
        q = [poly[0]]
        qt = [ptimes[0]] if ptimes is not None else []
        for a in range(len(poly) - 1):
            p0, p1 = poly[a], poly[a + 1]
            q += [(1 - u) * p0 + u * p1, u * p0 + (1 - u) * p1]
            if ptimes is not None:
                qt += [(1 - u) * ptimes[a] + u * ptimes[a + 1], u * ptimes[a] + (1 - u) * ptimes[a + 1]]
        q.append(poly[-1])
        if ptimes is not None:
            qt.append(ptimes[-1])
        return _resample(np.array(q), np.array(qt) if ptimes is not None else None, n)
    if shape in ("overshoot", "hook"):  # a short run past an end, straight on or turned back
        at_end = rng.random() < 0.5
        p = pts[::-1] if not at_end else pts
        t = (times[::-1] if times is not None else None) if not at_end else times
        back = max(2, len(p) // 12)
        d = p[-1] - p[-1 - back]
        norm = float(np.hypot(*d))
        if norm <= 0:
            return pts, times
        d /= norm
        length = rng.uniform(0.03, 0.1) * diag
        if shape == "hook":
            turn = math.radians(rng.uniform(60, 150)) * (1 if rng.random() < 0.5 else -1)
            d = np.array([d[0] * math.cos(turn) - d[1] * math.sin(turn), d[0] * math.sin(turn) + d[1] * math.cos(turn)])
        m = max(2, len(p) // 15)
        step = np.linspace(1.0 / m, 1.0, m)[:, None]
        tail = p[-1] + step * length * d
        p = np.vstack([p, tail])
        if t is not None:
            dt = float(np.median(np.abs(np.diff(t)))) if len(t) > 1 else 0.0
            t = np.concatenate([t, t[-1] + np.sign(t[-1] - t[0] or 1.0) * dt * np.arange(1, m + 1)])
        return (p, t) if at_end else (p[::-1], t[::-1] if t is not None else None)
    return pts, times


def _simplify(pts: np.ndarray, tol: float) -> list[int]:
    """The indices Ramer-Douglas-Peucker keeps at tolerance ``tol`` (iterative)."""
    keep = {0, len(pts) - 1}
    stack = [(0, len(pts) - 1)]
    while stack:
        a, b = stack.pop()
        if b - a < 2:
            continue
        chord = pts[b] - pts[a]
        length = float(np.hypot(*chord))
        rel = pts[a + 1:b] - pts[a]
        dist = (np.abs(chord[0] * rel[:, 1] - chord[1] * rel[:, 0]) / length if length > 0
                else np.hypot(rel[:, 0], rel[:, 1]))
        j = int(np.argmax(dist))
        if dist[j] > tol:
            keep.add(a + 1 + j)
            stack += [(a, a + 1 + j), (a + 1 + j, b)]
    return sorted(keep)


def _device(pts: np.ndarray, times: np.ndarray | None, diag: float, rng: np.random.Generator,
            ) -> tuple[np.ndarray, np.ndarray | None]:
    """Drawn again as a mouse or trackpad draws it: at a size of 60-300 px, a point every 1.5-8 px, on the pixel grid,
    with a pixel of jitter a third of the time; scaled back to the stroke's size."""
    size = rng.uniform(60.0, 300.0)
    scale = size / diag
    spacing = rng.uniform(1.5, 8.0)
    n = max(4, int(_arc(pts * scale)[-1] / spacing) + 1)
    p, t = _resample(pts * scale, times, n)
    if rng.random() < 1 / 3:
        p = p + rng.integers(-1, 2, size=p.shape)
    p = np.round(p)
    moved = np.ones(len(p), dtype=bool)
    moved[1:] = np.any(np.diff(p, axis=0) != 0, axis=1)
    p = p[moved]
    t = t[moved] if t is not None else None
    if len(p) < 2:
        return pts, times
    return p / scale, t


def _events(pts: np.ndarray, times: np.ndarray | None, diag: float, rng: np.random.Generator,
            ) -> tuple[np.ndarray, np.ndarray | None]:
    """Sampled by `SPARSE_EVENTS` events evenly in time, the first at pen-down and the last at pen-up, the pen's
    position between its points taken on the straight line between them; a stroke without times is taken as drawn at
    an even pace a point (as `bench_device_stress` takes it)."""
    clock = (np.maximum.accumulate(times) if times is not None and times[-1] > times[0]
             else np.arange(len(pts), dtype=float))
    keep = np.concatenate([[True], np.diff(clock) > 0])
    if np.count_nonzero(keep) < 2:
        return pts, times
    n = int(rng.integers(SPARSE_EVENTS[0], SPARSE_EVENTS[1] + 1))
    when = np.linspace(clock[0], clock[-1], n)
    out = np.column_stack([np.interp(when, clock[keep], pts[keep, k]) for k in range(2)])
    return out, (when if times is not None else None)


def _speed(times: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The pen times scaled by 0.5-2 and warped unevenly (each step's time by a smooth factor of 0.6-1.6)."""
    dt = np.diff(times)
    wave = np.exp(rng.uniform(-0.5, 0.5) * np.sin(np.linspace(0, rng.uniform(1, 4) * math.pi, len(dt))
                                                     + rng.uniform(0, 2 * math.pi)))
    dt = dt * wave * math.exp(rng.uniform(math.log(0.5), math.log(2.0)))
    return times[0] + np.concatenate(([0.0], np.cumsum(dt)))
