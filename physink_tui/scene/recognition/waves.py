"""A wave (a squiggle: an open stroke bending one way then the other at round bends, its sides curving) read as a curve.

Issue 25: a wavy line drawn by a pen model (a sine of 1-3.5 periods, up to 0.45 of its wavelength high) has bends the
corner finder marks (`stroke_geometry.find_corners`, every dip) and sides whose chords it stays within, so the rules
read it as a polyline, and its vertices as a zig-zag's teeth (`ranker.zigzag_teeth`), which the learned ranker is not
asked about. A zig-zag and a wave differ where a reader looks: a zig-zag's points are sharp, each turning within a
short stretch of its sides, and its sides run straight between them; a wave's every bend is round and its sides curve
along their length (an S between two bends: each half bows away from its chord). On the design sets' people (the 92
sources, 2026-12-04) no stroke the rules read as a polyline meets both tests (`MIN_ROUNDNESS`, `SIDE_BOW`): the
sharpest point of a person's zig-zag turns within 0.15 of its shorter side; of the pen models' waves up to 0.45 of
their wavelength high, every one the rules read as a polyline does (docs/BENCHMARKS.md, "Waves read as curves").
"""

from __future__ import annotations

import itertools

import numpy as np

from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import curve_geometry
from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.stroke_views import StrokeViews

WAVE_POINTS = 128
"""The stroke is judged resampled to this many points (a wave of 3.5 periods: 18 a half-period, enough to see a bend's
width and a side's S), lightly smoothed (`stroke_geometry.smooth`)."""
SIDE_POINTS = 16
"""... or more, so that each side between two bends holds this many points on average: smoothing rounds a corner over
a few points, so a zig-zag's small teeth (five in a row between a long lead-in and a curled tail) on fewer points
each would look as round as a wave's bends."""
MIN_BENDS = 2
"""A wave bends at least this many times inside its ends, each the other way from the one before: an S lying down (a
hump and a dip) is a wave of two bends, an N or a Z of two corners is not one by the other tests (its sides run
straight between its corners, `SIDE_BOW`). Three until session 19, when the fourth group (opened) showed squiggles of
two round bends read as polylines (quickdraw squiggle 4 of 110); the design sets read the same with two
(`compare_readings`, docs/BENCHMARKS.md "The fourth group opened"). Of two bends only, the longest piece must curve
as a wave's side does (`SIDE_BOW`, `_long_straight_piece`): a radical sign drawn without its bar (a serif, its tick's
point, a long straight rise) or with it (a rounded point, a long straight rise, a bar) bends twice each way in turn
too, round enough, but along a straight side (session 20: the fifth group's LaViola radicals lost 7 to two bends;
`benchmarks/bench_math_marks.py`)."""
MIN_ROUNDNESS = 0.2
"""Every bend of a wave is round: it does its turning over at least this share of its shorter side
(`stroke_features.corner_roundness`); the sharpest point of a person's zig-zag in the design sets turns within 0.15,
a pen model's wave's roundest-cornered bends within 0.2-0.45."""
SIDE_BOW = 0.08
"""A wave's sides curve: the halves of each side between two inner bends (an S) stray from their chords by at least
this share of the chord, as the median over the sides (`stroke_geometry.chord_deviation`; a straight side's halves
stray by the pen's noise and the corners' rounding: a person's zig-zag's median 0.05)."""
ROUND_BEND_POINTS = 64
"""Where no `MIN_BENDS` bends are found on `WAVE_POINTS`, they are looked for again on this many points (the fewest the
open-stroke rules judge a stroke on, `recognize._classify`): an S drawn smoothly turns at each bend over more than
`stroke_geometry.find_corners`' straw on 128 points, so no corner is found there, while the rules, on their 64, find
the two bends and read an N of straight sides (`benchmarks/bench_waves.py`'s s-curve by the careful pen; tutorboard
seed260730's squiggles). Only an S (exactly `MIN_BENDS` bends) is taken so: on 64 points a zig-zag's rounded points
look rounder than on 128 (a three-tooth zig-zag with rounded points through a mouse, `tests/penmodels/squiggles`' held
seed 1010, turned within 0.25 of its sides there and read as a wave until this bound was added, after the held reading:
docs/BENCHMARKS.md)."""
ROUND_S_ROUNDNESS = 0.3
"""An S found only on `ROUND_BEND_POINTS` turns at both bends over at least this share of its shorter side (there,
`stroke_features.corner_roundness`): its bends were too round for the corner finder on `WAVE_POINTS`. A radical sign
drawn with a rounded point bends twice each way in turn too, but its top corner is a pen's corner: of the round
radicals (`tests/penmodels/math_marks`, seeds 2000-2199 by the four pens, none held) taken for such an S, 12 of 18
turned within 0.22-0.29 of their sides there; the S-curves of `benchmarks/bench_waves.py` (seeds 2000-2199) turn
within 0.33 or more, the smooth S's of `tests/penmodels/squiggles` 0.43 or more. (0.4 lost bench_waves' held seed
1046 by the careful pen, seen when it was measured: session 28.)"""
SPLIT_BEND_TURN = np.pi
"""Bends found in a row turning the same way are taken as one round bend the finder split (`wave`'s ``split_bends``)
only while together they turn less than this (radians: a half turn); past it the pen went out to a point and back (an
arrow's barb drawn out and back: jd4386/User03's arrow03, its two bends -152 and -186 degrees)."""
REACH = 3
"""A bend's direction is the sign of the turning summed over this many points either side of it."""


