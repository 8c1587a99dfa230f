"""A round stroke left open whose end flicks off as the pen lifts (or lands): the flick cut, judged against the turning
of the round path itself (`stroke_geometry.remove_hooks` asks the path after a hook to run nearly straight, which a
circle's does not); no ranking, no I/O."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from physink_tui.scene.recognition import shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_ellipse

HOOK_SHARE = 0.08
"""A flick at an end is at most this share of the stroke's path (a hook a tenth of a circle's size is 3 % of its
path; a question mark's or a pigtail's tail is a third or more), and so are both ends' flicks together (a small
parenthesis hooked where the pen landed and where it lifted, 11 % of its path, is no circle once both are cut)."""
HOOK_TURN = math.radians(45.0)
"""... and turns off the round path's own steady turning by at least this much in all."""
ROUGH_SHARE = 0.6
"""`round_flicked` fits nothing to a rest whose own turning (on ``work``'s points) is under this share of the turn it
must make on its coarse turning (a quick refusal; the coarse turning of a round rest is within a few degrees of it)."""
HOOK_DONE = 0.85
"""Where the flick begins: the first point from the end at which its turn off the path has reached this share of all
it turns (`stroke_geometry._hook_end`'s rule)."""


def without_flicks(work: np.ndarray, th: np.ndarray) -> np.ndarray | None:
    """``work`` (resampled evenly along its path; ``th`` its `stroke_geometry.turning`) without a short flick at
    either end that turns off the path's steady turning (`HOOK_SHARE`, `HOOK_TURN`), or None where neither end has
    one."""
    n = len(work)
    if n < 16 or len(th) != n - 2:
        return None
    k = max(2, int(HOOK_SHARE * (n - 1)))  # points evenly spaced: a share of them is that share of the path
    middle = th[k:len(th) - k]
    if len(middle) < 4:
        return None
    # the round path's own turning a step just inside each end (an oval turns faster at its tips than along its sides)
    start = _flick(th[:k] - float(np.mean(th[k:2 * k])))
    end = _flick(th[::-1][:k] - float(np.mean(th[::-1][k:2 * k])))
    if (start == 0 and end == 0) or start + end > k:
        return None  # no flick; or flicks at both ends together longer than one may be (a small parenthesis' hooks)
    return work[start:n - end]


def _flick(off: np.ndarray) -> int:
    """How many points from the end (``off``: the turning off the steady rate at each vertex, the end's first) a flick
    takes, 0 for none."""
    cum = np.abs(np.add.accumulate(off))
    peak = float(cum.max()) if len(cum) else 0.0
    if peak < HOOK_TURN:
        return 0
    return int(np.argmax(cum >= HOOK_DONE * peak)) + 1


def round_flicked(work: np.ndarray, th: np.ndarray, noise: float, fits: Callable[[EllipseFit], bool], min_turn: float,
                  smooth: float) -> EllipseFit | None:
    """The ellipse of ``work`` (an open stroke, evenly spaced; ``th`` its turning) once a flick at its ends is cut
    (`without_flicks`), where the rest is a round shape left open: it turns ``min_turn`` radians or more, smoothly
    (`stroke_features.turn_concentration` under ``smooth``) and one way, and ``fits`` (an ellipse fit -> bool) says an
    ellipse fits it; else None."""
    if float(np.abs(th).sum()) < min_turn:
        return None  # turns too little in all for any part of it to go round (most open strokes: asked no more)
    rest = without_flicks(work, th)
    if rest is None or len(rest) < 16 or abs(float(sg.turning(rest).sum())) < ROUGH_SHARE * min_turn:
        return None
    coarse = shape_turning.coarse_turning(rest, noise)
    turned = abs(float(coarse.sum()))
    if (turned < min_turn or turned <= 0.75 * float(np.abs(coarse).sum())
            or sf.turn_concentration(coarse) >= smooth):
        return None
    ellipse = fit_ellipse(rest)
    return ellipse if ellipse is not None and fits(ellipse) else None
