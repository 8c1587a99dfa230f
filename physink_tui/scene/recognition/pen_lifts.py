"""A recorded stroke holding several attempts at a mark (the pen lifted between) is read by its last, the user told.

Some recorders keep one "stroke" from the first pen-down to the last pen-up of a gesture: a person who draws a bracket,
lifts, and draws it again over the first gives one stroke of two brackets joined by a straight jump, which reads as a
box; a circle gone over twice reads as a coil, a brace gone over three times as a scribble. Such a lift shows in the
stroke's times: no event for a second or more (`LIFT_PAUSE`), then the next event far from the last (`LIFT_STEPS`
ordinary steps and `LIFT_SHARE` of the stroke's size). A device that drops reports while the pen keeps moving (a
finger at a star's tip on a Tablet PC: 0.3-0.76 s, then one step a fifth of the star across) has not paused as long.

>>> line = [(float(x), 0.0) for x in range(50)]
>>> again = line + [(float(x), 1.0) for x in range(50)]
>>> at = [0.01 * i for i in range(50)] + [2.0 + 0.01 * i for i in range(50)]
>>> last_attempt(again, at)
slice(50, 100, None)
>>> last_attempt(line, at[:50]) is None
True
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

LIFT_PAUSE = 1.0
"""Seconds without an event before a far landing counts as a lift: a person re-aiming takes 1.5-5 s (shriyansnidhish's
recorder in hcira: 10th percentile 1.5 s of 284 lifts); reports dropped while a finger moved on lasted 0.3-0.76 s
(mmg, 91 gaps)."""
LIFT_STEPS = 5.0
"""A landing this many median steps from the last event (the pen moved while no event came)."""
LIFT_SHARE = 0.05
"""... and this share of the stroke's bounding-box diagonal (a jump, not a fast stretch of the line)."""
WHOLE_ATTEMPT = 0.5
"""The mark is the last attempt at least this share of the longest one's path length (a tap or a short tick after
the mark is not the mark)."""


def last_attempt(points: Sequence[Sequence[float]], times: Sequence[float] | None) -> slice | None:
    """Which points (a slice of ``points`` and ``times``) are the last whole attempt at the mark when the stroke holds
    several (the pen lifted between them), else None: a stroke drawn in one go, or one without usable times."""
    if times is None or len(times) != len(points) or len(points) < 4:
        return None
    try:
        at = np.asarray(times, dtype=float)
        # (``at[1:] - at[:-1]``: np.diff's differences, without its per-call overhead: every stroke is asked)
        if at.ndim != 1 or not np.isfinite(at).all() or not (at[1:] - at[:-1] >= LIFT_PAUSE).any():
            return None  # no pause long enough for a lift: the common stroke, told without reading its points
        pts = np.asarray([p[:2] for p in points], dtype=float)
    except (TypeError, ValueError, IndexError):
        return None  # the recogniser says what is wrong with such points
    if pts.ndim != 2 or pts.shape[1] != 2 or not np.isfinite(pts).all():
        return None
    steps = sg.step_lengths(pts)
    moving = steps[steps > 0]
    diag = float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))
    if len(moving) < 4 or diag == 0.0:
        return None
    jumps = np.flatnonzero((at[1:] - at[:-1] >= LIFT_PAUSE) & (steps >= LIFT_STEPS * sg.median(moving))
                           & (steps >= LIFT_SHARE * diag))
    lifts = [int(j) for j in jumps]
    if not lifts:
        return None
    cuts = [0, *(j + 1 for j in lifts), len(pts)]
    lengths = [float(steps[a:b - 1].sum()) for a, b in itertools.pairwise(cuts)]
    longest = max(lengths)
    if longest == 0.0:
        return None
    last = max(k for k, length in enumerate(lengths) if length >= WHOLE_ATTEMPT * longest)
    return slice(cuts[last], cuts[last + 1])


def told(times: Sequence[float], attempt: slice) -> str:
    """What the user is told of a stroke read by its ``attempt`` (`last_attempt`) alone: the earlier attempts are
    in the journal, not in the sketch."""
    start = attempt.start or 0
    pause = float(times[start]) - float(times[start - 1]) if start > 0 else 0.0
    return (f"read by its last attempt: no pen event for {pause:.1f} s, then the pen landed far away with no pen-up "
            "reported (a lift the device missed); the earlier attempt is kept in the journal, not drawn")
