"""Benchmark: one-corner marks (chevrons, ticks, checks, v's, carets, L corners) and straight lines, as drawn, under
the device transforms and drawn by the hurried pen, with a session's changes undone one at a time (transformed
strokes and pen-model drawings, not people).

Usage: .venv/bin/python benchmarks/bench_one_corner.py SET [SET ...] [--every K] [--without landing|refit]

Reads the sets as `bench_generalisation` does (`scored_rows`: the held-back groups stay out) and keeps the labels of
`CLASSES`. ``--without landing`` reads every stroke with `landing.settled` keeping every point (session 16's landing
rule undone); ``--without refit`` with the ranker model main had before session 16 (``f0d407d``'s `ranker_model`,
read from git, same features) and without its guard `ranker.kept_curve` (the refit undone). To read another revision
as a whole, run this script with ``PYTHONPATH`` set to that revision's exported tree. Prints per variant the strokes
misread, chevron-like marks and straight lines apart, as drawn, per device transform (one stroke in ``K``, seeded by
file, label and transform as `bench_device_stress` seeds them) and by the hurried pen (chevrons, checks and lines,
40 seeds each); then the misread strokes as drawn per (set, label).
"""

from __future__ import annotations

import argparse
import math
import random
import subprocess
import sys
import zlib
from collections import Counter
from pathlib import Path

import numpy as np
from bench_device_stress import COMBINED, MORE, TRANSFORMS, as_stroke
from bench_generalisation import is_held_back_new, scored_rows
from stroke_sets import Row, read_sets, source_of

import physink_tui
from physink_tui.scene.recognition import ranker
from physink_tui.scene.recognition.recognize import recognize_stroke

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
CLASSES = {
    "dollar1": ("v", "caret", "check"), "itt": ("v", "caret", "check"), "hcira": ("v", "caret", "check"),
    "ahmadosama": ("Tick", "GreaterThan", "LessThan", "BottomLeftCorner", "UpperLeftCorner", "UpperRightCorner"),
    "gtiwari": ("DownAndLeft", "DownAndRight", "LeftAndDown", "RightAndDown", "GreaterThanSign",
                "GreaterThanSignOppositeDirn", "LessThanSign", "LessThanSignOppositeDirn",
                "StrtLine_LeftDown_To_RightUp", "StrtLine_LeftUp_To_RightDown", "StrtLine_RightDown_To_LeftUp",
                "StrtLine_RightUp_To_LeftDown", "LeftOnly", "RightOnly"),
}
"""The labels read: one-corner marks (two straight segments) and, in gtiwari, straight lines."""
BEFORE_SESSION_16 = "f0d407d"


def straight(label: str) -> bool:
    return label.startswith("StrtLine") or label in ("LeftOnly", "RightOnly")


def undo(change: str) -> None:
    """Undo one of session 16's changes in this process (`--without`)."""
    if change == "landing":
        from physink_tui.scene.recognition import landing

        landing.settled = lambda pts, diag, noise: np.ones(len(pts), dtype=bool)
    elif change == "refit":
        text = subprocess.run(["git", "show", f"{BEFORE_SESSION_16}:physink_tui/scene/recognition/ranker_model.py"],
                              cwd=ROOT, capture_output=True, text=True, check=True).stdout
        space: dict[str, object] = {}
        exec(compile(text, "ranker_model@" + BEFORE_SESSION_16, "exec"), space)  # a data module: one dict
        model = ranker.model_from(space["MODEL"], "ranker_model@" + BEFORE_SESSION_16)
        ranker.shipped_model = lambda: model  # type: ignore[assignment]
        ranker.kept_curve = lambda found, sparse: False


def rows(paths: list[Path]) -> list[Row]:
    kept, _ = scored_rows(read_sets(paths, "bench_one_corner"))
    return [r for r in kept if not is_held_back_new(source_of(r, "person")) and r["label"] in CLASSES.get(
        str(r["source"]), ())]


