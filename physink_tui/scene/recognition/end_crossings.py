"""Where a stroke's first and last stretches of path cross: a closed outline whose ends ran on past each other (a
triangle closed in a hurry, a box or a diamond whose last side runs on past its first corner); no ranking, no I/O."""

from __future__ import annotations

import itertools

import numpy as np

from physink_tui.scene.recognition import open_shapes
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.loop_ends import END_SHARE
from physink_tui.scene.recognition.polygon_checks import crossings

RUN_ON = 0.5
"""A many-sided outline (`RUN_ON_CORNERS`) closed in a hurry may run one end on past the crossing by up to this share
of its size, the other within the gap a closed stroke's ends may leave (`closed_loops.CLOSED_GAP`): the pen models'
boxes and diamonds whose pen lands up to 0.25 of the first side before its first corner and runs on past it by up to
half the last side (`tests/penmodels/run_on_closes`) cross 0.2-0.35 of their size from the end (session 30)."""
RUN_ON_CORNERS = 3
"""The loop between the ends' crossing of such an outline turns at this many corners or more besides the crossing
(`stroke_geometry.find_corners`), its sides straight (`open_shapes.STRAIGHT`): a box, a diamond, a pentagon. An x's or
a delete mark's loop is a triangle (two corners besides the crossing), an alpha's, a pigtail's or a curl's round (none).
A triangle so closed is not told from a person's delete mark, a triangle whose ends cross and run on
(docs/BENCHMARKS.md, session 30: itt lvht1203's and hcira Subject3's delete marks cross 0.30-0.34 of their size from
one end and 0.15-0.16 from the other; tutorboard seed90210's triangle #247 0.33 and 0.17)."""


def crossed_close(work: np.ndarray, diag: float, near: float, run_on: float) -> bool:
    """Whether ``work``'s first and last stretches of path cross, each (at most `loop_ends.END_SHARE` of its points)
    within ``near`` of its size (``diag``) of its end; or, where ``run_on`` is longer, one within ``run_on`` of its end
    and the other within ``near``, the loop between the crossing many-sided (`many_sided`)."""
    n = len(work)
    k = max(2, int(END_SHARE * n))
    along = sg.along(work)
    back = along[-1] - along[::-1]

    def reach(f: float) -> tuple[int, int]:  # how many points from each end lie within ``f`` of the size, and one more
        return (min(int(np.searchsorted(along, f * diag, side="right")) + 1, k),
                min(int(np.searchsorted(back, f * diag, side="right")) + 1, k))

    head_n, tail_n = reach(near)
    if _crossing(work[:head_n], work[n - tail_n:]) is not None:
        return True
    if run_on <= near:
        return False
    far_head, far_tail = reach(run_on)
    for h, t in ((head_n, far_tail), (far_head, tail_n)):
        head, tail = work[:h], work[n - t:]
        if (head.min(axis=0) > tail.max(axis=0)).any() or (tail.min(axis=0) > head.max(axis=0)).any():
            continue  # their boxes do not meet
        found = _crossing(head, tail)
        if found is not None and found[1] + n - t - found[0] >= 8:
            return many_sided(work[found[0] + 1: n - t + found[1] + 1])
    return False


def _crossing(head: np.ndarray, tail: np.ndarray) -> tuple[int, int, float] | None:
    """The first step of ``head`` (by its index) that a step of ``tail`` crosses, the last such step of ``tail``, and
    how far along that step of ``head`` (0 to 1) they meet; None where none does."""
    if len(head) < 2 or len(tail) < 2:
        return None
    p, r = head[:-1, None, :], (head[1:] - head[:-1])[:, None, :]  # as np.diff, without its per-call overhead
    q, s = tail[None, :-1, :], (tail[1:] - tail[:-1])[None, :, :]
    den = r[..., 0] * s[..., 1] - r[..., 1] * s[..., 0]
    qp = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qp[..., 0] * s[..., 1] - qp[..., 1] * s[..., 0]) / den
        u = (qp[..., 0] * r[..., 1] - qp[..., 1] * r[..., 0]) / den
    hits = (den != 0) & (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1)
    if not hits.any():
        return None
    i, j = np.nonzero(hits)
    first = int(i[0])
    last = int(j[i == first][-1])
    return first, last, float(t[first, last])


def many_sided(loop: np.ndarray) -> bool:
    """Whether a loop (from a crossing round to it) turns at `RUN_ON_CORNERS` corners or more besides the crossing,
    its sides straight (`open_shapes.STRAIGHT`) and its outline through them crossing itself nowhere
    (`polygon_checks.crossings`: a star's does, and is judged as before, `closed_loops.star_run_past_its_start`)."""
    corners = sg.find_corners(loop)
    return (len(corners) - 2 >= RUN_ON_CORNERS
            and all(sg.chord_deviation(loop[c:d + 1]) < open_shapes.STRAIGHT for c, d in itertools.pairwise(corners))
            and crossings(loop[corners[:-1]]) == 0)


RUN_PAST = 1.0
"""A stroke whose one end lies near its path (`closed_loops.closed_loop`'s gap test) and whose ends cross, one within
`closed_loops.CLOSED_GAP` of its size of the crossing, is an x or a delete mark, not a closed triangle, where the other
end runs on past the crossing by this many times the side it continues or more, the loop between a triangle with
straight sides: an x's second diagonal runs on to its far corner (people's x's and delete marks read as polygons: hcira
klarubbio/s07 x05 1.14, s02 delete_mark02 1.13; the least of the x's and delete marks whose ends cross so 0.46), a
run-on triangle's last side stops short of another side's length (people's 0.85 at most, klarubbio/s02 triangle06; the
pen models' up to half a side). Session 31 (wt-tails)."""
X_REACH = 1 / 3
"""The end run on past the crossing is sought among this share of the stroke's points from it."""


def x_run_past(work: np.ndarray, diag: float, near: float) -> bool:
    """Whether ``work``'s ends cross, one within ``near`` of its size (``diag``) of its end and the other among
    `X_REACH` of its points, that other running on past the crossing by `RUN_PAST` times the side it continues or more,
    the loop between a triangle with straight sides (`RUN_PAST`); asked from either end alike."""
    n = len(work)
    k = max(2, int(X_REACH * n))
    along = sg.along(work)
    for pts, dist in ((work, along), (work[::-1], along[-1] - along[::-1])):
        h = min(int(np.searchsorted(dist, near * diag, side="right")) + 1, k)
        head, tail = pts[:h], pts[n - k:]
        if (head.min(axis=0) > tail.max(axis=0)).any() or (tail.min(axis=0) > head.max(axis=0)).any():
            continue
        found = _crossing(head, tail)
        if found is None:
            continue
        j = n - k + found[1]  # the tail's step the head crosses
        loop = pts[found[0] + 1: j + 1]
        if len(loop) < 8:
            continue
        corners = sg.find_corners(loop)
        if len(corners) != 4 or any(sg.chord_deviation(loop[c:d + 1]) >= open_shapes.STRAIGHT
                                    for c, d in itertools.pairwise(corners)):
            continue
        cross = pts[found[0]] + found[2] * (pts[found[0] + 1] - pts[found[0]])  # where the head's step meets the tail's
        run = abs(float(dist[-1] - dist[j + 1])) + float(np.hypot(*(pts[j + 1] - cross)))
        if run >= RUN_PAST * float(np.hypot(*(cross - loop[corners[-2]]))):
            return True
    return False
