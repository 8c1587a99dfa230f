"""Open strokes: lines, polylines, arcs, round shapes left open and free curves, judged by how the path turns;
no closed shapes (those are ranked in `recognize`), no I/O.

A line is judged at the coarse scale of the whole stroke; a polyline turns at corners between nearly straight
sides (bowed sides allowed when its corners are really sharp); an arc turns one way along a circle; a stroke
turning smoothly most of the way round is a round shape left open; anything else is a curve of cubic pieces.
Straightness allows the pen's absolute noise as well as a share of each side's length.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from physink_tui.scene.recognition import (
    angular_braces,
    bracket_marks,
    end_curls,
    lift_hooks,
    lines,
    lopsided_braces,
    open_marks,
    pen_noise,
    round_brackets,
    round_cores,
    rounded_chevrons,
    shape_turning,
    thin_braces,
)
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import arc_geometry, curve_geometry, round_geometry
from physink_tui.scene.recognition.primitives import Line, Polyline, Recognition
from physink_tui.scene.recognition.shape_fits import EllipseFit, fit_circle, fit_ellipse, fit_line

STRAIGHT = 0.12
"""A side is straight when it strays from its chord by less than this share of the chord (plus the noise)."""
LINE = 0.045
"""A whole stroke is a line when it strays from its fit by less than this share of its length (plus noise)."""
ROUND_ERROR = 0.09
"""Normalised RMS radial error under which a closed stroke is round (plus the pen's noise over the radius)."""
VERY_SHARP_CORNER = 100.0
SHARP_CORNER = 62.0
CORNER_SHARE = 0.45
NEARLY_ROUND = 1.25
BOWED_SIDE = math.tan(math.pi / 8) / 2
MAIN_SIDE = 0.15
"""A polyline of two or more corners has no main side (over `MAIN_SIDE` of the path) bowed from its chord by more
than `BOWED_SIDE` of it, as far as a quarter circle bows (tan(22.5 deg) / 2, 0.207): a mouse-drawn question mark's
or brace's curl turns at cusps but is a curve between them. A single corner may join bowed arms (a hurried check)."""
BRACE_HEADING_DEG = 30.0
BRACE_OFFSET = 0.2
BRACE_TIP = 0.5
"""A brace's tip: two sides heading the same way (within `BRACE_HEADING_DEG`), the second starting within
`BRACE_OFFSET` of the shorter's length from the first's line, joined by one to three sides (out and back, or a jog where
the tip's point was not found as a corner) each under `BRACE_TIP` of the shorter. Drawn with a mouse a brace is straight
runs and cusps; such a stroke is a curve (an arrow's head, a zigzag, a bracket turn away at their corners)."""
ARMS_IN_LINE = 45.0
"""A one-corner stroke turning both ways whose arms' chords turn less than this (degrees) is a brace: its tip sticks
out of a stroke that runs on in line (`_tip_in_line`)."""
SHORT_BEND = 0.25
"""A one-corner stroke turning one way bends within this share of its path (`_short_bend`): a tick's short first arm
makes its corner look round against that arm (ahmadosama's ticks, klarubbio/s06's checks, 0.10-0.29 of the path);
a question mark's curl read as one corner bends over 0.44 of it."""
SMOOTH = 0.55
"""A path doing less than this share of its turning in its sharpest fifth turns smoothly: it has no corners to
speak of (boxes ~0.9, stars and triangles over 0.6, circles ~0.3; `stroke_features.turn_concentration`)."""


def _pt(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))


