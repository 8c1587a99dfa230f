"""A round loop the pen landed on and ran on past its start as a long tail, read by the loop; no I/O."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from physink_tui.scene.recognition import open_shapes
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.candidates import ellipse_distances
from physink_tui.scene.recognition.shape_fits import fit_ellipse

END_SEARCH = 0.3
"""The loop's two ends (where the path comes back to itself) are looked for within this share of the path from either
end of the stroke."""
LOOP_SHARE = 0.8
"""The loop holds at least this share of the path, its tails together at most a quarter of it (the run-on circles so
read 0.81-0.96; the design sets' 868 pigtails with a loop 0.41-1.0, 19 in 20 under 0.69, a whole loop, 1.0, being a
closed stroke `closed_loops.closed_loop` reads first). No margin against the pen models' round-loop pigtails
(`penmodels.pigtail_habits`: their loops hold 0.76-0.84, rounder than people's circles): those holding 0.8 or more are
closed strokes read round before this is asked, as at main. From 0.74 the rule read five more of the ST5022
writers' circles (their tails run off as far as a loop-first pigtail's) and 19 more of those 120 marks (tuning and
held seeds, as meant) round: no honest line between them there."""
MEETS = 0.15
"""The path comes back to within this share of the loop's size of where the loop began (a crossing: none; the run-on
circles read 0.01-0.14, the closest approach between the ends' shares `END_SEARCH`)."""
ON_LOOP = 0.45
"""One end (the landing, as drawn, or the lifting, drawn the other way) stays within this many half-lengths of the
loop's ellipse (square across it, `candidates.ellipse_distances`): the pen landed on the loop (the sign set's ST5022
run-on circles 0.0-0.41; the design sets' 868 pigtails with a loop, both tails running off, the nearer 0.71 or more in
19 of 20)."""
ROUND_ASPECT = 0.6
"""The loop's ellipse is at least this wide for its length (the run-on circles 0.63-0.78; a pigtail's teardrop loop
mostly narrower, 0.53 the median)."""
SAME_WAY_DEG = 60.0
"""Where the loop closes, the path heads within this many degrees of where it headed as the loop began: the pen going
on round past its start (the run-on circles 3-55 degrees; the design sets' pigtails' tails cross at a corner, 53 degrees
or more in 19 of 20, 92 the median)."""
GOES_ROUND = 2.0
"""Only a stroke whose path is at least this many times its size is asked (a circle's is 2.2 times its diagonal, and its
tail adds to both; the run-on circles read 2.56-3.05): most strokes, lines and marks, are not (as
`closed_loops.closed_loop` asks 1.75 of a closed one), and are spared the search."""
TURNS_ROUND = 1.5
"""Nor one whose heading never swings this many half turns one way along it (the loop alone turns a whole turn, less
the at most `SAME_WAY_DEG` it heads off where it closes: 1.67 half turns or more; a tail may turn back after it)."""
HEADING_SHARE = 0.03
"""Headings are taken over this share of the path either side of the loop's ends (a pen's wobble is shorter)."""


def run_on_loop(work: np.ndarray, diag: float, sigma: float) -> np.ndarray | None:
    """The loop of ``work`` (evenly resampled along its path; ``diag`` its size, ``sigma`` the noise the ranking allows)
    where it is a round loop run on past its start (`LOOP_SHARE`, `MEETS`, `ON_LOOP`, `ROUND_ASPECT`, `SAME_WAY_DEG`,
    and its ellipse within `open_shapes.round_error`), else None.

    Issue 25, session 41: the sign set's ST5022 writers writer1010 and writer001 draw a circle by landing on it, going
    round and running on past the start as a tail of a tenth to a fifth of the path, crossing the loop or passing near
    it. `closed_loops.closed_loop` closes a stroke only where its tail is as short as a closed stroke's gap
    (`closed_loops.CLOSED_GAP`), and then a tail running off the loop's ellipse as far as a loop-first pigtail's is an
    open mark (`closed_loops.tail_runs_off`). A reader sees the circle: only one end leaves the loop (the pen landed on
    it), the loop holds most of the path, is round, and the path comes back across its start going on round. A $1
    pigtail's two tails both run off its loop and cross at a corner round a loop holding less of the path; a 6's end
    meets its stem at a corner; a spiral's laps do not come back to where they began."""
    if (sg.path_length(work) < GOES_ROUND * diag
            or float(np.ptp(np.add.accumulate(sg.turning(work)))) < TURNS_ROUND * math.pi):
        return None
    loop = measure(work, sigma)
    if (loop is None or loop.on_loop > ON_LOOP or loop.aspect < ROUND_ASPECT or loop.turn_deg > SAME_WAY_DEG
            or not loop.fits):
        return None
    return loop.points


