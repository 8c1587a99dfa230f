"""Strokes whose label contradicts their geometry (issue 25): for each stroke the recogniser reads wrong, the nearest
strokes of the other sources by the $1 recogniser's distance, and whether the stroke is nearer to strokes of
another label than to any stroke of its own.

Usage: .venv/bin/python benchmarks/label_contradictions.py SET [SET ...] [--files FILE ...]

The $1 distance (Wobbrock, Wilson and Li 2007) is the mean distance between two strokes' points after each is resampled
to `POINTS` points, turned so that its first point lies at angle 0 from its centroid, scaled to a square and centred,
minimised over a further turn of up to 45 degrees (golden-section search to 2 degrees). Here it is also minimised over
drawing the reference backwards (the recogniser does not care which end a stroke starts from). Only strokes of *other*
sources are compared (a person's own strokes would vouch for the person's labels). The held-back sources (both groups:
`bench_generalisation.held_back`, `second_group`, the second even since it was opened) are neither scored nor used as
references. Without ``--files`` every stroke the rules-and-ranker recogniser (`recognize_stroke`) reads wrong is listed;
a stroke is *contradicted* when its nearest other-source stroke carries another label, and that label's class accepts
the kind the recogniser gave (the geometry agrees with a reading the label table calls wrong).

`CONTRADICTIONS` are the contradictions proved from geometry alone (two attempts joined after a pause, a question mark
drawn as a zigzag, an open mark that loops, an x that does not cross itself, a curly brace without a point), each
with its threshold chosen on the sources it does not convict (`tests/test_label_contradictions.py`);
`bench_generalisation.py --contradictions` counts the strokes they convict per source, beside the raw figure.
"""

from __future__ import annotations

import argparse
import itertools
import math
from collections import Counter
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

import numpy as np
from bench_generalisation import held_back, scored_rows, second_group
from bench_recognition import table
from stroke_sets import Row, read_set, source_of

from physink_tui.scene.recognition import open_shapes, ranker
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

POINTS = 64
SQUARE = 250.0
HALF_TURN = math.radians(45.0)
PRECISION = math.radians(2.0)
PHI = 0.5 * (math.sqrt(5.0) - 1.0)


def zigzag(points: Sequence[Sequence[float]]) -> bool:
    """A zigzag by the recogniser's own geometry: three or more inner corners (`stroke_geometry.find_corners`,
    end stubs dropped), each turning more than 90 degrees and each the other way from the one before, joined by
    straight sides (`open_shapes.straight`)."""
    found = ranker._unit_work(points, None)
    if found is None:
        return False
    work = found[1]
    th = sg.turning(work)
    corners = sf.drop_end_stubs(work, sg.find_corners(work), sg.path_length(work))
    if len(corners) < 5 or not all(open_shapes.straight(work[a:b + 1], 0.0) for a, b in itertools.pairwise(corners)):
        return False
    n = len(th) + 2
    turns = [math.degrees(float(th[max(c - 3, 1) - 1:min(c + 3, n - 2)].sum())) for c in corners[1:-1]]
    return all(abs(t) > 90.0 for t in turns) and all(a * b < 0 for a, b in itertools.pairwise(turns))