def line(raw: np.ndarray, noise: float, diag: float, pen: float | None = None) -> Recognition | None:
    """A line, judged at the coarse scale of the whole stroke (jitter at the pen's own scale would make a
    short, slow line look long and wavy): close to its fit, no more ink than its chord, hooks ignored; also
    without a lead-in or tail that runs back along it (`open_marks.retraced_ends`), or bowed one way and back by the
    hand's swing (`open_marks.swung_line`; also without such a piece where it was a long hook:
    `open_marks.hooked_bow`), or straight by the line test without a tight round curl at one end
    (`end_curls.curled_ends`), or, without a hook at an end as long as a hand's (`lines.unhooked`: a short line's
    hook is a large share of it), straight within the pen's own wobble (`lines.within_wobble`). Those two are judged
    by the pen's stated noise ``pen`` (``noise`` where not given), not a measured jitter that may be the shape's own
    bends between a few far-apart events (`recognize.SPARSE_BENDS`). A tall, thin curly brace
    (`thin_braces.thin_brace`: a sharp point halfway, both ends curling back) is no line."""
    pen = noise if pen is None else min(pen, noise)
    found, swung, loose = _line(raw, noise, diag, pen)
    if found is None:
        kept = open_marks.retraced_ends(raw, noise)
        if kept is not None:
            found, rest_swung, loose = _line(kept, noise, sg.bbox_diagonal(kept), pen)
            if (swung is None and rest_swung is not None
                    and open_marks.hooked_bow(raw, kept, _test_points(raw, noise), noise)):
                swung = rest_swung  # a line the hand bowed, refused for the hook the cut took
    if found is None and swung is None:
        kept = end_curls.curled_ends(raw)
        if kept is not None:  # a line whose end the pen curled round where it landed or lifted: the rest straight
            found, _, loose = _line(kept, noise, sg.bbox_diagonal(kept), pen)  # (a bowed rest is a mouse's tick's arm)
    if (found is None or loose) and lines.ends_may_span(raw, pen, diag):
        # no line as drawn, or one only within the pen's wobble, where a hook at an end may be what strays: the
        # straightest line left once a hook is cut is the line drawn (its ends where the hand meant them)
        # (where none was, a piece may pass only within the pen's wobble: not where every piece strays farther)
        pieces = [] if found is None and lines.beyond_wobble(raw, noise, pen) else lines.unhooked(raw, pen)
        for kept in pieces:  # where a line was found already, the plain line test may judge the rest
            cut, _, _ = _line(kept, noise, sg.bbox_diagonal(kept), pen, bow=False, plain=found is not None)
            if cut is not None and (found is None or cut.confidence > found.confidence):
                found = cut
    if (found is not None or swung is not None) and thin_braces.thin_brace(raw, noise):
        return None  # a tall, thin brace: its point and curls within a line's stray
    return found if found is not None else swung


def _line(raw: np.ndarray, noise: float, diag: float, pen: float,
          bow: bool = True, plain: bool = False) -> tuple[Recognition | None, Recognition | None, bool]:
    """A line by the line test, or else one the hand's swing bowed (`open_marks.swung_line`), or None each, and
    whether the line passed only as straight within the pen's own wobble (`lines.within_wobble`, judged by ``pen``);
    with ``bow`` False, hooks are not cut again and only such a line counts, or, with ``plain``, one by the line test
    too."""
    if not _ends_span(raw, diag):
        return None, None, False  # its ends are not its extent's ends: no line (hooks cost less than half)
    # steps a few noise widths long (at least 48 of them): fine enough that a coil's loops are not lost
    coarse = _test_points(raw, noise, bow)
    _, direction, off = fit_line(coarse)
    on_line = coarse @ direction
    along = float(on_line.max() - on_line.min()) or 1e-12  # (`np.ptp`) the extent `fit_line`'s stray is a share of
    length = sg.path_length(coarse)
    chord = float(np.hypot(*(coarse[-1] - coarse[0])))
    if chord == 0.0:
        return None, None, False
    err = max(0.0, off - noise / chord)  # the pen's own wobble is not a bend
    slack = 1.0 + 3 * noise / chord

    def close(stray: float) -> bool:
        return (stray < LINE and length < 1.12 * chord * slack) or (stray < 0.5 * LINE and length < 1.3 * chord * slack)

    # nor, at its farthest, is a stroke's whole stray within the pen's wobble, unless it bows as an arc does; nor the
    # ink of that wobble between points closer than a few noise widths (`lines.ink`; the stray judged first, at no cost)
    strict = (bow or plain) and close(err)
    stray = off * along
    if strict or (stray < lines.wobble_reach(len(coarse)) * pen and lines.ink(coarse, pen) < 1.3 * chord * slack
                  and lines.within_wobble(coarse, stray, pen)):
        return Recognition("line", 1.0 - min(err, LINE) / LINE * 0.5, Line(_pt(coarse[0]), _pt(coarse[-1])),
                           (("arc", 0.2),)), None, not strict
    if bow and open_marks.swung_line(coarse, err, length / (chord * slack), noise, pen):
        return None, Recognition("line", 0.6, Line(_pt(coarse[0]), _pt(coarse[-1])), (("curve", 0.4),)), False
    return None, None, False


