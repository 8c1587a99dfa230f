"""A learned ranker over the kinds a stroke may be read as: geometric features and a conditional-logit score; numpy.

Issue 25's "design that can generalise": the rules (`recognize`, `open_shapes`) read a stroke as one kind; this module
describes the stroke by features a reader of sketches would name (closure, ink over extent, turning, corner count,
sharpness and roundness, how straight the sides are, fit errors of a line, circle and ellipse, how the pen slowed at
corners where times exist, and the open-stroke rules' own tests as 0/1 features) and, when the rules read an open stroke
as a polyline or a curve (`KINDS`), scores each as ``w_kind . phi + a * [the rules' answer]``: the model's kind replaces
the rules' only when the model gives it a chance over its margin (`Model.margin`). The weights are fitted offline
(`benchmarks/train_ranker.py`) and shipped in the package as a data module (`ranker_model`, imported: no file is read);
this module computes features and scores, deterministically.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import NamedTuple, Protocol

import numpy as np

from physink_tui.scene.recognition import bracket_marks, open_marks, open_shapes, open_stars, pen_noise, shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import curve_geometry, scale_geometry
from physink_tui.scene.recognition.primitives import Geometry, Polygon, Polyline, Recognition
from physink_tui.scene.recognition.ranker_pace import corner_slowdown, point_balance
from physink_tui.scene.recognition.ranker_weights import FEATURES as FEATURES  # the model's names, as ranker.*
from physink_tui.scene.recognition.ranker_weights import KINDS as KINDS
from physink_tui.scene.recognition.ranker_weights import MODEL_MODULE as MODEL_MODULE
from physink_tui.scene.recognition.ranker_weights import Model as Model
from physink_tui.scene.recognition.ranker_weights import model_from as model_from
from physink_tui.scene.recognition.ranker_weights import parse_model as parse_model
from physink_tui.scene.recognition.ranker_weights import shipped_model as shipped_model
from physink_tui.scene.recognition.shape_fits import fit_circle, fit_ellipse, fit_line

OPEN_GAP = 0.2
"""A polygon whose ends are at least this share of its size apart (`stroke_features.closure`; the rules' own closing
gap, `closed_loops.CLOSED_GAP`) may be an open mark: the model is asked."""
WORK_POINTS = 64
CHECK_ARMS = 2 / 3
"""A check's short arm is at most this share of its long arm (`checked_point`)."""
CHECK_POINT_SHARE = 1 / 3
"""A check whose hump starts at a second, weaker corner turns at least this share of all its turning at its point
(`checked_point`); a brace's tip or a question mark's bend less (0.22-0.32 of those the model rightly re-reads)."""


def family(kind: str | None, phi: np.ndarray) -> tuple[str, ...]:
    """The kinds a stroke read as ``kind``, with features ``phi``, may be re-ranked among (`KINDS`), the rules' first
    for a polygon; none for other kinds."""
    if kind in ("polyline", "curve"):
        return ("polyline", "curve")
    if kind == "polygon" and open_polygon(float(phi[FEATURES.index("closure")])):
        return ("polygon", "polyline", "curve")
    return ()


def open_polygon(closure: float) -> bool:
    """Whether a polygon whose ends are ``closure`` (`stroke_features.closure`) apart is open enough to ask."""
    return closure >= OPEN_GAP


class Drawn(NamedTuple):
    """What recognition already knows of the stroke it hands the ranker (`recognize.recognize_stroke`), so the ranker
    does not convert, clean and measure it again: the points without repeats, which of the given points they are,
    their centroid, their diagonal (`stroke_geometry.bbox_diagonal`) and their jitter (`pen_noise.jitter`)."""

    raw: np.ndarray
    keep: np.ndarray
    centre: np.ndarray
    diag: float
    jitter: float


class Unit(NamedTuple):
    """A stroke prepared once for the features (`_unit_work`): without repeated points (its times kept in step), its
    diagonal, the stroke moved to unit diagonal round its centroid, resampled and smoothed (``work``), and its jitter
    where already measured."""

    raw: np.ndarray
    work: np.ndarray
    times: list[float] | None
    diag: float
    jitter: float | None = None


