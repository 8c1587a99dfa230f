"""Measures `rounded_chevrons`' tests on every stroke `open_shapes.classify_open` reads as a curve or an arc (issue 25).

Usage: PYTHONPATH=<tree>:<tree>/benchmarks python benchmarks/chevron_margins.py GROUP OUT.jsonl [EVERY [FAMILIES]]
GROUP: st (the sign set's ST5022 writers), design or fourth (those groups' scored strokes, as tools/misses.py reads
them), pens-tune (the pen models' open marks, `bench_open_marks.PENS`, tuning seeds 0-29, timed and not), pens-extra
(extra tuning seeds 2000-2599, every EVERY-th, untimed; FAMILIES: only these, comma-separated).
One JSON row per `classify_open` call that reads a curve or an arc, or whose `rounded_chevron` exit fires
("kind_open": "chevron"): where the stroke came from, its label, the final reading, and for the stroke as judged
("w_", when it turns one way) and once an end swung back 30 degrees or more is cut ("c_", as branch
wt-chevrons3-rule cut it, the point's share on the whole path) `rounded_chevrons`' measures (share, straight, turn,
conc, reach) and three more (asym: the outer sides' angles to the chord apart; fullbow: each whole side's bow;
tipturn: the share of the turn within 10 % of the path about the point; sides: the outer parts' lengths' ratio).
Issue 25, session 39 (docs/BENCHMARKS.md, wt-chevrons4). Never reads the held-back sets or held seeds.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np

from physink_tui.scene.recognition import open_shapes, shape_turning
from physink_tui.scene.recognition import rounded_chevrons as rc
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

SWUNG = 30.0


def unswung(work: np.ndarray, coarse: np.ndarray) -> tuple[np.ndarray | None, float, float, float]:
    """``work`` without the ends swung back against its main way, resampled; the path cut before it, the whole
    path, the most an end swung back (degrees)."""
    th = np.degrees(coarse)
    way = 1.0 if float(th.sum()) >= 0.0 else -1.0
    half = (len(th) + 1) // 2
    cuts, swing = [], 0.0
    for turns in (way * th, way * th[::-1]):
        done = np.concatenate([[0.0], np.add.accumulate(turns)])[:half + 1]
        k = int(done.argmin())
        swing = max(swing, -float(done[k]))
        cuts.append(k / (len(th) + 1) if -float(done[k]) >= SWUNG else 0.0)
    if cuts == [0.0, 0.0]:
        return None, 0.0, 0.0, swing
    along = sg.along(work)
    length = float(along[-1])
    a = int(np.searchsorted(along, cuts[0] * length))
    b = int(np.searchsorted(along, (1.0 - cuts[1]) * length, side="right"))
    if b - a < 12:
        return None, 0.0, 0.0, swing
    return sg.resample(work[a:b], len(work)), float(along[a]), length, swing


def measures(work: np.ndarray, before: float = 0.0, whole: float | None = None) -> dict[str, float] | None:
    """`rounded_chevron`'s measures of ``work`` (share on the ``whole`` path where given)."""
    found = rc.point_and_sides(work)
    if found is None:
        return None
    k, along, first, second = found
    start, end, length = work[0], work[-1], float(along[-1])
    d = end - start
    share = (before + along[k]) / (length if whole is None else whole)
    straight = max(sg.chord_deviation(first), sg.chord_deviation(second))
    u, v = first[-1] - first[0], second[-1] - second[0]
    turn = abs(math.degrees(math.atan2(float(u[0] * v[1] - u[1] * v[0]), float(u @ v))))
    conc = sg.sharpest_turn(work, rc.BEND_SPAN * length) / turn if turn > 0 else 0.0
    reach = math.inf
    try:
        s = np.linalg.solve(np.array([u, -v]).T, second[0] - first[0])[0]
        corner = first[0] + s * u
        shorter = min(float(np.hypot(*(corner - start))), float(np.hypot(*(corner - end))))
        if shorter > 0:
            reach = float(np.hypot(*(corner - work[k]))) / shorter
    except np.linalg.LinAlgError:
        pass
    chord = math.atan2(float(d[1]), float(d[0]))
    a1 = abs(math.degrees(math.remainder(math.atan2(float(u[1]), float(u[0])) - chord, 2 * math.pi)))
    a2 = abs(math.degrees(math.remainder(math.atan2(float(v[1]), float(v[0])) - chord, 2 * math.pi)))
    th = np.degrees(sg.turning(work))
    total = abs(float(th.sum())) or 1e-9
    win = np.abs(along[1:-1] - along[k]) <= 0.1 * length
    return {"share": share, "straight": straight, "turn": turn, "conc": conc, "reach": reach,
            "asym": abs(a1 - a2), "fullbow": max(sg.chord_deviation(work[:k + 1]) if k >= 2 else 0.0,
                                                 sg.chord_deviation(work[k:]) if len(work) - k >= 3 else 0.0),
            "tipturn": abs(float(th[win].sum())) / total if len(th) == len(work) - 2 else math.nan,
            "sides": min(sg.path_length(first), sg.path_length(second)) / max(sg.path_length(first),
                                                                               sg.path_length(second), 1e-9)}