def _crossings(p: np.ndarray) -> Iterator[tuple[int, np.ndarray]]:
    """For each side ``i`` of the polyline ``p``, the later sides (counted from ``i + 2``) that cross it."""
    a, d = p[:-1], np.diff(p, axis=0)
    for i in range(len(a) - 2):
        r = a[i + 2:] - a[i]
        den = d[i, 0] * d[i + 2:, 1] - d[i, 1] * d[i + 2:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (r[:, 0] * d[i + 2:, 1] - r[:, 1] * d[i + 2:, 0]) / den
            u = (r[:, 0] * d[i, 1] - r[:, 1] * d[i, 0]) / den
        yield i, np.flatnonzero((den != 0) & (t > 0) & (t < 1) & (u > 0) & (u < 1))


def crosses_itself(points: Sequence[Sequence[float]]) -> bool:
    """Whether the stroke, resampled to `POINTS` points, crosses itself (two sides not next to each other meet)."""
    return any(len(hits) for _, hits in _crossings(template(points)))


def loop_share(points: Sequence[Sequence[float]]) -> float:
    """The largest share of the stroke's path (resampled to `POINTS` points) that runs between two of its sides
    crossing: 0 for a stroke that does not cross itself; a pigtail's loop, a star's, or a hook's small curl."""
    best = max((2 + int(hits[-1]) for _, hits in _crossings(template(points)) if len(hits)), default=0)
    return best / (POINTS - 1)


LOOP = 0.125
"""An open mark whose loop (`loop_share`) holds at least this share of its path loops as a pigtail does. Chosen
on the sources it does not convict: of the other design sources' open marks (`OPEN_MARKS`), those that cross
themselves without a jump in them loop round at most 0.11 of their path (mmg:22's lines, end hooks of
shriyansnidhish/s01's v and dollar1:s02's bracket)."""
OPEN_MARKS = frozenset({"v", "caret", "check", "left_sq_bracket", "right_sq_bracket", "zigzag", "line",
                        "question_mark"})
"""Labels whose gesture, as drawn in the sets, never loops: an open mark of straight or bent sides."""
PAUSE_MS = 1000.0
JUMP = 0.2
"""Two strokes recorded as one (`joined_after_a_pause`): a gap of at least `PAUSE_MS` between two samples `JUMP` or
more of the stroke's diagonal apart. Chosen on the sources with times other than hcira:shriyansnidhish/s01-s03
(the ones it convicts): the longest gap at such a jump there is 406 ms (mmg:41's stars drawn with a finger)."""


def joined_after_a_pause(stroke: Sequence[Sequence[float | None]]) -> bool:
    """Whether the stroke (points [x, y, t in ms]) is two attempts recorded as one: the pen left the surface for
    `PAUSE_MS` or more and came down `JUMP` of the stroke's diagonal away, with no sample between. False without
    times."""
    if len(stroke) < 3 or any(len(q) < 3 or q[2] is None for q in stroke):
        return False
    pts = np.asarray([q[:2] for q in stroke], dtype=float)
    t = np.asarray([q[2] for q in stroke], dtype=float)
    diag = float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))
    steps = np.hypot(*np.diff(pts, axis=0).T)
    return bool(np.any((steps >= JUMP * diag) & (np.diff(t) >= PAUSE_MS))) if diag > 0 else False


BRACES = frozenset({"left_curly_brace", "right_curly_brace"})
POINT_TURN = 20.0
"""A curly brace turns at its point, in the middle of its path: every other design source's brace turns at least 34
degrees within some `SPAN` of its path in its middle 40 % (`middle_turn`); one that turns less than this has no point
(a square bracket or an arc drawn under the label)."""
SPAN = 0.04


def middle_turn(points: Sequence[Sequence[float]]) -> float:
    """The most the stroke turns (degrees, between the chords before and after a point) within `SPAN` of its path
    either side, over the middle 40 % of its path (resampled to 128 points: a mouse's stair-steps average out)."""
    n = 128
    pts = np.asarray([q[:2] for q in points], dtype=float)
    at = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    if at[-1] == 0.0:
        return 0.0
    s = np.linspace(0.0, at[-1], n)
    p = np.column_stack([np.interp(s, at, pts[:, 0]), np.interp(s, at, pts[:, 1])])
    k = max(2, round(SPAN * (n - 1)))
    before, after = p[k:n - k] - p[:n - 2 * k], p[2 * k:] - p[k:n - k]
    turn = np.degrees(np.abs(np.arctan2(before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0],
                                        (before * after).sum(axis=1))))
    where = np.arange(k, n - k) / (n - 1)
    return float(turn[(where >= 0.3) & (where <= 0.7)].max())


def _loops(points: Sequence[Sequence[float]]) -> bool:
    return loop_share(points) >= LOOP


CONTRADICTIONS: tuple[tuple[str, frozenset[str] | None, Callable[[Sequence[Sequence[float]]], bool]], ...] = (
    ("two strokes joined after a pause", None, joined_after_a_pause),
    ("a question mark drawn as a zigzag", frozenset({"question_mark"}), zigzag),
    ("an open mark that loops", OPEN_MARKS, _loops),
    ("an x that does not cross itself", frozenset({"x"}), lambda p: not crosses_itself(p)),
    ("a curly brace without a point", BRACES, lambda p: middle_turn(p) < POINT_TURN),
)
"""The contradictions between a stroke's label and its geometry that the tests prove (name, the labels it applies to
or None for every label, the test on the stroke's points [x, y, t]). Each convicts (nearly) no stroke of its labels
on the sources it was not chosen on (`tests/test_label_contradictions.py`). `crosses_itself` for checks is not one:
1-3 checks cross themselves at an end hook in 8 of the other sources (`--invariants`)."""


