"""More of what devices do to a stroke (second device pass): pointer acceleration, a finger's lift and start, slow
corners, a touch grid, a y axis stored upward, tiny mouse drawings — each one device behaviour, for
`bench_device_stress` (transformed strokes, not people).

The parameters are grounded in device facts where this repository's shared data holds them
(``../shared/data/hid``: 24 real pen-tablet captures report every 2-8 ms, median 4 ms; ``../shared/data/tablets``:
pen digitisers resolve 80-200 lines/mm (5th-95th percentile of 492 tablets), the touch surfaces of Wacom's
CTH-480/PTH-451/651/851 only 4,095 units over 152-325 mm, 12.6-27 units/mm, 8-16 times coarser than their pens). The
rest are the ordinary facts of the devices, stated with each transform. Every transform takes the stroke's points
(n x 2) and times (seconds, or None) and a seeded generator, and returns the changed pair.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

Stroke = tuple[np.ndarray, np.ndarray | None]
Transform = Callable[[Stroke, np.random.Generator], Stroke]

TABLET_REPORT_S = 0.004
"""A pen tablet's median report interval in the 24 captures of ``../shared/data/hid`` (2-8 ms, median 4 ms)."""
TOUCH_COARSER = (8, 16)
"""How many times coarser a touch surface resolves than a pen on the same tablet (``../shared/data/tablets``: Wacom
touch 12.6-27 units/mm against pens' 200 lines/mm)."""


def _clock(pts: np.ndarray, t: np.ndarray | None) -> np.ndarray:
    if t is not None and len(t) > 1 and t[-1] > t[0]:
        return np.maximum.accumulate(t)
    return np.arange(len(pts)) * 0.01


def _diag(pts: np.ndarray) -> float:
    return float(np.hypot(*np.ptp(pts, axis=0))) if len(pts) else 0.0


def _size(pts: np.ndarray) -> float:
    return float(np.ptp(pts, axis=0).max()) if len(pts) else 0.0


