"""Whether the bursts of a mouse's events are tangent to one round curve (a loop), not on sides with corners between
them (an outline), judged by the turns either side of the jumps between bursts; no classification, no I/O."""

from __future__ import annotations

import itertools
import math

import numpy as np

from physink_tui.scene.recognition.shape_fits import EllipseFit

BURST_HEADING = 0.03
"""A burst's heading is taken from its first event to its last where they lie at least this share of the diagonal
apart (of the stroke's ellipse made a unit circle: a mouse's whole pixels at 60-200 px across make a heading over 2-6 px
a guess)."""
TANGENT_TURN = math.radians(150)
"""A jump across which the path turns by more than this in all is left out (a hook, or the run-on at the close heading
off the loop)."""
EVEN_TANGENTS = 0.4
"""A closed stroke in bursts is round where the turns either side of its jumps differ by at most this share of their
sum (`tangent_to_one_curve`). The pen models through the mouse, tuning seeds, the closed strokes the closeness test
(`pen_noise.BURST_CLOSER`) refuses: whole notes and small circles 0.04-0.55, median 0.31, 24 of 30 at 0.4 or under;
small, thin, rounded and slipped boxes 0.29-0.9, median 0.62, one under 0.5 (a small box read as a polygon before)."""
def tangent_turns(pts: np.ndarray, jumps: np.ndarray, ellipse: EllipseFit) -> tuple[float, float, int]:
    """Across each jump between bursts of ``pts`` (``jumps``: which steps jump), with the stroke's ``ellipse`` made a
    unit circle: the turn from the burst before to the jump's chord and from the chord to the burst after. Returns how
    much the two turns differ, summed; the turns summed; and over how many jumps. The two tangents from a point to a
    circle are equal, so a chord between two bursts on it makes equal angles with both; a polygon's bursts lie on its
    sides, the chord cutting a corner wherever they happened to fall, turning more at one end than the other. Bursts too
    short for a heading (`BURST_HEADING`) and jumps that turn back (`TANGENT_TURN`) are left out."""
    (cx, cy), rx, ry, angle, _ = ellipse
    c, s = math.cos(angle), math.sin(angle)
    rel = pts - np.array([cx, cy])
    unit = np.column_stack([(rel[:, 0] * c + rel[:, 1] * s) / rx, (-rel[:, 0] * s + rel[:, 1] * c) / ry])
    cut = [0, *(int(i) + 1 for i in np.flatnonzero(jumps)), len(pts)]
    heads: list[float | None] = []
    for a, b in itertools.pairwise(cut):
        chord = unit[b - 1] - unit[a]
        heads.append(math.atan2(chord[1], chord[0]) if math.hypot(*chord) >= BURST_HEADING * 2 * math.sqrt(2)
                     else None)
    unequal = total = 0.0
    count = 0
    for k in range(len(heads) - 1):
        before, after = heads[k], heads[k + 1]
        if before is None or after is None:
            continue
        jump = unit[cut[k + 1]] - unit[cut[k + 1] - 1]
        chord = math.atan2(jump[1], jump[0])
        first = (chord - before + math.pi) % (2 * math.pi) - math.pi
        second = (after - chord + math.pi) % (2 * math.pi) - math.pi
        if abs(first) + abs(second) <= TANGENT_TURN:
            unequal += abs(first - second)
            total += abs(first) + abs(second)
            count += 1
    return unequal, total, count


def tangent_to_one_curve(pts: np.ndarray, jumps: np.ndarray, ellipse: EllipseFit) -> bool:
    """Whether the bursts of a closed stroke are tangent to one round curve, its ``ellipse``: the turns either side of
    its jumps about equal (`EVEN_TANGENTS`, `tangent_turns`)."""
    unequal, total, _ = tangent_turns(pts, jumps, ellipse)
    return total > 0 and unequal <= EVEN_TANGENTS * total