RECORD: list[dict[str, object]] = []
TOOK: list[bool] = [False]


def _took(original):
    def rounded_chevron(work, noise):
        found = original(work, noise)
        TOOK[0] = found is not None
        return found
    return rounded_chevron


def _probe(original):
    def classify_open(work, noise, *args, **kwargs):
        TOOK[0] = False
        found = original(work, noise, *args, **kwargs)
        if (found.kind in ("curve", "arc") or TOOK[0]) and len(work) >= 12:
            coarse = shape_turning.coarse_turning(work, noise)
            row: dict[str, object] = {"kind_open": "chevron" if TOOK[0] else found.kind,
                                      "lobes": len(sf.turn_lobes(coarse)),
                                      "size": sg.path_length(work) / max(noise, 1e-9)}
            if row["lobes"] == 1:
                m = measures(work)
                if m:
                    row.update({f"w_{k}": v for k, v in m.items()})
            if row["lobes"] <= 3:
                body, before, whole, swing = unswung(work, coarse)
                row["swing"] = swing
                if body is not None and len(sf.turn_lobes(shape_turning.coarse_turning(body, noise))) == 1:
                    m = measures(body, before, whole)
                    if m:
                        row.update({f"c_{k}": v for k, v in m.items()})
                        row["cutshare"] = 1.0 - sg.path_length(body) / whole
            RECORD.append(row)
        return found
    return classify_open


open_shapes.classify_open = _probe(open_shapes.classify_open)
rc.rounded_chevron = _took(rc.rounded_chevron)


def read(points, times) -> str:
    RECORD.clear()
    return recognize_stroke(points, times).kind


def sets_rows(group: str):
    """(source, label, stroke, times) of the group's strokes."""
    if group == "st":
        for line in open(Path.home() / ".cache/physink/public-sets/sign.jsonl"):
            row = json.loads(line)
            if "ST5022" not in row["device"] or len(row["strokes"]) != 1:
                continue
            yield f"sign:{row['subject']}", row["label"], row["file"], row["strokes"][0]
    else:
        from bench_generalisation import held_back_new, scored_rows
        from stroke_sets import read_sets, source_of
        home = Path.home() / ".cache/physink"
        paths = [Path("/work/shared/data/strokes/dollar1-dev.jsonl"), home / "student-sets/itt.jsonl"] + [
            home / f"public-sets/{n}.jsonl" for n in ("itt-more", "hcira", "mmg", "ahmadosama", "gtiwari")]
        if group == "fourth":
            paths = [home / "public-sets/quickdraw.jsonl", home / "public-sets/tutorboard.jsonl"]
        rows = read_sets([p for p in paths if p.exists()], "chevron_margins")
        kept, _ = scored_rows(rows, fourth=group == "fourth")
        hb = held_back_new(kept)
        for row in kept:
            src = source_of(row, "person")
            if src in hb:
                continue
            yield src, row["label"], row.get("file") or row.get("id") or row.get("key"), row["strokes"][0]


def main() -> None:
    group, out = sys.argv[1], sys.argv[2]
    every = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    with open(out, "w") as fh:
        def emit(src, label, ident, kind, timed):
            for i, row in enumerate(RECORD):
                fh.write(json.dumps({"src": src, "label": label, "id": ident, "kind": kind, "timed": timed,
                                     "call": i, **row}) + "\n")
        if group in ("st", "design", "fourth"):
            for src, label, ident, stroke in sets_rows(group):
                times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
                kind = read([p[:2] for p in stroke], times)
                emit(src, label, ident, kind, times is not None)
            return
        import bench_open_marks as bom
        from penmodels import hurried_marks, mark_habits, math_marks, open_marks, paren_habits
        fams = {}
        for mod in (paren_habits, math_marks, hurried_marks, mark_habits, open_marks):
            fams.update(mod.FAMILIES)
        if len(sys.argv) > 4:  # only these families (comma-separated)
            fams = {f: fams[f] for f in sys.argv[4].split(",")}
        seeds, timings = ((range(30), (True, False)) if group == "pens-tune"
                          else (range(2000, 2600, every), (False,)))
        for fam, make in fams.items():
            for pen, draw in bom.PENS.items():
                for seed in seeds:
                    stroke = draw(make(seed), seed)
                    for timed in timings:
                        kind = read([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None)
                        emit(f"pen:{fam}:{pen}", fam, seed, kind, timed)
            fh.flush()


if __name__ == "__main__":
    main()