def _test_points(raw: np.ndarray, noise: float, bow: bool = True) -> np.ndarray:
    """``raw`` as the line test judges it: resampled by steps a few noise widths long (`lines.line_test_points`) and
    smoothed, without hooks (`stroke_geometry.remove_hooks`) unless ``bow`` is False."""
    n = lines.line_test_points(sg.path_length(raw), noise)
    coarse = sg.smooth(sg.resample(raw, n))
    if bow:  # else hooks are cut from one end or both already (`lines.unhooked`): the rest is judged as drawn
        coarse = sg.resample(sg.remove_hooks(coarse), n)
    return coarse


def _ends_span(raw: np.ndarray, diag: float | None = None) -> bool:
    """Whether the ends of ``raw`` are not under half its diagonal (``diag``, where known) apart, as a line's are."""
    return not float(np.hypot(*(raw[-1] - raw[0]))) < 0.5 * (sg.bbox_diagonal(raw) if diag is None else diag)


def round_error(ellipse: EllipseFit, noise: float) -> float:
    """How far from round a stroke may be and still be a circle or ellipse: `ROUND_ERROR`, plus the pen's
    noise as a share of the ellipse's mean radius."""
    _, rx, ry, _, _ = ellipse
    return ROUND_ERROR + noise / max(math.sqrt(rx * ry), 1e-12)


def straight(run: np.ndarray, noise: float, bow: float | None = None) -> bool:
    """Whether ``run`` is a straight side (`STRAIGHT`); ``bow``: its `stroke_geometry.chord_deviation` where known."""
    chord = float(np.hypot(*(run[-1] - run[0])))
    if not chord > 0:
        return False
    return (sg.chord_deviation(run) if bow is None else bow) * chord < max(STRAIGHT * chord, 1.5 * noise)


