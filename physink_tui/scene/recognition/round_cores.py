"""A round shape drawn with a lead from inside it or an end curling in past its start, read by its round core; no I/O.

Issue 25: circles read as curves. A hand often lands inside a circle and runs out to the rim before going round
(itt lvht1203), or curls its last stretch in, as a spiral's last turn (dollar1 s02, hcira jonathanzhang53/s04,
klarubbio/s06). The stroke goes most of a turn, smoothly, one way, as a circle left open does, but one ellipse no longer
fits all of it: the lead or the curl lies inside the round. What a reader sees is the round core with a stroke inside
it. The core is found by cutting the end that lies farther inside the ellipse fitted so far, a little at a time
(`STEP`, at most `MOST_CUT` of the path in all); what is cut must lie inside the core's ellipse (`INSIDE`): a pigtail's
or a 6's tail runs out of its loop, an arc's or a question mark's does not turn most of a turn.
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
