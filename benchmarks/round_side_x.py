"""Benchmark: whether an x drawn with one round side (an alpha, a fish) can be told from people's pigtails by its shape.

Usage: .venv/bin/python benchmarks/round_side_x.py [--margins 0,0.1,0.2,0.3,0.5,1] [--near 0.6] [--pens 0.2]

Issue 25, session 30 (wt-alpha): hcira jd4386/User05 draws 7 of 10 x's as a straight arm, a round loop up the side and
a straight arm back across the first; the rules read them as curves, as they read pigtails. This measures, on every
single stroke of the design sets and the fourth group (the held-back groups left out, as `compare_readings` leaves
them) that crosses itself once and that the rules read as a curve or an arc, what a rule could look at (`shape`): each
arm the longest straight run from an end (chord deviation at most `STRAIGHT`), where the crossing falls along each
(``fmax``, ``fmin``), the angle between the arms' headings (``ang``), the connector between the arms' far ends: how deep
it bows over its chord (``depth``), how wide the loop is across the arms' bisector against the arms' ends' spread
(``wide``), the share of its turning in its middle 40 % (``mid``), its share of the path (``conn``). The box round
User05's seven misses, grown by each margin (a share of each feature's range), is then asked what else it takes.
``--pens M`` also counts, of the pen models' x's with a round side and pigtails (`tests/penmodels/x_habits`
``round-side-x``, `pigtail_habits`; tuning seeds, every pen of `bench_bracket_habits`, points only), how many the box
grown by M takes. Read-only: no recogniser code is changed; it reads the rules' reading (``learned=False``) once per
stroke.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from compare_readings import _kept

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.closed_loops import self_crossings
from physink_tui.scene.recognition.recognize import recognize_stroke

ROOT = Path(__file__).resolve().parents[1]
CACHE = Path.home() / ".cache" / "physink"
SETS = [ROOT.parent / "shared/data/strokes/dollar1-dev.jsonl", CACHE / "student-sets/itt.jsonl",
        *(CACHE / f"public-sets/{name}.jsonl" for name in
          ("itt-more", "hcira", "mmg", "ahmadosama", "gtiwari", "quickdraw", "tutorboard"))]
"""The design sets and the fourth group's (the held-back groups are never read)."""
POINTS = 64
"""The stroke is judged on this many points along it, lightly smoothed."""
STRAIGHT = 0.06
"""An arm runs from an end as long as its points stay within this share of its chord from the chord."""
TAIL = 0.06
"""Each end's tail before the crossing is at least this share of the path (a closed shape's ends cross at a corner)."""
MISSES = "User05/x0[1235678]"
"""The seven x's with a round side the rules read as curves (hcira jd4386 User05)."""
KEYS = ("fmax", "fmin", "ang", "mid", "wide", "depth", "conn")


def _crossings(a: np.ndarray) -> list[tuple[int, int, float]]:
    """Every crossing of the path ``a`` with itself: the two steps' indices and where along the first it falls."""
    i, j = np.triu_indices(len(a) - 1, 2)
    p, r, q, s = a[i], a[i + 1] - a[i], a[j], a[j + 1] - a[j]
    den = r[:, 0] * s[:, 1] - r[:, 1] * s[:, 0]
    qp = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qp[:, 0] * s[:, 1] - qp[:, 1] * s[:, 0]) / den
        u = (qp[:, 0] * r[:, 1] - qp[:, 1] * r[:, 0]) / den
    hit = np.flatnonzero((den != 0) & (t > 0) & (t < 1) & (u > 0) & (u < 1))
    return [(int(i[k]), int(j[k]), float(t[k])) for k in hit]


def _arm_end(pts: np.ndarray) -> int:
    """The last point of the longest run from ``pts[0]`` whose points all lie within `STRAIGHT` of its chord."""
    rel = pts - pts[0]
    chord = np.hypot(rel[:, 0], rel[:, 1])
    unit = rel / np.where(chord > 0, chord, 1.0)[:, None]
    off = np.abs(rel[None, :, 0] * unit[:, None, 1] - rel[None, :, 1] * unit[:, None, 0])
    off = np.where(np.arange(len(pts))[None, :] <= np.arange(len(pts))[:, None], off, 0.0)
    ok = off.max(axis=1) <= STRAIGHT * np.where(chord > 0, chord, np.inf)
    ok[:2] = True
    bad = np.flatnonzero(~ok)
    return int(bad[0] - 1) if len(bad) else len(pts) - 1


