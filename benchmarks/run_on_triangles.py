"""Benchmark: whether people's triangles whose ends cross and run on can be told from people's x's and delete marks by
anything but how far the ends run on.

Usage: .venv/bin/python benchmarks/run_on_triangles.py [--hi 0.5] [--lo 0.2] [--list]

Issue 25, session 31 (wt-tails): tutorboard seed90210's triangle #247 runs on past its first corner (its ends cross
0.17 and 0.33 of its size from them) and is read as a polyline; `end_crossings` closes a loop of four sides or more so
run on, but not a triangle, since people's delete marks cross as far from their ends. This reads every single stroke of
the design sets and the fourth group (the held-back groups left out, as `compare_readings` leaves them), takes the path
the recogniser hands `closed_loops.closed_loop` first, and keeps the strokes whose first and last thirds cross with a
triangle between (two corners besides the crossing, `stroke_geometry.find_corners`). For those whose ends lie within
``--lo`` and ``--hi`` of their size of the crossing (the run-on zone) it measures: the tails (``lo``, ``hi``: path from
the crossing to each end over the size; ``rlo``, ``rhi``: over the side each continues), the loop's angle at the
crossing (``xang``), that angle less the loop's widest other (``xang_rel``), the loop's least and widest angles, how
sharp its corners are (``sharp``: the turning within 2 points of the corner over that within 8), how straight its
sides (``dev``: chord deviation), how far each tail bends off the side it continues (``da``, ``db``, degrees), the
loop's share of the path, and, where the stroke has times, the pen's speed at each pass through the crossing and at
the corners against its median (``v_x1``, ``v_x2``, ``v_corn``). Per feature: the range of triangles and of marks, and,
leave-one-source-out (a one-sided threshold set midway between the marks' extreme and the next triangle, chosen
without the scored person), how many triangles and marks it would close. Read-only.
"""

from __future__ import annotations

import argparse
import itertools
import math
import re
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from compare_readings import _kept
from round_side_x import SETS

from physink_tui.scene.recognition import closed_loops, end_crossings
from physink_tui.scene.recognition import recognize as recognize_module
from physink_tui.scene.recognition import stroke_geometry as sg

KEYS = ("xang", "xang_rel", "minang", "maxang", "sharp", "dev", "da", "db", "loopshare", "rlo", "rhi", "lo", "hi",
        "v_x1", "v_x2", "v_corn")
MARKS = ("delete_mark", "x", "v")
"""The labels of the marks a run-on triangle must not be taken for."""


def _angle(u: np.ndarray, v: np.ndarray) -> float:
    c = float(u @ v) / max(float(np.hypot(*u) * np.hypot(*v)), 1e-12)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def _times_at(points: list[list[float]], times: list[float] | None, work: np.ndarray) -> np.ndarray | None:
    """The time at each point of ``work``, by its share of the path (None without times)."""
    if times is None or len(times) != len(points) or times[-1] <= times[0]:
        return None
    pts = np.asarray(points, dtype=float)
    along = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    if along[-1] <= 0:
        return None
    at = sg.along(work)
    return np.interp(at / at[-1], along / along[-1], np.asarray(times, dtype=float))


def features(work: np.ndarray, diag: float, when: np.ndarray | None) -> dict[str, float] | None:
    """The features above of a path whose first and last thirds cross round a triangle, or None."""
    n = len(work)
    k = n // 3
    found = end_crossings._crossing(work[:k], work[n - k:])
    if found is None:
        return None
    i, j = found[0], n - k + found[1]
    p, r, s = work[i], work[i + 1] - work[i], work[j + 1] - work[j]
    den = float(r[0] * s[1] - r[1] * s[0])
    cross = p + float((work[j] - p)[0] * s[1] - (work[j] - p)[1] * s[0]) / den * r
    along = sg.along(work)
    ta = (along[i] + float(np.hypot(*(cross - work[i])))) / diag
    tb = (along[-1] - along[j + 1] + float(np.hypot(*(work[j + 1] - cross)))) / diag
    loop = np.vstack([cross, work[i + 1:j + 1], cross])
    corners = sg.find_corners(loop)
    if len(corners) != 4:
        return None
    c1, c2 = loop[corners[1]], loop[corners[2]]
    verts = [cross, c1, c2]
    angs = [_angle(verts[m - 1] - verts[m], verts[(m + 1) % 3] - verts[m]) for m in range(3)]
    ra, rb = ta * diag / float(np.hypot(*(c1 - cross))), tb * diag / float(np.hypot(*(c2 - cross)))
    th = np.abs(sg.turning(loop))
    sharp = [float(th[max(c - 2, 0):c + 3].sum()) / max(float(th[max(c - 8, 0):c + 9].sum()), 1e-9)
             for c in corners[1:3]]
    f = {"lo": min(ta, tb), "hi": max(ta, tb), "rlo": min(ra, rb), "rhi": max(ra, rb), "xang": angs[0],
         "xang_rel": angs[0] - max(angs[1:]), "minang": min(angs), "maxang": max(angs), "sharp": min(sharp),
         "dev": max(sg.chord_deviation(loop[c:d + 1]) for c, d in itertools.pairwise(corners)),
         "da": _angle(cross - work[0], c1 - cross), "db": _angle(cross - c2, work[-1] - cross),
         "loopshare": sg.path_length(loop) / along[-1]}
    if when is not None:
        with np.errstate(divide="ignore", invalid="ignore"):
            v = np.hypot(*np.diff(work, axis=0).T) / np.diff(when)
        v[~np.isfinite(v)] = np.nan
        med = float(np.nanmedian(v))

        def speed(at: int) -> float:
            near = v[max(at - 2, 0):at + 3]
            near = near[np.isfinite(near)]
            return float(near.min()) / med if len(near) and med > 0 else math.nan

        f.update(v_x1=speed(i), v_x2=speed(j), v_corn=max(speed(i + c) for c in corners[1:3]))
    return f