def contradiction(row: Row) -> str | None:
    """The first of `CONTRADICTIONS` that convicts the label of ``row`` (one stroke), or None."""
    stroke = row["strokes"][0]
    for name, labels, test in CONTRADICTIONS:
        if (labels is None or row["label"] in labels) and test(stroke):
            return name
    return None


INVARIANTS = {"a zigzag": zigzag, "crosses itself": crosses_itself}
"""Geometric facts that tell kinds apart whatever a person calls them, counted per source and label (`--invariants`)."""


def template(points: Sequence[Sequence[float]]) -> np.ndarray:
    """The stroke as the $1 recogniser compares it: `POINTS` points equally spaced along it, turned so that its
    first point lies at angle 0 from the centroid, scaled to a `SQUARE` and centred on the origin."""
    pts = np.asarray([p[:2] for p in points], dtype=float)
    seg = np.hypot(*np.diff(pts, axis=0).T)
    at = np.concatenate([[0.0], np.cumsum(seg)])
    if at[-1] == 0.0:
        return np.zeros((POINTS, 2))
    s = np.linspace(0.0, at[-1], POINTS)
    res = np.column_stack([np.interp(s, at, pts[:, 0]), np.interp(s, at, pts[:, 1])])
    centre = res.mean(axis=0)
    a = -math.atan2(res[0, 1] - centre[1], res[0, 0] - centre[0])
    rot = (res - centre) @ np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])
    size = np.maximum(rot.max(axis=0) - rot.min(axis=0), 1e-9)
    scaled = rot * (SQUARE / size)
    return scaled - scaled.mean(axis=0)


def _at_angle(query: np.ndarray, refs: np.ndarray, angles: np.ndarray) -> np.ndarray:
    c, s = np.cos(angles)[:, None], np.sin(angles)[:, None]
    x = query[None, :, 0] * c - query[None, :, 1] * s
    y = query[None, :, 0] * s + query[None, :, 1] * c
    return np.hypot(x - refs[:, :, 0], y - refs[:, :, 1]).mean(axis=1)


def distances(query: np.ndarray, refs: np.ndarray) -> np.ndarray:
    """The $1 distance from ``query`` to each of ``refs`` (templates), each at its best turn within 45 degrees."""
    lo, hi = np.full(len(refs), -HALF_TURN), np.full(len(refs), HALF_TURN)
    x1, x2 = PHI * lo + (1 - PHI) * hi, (1 - PHI) * lo + PHI * hi
    f1, f2 = _at_angle(query, refs, x1), _at_angle(query, refs, x2)
    while float((hi - lo).max()) > PRECISION:
        left = f1 < f2  # the least lies left of x2: drop (x2, hi]; else drop [lo, x1)
        hi, lo = np.where(left, x2, hi), np.where(left, lo, x1)
        keep_x, keep_f = np.where(left, x1, x2), np.where(left, f1, f2)
        new_x = np.where(left, PHI * lo + (1 - PHI) * hi, (1 - PHI) * lo + PHI * hi)
        new_f = _at_angle(query, refs, new_x)
        x1, f1 = np.where(left, new_x, keep_x), np.where(left, new_f, keep_f)
        x2, f2 = np.where(left, keep_x, new_x), np.where(left, keep_f, new_f)
    return np.minimum(f1, f2)


def nearest(rows: list[Row], i: int, refs: np.ndarray, sources: np.ndarray, k: int = 5,
            ) -> list[tuple[float, str, str]]:
    """The ``k`` strokes of other sources nearest to stroke ``i`` (distance, label, file), either way round."""
    other = np.flatnonzero(sources != sources[i])
    query = template(rows[i]["strokes"][0])
    d = np.minimum(distances(query, refs[other, 0]), distances(query, refs[other, 1]))
    order = np.argsort(d, kind="stable")[:k]
    return [(float(d[j]), rows[other[j]]["label"], rows[other[j]]["file"]) for j in order]


def references(rows: list[Row]) -> np.ndarray:
    """Each stroke's template drawn forwards and backwards: shape (strokes, 2, `POINTS`, 2)."""
    return np.array([[template(r["strokes"][0]), template(r["strokes"][0][::-1])] for r in rows])