def shape(unit: np.ndarray) -> dict[str, float] | None:
    """The features above of a stroke at unit size, or None where it does not cross itself once with long tails."""
    if self_crossings(unit) != 1:
        return None
    pts = sg.smooth(sg.resample(unit, POINTS))
    found = _crossings(pts)
    if len(found) != 1:
        return None
    i, j, t = found[0]
    cross = pts[i] + t * (pts[i + 1] - pts[i])
    length = sg.path_length(pts)
    tail1, tail2 = float(np.hypot(*(cross - pts[0]))), float(np.hypot(*(cross - pts[-1])))
    a, b = _arm_end(pts), POINTS - 1 - _arm_end(pts[::-1])
    if min(tail1, tail2) < TAIL * length or b - a < 4:
        return None
    arm1, arm2 = float(np.hypot(*(pts[a] - pts[0]))), float(np.hypot(*(pts[b] - pts[-1])))
    h1, h2 = (pts[a] - pts[0]) / max(arm1, 1e-12), (pts[-1] - pts[b]) / max(arm2, 1e-12)
    f1, f2 = tail1 / max(arm1, 1e-12), tail2 / max(arm2, 1e-12)
    conn = pts[a:b + 1]
    th = np.abs(sg.turning(conn))
    along = sg.along(conn)
    middle = (along[1:-1] >= 0.3 * along[-1]) & (along[1:-1] <= 0.7 * along[-1])
    chord = pts[b] - pts[a]
    span = float(np.hypot(*chord))
    across = ((conn - pts[a]) @ np.array([chord[1], -chord[0]])) / max(span, 1e-12)
    d1, d2 = pts[a] - cross, pts[b] - cross
    bis = d1 / np.hypot(*d1) + d2 / np.hypot(*d2)
    bis /= np.hypot(*bis)
    side = np.array([bis[1], -bis[0]])
    loop = (pts[i + 1:j + 1] - cross) @ side
    spread = abs(float(d1 @ side)) + abs(float(d2 @ side))
    return {"fmax": max(f1, f2), "fmin": min(f1, f2),
            "ang": math.degrees(math.acos(max(-1.0, min(1.0, float(h1 @ h2))))),
            "mid": float(th[middle].sum() / max(float(th.sum()), 1e-12)),
            "wide": float(loop.max() - loop.min()) / max(spread, 1e-12),
            "depth": float(np.abs(across).max()) / max(span, 1e-12),
            "conn": float(along[-1] / length)}


def main() -> None:
    """Print the seven misses' features, then what the box round them takes at each margin."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--margins", default="0,0.1,0.2,0.3,0.5,1")
    parser.add_argument("--near", type=float, default=0.6, help="list other strokes within this many ranges")
    parser.add_argument("--pens", type=float, default=None, help="count the pen models' marks in the box so grown")
    args = parser.parse_args()
    import re
    rows = []
    for _, points, times, where in _kept([p for p in SETS if p.is_file()], True):
        a = sg.drop_duplicates(np.asarray(points, dtype=float))
        scale = float(np.abs(a - a.mean(axis=0)).max()) if len(a) > 2 else 0.0
        if scale == 0.0:
            continue
        f = shape((a - a.mean(axis=0)) / scale)
        if f is None or recognize_stroke(points, times, learned=False).kind not in ("curve", "arc"):
            continue
        rows.append((where, f, bool(re.search(MISSES, where))))
    misses = [f for _, f, miss in rows if miss]
    lo = {k: min(f[k] for f in misses) for k in KEYS}
    hi = {k: max(f[k] for f in misses) for k in KEYS}
    print(f"{len(rows)} strokes cross themselves once and are read as curves or arcs by the rules; "
          f"{len(misses)} are the misses")
    print("misses' ranges: " + ", ".join(f"{k} {lo[k]:.3f}-{hi[k]:.3f}" for k in KEYS))
    for margin in (float(m) for m in args.margins.split(",")):
        took = [w for w, f, miss in rows if not miss and all(
            lo[k] - margin * (hi[k] - lo[k]) <= f[k] <= hi[k] + margin * (hi[k] - lo[k]) for k in KEYS)]
        print(f"margin {margin:g}: takes {len(took)}" + "".join(f"\n  {w}" for w in took))
    print(f"other strokes within {args.near:g} of a range of the box (how far out, by feature):")
    for where, f, miss in rows:
        out = {k: max(lo[k] - f[k], f[k] - hi[k], 0.0) / (hi[k] - lo[k]) for k in KEYS}
        if not miss and max(out.values()) < args.near:
            print(f"  {max(out.values()):.2f} {where} " + " ".join(f"{k} {v:.2f}" for k, v in out.items() if v > 0))
    if args.pens is not None:
        _pens(lo, hi, args.pens)


def _pens(lo: dict[str, float], hi: dict[str, float], margin: float) -> None:
    """How many of each pen-model family's marks (tuning seeds, every pen) the box grown by ``margin`` takes."""
    sys.path.insert(0, str(ROOT / "tests"))
    from bench_bracket_habits import PENS, drawn
    from bench_open_marks import TUNING_SEEDS
    from penmodels import pigtail_habits, x_habits

    families = {"round-side-x": x_habits.FAMILIES["round-side-x"], **pigtail_habits.FAMILIES}
    for family in families:
        taken = total = 0
        for pen in PENS:
            for seed in TUNING_SEEDS:
                a = sg.drop_duplicates(np.asarray([p[:2] for p in drawn(family, pen, seed, families)], dtype=float))
                f = shape((a - a.mean(axis=0)) / float(np.abs(a - a.mean(axis=0)).max()))
                total += 1
                taken += f is not None and all(
                    lo[k] - margin * (hi[k] - lo[k]) <= f[k] <= hi[k] + margin * (hi[k] - lo[k]) for k in KEYS)
        print(f"pen models, {family}: the box grown by {margin:g} takes {taken} of {total}")


if __name__ == "__main__":
    main()
