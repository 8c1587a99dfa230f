"""Four of the learned ranker's features telling a polyline's rounded corners from a curve's even bend; numpy only.

A bracket, a check or a tick drawn with a slightly rounded corner turns a lot within a short span of its path and
hardly at all between (its sides are straight); a parenthesis, an arc or a brace's bow turns all along. The corner
finder (`stroke_geometry.find_corners`) may miss such a corner, and the rules read a curve; these features measure
how the turning is spread along the stroke without finding corners (issue 25, session 40)."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

PEAK_SPAN = 0.1
"""The span (share of the path) within which a turn counts as made at one place: a rounded corner of a hand's
bracket or check turns within it, a curve's even bend turns a tenth of its turning there."""
SIDE_SHARE = 0.2
"""The share of the path (its most sharply turning points) counted as corners by `corner_features`' outside turn."""
PEAK_TURN = 45.0
"""A stretch of `PEAK_SPAN` turning at least this much (degrees, net) is a corner, cut before the sides' bow is
measured (`corner_features`): 450 degrees over the path's length, more than any open curve's even bend."""
MAX_PEAKS = 4
SIDE_MIN = 0.1
"""A piece left between cut corners counts as a side when it is at least this share of the path."""


def corner_features(work: np.ndarray, th: np.ndarray) -> tuple[float, float, float, float]:
    """``(spread, peak, outside, side_bow)`` of the stroke ``work`` (points about equally spaced) whose turning is
    ``th`` (`stroke_geometry.turning`): the share of the path over which it effectively turns ((sum |th|)^2 over
    n sum th^2: 1 for an even bend, about the corners' share of the path for a polyline); the most it turns (net)
    within `PEAK_SPAN` of its path (`stroke_geometry.sharpest_turn`) over all it turns; the share of its turning made
    outside its `SIDE_SHARE` most sharply turning points; and the largest bow (`stroke_geometry.chord_deviation`,
    at most 1) of the sides left once every stretch of `PEAK_SPAN` turning `PEAK_TURN` or more is cut out (up to
    `MAX_PEAKS`, the sharpest first): a polyline's sides are straight, a curve is one bowed piece. Each is the same
    drawn from either end."""
    a = np.abs(th)
    total = float(np.add.reduce(a))
    n = len(a)
    if n < 3 or total <= 1e-9:
        return 1.0, 0.0, 1.0, 0.0
    spread = total * total / (n * float(np.add.reduce(a * a)))
    w = max(1, round(PEAK_SPAN * (len(work) - 1)))
    done = np.concatenate([[0.0], np.add.accumulate(np.degrees(th))])
    net = np.abs(done[w:] - done[:-w]) if w < len(done) else np.array([abs(float(done[-1]))])
    peak = min(float(np.maximum.reduce(net)) / math.degrees(total), 1.0)
    k = max(1, round(SIDE_SHARE * n))
    outside = float(np.add.reduce(np.sort(a)[:-k])) / total
    return spread, peak, outside, _side_bow(work, net, w)


def _side_bow(work: np.ndarray, net: np.ndarray, w: int) -> float:
    """The largest bow of the pieces of ``work`` left between its corners (`corner_features`): ``net[i]`` is the
    turning at points ``i + 1 .. i + w`` of ``work``, so a corner there is cut from point ``i`` to point ``i + w``."""
    free = np.ones(len(net), dtype=bool)
    cuts: list[tuple[int, int]] = []
    for _ in range(MAX_PEAKS):
        score = np.where(free, net, -1.0)
        i = int(np.argmax(score))
        if score[i] < PEAK_TURN:
            break
        cuts.append((i, i + w))
        free[max(0, i - w):i + w + 1] = False  # no window overlapping this one
    edges = [0] + [p for c in sorted(cuts) for p in c] + [len(work) - 1]
    length = sg.path_length(work)
    bows = [sg.chord_deviation(work[a:b + 1]) for a, b in zip(edges[::2], edges[1::2], strict=True)
            if b - a >= 2 and sg.path_length(work[a:b + 1]) >= SIDE_MIN * length]
    return min(max(bows), 1.0) if bows else 0.0