def classify_open(work: np.ndarray, noise: float, round_corner: float = math.inf,
                  events: tuple[np.ndarray, float] | None = None) -> Recognition:
    """An open stroke (resampled, hooks and corner loops removed) as a round shape left open, a polyline (whose
    corners are no rounder than ``round_corner``, see `stroke_features.corner_roundness`), an arc or a curve.
    ``events``: the stroke's points as the device sent them and their bounding-box diagonal, where known."""
    length = sg.path_length(work)
    th = sg.turning(work)
    total_turn = float(th.sum())
    found = sg.find_corners(work, every_dip=True, th=th)
    corners = _kept_arm(work, found, length)
    runs = [work[a:b + 1] for a, b in itertools.pairwise(corners)]
    bows = [sg.chord_deviation(run) for run in runs]  # each side's, for the tests below
    straight_runs = [straight(run, noise, bow) or sg.path_length(run) < 0.06 * length
                     for run, bow in zip(runs, bows, strict=True)]
    coarse = shape_turning.coarse_turning(work, noise)
    lobes = sf.turn_lobes(coarse)  # `stroke_features.lobes`, once for every rule below
    concentration = sf.turn_concentration(coarse)
    bracket_found: list[tuple[tuple[float, float], ...] | None] = []

    def rounded_bracket() -> tuple[tuple[float, float], ...] | None:  # measured once, where first asked
        if not bracket_found:
            bracket_found.append(round_brackets.rounded_bracket(work, lobes))
        return bracket_found[0]

    # a polyline turning the same way at sharp corners is not round; a few far-apart events' chords are not corners
    smooth = concentration < SMOOTH or (events is not None and pen_noise.turns_evenly_at_events(*events, SMOOTH))
    round_enough = (smooth and abs(total_turn) >= NEARLY_ROUND * math.pi
                    and abs(float(coarse.sum())) > 0.75 * float(np.abs(coarse).sum()))
    if round_enough:
        # most of a turn, smoothly: a round shape left open (people often stop short of the start); not a bracket
        # rounded at both corners, which turns that far only with its hooks and has a straight spine
        open_ellipse = fit_ellipse(work)
        if (open_ellipse is not None and open_ellipse[4] < 0.6 * round_error(open_ellipse, noise)
                and rounded_bracket() is None):
            geom, kind = round_geometry(open_ellipse)
            return Recognition(kind, 0.7, geom, (("arc", 0.5),))
        # a lead in from inside, or an end curled in past the start: the round core with a stroke inside it
        core = round_cores.round_core(work, lambda e: e[4] < 0.6 * round_error(e, noise), NEARLY_ROUND * math.pi,
                                      open_ellipse)
        if core is not None and rounded_bracket() is None:
            geom, kind = round_geometry(core)
            return Recognition(kind, 0.65, geom, (("curve", 0.5),))
    flicked = None if round_enough else lift_hooks.round_flicked(
        work, th, noise, lambda e: e[4] < 0.6 * round_error(e, noise), NEARLY_ROUND * math.pi, SMOOTH)
    if flicked is not None and rounded_bracket() is None:
        # a round stroke left open that flicks off its path where the pen lifted (or landed): round without the flick
        geom, kind = round_geometry(flicked)
        return Recognition(kind, 0.65, geom, (("curve", 0.5),))
    roundness = sf.corner_roundness(work, corners, th=th)
    sharp = (_roundest_corner(th, corners, roundness) <= round_corner or _rounded_bracket(corners, straight_runs, lobes)
             or _short_bend(work, corners, roundness, lobes))
    if (len(straight_runs) >= 2 and sharp and not _bowed_between_corners(work, corners, length, bows)
            and not _brace_tip(work, corners) and not _tip_in_line(work, corners, lobes)
            and not bracket_marks.looped_point(th, corners, lobes)
            and not bracket_marks.brace_point(work, corners, lobes)
            and not angular_braces.angular_brace(work, lobes, noise, coarse)
            and not lopsided_braces.lopsided_brace(work, lobes, noise, coarse)
            and (all(straight_runs) or _bent_polyline(th, corners, lobes, bows)
                 or _tick_into_bend(work, corners, straight_runs, roundness, lobes))):
        return Recognition("polyline", 0.85, Polyline(tuple(_pt(work[c]) for c in corners)), (("curve", 0.3),))
    if (len(corners) >= open_marks.SAW_TEETH + 2 and open_marks.sawtooth(work, th, corners, straight_runs, roundness)
            and not _brace_tip(work, corners) and not angular_braces.angular_brace(work, lobes, noise, coarse)):
        # a zig-zag's sharp teeth between a loose lead-in and a curled tail (`open_marks.sawtooth`)
        return Recognition("polyline", 0.8, Polyline(tuple(_pt(work[c]) for c in corners)), (("curve", 0.3),))
    bracket = bracket_marks.rounded_bracket_corners(work, th, corners, lobes)
    if bracket is not None:  # one corner rounded off: a square bracket still
        return Recognition("polyline", 0.75, Polyline(tuple(_pt(work[c]) for c in bracket)), (("curve", 0.4),))
    rounded = rounded_bracket()
    if rounded is not None:  # both corners rounded off: a square bracket still
        return Recognition("polyline", 0.75, Polyline(rounded), (("curve", 0.4),))
    point = bracket_marks.rounded_point(work, th, lobes) if len(corners) <= 3 else None
    if point is not None:  # a tick, check or v swung round its point
        return Recognition("polyline", 0.7, Polyline(tuple(_pt(work[c]) for c in point)), (("curve", 0.4),))
    hooked = bracket_marks.unhooked_point(work, found, noise) if len(found) <= 4 else None
    if hooked is not None:  # the same, once a hook where the pen landed or lifted is cut
        return Recognition("polyline", 0.7, Polyline(hooked), (("curve", 0.4),))
    chevron = rounded_chevrons.rounded_chevron(work, noise, coarse) if len(lobes) == 1 else None
    if chevron is not None:  # a chevron swung round its corner, both sides straight
        return Recognition("polyline", 0.7, Polyline(chevron), (("curve", 0.4),))
    if len(corners) <= 3 or concentration < 0.5:
        centre, radius, circle_err = fit_circle(work)
        one_way = abs(float(coarse.sum())) > 0.8 * float(np.abs(coarse).sum())  # no S-bends
        if circle_err < 0.06 and 0.35 < abs(total_turn) < 1.8 * math.pi and one_way:
            return Recognition("arc", 1.0 - circle_err * 5, arc_geometry(work, centre, radius), (("curve", 0.5),))
    return Recognition("curve", 0.7, curve_geometry(work, corners), (("polyline", 0.3),))