def evidence(rows: list[Row], picked: list[int]) -> list[dict]:
    """For each stroke of ``picked``: its nearest other-source strokes, the nearest of its own label, and its
    recognised kind."""
    refs = references(rows)
    sources = np.array([source_of(r, "person") for r in rows])
    labels = np.array([r["label"] for r in rows])
    out = []
    for i in picked:
        near = nearest(rows, i, refs, sources)
        query = template(rows[i]["strokes"][0])
        own = np.flatnonzero((sources != sources[i]) & (labels == rows[i]["label"]))
        d_own = float(np.minimum(distances(query, refs[own, 0]), distances(query, refs[own, 1])).min()) \
            if len(own) else math.inf
        stroke = rows[i]["strokes"][0]
        times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
        kind = recognize_stroke([p[:2] for p in stroke], times).kind
        out.append({"row": rows[i], "source": str(sources[i]), "kind": kind, "near": near, "own": d_own})
    return out


def invariant_table(rows: list[Row]) -> str:
    """Per label, how many strokes have each invariant: for each source, and for all sources."""
    sources = sorted({source_of(r, "person") for r in rows})
    count: Counter = Counter()
    for r in rows:
        for name, test in INVARIANTS.items():
            if test(r["strokes"][0]):
                count[name, r["label"], source_of(r, "person")] += 1
    strokes = Counter((r["label"], source_of(r, "person")) for r in rows)
    lines = []
    for label in sorted({r["label"] for r in rows}):
        for name in INVARIANTS:
            cells = [f"{count[name, label, s]}/{strokes[label, s]}" if strokes[label, s] else "" for s in sources]
            total = sum(count[name, label, s] for s in sources)
            lines.append([label, name, f"{total}/{sum(strokes[label, s] for s in sources)}", *cells])
    return table(["label", "invariant", "all", *sources], lines)


def verdict(e: dict) -> str:
    """"another label, all 5" when none of the stroke's 5 nearest other-source strokes has its label and its own
    label's nearest is farther than all 5; "another label" when the nearest has another label and is nearer than
    its own label's nearest; else "own label"."""
    (d1, label1, _), *_ = e["near"]
    own = e["row"]["label"]
    if all(lab != own for _, lab, _ in e["near"]) and e["own"] > e["near"][-1][0]:
        return "another label, all 5"
    return "another label" if label1 != own and d1 < e["own"] else "own label"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--files", nargs="*", help="score these strokes (file names as the sets give them)")
    ap.add_argument("--invariants", action="store_true", help="count each of `INVARIANTS` per source and label")
    ap.add_argument("--control", type=int, default=0, metavar="N",
                    help="also score every Nth stroke read right, as a control of how often a right one is flagged")
    args = ap.parse_args()
    rows: list[Row] = []
    for path in args.sets:
        rows += read_set(path)
    rows, _ = scored_rows(rows)
    group = held_back(rows) | second_group(rows)
    rows = [r for r in rows if source_of(r, "person") not in group]  # never read, never a reference
    if args.invariants:
        print(invariant_table(rows) + "\n")
    if args.files:
        picked = [i for i, r in enumerate(rows) if r["file"] in set(args.files)]
    else:
        picked = []
        for i, r in enumerate(rows):
            stroke = r["strokes"][0]
            times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
            if recognize_stroke([p[:2] for p in stroke], times).kind not in r["accepts"]:
                picked.append(i)
    found = evidence(rows, picked)
    lines, flags = [], Counter()
    for e in found:
        labels5 = ", ".join(f"{lab} {d:.0f}" for d, lab, _ in e["near"])
        flagged = verdict(e)
        flags.update([flagged])
        lines.append([e["source"], e["row"]["file"].rsplit("/", 1)[-1], e["row"]["label"], e["kind"] or "-",
                      labels5, f"{e['own']:.0f}", flagged])
    print(table(["source", "stroke", "label", "read as", "5 nearest of other sources ($1 distance)",
                 "nearest of its own label", "verdict"], lines))
    print(f"\nOf {len(found)} strokes read wrong: {flags['another label'] + flags['another label, all 5']} nearer to "
          f"another label's strokes than to any of their own ({flags['another label, all 5']} with none of their 5 "
          "nearest of their label).")
    if args.control:
        right = [i for i in range(len(rows)) if i not in set(picked)][::args.control]
        control = Counter(verdict(e) for e in evidence(rows, right))
        print(f"Control, every {args.control}th stroke read right ({len(right)}): "
              f"{control['another label'] + control['another label, all 5']} nearer to another label "
              f"({control['another label, all 5']} with none of their 5 nearest of their label).")


if __name__ == "__main__":
    main()