def gather() -> list[tuple[str, str, str, dict[str, float]]]:
    """(person, label, the shipped reading, features) of every stroke whose ends cross round a triangle."""
    seen: list[tuple[np.ndarray, float]] = []
    real = closed_loops.closed_loop

    def spy(raw: np.ndarray, work: np.ndarray, diag: float, sigma: float) -> tuple:
        seen.append((work.copy(), diag))
        return real(raw, work, diag, sigma)

    recognize_module.closed_loops.closed_loop = spy
    rows = []
    try:
        for _, points, times, where in _kept([p for p in SETS if p.is_file()], True):
            seen.clear()
            kind = recognize_module.recognize_stroke(points, times).kind
            if not seen:
                continue
            work, diag = seen[0]
            f = features(work, diag, _times_at(points, times, work))
            if f is not None:
                label = re.search(r'"(.*)"$', where)
                rows.append((where, label.group(1).lower() if label else "", str(kind), f))
    finally:
        recognize_module.closed_loops.closed_loop = real
    return rows


def loso(tri: list[tuple[str, float]], marks: list[tuple[str, float]]) -> tuple[int, int]:
    """How many triangles and marks a one-sided threshold closes, each person scored with a threshold set without
    them: above (or below) every mark of the others, midway to the next triangle, the side closing more triangles."""
    closed_tri = closed_marks = 0
    for person in sorted({p for p, _ in tri + marks}):
        best: tuple[int, float, float] = (-1, 1.0, math.inf)
        for sign in (1.0, -1.0):
            t = np.array([sign * v for p, v in tri if p != person])
            m = np.array([sign * v for p, v in marks if p != person])
            top = float(m.max()) if len(m) else -math.inf
            above = t[t > top]
            if len(above) > best[0]:
                best = (len(above), sign, (top + float(above.min())) / 2 if len(above) else math.inf)
        _, sign, cut = best
        closed_tri += int(sum(sign * v > cut for p, v in tri if p == person))
        closed_marks += int(sum(sign * v > cut for p, v in marks if p == person))
    return closed_tri, closed_marks


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--lo", type=float, default=0.2, help="the nearer end within this share of the size")
    parser.add_argument("--hi", type=float, default=0.5, help="the farther end within this share")
    parser.add_argument("--list", action="store_true", help="list the zone's strokes and their features")
    args = parser.parse_args()
    rows = gather()
    zone = [r for r in rows if r[3]["lo"] <= args.lo and args.lo < r[3]["hi"] <= args.hi]
    tri = [r for r in zone if r[1] == "triangle" and r[2] in ("polygon", "polyline")]
    marks = [r for r in zone if r[1] in MARKS]
    print(f"{len(rows)} strokes' first and last thirds cross round a triangle; in the zone (one end within "
          f"{args.lo:g} of the size, the other {args.lo:g}-{args.hi:g}): {len(tri)} triangles "
          f"({sum(r[2] != 'polygon' for r in tri)} read open), {len(marks)} x's, delete marks and v's "
          f"({sum(r[2] == 'polygon' for r in marks)} read as polygons)\n")
    print("| feature | triangles | marks | LOSO: triangles closed | marks closed |\n|---|---|---|---:|---:|")
    for key in KEYS:
        t = [(r[0].split()[0], r[3][key]) for r in tri if math.isfinite(r[3].get(key, math.nan))]
        m = [(r[0].split()[0], r[3][key]) for r in marks if math.isfinite(r[3].get(key, math.nan))]
        if not t or not m:
            print(f"| {key} | {len(t)} with times | {len(m)} with times | - | - |")
            continue
        ct, cm = loso(t, m)
        print(f"| {key} | {min(v for _, v in t):.2f}-{max(v for _, v in t):.2f} ({len(t)}) "
              f"| {min(v for _, v in m):.2f}-{max(v for _, v in m):.2f} ({len(m)}) | {ct}/{len(t)} | {cm}/{len(m)} |")
    if args.list:
        for where, label, kind, f in sorted(tri + marks, key=lambda r: (r[1], r[3]["hi"])):
            print(f"{label:12s} {kind:9s} " + " ".join(f"{k} {f.get(k, math.nan):.2f}" for k in KEYS) + f"  {where}")


if __name__ == "__main__":
    main()