def _roundest_corner(th: np.ndarray, corners: list[int], roundness: list[float]) -> float:
    """The roundest inner corner's `stroke_features.corner_roundness`; beside a really sharp corner
    (`VERY_SHARP_CORNER`), a bend turning less than `SHARP_CORNER` is an arm's wobble (a hurried check's short arm
    waved on its way down), not a corner whose roundness makes the mark round."""
    turns = sf.corner_turns(th, corners) if len(corners) > 2 else []
    wobble = bool(turns) and max(turns) >= VERY_SHARP_CORNER
    return max((r for r, t in zip(roundness, turns or [math.inf] * len(roundness), strict=True)
                if not (wobble and t < SHARP_CORNER)), default=0.0)


def _kept_arm(work: np.ndarray, found: list[int], length: float) -> list[int]:
    """The corners without those cutting a tiny piece off an end (`stroke_features.drop_end_stubs`), unless the
    stroke's one corner cuts off a short straight arm (`stroke_geometry.end_arm`: a tick's first arm)."""
    corners = sf.drop_end_stubs(work, found, length)
    if len(corners) == 2 and len(found) == 3:
        c = found[1]
        piece, rest = (work[:c + 1], work[c:]) if 2 * c < len(work) else (work[c:][::-1], work[:c + 1][::-1])
        if sg.end_arm(piece, rest, length):
            return found
    return corners


def _bowed_between_corners(work: np.ndarray, corners: list[int], length: float, bows: list[float]) -> bool:
    """Whether a stroke with two or more inner corners has a main side that bows like an arc (`BOWED_SIDE`).
    ``bows``: each side's `stroke_geometry.chord_deviation`, as in `_bent_polyline`."""
    if len(corners) < 4:
        return False
    return any(bow > BOWED_SIDE for (a, b), bow in zip(itertools.pairwise(corners), bows, strict=True)
               if sg.path_length(work[a:b + 1]) > MAIN_SIDE * length)


def _rounded_bracket(corners: list[int], straight_runs: list[bool], lobes: list[float]) -> bool:
    """Three straight sides turning the same way at both corners (a square bracket, a U): its corners may be rounded
    as far as its short arms are long (a brace's or a question mark's bends turn both ways). ``lobes``: the stroke's
    `stroke_features.lobes`, as in the functions below."""
    return len(corners) == 4 and all(straight_runs) and len(lobes) == 1


def _short_bend(work: np.ndarray, corners: list[int], roundness: list[float], lobes: list[float]) -> bool:
    """Whether the stroke turns one way at its one corner (a tick, a check, a v) within `SHORT_BEND` of its path: the
    bend may be as long as a short arm, as a question mark's curl is, but is short against the whole stroke."""
    if len(corners) != 3 or len(lobes) != 1:
        return False
    length = sg.path_length(work)
    shorter = min(sg.path_length(work[: corners[1] + 1]), sg.path_length(work[corners[1]:]))
    return roundness[0] * shorter < SHORT_BEND * length


