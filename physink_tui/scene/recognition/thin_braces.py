"""A tall, thin curly brace that the line test takes for a line, told from one by its point and curls; no I/O.

Issue 25 (session 21): a brace drawn tall and thin (its curls and point standing out under a tenth of its length,
itt EmmaSophieReichert's and hcira hat359/user3's right braces, the `brace_habits` pen models' tall-thin family) strays
from its fitted line less than a line may (`open_shapes.LINE`), and its curls are cut as the pen's hooks: the line
test reads a line. What a reader sees is a brace: a point about halfway that sticks out sharply from the line of its
arms, and both ends curling back to the other side of that line. A line has no point in its middle (a pen's wobble,
a swung line's bow and a line's hooks are no point: `POINT_NOISE`, `stroke_geometry.POINT_TURN_DEG`), and a hooked
line's hooks do not both curl away from a point.
"""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

JUDGED_POINTS = 64
"""The stroke is judged resampled to this many points, lightly smoothed (`stroke_geometry.smooth`)."""
POINT_AT = (0.3, 0.7)
"""The point (where the stroke turns most sharply in this stretch of its path, shares of it: by
`stroke_geometry.POINT_TURN_DEG` or more within `stroke_geometry.POINT_SPAN`, and no arm turns so: a shaky hand's line
wobbles all along, a brace has one point between its curls)..."""
POINT_NOISE = 3.0
"""...stands out of each arm's line (the chord of the arm's run between 35 % and 80 % of the way from its end to the
point) by at least this many of the pen's noise widths (a straight line's wobble reaches about three,
`lines.wobble_reach`)..."""
CURL_NOISE = 2.0
"""...and each end stands off its arm's line on the other side by at least this many noise widths: the curls carry
the ends back behind the arms. A v's or an obtuse chevron's arm runs on to its end and to its point (both on its
line), a bow's or an arc's ends and middle lie on the same side of any of its chords, a line's hooks curl off its
ends with no point between them."""
NO_RETURN = 0.1
"""The stroke runs along the line joining its ends, turning back along it by less than this share of that line."""


def thin_brace(raw: np.ndarray, noise: float) -> bool:
    """Whether the stroke ``raw`` (``noise``: the pen's, in its units) is a tall, thin curly brace: a sharp point
    (`stroke_geometry.POINT_TURN_DEG` within `stroke_geometry.POINT_SPAN`) about halfway (`POINT_AT`) standing out of
    each arm's line by `POINT_NOISE` noise widths, the arm's end standing off it the other way (`CURL_NOISE`), the
    stroke running along its chord (`NO_RETURN`). None of these tests asks which way the brace faces or which end it
    was drawn from."""
    if len(raw) < 8:
        return False
    pts = sg.smooth(sg.resample(raw, JUDGED_POINTS))
    start, end = pts[0], pts[-1]
    chord = float(np.hypot(*(end - start)))
    if chord == 0.0:
        return False
    unit = (end - start) / chord
    rel = pts - start
    along = rel @ unit
    if float(np.max(np.maximum.accumulate(along) - along)) >= NO_RETURN * chord:
        return False  # checked first, with the point below: most strokes the line test passes are lines
    cum = sg.along(pts)
    length = float(cum[-1])
    middle = np.flatnonzero((cum >= POINT_AT[0] * length) & (cum <= POINT_AT[1] * length))
    if len(middle) == 0:
        return False
    # the point: where the stroke turns most sharply in that stretch (the farthest from the chord where curls of
    # unlike width tilt it is a curl's foot, not the point)
    step = length / (len(pts) - 1)
    w = max(1, round(sg.POINT_SPAN * length / step))
    done = np.concatenate([[0.0], np.add.accumulate(np.degrees(sg.turning(pts)))])  # done[j]: turned at points 1 .. j
    sharp = np.zeros(len(pts))  # each point's turn within `stroke_geometry.POINT_SPAN` round it (`sharpest_turn`'s)
    sharp[(w + 1) // 2:(w + 1) // 2 + len(done) - w] = np.abs(done[w:] - done[:-w])
    k = int(middle[np.argmax(sharp[middle])])
    if sharp[k] < sg.POINT_TURN_DEG:
        return False  # no point: a line's wobble, a swung line's bow
    at = float(cum[k])
    in_arms = ((cum >= 0.35 * at) & (cum <= 0.8 * at),
               (cum >= at + 0.2 * (length - at)) & (cum <= at + 0.65 * (length - at)))
    sides = []
    for run, tip_end in zip(in_arms, (pts[0], pts[-1]), strict=True):
        arm = pts[run]
        if len(arm) < 2 or float(sharp[run].max()) >= sg.POINT_TURN_DEG:
            return False  # an arm with a point of its own: a shaky hand's wobble, not a brace's one point
        d = arm[-1] - arm[0]
        norm = float(np.hypot(*d))
        if norm == 0.0:
            return False
        normal = np.array([d[1], -d[0]]) / norm
        point_off, end_off = float((pts[k] - arm[0]) @ normal), float((tip_end - arm[0]) @ normal)
        if abs(point_off) < POINT_NOISE * noise or abs(end_off) < CURL_NOISE * noise or point_off * end_off > 0:
            return False
        sides.append(point_off > 0)
    return sides[0] == sides[1]  # the same point for both arms, not an S