def _unit_work(points: Sequence[Sequence[float]], times: Sequence[float] | None, drawn: Drawn | None = None,
               ) -> Unit | None:
    """The stroke prepared for the features (`Unit`; None when it has no extent), from ``drawn`` where given."""
    if drawn is not None:
        kept_times = (list(itertools.compress(times, drawn.keep.tolist()))
                      if times is not None and len(times) == len(drawn.keep) else None)
        work = sg.smooth(sg.resample((drawn.raw - drawn.centre) / drawn.diag, WORK_POINTS))
        return Unit(drawn.raw, work, kept_times, drawn.diag, drawn.jitter)
    try:
        pts = np.asarray(points, dtype=float)[:, :2]
    except (ValueError, IndexError):  # rows of different lengths (x, y and sometimes t)
        pts = np.asarray([p[:2] for p in points], dtype=float)
    if len(pts) < 2 or not np.isfinite(pts).all():
        return None
    keep = np.ones(len(pts), dtype=bool)
    keep[1:] = np.any(np.diff(pts, axis=0) != 0.0, axis=1)
    raw = pts[keep]
    kept_times = list(itertools.compress(times, keep.tolist())) if times is not None and len(
        times) == len(pts) else None
    diag = sg.bbox_diagonal(raw) if len(raw) >= 2 else 0.0
    if diag == 0.0:
        return None
    work = sg.smooth(sg.resample((raw - raw.mean(axis=0)) / diag, WORK_POINTS))
    return Unit(raw, work, kept_times, diag)


def features(points: Sequence[Sequence[float]], times: Sequence[float] | None, noise: float = 1.0) -> np.ndarray:
    """The stroke's features (`FEATURES`), size-free; ``noise`` is the pen's jitter in the points' units."""
    phi = _features(_unit_work(points, times), noise)
    assert phi is not None  # only a polyline's features stop early
    return phi


CHECK_FEATURES = tuple(FEATURES.index(f) for f in ("corners", "abs_turn", "max_corner_turn", "lobes", "point_balance"))
"""The features `checked_point` reads."""