def _tick_into_bend(work: np.ndarray, corners: list[int], straight_runs: list[bool], roundness: list[float],
                    lobes: list[float]) -> bool:
    """Whether a one-corner stroke turning one way is a tick whose short arm bows into its corner: the long arm is
    straight with no point in its middle (`stroke_geometry.POINT_TURN_DEG`: a brace whose tip was not found as a
    corner has a spine `straight` calls straight), the short one bows less than a quarter circle (`BOWED_SIDE`) and
    the bend is short (`_short_bend`)."""
    if len(corners) != 3 or not _short_bend(work, corners, roundness, lobes):
        return False
    first, second = work[:corners[1] + 1], work[corners[1]:]
    if sg.path_length(first) < sg.path_length(second):
        short, long, long_straight = first, second, straight_runs[1]
    else:
        short, long, long_straight = second, first, straight_runs[0]
    middle = long[len(long) // 5: len(long) - len(long) // 5]
    return (long_straight and sg.chord_deviation(short) < BOWED_SIDE
            and sg.sharpest_turn(middle, sg.POINT_SPAN * sg.path_length(work)) < sg.POINT_TURN_DEG)


def _tip_in_line(work: np.ndarray, corners: list[int], lobes: list[float]) -> bool:
    """Whether the stroke's one corner joins arms running on nearly in line (their chords within `ARMS_IN_LINE`
    degrees) in a stroke that turns both ways: a brace's tip between curled ends, not a v's, check's or tick's point
    (their arms meet at 55 degrees or more; s04's bowed checks are the closest)."""
    if len(corners) != 3 or len(lobes) < 2:
        return False
    u, v = work[corners[1]] - work[0], work[-1] - work[corners[1]]
    norms = float(np.hypot(*u) * np.hypot(*v))
    return norms > 0 and float(u @ v) > math.cos(math.radians(ARMS_IN_LINE)) * norms


def _brace_tip(work: np.ndarray, corners: list[int]) -> bool:
    """Whether the stroke runs on in line through a short pointed excursion of one to three sides (`BRACE_TIP`)."""
    vertices = work[corners]
    sides = vertices[1:] - vertices[:-1]  # as np.diff, without its per-call overhead
    lengths = np.hypot(*sides.T)
    for i, j in ((i, i + k) for k in (2, 3, 4) for i in range(len(sides) - k)):
        shorter = min(lengths[i], lengths[j])
        if shorter == 0.0 or max(lengths[i + 1:j]) >= BRACE_TIP * shorter:
            continue
        u, v = sides[i] / lengths[i], sides[j] / lengths[j]
        rel = work[corners[j]] - work[corners[i + 1]]
        if (float(u @ v) > math.cos(math.radians(BRACE_HEADING_DEG))
                and abs(float(rel[0] * u[1] - rel[1] * u[0])) < BRACE_OFFSET * shorter):
            return True
    return False


def _bent_polyline(th: np.ndarray, corners: list[int], lobes: list[float], bows: list[float]) -> bool:
    """A polyline drawn with bowed or curled sides (a check mark's arms): it turns at a really sharp
    corner, in at most three lobes none of which curls right round (a pigtail's loop), or mostly at
    sharp corners with nearly straight sides (an arrow whose head doubles back). A question mark's
    bend, where a corner finder may cut its curl, turns less than 90 degrees. ``lobes``: the stroke's
    `stroke_features.lobes`; ``bows``: each side's (corner to corner) `stroke_geometry.chord_deviation`."""
    turns = sf.corner_turns(th, corners)
    few_lobes = len(lobes) <= 3 and max((abs(v) for v in lobes), default=0.0) < 250.0
    if few_lobes and max(turns) >= VERY_SHARP_CORNER:
        return True
    if max(sf.bends(th, corners)) >= 120.0 or min(turns) < SHARP_CORNER or max(turns) < 90.0:
        return False
    share = sf.corner_share(th, corners)
    worst = max(bows)
    if share >= 0.7 and worst < 1.4 * STRAIGHT:
        return True
    return few_lobes and share >= CORNER_SHARE


def straight_armed_mark(found: Recognition, pts: np.ndarray, noise: float) -> bool:
    """Whether the rules read a one-corner mark (a tick, check, v, caret, chevron or L) whose arms, as drawn in
    ``pts``, are both `straight` (``noise`` in their units), not running on in line (`ARMS_IN_LINE`), the longer with
    no point along it (`stroke_geometry.POINT_TURN_DEG`: a thin brace's tip): such a mark is not asked of the learned
    ranker (`recognize.recognize_stroke`), whose curve is for bowed arms (a mouse's brace or question mark is straight
    runs and cusps, bowed between them)."""
    geometry = found.geometry
    if found.kind != "polyline" or not isinstance(geometry, Polyline) or len(geometry.points) != 3:
        return False
    k = int(np.argmin(np.hypot(*(pts - np.asarray(geometry.points[1])).T)))
    arms = (pts[:k + 1], pts[k:])
    u, v = pts[k] - pts[0], pts[-1] - pts[k]
    norms = float(np.hypot(*u) * np.hypot(*v))
    if not norms > 0 or float(u @ v) > math.cos(math.radians(ARMS_IN_LINE)) * norms:
        return False  # arms running on nearly in line: a brace's tip
    if not all(len(arm) >= 2 and straight(arm, noise) for arm in arms):
        return False
    long = sg.smooth(sg.resample(max(arms, key=sg.path_length), 64))  # no point along it (a thin brace's tip)
    middle = long[len(long) // 5: len(long) - len(long) // 5]
    return sg.sharpest_turn(middle, sg.POINT_SPAN * sg.path_length(pts)) < sg.POINT_TURN_DEG