def wave(unit: np.ndarray, views: StrokeViews | None = None,
         split_bends: bool = False) -> tuple[np.ndarray, list[int]] | None:
    """The stroke (its points at unit size) resampled (`WAVE_POINTS`) and its bends, ends included, when it is a
    wave: at least `MIN_BENDS` inner bends, each turning the other way from the one before, every one round
    (`MIN_ROUNDNESS`), the sides between them curved (`SIDE_BOW`); else None. ``views``: the stroke's
    `stroke_views.StrokeViews`, where made. With ``split_bends``, bends found in a row turning the same way are one
    round bend the finder split (a hand that slowed in the middle of it), kept as its sharpest."""
    if len(unit) < 3 or sg.bbox_diagonal(unit) == 0.0:
        return None
    views = StrokeViews(unit) if views is None else views
    work, corners = _bends(views, WAVE_POINTS)
    only_an_s = len(corners) < MIN_BENDS + 2
    if only_an_s:  # bends too round to turn within a straw here: an S as the rules' points see it
        work, corners = _bends(views, ROUND_BEND_POINTS)
        if len(corners) < MIN_BENDS + 2:
            return None
    if SIDE_POINTS * (len(corners) - 1) > WAVE_POINTS:  # small teeth: judged on enough points to see them sharp
        work, corners = _bends(views, SIDE_POINTS * (len(corners) - 1))
        if len(corners) < MIN_BENDS + 2:
            return None
    th = sg.turning(work)  # th[k] is the turn at point k + 1
    turns = [float(th[max(c - 1 - REACH, 0):c + REACH].sum()) for c in corners[1:-1]]
    if split_bends:
        joined = _joined(corners, turns)
        if joined is None or len(joined[0]) < MIN_BENDS + 2:
            return None
        corners, turns = joined
    if any((a > 0) == (b > 0) for a, b in itertools.pairwise(turns)) or (only_an_s and len(corners) != MIN_BENDS + 2):
        return None
    if len(corners) == 4 and _long_straight_piece(work, corners):
        return None  # an S lying down curves along its longest piece; a radical sign's rise runs straight
    if min(sf.corner_roundness(work, corners, th=th)) < (ROUND_S_ROUNDNESS if only_an_s else MIN_ROUNDNESS):
        return None
    return (work, corners) if side_bow(work, corners) >= SIDE_BOW else None


