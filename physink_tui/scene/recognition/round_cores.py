"""A round shape drawn with a lead from inside it or an end curling in past its start, read by its round core; no I/O.

Issue 25: circles read as curves. A hand often lands inside a circle and runs out to the rim before going round
(itt lvht1203), or curls its last stretch in, as a spiral's last turn (dollar1 s02, hcira jonathanzhang53/s04,
klarubbio/s06). The stroke goes most of a turn, smoothly, one way, as a circle left open does, but one ellipse no longer
fits all of it: the lead or the curl lies inside the round. What a reader sees is the round core with a stroke inside
it. The core is found by cutting the end that lies farther inside the ellipse fitted so far, a little at a time
(`STEP`, at most `MOST_CUT` of the path in all); what is cut must lie inside the core's ellipse (`INSIDE`): a pigtail's
or a 6's tail runs out of its loop, an arc's or a question mark's does not turn most of a turn.

Issue 25, session 36: a Tablet PC pen's circle often goes round past its start and runs on out of the loop, or lands
outside it and crosses in (the `sign` set's ST5022 writers). Its tails are short against a pigtail's, and the loop
between closes as a question mark's curl does not: `run_on_core` reads it by that loop.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse

STEP = 0.025
"""Each cut takes this share of the path off one end."""
MOST_CUT = 0.4
"""At most this share of the path is cut, both ends together (a lead from the middle of a circle is about 0.07 of
the path; a spiral's last half turn curling in to half the radius, about 0.3)."""
INSIDE = 1.05
"""Every point cut lies within this many times the core's ellipse's radius in its direction from the centre."""
MIN_POINTS = 16
"""A core of fewer points is no round shape (the fit needs points round the whole turn)."""


def _radial(pts: np.ndarray, ellipse: EllipseFit) -> np.ndarray:
    """Each point's distance from the ellipse's centre over the ellipse's radius in that direction."""
    centre, rx, ry, angle, _ = ellipse
    rel = pts - centre
    c, s = math.cos(angle), math.sin(angle)
    u = (rel[:, 0] * c + rel[:, 1] * s) / rx
    v = (-rel[:, 0] * s + rel[:, 1] * c) / ry
    return np.hypot(u, v)


def round_core(work: np.ndarray, fits: Callable[[EllipseFit], bool], min_turn: float,
               whole: EllipseFit | None = None) -> EllipseFit | None:
    """The ellipse of ``work``'s round core, or None: ``work`` (an open stroke, equally spaced points) less a lead or
    curl at its ends that lies inside that ellipse (`INSIDE`), at most `MOST_CUT` of the path, the core still turning
    by ``min_turn`` radians or more; ``fits`` (an ellipse fit -> bool) says whether an ellipse fits the core;
    ``whole``: the ellipse already fitted to all of ``work``, where the caller has it."""
    n = len(work)
    step = max(1, round(STEP * (n - 1)))
    most = int(MOST_CUT * (n - 1))
    lo, hi = 0, n
    while True:
        core = work[lo:hi]
        if len(core) < MIN_POINTS:
            return None
        ellipse = whole if whole is not None and lo == 0 and hi == n else fit_ellipse(core)
        if ellipse is None or not (ellipse[1] > 0 and ellipse[2] > 0):
            return None
        if fits(ellipse):
            if lo + n - hi == 0:
                return None  # nothing cut: the plain fit's question, not this one's
            cut = np.concatenate([work[:lo], work[hi:]])
            if abs(float(sg.turning(core).sum())) < min_turn or float(_radial(cut, ellipse).max()) > INSIDE:
                return None
            return ellipse
        if lo + (n - hi) + step > most:
            return None
        # cut the end lying farther inside the round fitted so far (a lead's or a curl's points lie inside it); one
        # reaching out of it (a pigtail's tail) ends the search at once: what is cut must lie inside
        head = _radial(core[:step], ellipse)
        tail = _radial(core[-step:], ellipse)
        cut_head = float(head.mean()) <= float(tail.mean())
        if float((head if cut_head else tail).max()) > INSIDE:
            return None
        if cut_head:
            lo += step
        else:
            hi -= step


RUN_ON_CUT = 0.15
"""At most this share of the path, both ends together, runs off a loop as its tails where the pen overshot its start
and swung on out (`run_on_core`). Measured on the design group's 656 pigtails and question marks that reach the open
reading (session 36, wt-bracket): a pigtail's tails are at least 0.20 of its path wherever the rest turns 1.6 pi and
fits an ellipse; the ST5022 writers' circles of the `sign` set run on 0.03-0.17."""
RUN_ON_TURN = 1.7 * math.pi
"""The loop left once its tails are cut turns at least this far (nearly round, back past the start; the `sign` circles
that overshoot turn 1.76-1.91 pi). A question mark's hook and curl may turn as far (dollar1 s04 medium question_mark10,
its stem cut: 1.73 pi), so the loop must also close (`RUN_ON_GAP`)."""
RUN_ON_GAP = 0.35
"""The loop's ends (its tails cut) lie within this share of its length (the ellipse's longer axis) of each other: it
came back round to its start. A question mark whose hook and curl turn that far leaves its loop open by about half its
length (dollar1 s04 medium question_mark10: 0.47); the `sign` circles run on 0.17-0.29."""


def run_on_core(work: np.ndarray, fits: Callable[[EllipseFit], bool]) -> EllipseFit | None:
    """The ellipse of ``work``'s loop where the pen went round past its start and ran on out of the loop (or landed
    outside it): ``work`` (an open stroke, equally spaced points) less tails at its ends, inside or outside the loop, of
    at most `RUN_ON_CUT` of the path together, the rest turning `RUN_ON_TURN` or more, fitting an ellipse (``fits``)
    and closing within `RUN_ON_GAP`; the least cut that does, the end cut first where both do. None where none does or
    nothing need be cut (a tail outside a loop over `RUN_ON_CUT` is a pigtail's or a 6's, `round_core`'s)."""
    th = sg.turning(work)
    if float(np.abs(th).sum()) < RUN_ON_TURN:
        return None  # no part turns farther than the whole path turns either way
    n = len(work)
    step = max(1, round(STEP * (n - 1)))
    most = int(RUN_ON_CUT * (n - 1))
    for cut in range(step, most + 1, step):
        for tail in range(cut, -1, -step):
            core = work[cut - tail:n - tail]
            if len(core) < MIN_POINTS or abs(float(th[cut - tail:n - tail - 2].sum())) < RUN_ON_TURN:
                continue
            gap = float(np.hypot(*(core[-1] - core[0])))
            if gap > RUN_ON_GAP * sg.bbox_diagonal(core):
                continue  # open wider than any loop this size closes (its longer axis is within its box's diagonal)
            ellipse = fit_ellipse(core)
            if (ellipse is not None and ellipse[1] > 0 and ellipse[2] > 0 and fits(ellipse)
                    and gap <= RUN_ON_GAP * 2 * max(ellipse[1], ellipse[2])):
                return ellipse
    return None
