"""A curly brace drawn square-cornered, a square bracket with a point on its spine, read as a brace; no I/O.

Issue 25 (session 23): a hand on a mouse or a trackpad, which cannot swing a curl, draws a brace as a bracket's end
arms turned at square corners onto a spine, with a small point halfway along it (hcira jonathanzhang53/s01's right
brace 1). Where the point sticks out under a twentieth of the spine, the open-stroke rules' corner finder, on points
several pixels apart, smooths it away: four corners, one way round, a bracket (a polyline). What a reader sees is a
brace: a sharp point about halfway (`POINT_AT`) between two straight pieces of spine running on in line with each
other (`IN_LINE_DEG`), standing out of each piece's line away from the arms (`POINT_NOISE` noise widths and
`POINT_OUT` of the spine), each end standing off that line on the arms' side (`END_OFF`). A bracket's spine has no
point (a hand's wobble along it turns less than `stroke_geometry.POINT_TURN_DEG` or stands out less); a zig-zag's or a
W's pieces either side of its middle tooth slant apart; a step's pieces are offset, not in line, and turn at right
angles; an arrow's head is at an end.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

JUDGED_POINTS = 160
"""The stroke is judged on this many points equally spaced, lightly smoothed (`stroke_geometry.smooth`): a point a
twentieth of a 300 px spine out keeps most of its depth (on the open-stroke rules' 7-8 px steps it is smoothed away)."""
SPACING = 2.0
"""...but no closer than this many of the pen's noise widths (a mouse's whole-pixel stairs turn 20-30 degrees within a
few pixels: on points farther apart they are smoothed away)..."""
MIN_POINTS = 64
"""...and at least this many."""
POINT_AT = (0.3, 0.7)
"""The point, where the stroke turns most sharply in this stretch of its path (shares of it), by
`stroke_geometry.POINT_TURN_DEG` or more within `stroke_geometry.POINT_SPAN` (as `thin_braces.POINT_AT`)..."""
POINT_REACH = 0.12
"""...has its bends (out of the spine, round the point, back) within this share of the path of it..."""
PIECE_SHARE = 0.1
"""...and on each side, past them, a piece of spine up to the next sharp turn (a square corner) or the stroke's end, at
least this share of the path (an arm's hook or a zig-zag's short tooth is no spine)..."""
PIECE_STRAIGHT = 0.08
"""...straight, straying from its chord by less than this share of it (`bracket_marks.BRACKET_STRAIGHT` is 0.12: a
spine is straighter than a hand's arms)..."""
IN_LINE_DEG = 20.0
"""...the two pieces heading within this many degrees of each other..."""
IN_LINE_OFF = 0.75
"""...and each piece's middle within this share of the point's depth of the other's line: the spine runs on through
the point (a W's or a zig-zag's pieces slant apart; a step's are offset as far as its riser; the halves of a spine a
hand drew in two strokes of the wrist stand a few pixels apart: hcira jonathanzhang53/s01's right brace 1, 0.55)."""
POINT_NOISE = 3.0
"""The point stands out of each piece's line by at least this many of the pen's noise widths (a straight line's wobble
reaches about three, `lines.wobble_reach`)..."""
POINT_OUT = 0.025
"""...and by at least this share of the spine (both pieces and the point between them): a mouse's jog or a hand's
tremor along a bracket's spine stands out less..."""
POINT_DEEP = 0.35
"""...and by less than this share of it (a deeper point makes a brace the other rules read: `angular_braces`,
`bracket_marks.brace_point`; a deep notch is a chevron's)."""
END_OFF = 1.0
"""Each end stands off its piece's line on the side away from the point by at least this many times the point's
depth..."""
END_NOISE = 2.0
"""...and this many noise widths: the end arms carry the ends to the other side (a hooked line's hooks are short)."""
NO_RETURN = 0.1
"""The stroke runs along the line joining its ends, turning back along it by less than this share of that line."""


def _sharp(pts: np.ndarray, length: float) -> np.ndarray:
    """Each point's turn (degrees, net) within `stroke_geometry.POINT_SPAN` of the path round it: over an odd number of
    turning points centred on it (an even window would lean one point toward the stroke's end, and the point and the
    spine's pieces then fall one point apart drawn from the other end: hcira jonathanzhang53/s01's right brace 1 read
    a brace as drawn and a bracket reversed)."""
    step = length / (len(pts) - 1)
    w = max(1, round(sg.POINT_SPAN * length / step)) | 1
    done = np.concatenate([[0.0], np.add.accumulate(np.degrees(sg.turning(pts)))])
    sharp = np.zeros(len(pts))
    sharp[(w + 1) // 2:(w + 1) // 2 + len(done) - w] = np.abs(done[w:] - done[:-w])
    return sharp


def _piece(sharp: np.ndarray, cum: np.ndarray, k: int, way: int) -> tuple[int, int] | None:
    """The piece of spine on one side of the point ``k`` (``way``: +1 after it, -1 before it), as indices in drawing
    order (first <= last): the first run turning less than `stroke_geometry.POINT_TURN_DEG` all along that is at least
    `PIECE_SHARE` of the path (``cum``: the path's length at each point), found within `POINT_REACH` of the point (the
    point's bends, out of the spine and back, are passed over), up to where the stroke next turns sharply or ends;
    None where there is none."""
    last, length = len(sharp) - 1, float(cum[-1])
    i = k
    while 0 <= i <= last and abs(float(cum[i] - cum[k])) <= POINT_REACH * length:
        if sharp[i] >= sg.POINT_TURN_DEG:
            i += way
            continue
        j = i
        while 0 <= j + way <= last and sharp[j + way] < sg.POINT_TURN_DEG:
            j += way
        if abs(float(cum[j] - cum[i])) >= PIECE_SHARE * length:
            return (i, j) if way > 0 else (j, i)
        i = j + way
    return None


def square_brace(raw: np.ndarray, noise: float, views: StrokeViews | None = None) -> bool:
    """Whether the open stroke ``raw`` (its points as drawn; ``noise`` the pen's, in their units) is a brace drawn
    square-cornered: a sharp point about halfway (`POINT_AT`) between two straight pieces of spine (`PIECE_SHARE`,
    `PIECE_STRAIGHT`) in line with each other (`IN_LINE_DEG`, `IN_LINE_OFF`), standing out of each piece's line
    (`POINT_NOISE`, `POINT_OUT`, `POINT_DEEP`) away from the ends (`END_OFF`, `END_NOISE`), the stroke running along
    the line joining its ends (`NO_RETURN`). The same whichever end it was drawn from, whichever way it faces.
    ``views``: ``raw``'s `stroke_views.StrokeViews`, where made (the answer then found once for each ``noise``)."""
    if views is not None:
        return views.once(("square_brace", noise), lambda: _square_brace(raw, noise, views))
    return _square_brace(raw, noise, None)


def _square_brace(raw: np.ndarray, noise: float, views: StrokeViews | None) -> bool:
    if len(raw) < 8:
        return False
    n = JUDGED_POINTS
    if noise > 0:
        n = int(min(JUDGED_POINTS, max(MIN_POINTS, sg.path_length(raw) / (SPACING * noise))))
    pts = sg.smooth(sg.resample(raw, n)) if views is None else views.smoothed(n)
    start, end = pts[0], pts[-1]
    chord = float(np.hypot(*(end - start)))
    if chord == 0.0:
        return False
    along = (pts - start) @ ((end - start) / chord)
    if float(np.max(np.maximum.accumulate(along) - along)) >= NO_RETURN * chord:
        return False  # checked first: most strokes are no brace
    cum = sg.along(pts)
    length = float(cum[-1])
    middle = np.flatnonzero((cum >= POINT_AT[0] * length) & (cum <= POINT_AT[1] * length))
    if len(middle) == 0 or length == 0.0:
        return False
    sharp = _sharp(pts, length)
    k = int(middle[np.argmax(sharp[middle])])
    if sharp[k] < sg.POINT_TURN_DEG:
        return False
    found = [_piece(sharp, cum, k, -1), _piece(sharp, cum, k, 1)]
    if found[0] is None or found[1] is None:
        return False
    pieces: list[tuple[int, int]] = [found[0], found[1]]
    lines = []
    for a, b in pieces:
        piece = pts[a:b + 1]
        d = piece[-1] - piece[0]
        norm = float(np.hypot(*d))
        if norm == 0.0 or sg.chord_deviation(piece) >= PIECE_STRAIGHT:
            return False
        lines.append((piece.mean(axis=0), d / norm))
    if float(lines[0][1] @ lines[1][1]) < math.cos(math.radians(IN_LINE_DEG)):
        return False
    spine = float(cum[pieces[1][1]] - cum[pieces[0][0]])
    depths, offs = [], []
    for (centre, u), tip_end, (other, _) in zip(lines, (start, end), lines[::-1], strict=True):
        normal = np.array([u[1], -u[0]])
        depths.append(float((pts[k] - centre) @ normal))
        offs.append((float((tip_end - centre) @ normal), float((other - centre) @ normal)))
    if depths[0] * depths[1] <= 0:
        return False  # the point on the same side of both pieces
    depth = min(abs(d) for d in depths)
    if not max(POINT_NOISE * noise, POINT_OUT * spine) <= depth < POINT_DEEP * spine:
        return False
    side = math.copysign(1.0, depths[0])
    return all(-side * end_off >= max(END_OFF * depth, END_NOISE * noise) and abs(mid_off) <= IN_LINE_OFF * abs(own)
               for (end_off, mid_off), own in zip(offs, depths, strict=True))


def kept_brace(found: Recognition, unit: np.ndarray, noise: float, views: StrokeViews | None = None) -> bool:
    """Whether the rules read a curve from a stroke (``unit``: its points at unit size, ``noise`` the pen's in those
    units) that is a `square_brace`: not asked of the learned ranker (`recognize`), which sees its square corners and
    straight runs as a bracket's, a polyline."""
    return found.kind == "curve" and square_brace(unit, noise, views)
