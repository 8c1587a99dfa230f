"""Where a closed stroke's loop begins and ends: a hook or lead-in where the pen landed and an overshoot where it lifted
are cut off, a lead drawn out and back along the path that the shape draws again is cut from any stroke, and a loop
much smaller than the stroke is left to the open marks; no ranking, no I/O."""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

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


LEAD_SHARE = 0.35
"""A lead the pen draws out and back along itself before the shape (`retraced_lead`) is at most this share of the
stroke's path, and what follows it at least twice as long (a line drawn to and fro is no lead and a shape)."""
LEAD_REACH = 0.1
"""Such a lead reaches at least this share of the stroke's size from where the pen landed (shorter, a hook's)."""
LEAD_BACK = 0.25
"""It comes back to within this share of its reach of where it began, ..."""
LEAD_ALONG = 0.05
"""... nine in ten of its points on the way back within this share of the stroke's size of its way out, and nine in ten
of those on the way out as near the shape drawn after it (which draws it again)."""


def retraced_lead(work: np.ndarray, diag: float) -> int:
    """Where the stroke begins for good (0 where it has no lead): the pen landed, ran out and back along its own path
    (`LEAD_REACH`, `LEAD_BACK`, `LEAD_ALONG`) and drew the shape from there: a box's first side or a circle's first arc
    drawn twice over. Cut, the shape is read as drawn once; ``work`` is the stroke resampled evenly along its path."""
    n = len(work)
    steps = sg.step_lengths(work)
    along = np.concatenate([[0.0], np.add.accumulate(steps)])
    if n < 8 or along[-1] <= 0.0:
        return 0
    head = int(np.searchsorted(along, LEAD_SHARE * along[-1], side="right"))
    d0 = np.hypot(*(work[:head] - work[0]).T)
    if len(d0) < 4:
        return 0
    reach = np.maximum.accumulate(d0)  # the farthest the pen has been from where it landed, so far
    home_again = np.flatnonzero((d0 <= LEAD_BACK * reach) & (reach >= LEAD_REACH * diag))
    if not len(home_again):
        return 0
    first = int(home_again[0])
    tip = int(np.argmax(d0[:first]))
    near = first  # the run of points back near the landing, of which the nearest is where the shape begins
    while near + 1 < len(d0) and d0[near + 1] <= LEAD_BACK * reach[first]:
        near += 1
    back = first + int(np.argmin(d0[first:near + 1]))
    if along[-1] - along[back] < 2 * along[back]:
        return 0
    out, home = work[: tip + 1], work[tip:back + 1]
    if _strays(home, out, LEAD_ALONG * diag):
        return 0
    # drawn again by the shape (a box's first side, a circle's first arc), else the lead is a side of its own (a star
    # whose first side the pen drew there and back, then went on round without it)
    return 0 if _strays(out, work[back:], LEAD_ALONG * diag) else back


def _strays(path: np.ndarray, other: np.ndarray, reach: float) -> bool:
    """Whether more than one in ten of ``path``'s points lie farther than ``reach`` from every point of ``other``."""
    gaps = np.hypot(path[:, None, 0] - other[None, :, 0], path[:, None, 1] - other[None, :, 1]).min(axis=1)
    return float(np.quantile(gaps, 0.9)) > reach


def without_retraced_ends(work: np.ndarray, diag: float) -> np.ndarray:
    """``work`` without a lead drawn out and back along itself at either end (`retraced_lead`; at the end, the same
    drawn backwards), resampled to as many points."""
    start = retraced_lead(work, diag)
    end = len(work) - retraced_lead(work[::-1], diag)
    if start == 0 and end == len(work):
        return work
    return sg.resample(work[start:end], len(work))


HOOKED_TURN = 2.15
"""A stroke turning past this many half turns one way is asked whether it runs back over its first lap
(`closed_loops.closed_loop`, `stroke_features.retraced`): a shape drawn twice."""
UNHOOKED_TURN = 1.5
"""Unless, once the hooks at its ends are cut (`stroke_geometry.remove_hooks`), it turns at most this many half turns:
no lap at all, so nothing drawn twice (`turned_by_hooks`)."""


def turned_by_hooks(work: np.ndarray) -> bool:
    """Whether ``work`` turns past `HOOKED_TURN` half turns only by the hooks at its ends (those
    `stroke_geometry.remove_hooks` cuts), the rest turning at most `UNHOOKED_TURN`: a chevron hooked at both ends,
    each hook curling the way its point turns (the sign set's ST5022 writers' chevrons read as polygons turn
    2.63-2.78 pi in all, 0.80-0.99 pi without their hooks; issue 25, session 37), whose last hook, doubling back along
    its last side, runs over the end of its first lap (`stroke_features.retraced`)."""
    unhooked = sg.remove_hooks(work)
    return len(unhooked) < len(work) and abs(float(np.add.reduce(sg.turning(unhooked)))) <= UNHOOKED_TURN * np.pi