def _features(found: Unit | None, noise: float, *, polyline: bool = False, timed: bool = True) -> np.ndarray | None:
    """`features` of a stroke already prepared by `_unit_work`. With ``polyline`` (the rules read one), None as soon
    as the features `checked_point` reads show a hurried check, which `choose` does not ask the model about, or the
    stroke is a tick swung round its point (`bracket_marks.rounded_point`, no corner found, or
    `bracket_marks.unhooked_point`, a corner found only where a hook is cut), which `rerank` does not ask it about
    either: the others (fits, corner shapes, the rules' tests) are not computed. Without ``timed`` (a model that
    weighs neither `TIMED_FEATURES` at all: `reads_times`), those are left 0."""
    out = np.zeros(len(FEATURES))
    if found is None:
        return out
    raw, work, times, diag, jitter = found
    noise = max(noise, pen_noise.jitter(raw) if jitter is None else jitter) / diag
    length = sg.path_length(work)
    th = sg.turning(work)
    found_corners = sg.find_corners(work, th=th)
    corners = sf.drop_end_stubs(work, found_corners, length)
    abs_th = np.abs(th)
    coarse = shape_turning.coarse_turning(work, noise)
    turns = sf.corner_turns(th, corners)
    lobes = sf.turn_lobes(coarse)
    checks = ((len(corners) - 2) / 8.0, float(np.add.reduce(abs_th)) / (2 * math.pi), max(turns) / 180.0,
              len(lobes) / 4.0, point_balance(work, corners, turns))  # `CHECK_FEATURES`, in that order
    if polyline:
        out[list(CHECK_FEATURES)] = checks
        if checked_point(out if np.isfinite(out).all() else np.nan_to_num(out, nan=0.0, posinf=1.0, neginf=0.0)):
            return None
        if ((len(corners) == 2 and bracket_marks.swung_tick(work, th, lobes, noise))
                or (len(found_corners) <= 4 and bracket_marks.unhooked_point(work, found_corners, noise) is not None)):
            return None  # a tick swung round its point (a hook cut), the rules' polyline: the model is not asked either
    runs = [work[a:b + 1] for a, b in itertools.pairwise(corners)]
    deviation = [sg.chord_deviation(r) for r in runs]
    straights = [open_shapes.straight(r, noise, d) for r, d in zip(runs, deviation, strict=True)]
    bows = [min(d, 1.0) for d in deviation] or [0.0]
    roundness = [min(r, 2.0) for r in sf.corner_roundness(work, corners, th=th)] or [0.0]
    ellipse = fit_ellipse(work)
    _, _, circle_err = fit_circle(work)
    _, _, line_err = fit_line(work)
    coarse_sum, coarse_abs = float(np.add.reduce(coarse)), float(np.add.reduce(np.abs(coarse)))
    out[:] = [
        sf.closure(work, sg.bbox_diagonal(work)), length / 4.0, abs(float(np.add.reduce(th))) / (2 * math.pi),
        checks[1], checks[0], sf.turn_concentration(coarse),
        max(roundness), _mean(roundness), sum(d < 0.12 for d in deviation) / len(deviation) if runs else 0.0,
        max(bows), _mean(bows), checks[2], min(turns) / 180.0, checks[3],
        min(ellipse[4], 1.0) if ellipse is not None else 1.0, min(circle_err, 1.0),
        ellipse[2] / max(ellipse[1], 1e-12) if ellipse is not None else 0.0, min(line_err, 1.0),
        sf.corner_share(th, corners) if len(corners) > 2 else 0.0,
        abs(coarse_sum) / max(coarse_abs, 1e-12), max(sf.bends(th, corners)) / 180.0,
        math.log(max(len(raw), 2)) / 5.0, float(len(corners) == 3), float(len(corners) == 4),
        float(bool(runs) and all(straights)),
        float(len(corners) > 2 and open_shapes._bent_polyline(th, corners, lobes, deviation)),
        float(open_shapes._brace_tip(work, corners)),
        float(open_shapes._bowed_between_corners(work, corners, length, deviation)),
        float(open_shapes._rounded_bracket(corners, straights, lobes)), 0.0, 0.0, checks[4]]
    slow = corner_slowdown(raw, times, corners, len(work)) if timed else None
    if slow is not None:
        at = FEATURES.index("has_times")
        out[at:at + 2] = [1.0, slow]
    if not np.isfinite(out).all():  # as np.nan_to_num(out, nan=0.0, posinf=1.0, neginf=0.0), only where needed
        out = np.nan_to_num(out, nan=0.0, posinf=1.0, neginf=0.0)
    return out


def _mean(values: list[float]) -> float:
    """``float(np.mean(values))`` to the bit (numpy's own sum, over the count), without its per-call overhead."""
    return float(np.add.reduce(np.asarray(values, dtype=float))) / len(values)


TIMED_FEATURES = ("has_times", "corner_slowdown")
"""The features only a stroke's times give (`corner_slowdown`)."""


def reads_times(model: Model) -> bool:
    """Whether ``model`` weighs `TIMED_FEATURES` for any kind: if not, what they are changes no score (a weight of 0
    times a finite feature adds exactly nothing), and `rerank` does not measure them."""
    return bool(model.theta[_TIMED_COLUMNS].any())


_TIMED_COLUMNS = np.array([k * (len(FEATURES) + 1) + FEATURES.index(f) for k in range(len(KINDS))
                           for f in TIMED_FEATURES])
"""Where `design` puts `TIMED_FEATURES` for each kind (the weights `reads_times` looks at)."""


def design(kinds: Sequence[str], phi: np.ndarray, rules_kind: str) -> np.ndarray:
    """One row per candidate kind: the kind's own copy of ``[phi, 1]`` (``phi``: the standardised `FEATURES`; zeros
    elsewhere), then whether it is the rules' answer."""
    width = len(FEATURES) + 1
    x = np.zeros((len(kinds), len(KINDS) * width + 1))
    for i, k in enumerate(kinds):
        j = KINDS.index(k) * width
        x[i, j:j + width - 1] = phi
        x[i, j + width - 1] = 1.0
        x[i, -1] = float(k == rules_kind)
    return x


