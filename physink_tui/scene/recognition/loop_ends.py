"""Where a closed stroke's loop begins and ends: a hook or lead-in where the pen landed and an overshoot where it lifted
are cut off, and a loop much smaller than the stroke is left to the open marks; no ranking, no I/O."""

from __future__ import annotations

import numpy as np

SMALL_LOOP = 0.5
"""A loop cut from a stroke's ends (a hook, an overshoot, a lead-in cut off) is the shape drawn only when it is at
least this share of the whole stroke's size; smaller, it is part of an open mark: an arrow whose head closes on its
shaft, an x drawn as a loop with crossing tails."""


def cut_ends(work: np.ndarray, gap: float, d_tail: np.ndarray, d_head: np.ndarray) -> np.ndarray:
    """The stroke once round: an overshoot past the start, or a start before the end, cut at the closest approach;
    else cut where the first and last `END_SHARE` come closest, when that is much closer than the ends are: a
    hook where the pen landed and an overshoot where it lifted (neither end alone comes near the other's path)."""
    n = len(work)
    tail_n = len(d_tail)
    if float(d_tail.min()) < 0.5 * gap and d_tail.argmin() < tail_n - 2:
        return work[: n - tail_n + int(d_tail.argmin()) + 1]  # drawn past the start
    if float(d_head.min()) < 0.5 * gap and d_head.argmin() > 1:
        return work[int(d_head.argmin()):]  # started before where it ends
    k = max(2, int(END_SHARE * n))
    head, tail = work[:k], work[n - k:]
    d = np.hypot(*(head[:, None, :] - tail[None, :, :]).transpose(2, 0, 1))
    i, j = np.unravel_index(int(np.argmin(d)), d.shape)
    if float(d[i, j]) < 0.5 * gap:
        return work[int(i): n - k + int(j) + 1]
    return work


END_SHARE = 1 / 6
"""A hook or an overshoot at a closed stroke's end is at most this share of its points (a side of a box is a
quarter; a star's first and last sides cross no other side within it)."""