class Loop(NamedTuple):
    """A loop `measure` found in a stroke, and what `run_on_loop` judges of it."""

    points: np.ndarray
    """The stroke's points from where the loop begins to where the path comes back to it."""
    on_loop: float
    """How far the nearer of the stroke's two ends strays off the loop's ellipse, in half-lengths (`ON_LOOP`)."""
    aspect: float
    """The ellipse's width over its length (`ROUND_ASPECT`)."""
    turn_deg: float
    """The angle between the headings where the loop begins and where it closes, degrees (`SAME_WAY_DEG`)."""
    fits: bool
    """Whether the ellipse fits the loop as a round shape's (`open_shapes.round_error`)."""


def measure(work: np.ndarray, sigma: float) -> Loop | None:
    """The loop where the path comes back nearest to itself between its two end shares (`END_SEARCH`), and what
    `run_on_loop` judges of it; None where the path does not come back (`MEETS`) or the loop holds under `LOOP_SHARE`
    of it (nothing more is measured)."""
    n = len(work)
    along = sg.along(work)
    length = float(along[-1])
    if n < 16 or length <= 0.0:
        return None
    head = np.flatnonzero(along <= END_SEARCH * length)
    tail = np.flatnonzero(along >= (1.0 - END_SEARCH) * length)
    d = np.hypot(work[head, None, 0] - work[None, tail, 0], work[head, None, 1] - work[None, tail, 1])
    a, b = np.unravel_index(int(np.argmin(d)), d.shape)
    i, j = int(head[a]), int(tail[b])
    loop = work[i:j + 1]
    size = sg.bbox_diagonal(loop)
    share = float(along[j] - along[i]) / length
    if len(loop) < 16 or share < LOOP_SHARE or not float(d[a, b]) <= MEETS * size:
        return None
    ellipse = fit_ellipse(loop)
    if ellipse is None or not (ellipse[1] > 0.0 and ellipse[2] > 0.0):
        return None
    centre, rx, ry, angle, err = ellipse
    strays = [float(ellipse_distances(end, centre, rx, ry, angle).max()) / rx if len(end) > 1 else 0.0
              for end in (work[:i + 1], work[j:])]
    reach = max(1, int(HEADING_SHARE * n))
    into = work[min(i + reach, n - 1)] - work[max(i - reach, 0)]
    out = work[min(j + reach, n - 1)] - work[max(j - reach, 0)]
    turn = sg.angle_deg(into, out)
    if turn is None:
        return None
    return Loop(loop, min(strays), ry / rx, turn, err <= open_shapes.round_error(ellipse, sigma))


class AskedOnce:
    """`run_on_loop` of one stroke's judged points, asked only where it matters and at most once."""

    __slots__ = ("_asked", "_diag", "_loop", "_sigma", "_work")

    def __init__(self, work: np.ndarray, diag: float, sigma: float) -> None:
        self._work, self._diag, self._sigma = work, diag, sigma
        self._asked = False
        self._loop: np.ndarray | None = None

    def __call__(self) -> np.ndarray | None:
        if not self._asked:
            self._loop = run_on_loop(self._work, self._diag, self._sigma)
            self._asked = True
        return self._loop
