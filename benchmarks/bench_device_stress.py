"""Benchmark: how the way a device samples a stroke moves recognition — the design sources' strokes transformed as a
trackpad, a mouse, a finger or a tkinter canvas would give them (transformed strokes, not people).

Usage: .venv/bin/python benchmarks/bench_device_stress.py SET [SET ...] [--every K] [--only NAME,...] [--json OUT]

Reads the sets as `bench_generalisation` does (`scored_rows`: the third to fifth held-back groups stay out) and
keeps one stroke in ``K`` (by a hash of its file and label: the same strokes every run). Each transform changes one
thing a device does (`TRANSFORMS`): whole pixels at a small size, repeated points, a coarse event rate (every 15-30 ms;
8-25 events on a fast stroke), uneven
bursts of events, a mouse's axis-aligned stair steps, a finger's blunted corners and wide arcs, ends carried past
where they were meant to stop, no times or times only at the ends; `COMBINED` chains a few as one device would;
`MORE` (`device_habits`) adds pointer acceleration, a finger's lift and start, slow corners, a touch grid, y stored
upward and tiny mouse drawings. Each stroke's random choices are seeded by its file, label and the transform's name:
deterministic. Every stroke is read once a variant, and both readings are kept: the rules' (before the learned
ranker) and the shipped recogniser's. Prints Markdown: per set and per class, the accuracy of each variant beside
the strokes as drawn. A figure here is a figure on transformed strokes, not on people using those devices.
"""

from __future__ import annotations

import argparse
import json
import sys
import zlib
from collections import defaultdict
from collections.abc import Callable
from pathlib import Path

import numpy as np
from bench_generalisation import is_held_back_new, scored_rows
from bench_recognition import machine, table
from device_habits import TRANSFORMS_MORE, acceleration, lift_hook, lift_pause, start_blob, touch_grid
from label_kinds import read_table
from stroke_sets import Row, read_sets, source_of

from physink_tui.scene.recognition import ranker
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.recognize import recognize_stroke

Stroke = tuple[np.ndarray, np.ndarray | None]
"""Points (n x 2) and their times in seconds (None where the device gave none)."""
Transform = Callable[[Stroke, np.random.Generator], Stroke]


def _arc(pts: np.ndarray) -> np.ndarray:
    return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])


def _at(pts: np.ndarray, times: np.ndarray, when: np.ndarray) -> np.ndarray:
    """The pen's position at ``when`` (linear between samples; repeated times keep their first point)."""
    keep = np.concatenate([[True], np.diff(times) > 0])
    return np.column_stack([np.interp(when, times[keep], pts[keep, k]) for k in range(2)])


def _clock(stroke: Stroke) -> np.ndarray:
    """The stroke's times, or an even 10 ms a point where it has none (a device samples in time)."""
    pts, t = stroke
    if t is not None and t[-1] > t[0]:
        return np.maximum.accumulate(t)
    return np.arange(len(pts)) * 0.01


def _size(pts: np.ndarray) -> float:
    return float(np.ptp(pts, axis=0).max())


def pixels(low: float, high: float) -> Transform:
    """Scaled to ``low``-``high`` px across and rounded to whole pixels (the grid's phase drawn at random), repeats
    kept: a trackpad or a tkinter canvas at a small size."""
    def change(stroke: Stroke, rng: np.random.Generator) -> Stroke:
        pts, t = stroke
        scale = rng.uniform(low, high) / max(_size(pts), 1e-9)
        return np.round(pts * scale + rng.uniform(0, 1, 2)), t
    return change