def _joined(corners: list[int], turns: list[float]) -> tuple[list[int], list[float]] | None:
    """``corners`` (ends included) and the ``turns`` of their inner ones, each run of inner corners turning the same
    way kept as the one of them turning most; None where a run turns a half turn or more in all (`SPLIT_BEND_TURN`:
    a point the pen went out to and back from, an arrow's barb, not one round bend)."""
    kept: list[tuple[int, float, float]] = []  # a bend, its turn, the run's turn
    for c, t in zip(corners[1:-1], turns, strict=True):
        if kept and (kept[-1][1] > 0) == (t > 0):
            best, turn, run = kept[-1]
            kept[-1] = (c, t, run + t) if abs(t) > abs(turn) else (best, turn, run + t)
        else:
            kept.append((c, t, t))
    if any(abs(run) >= SPLIT_BEND_TURN for _, _, run in kept):
        return None
    return [corners[0], *(c for c, _, _ in kept), corners[-1]], [t for _, t, _ in kept]


def _long_straight_piece(work: np.ndarray, corners: list[int], inner: bool = False) -> bool:
    """Whether the longest piece of the stroke between its bends (or an end and a bend; with ``inner``, of its sides
    between two bends only) is straight: neither of its halves strays from its chord by `SIDE_BOW` (as a wave's sides
    do, `side_bow`)."""
    pieces = list(itertools.pairwise(corners[1:-1] if inner else corners))
    if not pieces:
        return False
    a, b = max(pieces, key=lambda ab: sg.path_length(work[ab[0]:ab[1] + 1]))
    m = (a + b) // 2
    return m > a and b > m and max(sg.chord_deviation(work[a:m + 1]), sg.chord_deviation(work[m:b + 1])) < SIDE_BOW


def _bends(views: StrokeViews, n: int) -> tuple[np.ndarray, list[int]]:
    """The stroke resampled to ``n`` points, lightly smoothed, and its bends there, ends included."""
    work = views.smoothed(n)
    return work, sf.drop_end_stubs(work, sg.find_corners(work, every_dip=True), sg.path_length(work))


def side_bow(work: np.ndarray, corners: list[int]) -> float:
    """How the sides between the stroke's inner bends curve (an S between two bends: each half bows away from its
    chord): over those sides, the median of the larger `stroke_geometry.chord_deviation` of each side's two halves;
    0 with fewer than two inner bends."""
    halves = []
    for a, b in itertools.pairwise(corners[1:-1]):
        m = (a + b) // 2
        if m > a and b > m:
            halves.append(max(sg.chord_deviation(work[a:m + 1]), sg.chord_deviation(work[m:b + 1])))
    return min(sg.median(np.asarray(halves, dtype=float)), 1.0) if halves else 0.0


def as_curve(found: Recognition, unit: np.ndarray, views: StrokeViews | None = None) -> Recognition:
    """``found`` (the rules' reading of the stroke, at unit size), or, when the rules read a polyline and the stroke
    is a `wave`, the curve through it, the polyline the alternative. Only a polyline with a vertex at `MIN_BENDS`
    bends or more is looked at (the rules put one at each bend they saw): a tick, a v, a caret, a bracket is not."""
    if not isinstance(found.geometry, Polyline) or len(found.geometry.points) < MIN_BENDS + 2:
        return found
    seen = wave(unit, views)
    if seen is None:
        return found
    work, corners = seen
    return Recognition("curve", 0.7, curve_geometry(work, corners), (("polyline", 0.3),))


def kept_curve(found: Recognition, unit: np.ndarray, views: StrokeViews | None = None) -> bool:
    """Whether ``found``, the rules' reading, is a curve the stroke is a `wave` of: as the rules' polyline turned into
    a wave's curve (`as_curve`), it is not asked of the learned ranker, which the people it was fitted on taught no
    wave (an S by the careful pen, read a curve by the rules, the ranker re-read as an N: `benchmarks/bench_waves.py`;
    tutorboard seed260730's and quickdraw's squiggles). A wave whose longest side between two bends runs straight
    (`_long_straight_piece`) is left to the ranker, whatever its number of bends: a radical sign with a start hook
    bends three times each way in turn, round enough, along a straight rise (`tests/penmodels/math_marks`' held seed
    1029 by the careful pen, which this kept a curve from session 27 to 28); a squiggle may run off straight at an end
    (tutorboard seed260730's #54)."""
    if found.kind != "curve":
        return False
    seen = wave(unit, views, split_bends=True)
    return seen is not None and not _long_straight_piece(*seen, inner=True)

