"""A chain of sharp corners joined by straight sides (staircases, square waves, zig-zags), judged at its sides' scale.

Issue 25: staircases, crenellations and saw teeth drawn by the pen models read as curves, the more so the more and
the smaller their steps against the stroke: the rules look for corners on points spaced by the stroke's size
(`recognize._classify`: 64-600 points), where a step a twentieth of the stroke is a few points, its corners merged
with its neighbours' or taken for round bends, and the learned ranker (`ranker`) sees the stroke on 64 points, where
small square steps are wobble. A reader judges each corner against the sides it joins, whatever their size against
the whole: here the stroke is looked at on points a few of the pen's noise widths apart (`SPACING`), the finest scale
at which a side is told from the pen's jitter; a corner is where the path turns by `MIN_TURN_DEG` or more within a
few of those points, and the stroke is a chain when it has `MIN_CORNERS` such corners or more, every side between
them straight (`MIDDLE_STRAIGHT`), every corner sharp against its shorter side (`ROUND_RADIUS`, `SHARPEST`: a wave's
bends are all round) and the sides repeat (`_regular`: a stepped or toothed mark; a mouse's brace drawn as straight
runs and cusps turns every which way and has a short tip between long arms). Such a stroke is a polyline through
those corners, not asked of the learned ranker (`recognize.recognize_stroke`). A rule of the rules' reading, never
a refit: the ranker's model (`ranker_model`) is untouched.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.shape_fits import fit_line
from physink_tui.scene.recognition.stroke_views import StrokeViews

SPACING = 1.5
"""The stroke is resampled to points this many of the pen's noise widths apart (at least `MIN_POINTS`, at most
`MAX_POINTS`) and lightly smoothed (`stroke_geometry.smooth`)."""
MIN_POINTS = 64
MAX_POINTS = 1200
REACH = 3
"""A corner's turn is summed over this many points either side of it (`stroke_features.corner_turns`)."""
MIN_TURN_DEG = 50.0
"""A corner turns the path by at least this much within `REACH` points either side."""
MIN_CORNERS = 4
"""A chain has at least this many corners inside its ends (a staircase of two steps; a v, a bracket, an N or a check
are left to the rules)."""
ROUND_RADIUS = 0.3
"""Every corner is sharp: rounded (if at all) with a radius under this share of its shorter side (a hurried hand
rounds a corner by up to 0.15 of it, `tests/penmodels/hurried`) ..."""
CUT_NOISE = 2.0
"""... beyond this many of the pen's noise widths (`rounding`)."""
SHARPEST = 0.03
"""... and the sharpest is rounded by no more than this share of its shorter side: a chain has sharp corners, not
only round bends. Of the pen models' staircases, square waves and zig-zags that are chains, every one has a corner
within the noise (`benchmarks/bench_stairs.py`, seeds 0-29); of their waves (`benchmarks/bench_waves.py`, seeds
0-29) whose bends the chain's other tests pass, the sharpest bend is rounded by 0.054 of its shorter side or more."""
MIN_SIDE_POINTS = 2 * REACH
"""A side has at least this many points: two corners closer are one (`_joined`)."""
MIDDLE_STRAIGHT = 0.06
"""A side's middle (`_middle`) strays from its chord by less than this share of it: half `open_shapes.STRAIGHT`, as
far as the middle half of a side bowed by `open_shapes.STRAIGHT` strays from its own chord."""
PARALLEL_DEG = 25.0
REGULAR = 0.75
"""A chain repeats (`_regular`): this share of its sides run within `PARALLEL_DEG` of the side two before them. A
mouse's brace or question mark, straight runs and cusps at the pen's scale, turns every which way."""
RHYTHM = 4.0
"""... and its inner sides keep a rhythm (`_regular`): a staircase's uneven steps differ up to threefold; a brace drawn
as a zig-zag has a short tip between long arms (five times as long)."""
CORNER_SHARE = 0.25
"""A side's points this near either of its ends (as a share of its points) belong to its corner: a hurried hand runs
past a corner by up to an eighth of the side and cuts back onto it (`tests/penmodels/hurried`)."""
HOOK_POINTS = 4
"""... and at the stroke's ends this many points: where the pen landed or lifted with a small hook (2-5 px on the
hurried hand, `tests/penmodels/hurried`; the points are 1.5 noise widths apart)."""
END_STUB = 0.3
"""A first or last side shorter than this share of the side next to it is the pen's landing or lifting hook: the
chain starts (or ends) at its corner."""