def duplicates(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A third of the points repeated once or twice (an event sent again with the same position and time)."""
    pts, t = stroke
    times = np.where(rng.random(len(pts)) < 1 / 3, rng.integers(2, 4, len(pts)), 1)
    return np.repeat(pts, times, axis=0), None if t is None else np.repeat(t, times)


def coarse(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """An event every 15-30 ms (one rate a stroke), the last at pen-up (a stroke without times taken as sampled
    every 10 ms)."""
    pts, t = stroke
    clock = _clock(stroke)
    when = np.arange(clock[0], clock[-1], rng.uniform(0.015, 0.030))
    when = np.concatenate([when, [clock[-1]]]) if clock[-1] - when[-1] > 1e-9 else when
    return _at(pts, clock, when), when if t is not None else None


def events(n: int) -> Transform:
    """``n`` events evenly in time over the stroke, the first at pen-down and the last at pen-up."""
    def change(stroke: Stroke, rng: np.random.Generator) -> Stroke:
        pts, t = stroke
        clock = _clock(stroke)
        when = np.linspace(clock[0], clock[-1], n)
        return _at(pts, clock, when), when if t is not None else None
    return change


def fast(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """8-25 events evenly in time: a stroke drawn in 0.2-0.5 s at an event every 15-30 ms."""
    return events(int(rng.integers(8, 26)))(stroke, rng)


def bursts(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """Events in bursts: 2-5 events 2-4 ms apart, then a 25-60 ms gap (a busy event loop)."""
    pts, _ = stroke
    t = _clock(stroke)
    when, now = [t[0]], t[0]
    while now < t[-1]:
        for _ in range(int(rng.integers(2, 6))):
            now += rng.uniform(0.002, 0.004)
            when.append(now)
        now += rng.uniform(0.025, 0.060)
        when.append(now)
    out = np.minimum(np.array(when), t[-1])
    out = np.concatenate([out[out < t[-1]], [t[-1]]])
    return _at(pts, t, out), out if stroke[1] is not None else None


def stairs(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A slow mouse at 60-200 px across: the path in whole pixels, each pixel step on one axis at a time (a diagonal
    becomes a staircase); times follow the path."""
    pts, _ = stroke
    t = _clock(stroke)
    pts = pts * (rng.uniform(60, 200) / max(_size(pts), 1e-9)) + rng.uniform(0, 1, 2)
    s = _arc(pts)
    fine = np.linspace(0.0, s[-1], max(int(s[-1] / 0.5), 2))
    keep = np.concatenate([[True], np.diff(s) > 0])
    grid = np.round(np.column_stack([np.interp(fine, s[keep], pts[keep, k]) for k in range(2)]))
    clock = np.interp(fine, s[keep], t[keep])
    out, when = [grid[0]], [clock[0]]
    for p, c in zip(grid[1:], clock[1:], strict=True):
        q = out[-1]
        if p[0] == q[0] and p[1] == q[1]:
            continue
        if p[0] != q[0] and p[1] != q[1]:  # x first, then y
            out.append(np.array([p[0], q[1]]))
            when.append((when[-1] + c) / 2)
        out.append(p)
        when.append(c)
    return np.array(out), np.array(when) if stroke[1] is not None else None


def finger(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """A finger at 150-400 px across: the path smoothed along its length over 3-6 % of its diagonal (corners blunted
    to arcs), ends kept where they were."""
    pts, t = stroke
    pts = pts * (rng.uniform(150, 400) / max(_size(pts), 1e-9))
    s = _arc(pts)
    if s[-1] == 0:
        return pts, t
    sigma = rng.uniform(0.03, 0.06) * float(np.hypot(*np.ptp(pts, axis=0)))
    n = max(len(pts), 64)
    fine = np.linspace(0.0, s[-1], n)
    keep = np.concatenate([[True], np.diff(s) > 0])
    even = np.column_stack([np.interp(fine, s[keep], pts[keep, k]) for k in range(2)])
    step = fine[1] - fine[0]
    half = int(3 * sigma / step) + 1
    kernel = np.exp(-0.5 * (np.arange(-half, half + 1) * step / sigma) ** 2)
    padded = np.concatenate([np.repeat(even[:1], half, axis=0), even, np.repeat(even[-1:], half, axis=0)])
    smooth = np.column_stack([np.convolve(padded[:, k], kernel / kernel.sum(), mode="valid") for k in range(2)])
    smooth[0], smooth[-1] = even[0], even[-1]
    when = None if t is None else np.interp(fine, s[keep], _clock(stroke)[keep])
    return smooth, when


def overshoot(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """Both ends carried on along their last direction for 3-8 % of the diagonal (the hand not stopping in time)."""
    pts, t = stroke
    diag = float(np.hypot(*np.ptp(pts, axis=0)))
    s = _arc(pts)
    if s[-1] == 0 or diag == 0:
        return pts, t
    tt = _clock(stroke)
    out, when = [pts], [tt]
    for end in (0, -1):
        far = s[-1] - s if end == -1 else s
        j = int(np.argmax(far >= min(0.05 * s[-1], 0.05 * diag)))  # a point about 5 % along from this end
        d = pts[end] - pts[j]
        if np.hypot(*d) == 0:
            continue
        d = d / np.hypot(*d)
        extra = pts[end] + np.outer(np.linspace(0.2, 1.0, 5), d) * rng.uniform(0.03, 0.08) * diag
        dt = np.linspace(0.004, 0.02, 5)
        if end == 0:
            out.insert(0, extra[::-1])
            when.insert(0, tt[0] - dt[::-1])
        else:
            out.append(extra)
            when.append(tt[-1] + dt)
    return np.concatenate(out), np.concatenate(when) if t is not None else None


def no_times(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """The device gives no times."""
    return stroke[0], None


def end_times(stroke: Stroke, rng: np.random.Generator) -> Stroke:
    """Times only at pen-down and pen-up, the points between spread evenly (what a caller fills in)."""
    pts, t = stroke
    if t is None:
        return stroke
    return pts, np.linspace(t[0], t[-1], len(pts))


def chain(*steps: Transform) -> Transform:
    def change(stroke: Stroke, rng: np.random.Generator) -> Stroke:
        for step in steps:
            stroke = step(stroke, rng)
        return stroke
    return change


TRANSFORMS: dict[str, Transform] = {
    "pixels 30-80 px": pixels(30, 80),
    "pixels 80-150 px": pixels(80, 150),
    "repeated points": duplicates,
    "events every 15-30 ms": coarse,
    "8-25 events (fast)": fast,
    "event bursts": bursts,
    "mouse stairs": stairs,
    "finger": finger,
    "overshoot": overshoot,
    "no times": no_times,
    "times at the ends": end_times,
}
COMBINED: dict[str, Transform] = {
    "trackpad: 30-80 px, 8-25 events, repeats": chain(pixels(30, 80), fast, duplicates),
    "mouse: stairs, bursts, repeats": chain(stairs, bursts, duplicates),
    "touch: finger, overshoot, events every 15-30 ms": chain(finger, overshoot, coarse),
    "tkinter: 30-80 px, no times": chain(pixels(30, 80), no_times),
}
MORE: dict[str, Transform] = {
    **TRANSFORMS_MORE,
    "tiny mouse: pixels 20-40 px": pixels(20, 40),
    "trackpad 2: acceleration, 8-25 events, start blob, lift hook": chain(acceleration, fast, start_blob, lift_hook),
    "touch 2: start blob, touch grid, events every 15-30 ms, lift pause": chain(start_blob, touch_grid, coarse,
                                                                               lift_pause),
    "tiny mouse 2: 20-40 px, bursts, repeats": chain(pixels(20, 40), bursts, duplicates),
}
"""The second device pass's transforms (`device_habits`) and combinations; `TRANSFORMS` and `COMBINED` stay as the
sixth pass left them, so its figures stay comparable."""


def read(stroke: Stroke) -> tuple[Recognition, Recognition]:
    """The rules' reading (what the learned ranker was given, or the answer where it was not asked) and the
    shipped recogniser's, from one call."""
    seen: list[Recognition] = []
    shipped = ranker.rerank

    def spy(points, times, noise, found, *rest):  # type: ignore[no-untyped-def]
        seen.append(found)
        return shipped(points, times, noise, found, *rest)

    ranker.rerank = spy
    try:
        pts, t = stroke
        found = recognize_stroke(pts.tolist(), None if t is None else t.tolist())
    finally:
        ranker.rerank = shipped
    return (seen[0] if seen else found), found


def as_stroke(row: Row) -> Stroke:
    pts = row["strokes"][0]
    xy = np.array([p[:2] for p in pts], dtype=float)
    timed = all(len(p) > 2 and p[2] is not None for p in pts)
    return xy, np.array([p[2] / 1000 for p in pts], dtype=float) if timed else None


def score(rows: list[Row], change: Transform | None, name: str) -> np.ndarray:
    """Per row: (rules right, shipped right)."""
    out = np.zeros((len(rows), 2), dtype=bool)
    for i, row in enumerate(rows):
        stroke = as_stroke(row)
        if change is not None:
            rng = np.random.default_rng(zlib.crc32(f"{row['file']}|{row['label']}|{name}".encode()))
            stroke = change(stroke, rng)
        rules, shipped = read(stroke)
        out[i] = (rules.kind in row["accepts"], shipped.kind in row["accepts"])
    return out


def report(rows: list[Row], results: dict[str, np.ndarray]) -> None:
    names = list(results)
    sets = np.array([r["source"] for r in rows])
    labels = read_table()
    classes = np.array([labels.label_class(r["source"], r["label"]) for r in rows])
    base = results["as drawn"]
    print("### Per variant, pooled (rules alone / shipped)\n")
    out = []
    for name in names:
        got = results[name]
        out.append([name, len(rows), f"{100 * got[:, 0].mean():.2f}", f"{100 * got[:, 1].mean():.2f}",
                    f"{100 * (got[:, 1].mean() - base[:, 1].mean()):+.2f}"])
    print(table(["variant", "strokes", "rules %", "shipped %", "shipped change (points)"], out) + "\n")
    for title, keys, col in (("per set, shipped", sorted(set(sets)), sets),
                             ("per class, shipped", sorted(set(classes)), classes),
                             ("per class, rules alone", sorted(set(classes)), classes)):
        k = 0 if "rules" in title else 1
        print(f"### Change from as drawn, {title} (points; as drawn: % of strokes)\n")
        body = []
        for key in keys:
            sel = col == key
            cells = [f"{100 * base[sel, k].mean():.1f} ({int(sel.sum())})"]
            cells += [f"{100 * (results[n][sel, k].mean() - base[sel, k].mean()):+.1f}" for n in names[1:]]
            body.append([key, *cells])
        print(table(["", "as drawn", *names[1:]], body) + "\n")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+", help=".jsonl files or set folders (never the held-back groups')")
    ap.add_argument("--every", type=int, default=3, help="keep one stroke in K (by a hash: the same ones every run)")
    ap.add_argument("--only", default="", help="variant names, comma- or (names with commas) semicolon-separated")
    ap.add_argument("--json", type=Path, help="also write each variant's per-row results here")
    args = ap.parse_args()
    rows = read_sets(args.sets, "bench_device_stress")
    kept, _ = scored_rows(rows)
    kept = [r for r in kept if not is_held_back_new(source_of(r, "person"))
            and zlib.crc32(f"{r['file']}|{r['label']}".encode()) % args.every == 0]
    variants: dict[str, Transform | None] = {"as drawn": None, **TRANSFORMS, **COMBINED, **MORE}
    if args.only:
        wanted = set(args.only.split(";" if ";" in args.only else ","))  # ';' for names with commas
        variants = {n: c for n, c in variants.items() if n == "as drawn" or n in wanted}
    print(f"## Device stress, transformed strokes, not people ({machine()})\n")
    print(f"{len(kept)} strokes (one in {args.every}) of " + ", ".join(sorted({r['source'] for r in kept})) + ".\n")
    results = {name: score(kept, change, name) for name, change in variants.items()}
    report(kept, results)
    if args.json:
        data = defaultdict(dict)
        for name, got in results.items():
            data[name] = {"rules": got[:, 0].astype(int).tolist(), "shipped": got[:, 1].astype(int).tolist()}
        args.json.write_text(json.dumps({"files": [r["file"] for r in kept], **data}), encoding="utf-8")


if __name__ == "__main__":
    sys.exit(main())