def offered(kinds: Sequence[str], phi: np.ndarray) -> list[bool]:
    """Which kinds `geometry` can draw for a stroke with features ``phi``: a polyline needs an inner corner."""
    inner = round(float(phi[FEATURES.index("corners")]) * 8)
    return [k != "polyline" or inner >= 1 for k in kinds]


def choose(rules_kind: str, phi: np.ndarray, model: Model) -> tuple[str, float]:
    """The kind of ``rules_kind``'s family the model scores best, when its chance under the model is over the
    model's margin, else the rules' answer; and that kind's chance. A polyline the rules read as a hurried check
    (`checked_point`) is not asked of the model."""
    kinds = family(rules_kind, phi)
    if not kinds or (rules_kind == "polyline" and checked_point(phi)):
        return rules_kind, 1.0
    scores = design(kinds, (phi[:len(FEATURES)] - model.mean) / model.std, rules_kind) @ model.theta
    scores = np.where(offered(kinds, phi), scores, -np.inf)
    chance = np.exp(scores - scores.max())
    chance /= chance.sum()
    best = int(scores.argmax())  # the first of equals: the family's order
    if kinds[best] == rules_kind or chance[best] > model.margin:
        return kinds[best], float(chance[best])
    return rules_kind, float(chance[kinds.index(rules_kind)])


def checked_point(phi: np.ndarray) -> bool:
    """Whether the stroke turns at one really sharp corner (`open_shapes.VERY_SHARP_CORNER`), off-centre (a short arm
    and a long one, `CHECK_ARMS`), in at most three lobes: the rules' hurried check, whose arms may bow; also when a
    second, weaker corner marks where a bowed arm's hump starts, so long as the point holds `CHECK_POINT_SHARE` of
    all the stroke's turning. The rules read it as a polyline on purpose; a model fitted on people who draw checks
    with straight arms reads bowed arms as a curve's, so it is not asked. A point turning past half a turn
    (`bracket_marks.LOOPED_POINT`) is a loop, as a brace's looped point, not a check's (issue 25, sixth pass)."""
    corners = round(float(phi[FEATURES.index("corners")]) * 8)
    turn = float(phi[FEATURES.index("max_corner_turn")]) * 180.0
    lobes = round(float(phi[FEATURES.index("lobes")]) * 4)
    balance = float(phi[FEATURES.index("point_balance")])
    if turn < open_shapes.VERY_SHARP_CORNER or turn > bracket_marks.LOOPED_POINT or lobes > 3 or balance > CHECK_ARMS:
        return False
    whole = float(phi[FEATURES.index("abs_turn")]) * 360.0
    return corners == 1 or (corners == 2 and turn >= CHECK_POINT_SHARE * whole)


def rerank(points: Sequence[Sequence[float]], times: Sequence[float] | None, noise: float, found: Recognition,
           model: Model, drawn: Drawn | None = None, sparse: bool = False) -> Recognition:
    """``found`` (the rules' reading of the stroke), or the kind the model prefers with its geometry drawn from
    the stroke, the rules' kind then the first alternative; ``drawn``, where given, is what recognition already
    measured of ``points`` (`Drawn`); ``sparse``: the points are so far apart that their jitter is the shape's own
    bends (`recognize.sparse_bends`), where a curve the rules read is kept (`kept_curve`)."""
    asked = question(points, times, noise, found, drawn, sparse, timed=reads_times(model))
    if asked is None or found.kind is None:
        return found
    phi, unit = asked
    kind, chance = choose(found.kind, phi, model)
    if kind == found.kind:
        return found
    shape = geometry(kind, unit[1])
    if shape is None:
        return found
    raw, _, _, diag, _ = unit
    return Recognition(kind, round(chance, 4), scale_geometry(shape, raw.mean(axis=0), diag),
                       ((found.kind, round(1.0 - chance, 4)),))


