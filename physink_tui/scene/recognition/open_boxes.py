"""Whether an open stroke is a four-sided outline the pen left open by part of a side (a box whose last side stops
half way, or begun mid-wall and lifted at the corner before the start), to be read closed; no fitting, no I/O."""

from __future__ import annotations

import itertools
import math

import numpy as np

from physink_tui.scene.recognition import open_shapes
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.closed_loops import LAST_SIDE_BOW, LEFT_OPEN_CLOSURE

CORNER_SLACK_DEG = 35.0
"""Each corner turns within this many degrees of a right angle, all the same way (the three drawn and the fourth, where
the first and last sides' lines meet): a box, or a quad with a wall askew as far as `quads.WALL_ASKEW` (34 degrees)
lets a box lean."""
PART_DRAWN = 0.3
"""The first and last sides are each drawn for at least this share of the side they make up to the fourth corner: a
side, not a hook (a bracket's landing hook turned in is a tenth of its spine or less; a box missing 0.4-0.65 of its
last side keeps 0.35-0.6 of it)."""
RUN_PAST = 0.25
"""The first or last side may run past the fourth corner by this share of itself (the pen lifting on past the corner
of a box begun mid-wall: itt Bam33751 rectangle_09); further, the ends cross, which `closed_loops.ends_cross` reads."""
LEAST_TURN = 0.4 * math.pi
"""The path of a box left open turns one way at three corners, each within `CORNER_SLACK_DEG` of square: at least
three times 55 degrees, less what a hook at an end may undo (`closed_loops.LEFT_OPEN_WOBBLE`, a quarter turn); a
zig-zag or a wave turns back and forth, netting less. Asked first, before any corner is looked for."""
KEPT_END = 0.03
"""A run at an end of the stroke as short as this share of the path is a stub, not a side (`four_sides`): a box's last
side drawn for a third of a short side of a 2.5:1 box is 0.05 of the path, under the 0.07 the polygons left open
drop (`stroke_features.drop_end_stubs`)."""


def four_sides(work: np.ndarray) -> list[np.ndarray] | None:
    """The four runs of an open stroke with three corners (`stroke_geometry.find_corners`; an end run under `KEPT_END`
    of the path dropped as a stub, and where that leaves four corners, one under `stroke_features.drop_end_stubs`'
    share: a hook; where it finds two, the third where the run bowing most, if not straight, strays furthest from its
    chord: a corner rounded off), or None when it has other than three."""
    length = sg.path_length(work)
    corners = sf.drop_end_stubs(work, sg.find_corners(work), length, KEPT_END)
    if len(corners) == 6:  # a hook at an end besides the three corners
        corners = sf.drop_end_stubs(work, corners, length)
    if len(corners) == 4:  # a corner swung round too wide for the corner finder: where its run bows out most
        bows = [sg.chord_deviation(work[a:b + 1]) for a, b in itertools.pairwise(corners)]
        k = int(np.argmax(bows))
        if bows[k] >= open_shapes.STRAIGHT:
            corners.insert(k + 1, corners[k] + _farthest_from_chord(work[corners[k]:corners[k + 1] + 1]))
    if len(corners) != 5:
        return None
    return [work[a:b + 1] for a, b in itertools.pairwise(corners)]


def _farthest_from_chord(run: np.ndarray) -> int:
    rel = run - run[0]
    chord = rel[-1] / max(float(np.hypot(*rel[-1])), 1e-12)
    return int(np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]).argmax())


def _heading(v: np.ndarray) -> float:
    return math.atan2(float(v[1]), float(v[0]))


def _turn(a: float, b: float) -> float:
    return (b - a + math.pi) % (2 * math.pi) - math.pi


def box_left_open(work: np.ndarray, diag: float) -> bool:
    """Whether ``work`` (an open stroke's working points, ``diag`` its diagonal) is a four-sided outline left open by
    part of its first or last side: three corners drawn, and the fourth where the first and last sides' lines meet, each
    within `CORNER_SLACK_DEG` of square, turning the same way; its sides straight (`open_shapes.STRAIGHT`; the first and
    last may bow as `closed_loops.LAST_SIDE_BOW`); the ends apart by less than `closed_loops.LEFT_OPEN_CLOSURE` of the
    diagonal, and the first and last sides drawn for `PART_DRAWN` of themselves or more, either run past the fourth
    corner by no more than `RUN_PAST` of it.

    >>> side = [(x, 0.0) for x in range(0, 100, 4)]
    >>> box = side + [(100.0, y) for y in range(0, 60, 4)] + [(x, 60.0) for x in range(100, 0, -4)]
    >>> box_left_open(np.array(box + [(0.0, y) for y in range(60, 28, -4)], dtype=float), 117.0)
    True
    >>> box_left_open(np.array(box + [(0.0, y) for y in range(60, 52, -4)], dtype=float), 117.0)  # a hook
    False
    """
    if sg.path_length(work) < 1.75 * diag or sf.closure(work, diag) >= LEFT_OPEN_CLOSURE:
        return False
    if abs(float(sg.turning(work).sum())) < LEAST_TURN:
        return False
    runs = four_sides(work)
    if runs is None:
        return False
    bows = [sg.chord_deviation(r) for r in runs]
    if max(bows[1:3]) >= open_shapes.STRAIGHT or max(bows[0], bows[3]) >= LAST_SIDE_BOW:
        return False
    chords = [r[-1] - r[0] for r in runs]
    lengths = [float(np.hypot(*c)) for c in chords]
    if min(lengths) <= 0.0:
        return False
    headings = [_heading(c) for c in chords]
    turns = [_turn(a, b) for a, b in itertools.pairwise([*headings, headings[0]])]
    if not (all(t > 0 for t in turns) or all(t < 0 for t in turns)):
        return False
    if any(abs(abs(t) - math.pi / 2) > math.radians(CORNER_SLACK_DEG) for t in turns):
        return False
    first, last = chords[0] / lengths[0], chords[3] / lengths[3]
    # the fourth corner, where the lines meet: start - behind * first = end + ahead * last
    cross = float(first[0] * last[1] - first[1] * last[0])
    gap = work[0] - work[-1]
    behind = float(gap[0] * last[1] - gap[1] * last[0]) / cross
    ahead = float(gap[1] * first[0] - gap[0] * first[1]) / cross
    if max(behind, ahead) <= 0.0:  # both ends ran past the corner: the ends cross
        return False
    return all(missing >= -RUN_PAST * drawn and drawn >= PART_DRAWN * (drawn + max(missing, 0.0))
               for drawn, missing in ((lengths[0], behind), (lengths[3], ahead)))