def corner_chain(unit: np.ndarray, noise: float, views: StrokeViews | None = None) -> np.ndarray | None:
    """The chain's corners, ends included (points of the resampled stroke; a hook at an end left out), when ``unit``
    (the stroke at unit size; ``noise``, the pen's jitter in the same units) is a chain of sharp corners joined by
    straight sides; else None. ``views``: the stroke's `stroke_views.StrokeViews`, where made."""
    length = sg.path_length(unit)
    if not noise > 0 or not length > 0:
        return None
    n = int(min(MAX_POINTS, max(MIN_POINTS, length / (SPACING * noise))))
    work = (StrokeViews(unit) if views is None else views).smoothed(n)
    th = sg.turning(work)
    corners = _corners(th, len(work))
    if len(corners) < MIN_CORNERS + 2:
        return None  # (joining and dropping stubs only take corners away)
    corners = _stubs_dropped(work, _joined(work, th, corners))
    if len(corners) < MIN_CORNERS + 2:
        return None
    runs = [work[a:b + 1] for a, b in itertools.pairwise(corners)]
    ends = [(k > 0, k < len(runs) - 1) for k in range(len(runs))]  # which ends of each side are corners
    if not all(_straight_middle(run, noise, *at) for run, at in zip(runs, ends, strict=True)) or not _regular(runs):
        return None
    round_by = [rounding(work, a, c, b, noise) for a, c, b in zip(corners, corners[1:], corners[2:], strict=False)]
    if max(round_by) > ROUND_RADIUS or min(round_by) > SHARPEST:
        return None
    return work[corners]


def _straight_middle(run: np.ndarray, noise: float, after: bool = True, before: bool = True) -> bool:
    """Whether ``run`` (a side) is straight without its points near a corner (`_middle`) where it starts ``after``
    one and ends ``before`` one: it strays from its chord by under `MIDDLE_STRAIGHT` of the chord or 1.5 noise widths
    (as `open_shapes.straight`). How the pen turned at a corner (rounded it, ran past it and cut back) is the
    corner's, judged by its `rounding`; a first or last side is straight to the stroke's end (a curl there is a
    brace's or a question mark's) but for the pen's landing or lifting hook (`HOOK_POINTS`)."""
    middle = _middle(run, after, before)
    chord = float(np.hypot(*(middle[-1] - middle[0])))
    return chord > 0 and sg.chord_deviation(middle) * chord < max(MIDDLE_STRAIGHT * chord, 1.5 * noise)


def _regular(runs: list[np.ndarray]) -> bool:
    """Whether the sides repeat: at least `REGULAR` of the sides run parallel (within `PARALLEL_DEG`, either way) to
    the side two before them (a staircase's treads and risers, a square wave's tops and walls, a zig-zag's rising and
    falling sides), and each side between two corners is within `RHYTHM` times as long as the one two before it, or as
    short (the first and last side may be a landing's or a lead-in's)."""
    chords = np.array([run[-1] - run[0] for run in runs])
    heading = np.arctan2(chords[:, 1], chords[:, 0])
    apart = np.abs((heading[2:] - heading[:-2] + math.pi / 2) % math.pi - math.pi / 2)
    if float(np.mean(apart <= math.radians(PARALLEL_DEG))) < REGULAR:
        return False
    inner = [sg.path_length(run) for run in runs[1:-1]]
    return all(max(a, b) <= RHYTHM * min(a, b) for a, b in zip(inner, inner[2:], strict=False))


def _middle(run: np.ndarray, after: bool = True, before: bool = True) -> np.ndarray:
    """``run`` without `CORNER_SHARE` of its points at its start (``after`` a corner; else up to `HOOK_POINTS`) and at
    its end (``before`` one; else up to `HOOK_POINTS`); all of it when that leaves under three."""
    k = int(CORNER_SHARE * len(run))
    start, stop = (k if after else min(k, HOOK_POINTS)), (k if before else min(k, HOOK_POINTS))
    middle = run[start:len(run) - stop]
    return middle if len(middle) >= 3 else run