def question(points: Sequence[Sequence[float]], times: Sequence[float] | None, noise: float, found: Recognition,
             drawn: Drawn | None = None, sparse: bool = False, *, timed: bool = True) -> tuple[np.ndarray, Unit] | None:
    """What `rerank` asks the model of the rules' reading ``found`` (the features, the stroke prepared for them), or
    None where it is not asked (not of `KINDS`, a zig-zag's teeth, a sparse curve, a closed polygon, a hurried check,
    a swung tick); `benchmarks/train_ranker.py` describes each stroke by it (the model fitted on what it is asked)."""
    if found.kind not in KINDS or zigzag_teeth(found) or kept_curve(found, sparse):
        return None
    if found.kind == "polygon" and (not _ends_apart(points, drawn) or star_left(found)):
        return None
    unit = _unit_work(points, times, drawn)
    if unit is None or (found.kind == "polygon" and not open_polygon(sf.closure(unit[1], sg.bbox_diagonal(unit[1])))):
        return None
    phi = _features(unit, noise, polyline=found.kind == "polyline", timed=timed)
    return None if phi is None else (phi, unit)  # None: a hurried check, not asked (`choose`)


class Asker(Protocol):
    """What `recognize.recognize_stroke` may ask in `rerank`'s stead (its ``learned``): `rerank` without the model."""

    def __call__(self, points: Sequence[Sequence[float]], times: Sequence[float] | None, noise: float,
                 found: Recognition, drawn: Drawn | None, sparse: bool) -> Recognition: ...


def star_left(found: Recognition) -> bool:
    """Whether the rules' polygon is a star's outline (`open_stars.star_outline`): not asked of the model, fitted on
    few stars left open, which takes one closed across its gap for a curve (issue 25, session 33)."""
    return isinstance(found.geometry, Polygon) and open_stars.star_outline(found.geometry.points)


def zigzag_teeth(found: Recognition) -> bool:
    """Whether the rules' polyline has a zig-zag's teeth (`open_marks.sawtooth_vertices`, on the corners the rules
    found, which see small teeth the model's 64 points smooth away): not asked of the model, whose features (fitted
    on few zig-zags) take a curled tail's bow for a curve's. Asked of the vertices in both orders (a tooth's sides
    are compared with the sides two before it, so one order weighs the side leading into the teeth, the other the
    side leading out): a stroke is the same zig-zag whichever end it was drawn from (issue 25, session 30)."""
    return (found.kind == "polyline" and isinstance(found.geometry, Polyline)
            and open_marks.sawtooth_vertices(found.geometry.points)
            and open_marks.sawtooth_vertices(found.geometry.points[::-1]))


def kept_curve(found: Recognition, sparse: bool) -> bool:
    """Whether the rules read a curve from points so far apart that their jitter is the shape's own bends
    (``sparse``, `recognize.sparse_bends`: a device's 8-25 events), not asked of the model: far-apart events make
    bends look like straight runs and corners, never corners round, so a curve the rules still see is the shape's."""
    return sparse and found.kind == "curve"


def _ends_apart(points: Sequence[Sequence[float]], drawn: Drawn | None = None) -> bool:
    """Whether a polygon's ends may be far enough apart to ask (`open_polygon`), judged before any other work: most
    polygons are closed. A stroke whose ends are under half `OPEN_GAP` of its size apart is closed: resampling and
    smoothing keep its ends and only shrink its size, so its closure could reach `OPEN_GAP` only were its size halved
    by smoothing. (``drawn``'s points without repeats have the same ends and extent as ``points``.)"""
    if drawn is not None:
        pts, size = drawn.raw, drawn.diag
    else:
        try:
            pts = np.asarray(points, dtype=float)[:, :2]
        except (ValueError, IndexError):  # rows of different lengths (x, y and sometimes t)
            pts = np.asarray([p[:2] for p in points], dtype=float)
        size = sg.bbox_diagonal(pts) if len(pts) >= 2 and np.isfinite(pts).all() else 0.0
    return size > 0.0 and float(np.hypot(*(pts[-1] - pts[0]))) >= 0.5 * OPEN_GAP * size


def geometry(kind: str, work: np.ndarray) -> Geometry | None:
    """The clean shape of ``kind`` drawn from ``work`` (the stroke at unit size, resampled), as `open_shapes` draws
    it: a polyline through the stroke's corners, or a curve of cubic pieces."""
    corners = sf.drop_end_stubs(work, sg.find_corners(work), sg.path_length(work))
    if kind == "polyline" and len(corners) >= 3:
        return Polyline(tuple(_pt(work[c]) for c in corners))
    if kind == "curve":
        return curve_geometry(work, corners)
    return None


def _pt(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))