def acceleration(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A trackpad's pointer acceleration: each event's motion multiplied by a gain that rises with the finger's speed
    (gain (v / median v) ** k, k 0.3-0.7, within 0.4-2.5): slow parts of the stroke shrink, fast parts stretch. The
    hand steers by the pointer on the screen, so where the stroke ends relative to where it began is kept (the drift
    the gain makes is taken back evenly along the path: a closed shape still closes); the shape between is warped."""
    pts, t = stroke
    if len(pts) < 3:
        return stroke
    clock = _clock(pts, t)
    step = np.diff(pts, axis=0)
    dt = np.maximum(np.diff(clock), 1e-3)
    length = np.hypot(*step.T)
    speed = length / dt
    moving = speed[speed > 0]
    if len(moving) == 0:
        return stroke
    gain = np.clip((np.maximum(speed, 1e-9) / float(np.median(moving))) ** rng.uniform(0.3, 0.7), 0.4, 2.5)
    moved = step * gain[:, None]
    drift = moved.sum(axis=0) - step.sum(axis=0)
    share = length * gain / max(float((length * gain).sum()), 1e-12)
    moved -= np.outer(share, drift)
    return np.vstack([pts[:1], pts[:1] + np.cumsum(moved, axis=0)]), t


def lift_hook(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A trackpad's lift: as the finger rolls off, the contact's centre moves 2-6 % of the diagonal in one
    direction (at 45-180 degrees from the stroke's last heading) over 2-4 events 8-12 ms apart."""
    pts, t = stroke
    diag = _diag(pts)
    if len(pts) < 3 or diag == 0:
        return stroke
    back = pts[-1] - pts[max(0, len(pts) - 4)]
    heading = float(np.arctan2(back[1], back[0])) if np.hypot(*back) > 0 else 0.0
    turn = rng.uniform(np.pi / 4, np.pi) * rng.choice([-1.0, 1.0])
    d = np.array([np.cos(heading + turn), np.sin(heading + turn)])
    k = int(rng.integers(2, 5))
    hook = pts[-1] + np.outer(np.linspace(1 / k, 1.0, k), d) * rng.uniform(0.02, 0.06) * diag
    out = np.vstack([pts, hook])
    if t is None:
        return out, None
    return out, np.concatenate([t, t[-1] + np.cumsum(rng.uniform(0.008, 0.012, k))])


def lift_pause(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A finger resting before it lifts: 4-12 more events every `TABLET_REPORT_S` at the end, each within 0.5-1 % of
    the diagonal of the last point (the contact's centre wandering as pressure drops)."""
    pts, t = stroke
    diag = _diag(pts)
    if len(pts) < 2 or diag == 0:
        return stroke
    k = int(rng.integers(4, 13))
    cluster = pts[-1] + rng.normal(0, 1, (k, 2)) * rng.uniform(0.005, 0.01) * diag / np.sqrt(2)
    out = np.vstack([pts, cluster])
    return out, None if t is None else np.concatenate([t, t[-1] + TABLET_REPORT_S * np.arange(1, k + 1)])


def start_blob(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A finger settling before the stroke departs: 4-10 events every `TABLET_REPORT_S` around the first point,
    within 1-3 % of the diagonal of it (a fingertip's contact shifting as it lands)."""
    pts, t = stroke
    diag = _diag(pts)
    if len(pts) < 2 or diag == 0:
        return stroke
    k = int(rng.integers(4, 11))
    blob = pts[0] + rng.normal(0, 1, (k, 2)) * rng.uniform(0.01, 0.03) * diag / np.sqrt(2)
    out = np.vstack([pts[:1], blob, pts[1:]])
    if t is None:
        return out, None
    lead = t[0] + TABLET_REPORT_S * np.arange(0, k + 1)
    return out, np.concatenate([lead, t[1:] + TABLET_REPORT_S * k])


def slow_corners(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A very slow hand at 100-300 px on a tablet: at each sharp turn (over 45 degrees within a few points) the pen
    dwells 40-120 ms, a report every `TABLET_REPORT_S`, each within 0.3-0.6 px of the corner (sub-pixel tremor; the
    points are not rounded)."""
    pts, t = stroke
    if len(pts) < 5:
        return stroke
    pts = pts * (rng.uniform(100, 300) / max(_size(pts), 1e-9))
    clock = _clock(pts, t)
    ahead, behind = pts[4:] - pts[2:-2], pts[2:-2] - pts[:-4]
    norm = np.hypot(*ahead.T) * np.hypot(*behind.T)
    cos = np.where(norm > 0, np.einsum("ij,ij->i", ahead, behind) / np.maximum(norm, 1e-12), 1.0)
    sharp = np.flatnonzero(cos < np.cos(np.pi / 4)) + 2
    corners = [int(i) for k, i in enumerate(sharp) if k == 0 or i - sharp[k - 1] > 3]  # one dwell a corner
    out, when, shift = [], [], 0.0
    for i, (p, c) in enumerate(zip(pts, clock, strict=True)):
        out.append(p[None])
        when.append(np.array([c + shift]))
        if i in corners:
            k = int(rng.uniform(0.04, 0.12) / TABLET_REPORT_S)
            out.append(p + rng.normal(0, rng.uniform(0.3, 0.6) / np.sqrt(2), (k, 2)))
            when.append(c + shift + TABLET_REPORT_S * np.arange(1, k + 1))
            shift += TABLET_REPORT_S * k
    return np.concatenate(out), np.concatenate(when) if t is not None else None


def touch_grid(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A touch surface at 100-300 display px across, its positions on a grid `TOUCH_COARSER` (8-16) times coarser
    than a pen's 0.25 px (2-4 px cells, the grid's phase at random); repeats kept."""
    pts, t = stroke
    pts = pts * (rng.uniform(100, 300) / max(_size(pts), 1e-9))
    cell = 0.25 * rng.uniform(*TOUCH_COARSER)
    phase = rng.uniform(0, cell, 2)
    return np.round((pts - phase) / cell) * cell + phase, t


def y_up(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A set that stores y upward (mathematics' axes) read as a screen's y downward: the stroke mirrored top to
    bottom."""
    pts, t = stroke
    return pts * np.array([1.0, -1.0]), t


TRANSFORMS_MORE: dict[str, Callable[..., Stroke]] = {
    "pointer acceleration": acceleration,
    "lift hook": lift_hook,
    "lift pause": lift_pause,
    "start blob": start_blob,
    "slow corners": slow_corners,
    "touch grid 2-4 px": touch_grid,
    "y up": y_up,
}
"""One device behaviour each; the tiny mouse drawing (20-40 px in whole pixels) is `bench_device_stress.pixels`."""