def rounding(work: np.ndarray, a: int, c: int, b: int, noise: float) -> float:
    """How round the corner at ``c`` (between the sides from ``a`` and to ``b``) is against its shorter side: the radius
    it is rounded with over that side, beyond `CUT_NOISE` of the pen's ``noise``. The lines through its sides'
    middles (`_middle`) meet at the corner meant; a corner rounded with radius r and turning by theta passes
    r (sec(theta / 2) - 1) from it. Infinite where the sides run on nearly in line (no corner between them)."""
    first, second = work[a:c + 1], work[c:b + 1]
    p, u, _ = fit_line(_middle(first))
    q, v, _ = fit_line(_middle(second))
    u = u if float(u @ (first[-1] - first[0])) >= 0 else -u  # along the path
    v = v if float(v @ (second[-1] - second[0])) >= 0 else -v
    cross = float(u[0] * v[1] - u[1] * v[0])
    turn = math.atan2(abs(cross), float(u @ v))
    if turn < math.radians(MIN_TURN_DEG) / 2:
        return math.inf
    apex = p + float((q - p)[0] * v[1] - (q - p)[1] * v[0]) / cross * u
    cut = float(np.minimum.reduce(np.hypot(*(work[(a + c) // 2:(c + b) // 2 + 1] - apex).T)))
    shorter = min(sg.path_length(first), sg.path_length(second))
    return max(cut - CUT_NOISE * noise, 0.0) / (shorter * (1 / math.cos(turn / 2) - 1))


def _corners(th: np.ndarray, n: int) -> list[int]:
    """Indices of the points where the path turns by `MIN_TURN_DEG` or more within `REACH` points either side, taken
    where it turns most sharply first (over a point either side), each counting only turning that no corner taken
    before it counted (a corner spread over a few points is one corner; two corners a few points apart are two, each
    where it turns); the ends included."""
    cum = np.concatenate([[0.0], np.add.accumulate(th)])  # cum[k]: turning done before point k + 1
    idx = np.arange(1, n - 1)
    sharpness = np.abs(cum[np.minimum(idx + 1, n - 2)] - cum[np.maximum(idx - 1, 1) - 1])
    least = math.radians(MIN_TURN_DEG)
    # only points turning sharply enough over a point either side, whose window turns by `least` or more all told
    # (whichever of its points are free, their net turn is no more): at this fine scale most points of a smooth or
    # jittery path turn a little, and few can be corners (a hair's margin for rounding: the rest fail the test anyway)
    whole = np.concatenate([[0.0], np.add.accumulate(np.abs(th))])
    lo, hi = np.maximum(idx - REACH, 1) - 1, np.minimum(idx + REACH, n - 2)
    may = (sharpness >= least / (2 * REACH + 1)) & (whole[hi] - whole[lo] >= least * (1 - 1e-9))
    free = np.ones(len(th), dtype=bool)  # turning not yet counted by a corner (th[k - 1] is point k's)
    taken: list[int] = []
    looked = np.flatnonzero(may)
    for k in looked[np.argsort(-sharpness[looked], kind="stable")].tolist():
        c, a, b = k + 1, int(lo[k]), int(hi[k])
        if free[c - 1] and abs(float(np.add.reduce(th[a:b][free[a:b]]))) >= least:
            taken.append(c)
            free[a:b] = False
    return [0, *sorted(taken), n - 1]


def _joined(work: np.ndarray, th: np.ndarray, corners: list[int]) -> list[int]:
    """``corners`` where two inner corners closer than `MIN_SIDE_POINTS` points along the path or half as many points'
    spacing straight across (the pen may stop and wobble back at a corner; no side between them at this scale) are
    one corner, at the sharper, where together they turn by `MIN_TURN_DEG` or more (a corner turned in two goes, or
    run past and cut back), or none (a jog one way and back, too small to be a step)."""
    corners = list(corners)
    spacing = sg.path_length(work) / (len(work) - 1)
    while True:
        gaps = [(min(corners[k + 1] - corners[k], 2 * float(np.hypot(*(work[corners[k + 1]] - work[corners[k]])))
                     / spacing), k) for k in range(1, len(corners) - 2)]
        gap, k = min(gaps, default=(MIN_SIDE_POINTS, 0))
        if gap >= MIN_SIDE_POINTS:
            return corners
        a, b = corners[k], corners[k + 1]
        first, second = (float(np.add.reduce(th[max(c - 1 - REACH, 0):c + REACH])) for c in (a, b))
        together = float(np.add.reduce(th[max(a - 1 - REACH, 0):b + REACH]))
        sharper = a if abs(first) >= abs(second) else b
        corners[k:k + 2] = [sharper] if abs(together) >= math.radians(MIN_TURN_DEG) else []


def _stubs_dropped(work: np.ndarray, corners: list[int]) -> list[int]:
    """``corners`` without an end piece shorter than `END_STUB` of the side next to it (the chain starts or ends at
    that piece's corner)."""
    corners = list(corners)

    def side(a: int, b: int) -> float:
        return sg.path_length(work[a:b + 1])

    while len(corners) > 3 and side(corners[0], corners[1]) < END_STUB * side(corners[1], corners[2]):
        corners.pop(0)
    while len(corners) > 3 and side(corners[-2], corners[-1]) < END_STUB * side(corners[-3], corners[-2]):
        corners.pop()
    return corners


def chain_reading(found: Recognition, unit: np.ndarray, noise: float, views: StrokeViews | None = None,
                  ) -> Recognition | None:
    """None unless ``found`` (the rules' reading of the stroke, at unit size) is a curve, a line or a polyline and the
    stroke is a `corner_chain`; then the reading to keep, which the learned ranker is not asked about: the rules'
    polyline where it has as many corners as the chain, else the polyline through the chain's corners (instead of a
    curve or a line, that kind the alternative)."""
    if found.kind not in ("curve", "line", "polyline"):
        return None
    chain = corner_chain(unit, noise, views)
    if chain is None:
        return None
    if isinstance(found.geometry, Polyline) and len(found.geometry.points) >= len(chain):
        return found
    shape = Polyline(tuple((float(x), float(y)) for x, y in chain))
    if found.kind == "polyline":
        return Recognition("polyline", found.confidence, shape, found.alternatives)
    return Recognition("polyline", 0.8, shape, ((found.kind, 0.2),))