def hurried() -> list[tuple[str, bool, list[tuple[float, float, float]]]]:
    """(what, is a line, stroke) for 40 seeds of a chevron (arms 0.85-1 of each other), a check (short arm 0.3-0.5 of
    the long one), opening 35-100 degrees, and a line; 60-220 px, any angle; drawn by the hurried pen."""
    from penmodels.hurried import single_strokes  # type: ignore[import-not-found]
    from penmodels.shapes import Path as PenPath  # type: ignore[import-not-found]

    out = []
    for seed in range(40):
        rng = random.Random(f"one-corner:{seed}")
        size = rng.uniform(60, 220)
        for what in ("chevron", "check", "line"):
            a = rng.uniform(0, 2 * math.pi)
            d1 = np.array([math.cos(a), math.sin(a)])
            vertices: tuple[tuple[float, ...], ...]
            if what == "line":
                vertices = ((600.0, 400.0), tuple(map(float, np.array([600.0, 400.0]) + d1 * size)))
            else:
                b = a + math.radians(rng.uniform(35, 100))
                short = size * (rng.uniform(0.85, 1.0) if what == "chevron" else rng.uniform(0.3, 0.5))
                d2 = np.array([math.cos(b), math.sin(b)])
                vertices = (tuple(map(float, np.array([600.0, 400.0]) + d1 * short)), (600.0, 400.0),
                            tuple(map(float, np.array([600.0, 400.0]) + d2 * size)))
            strokes = single_strokes(PenPath(vertices), seed=seed)
            if len(strokes) == 1:
                out.append((what, what == "line", strokes[0]))
    return out


def _kind(pts: np.ndarray, t: np.ndarray | None) -> str | None:
    return recognize_stroke(pts.tolist(), None if t is None else t.tolist()).kind


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+", help=".jsonl files or set folders (never the held-back groups')")
    ap.add_argument("--every", type=int, default=3, help="device transforms: one stroke in K (by a hash)")
    ap.add_argument("--without", choices=("landing", "refit"), help="undo one of session 16's changes")
    args = ap.parse_args()
    if args.without:
        undo(args.without)
    kept = rows(args.sets)
    print(f"## One-corner marks and straight lines ({physink_tui.__file__}; without: {args.without or 'nothing'})\n")
    wrong_drawn: Counter[tuple[str, str]] = Counter()
    drawn: Counter[str] = Counter()
    for r in kept:
        miss = _kind(*as_stroke(r)) not in r["accepts"]
        wrong_drawn[(str(r["source"]), str(r["label"]))] += miss
        drawn["line" if straight(str(r["label"])) else "mark"] += miss
    print("| variant | one-corner marks misread | straight lines misread |\n|---|---:|---:|")
    marks = sum(not straight(str(r["label"])) for r in kept)
    print(f"| as drawn ({len(kept)} strokes; {marks} marks) | {drawn['mark']} | {drawn['line']} |")
    sub = [r for r in kept if zlib.crc32(f"{r['file']}|{r['label']}".encode()) % args.every == 0]
    pooled: Counter[str] = Counter()
    for name, change in {**TRANSFORMS, **COMBINED, **MORE}.items():
        got: Counter[str] = Counter()
        for r in sub:
            rng = np.random.default_rng(zlib.crc32(f"{r['file']}|{r['label']}|{name}".encode()))
            got["line" if straight(str(r["label"])) else "mark"] += _kind(*change(as_stroke(r), rng)) not in r[
                "accepts"]
        pooled += got
        print(f"| {name} ({len(sub)} strokes) | {got['mark']} | {got['line']} |")
    print(f"| all transforms pooled | {pooled['mark']} | {pooled['line']} |")
    pen: Counter[str] = Counter()
    for what, is_line, stroke in hurried():
        kind = recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke]).kind
        pen[what] += kind != ("line" if is_line else "polyline")
    print(f"| hurried pen, 40 seeds each (chevron / check / line) | {pen['chevron']} / {pen['check']} | "
          f"{pen['line']} |\n")
    print("Misread as drawn, per set and label: " + "; ".join(
        f"{s} {label} {n}" for (s, label), n in sorted(wrong_drawn.items()) if n))


if __name__ == "__main__":
    main()
