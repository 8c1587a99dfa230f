"""Benchmark: whether this tree reads strokes exactly as another revision does: a speed change must change no reading.

Usage: .venv/bin/python benchmarks/compare_readings.py SET [SET ...] [--baseline main] [--tolerance 0] [--noise auto]
       [--fourth] [--list]

Every single-stroke sample of each SET (a .jsonl file or a folder `stroke_sets` reads) is recognised twice by each
tree: as recorded (times in seconds where the set has them, as `bench_generalisation` passes them) and resampled to
200 points (as `bench_side_by_side` times it). The baseline revision's ``physink_tui`` is exported with ``git archive``
into a temporary folder (`bench_side_by_side.export`); one worker process per tree imports its own package through
PYTHONPATH and writes every reading (kind, confidence, beautified geometry, alternatives, reason) as JSON, whose floats
round-trip exactly. Prints how many readings differ in kind, and in anything at all (geometry beyond ``--tolerance``,
confidence, alternatives), by set; nothing about any stroke. The second to fifth held-back groups
(`bench_generalisation.is_held_back_new`, `held_back_set`) are left out entirely: their strokes are not recognised;
but for ``--fourth``, which reads the fourth group's sets too (`bench_generalisation.FOURTH_SETS`, opened as design
material in session 19).
``--noise auto`` has this tree read every stroke with ``noise=None`` (judged from the stroke: `units.stroke_noise`),
the baseline with its default (a pixel).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODES = ("as drawn", "200 points")


def strokes(paths: list[Path], fourth: bool = False) -> list[tuple[str, list[list[float]], list[float] | None]]:
    """Each kept single-stroke sample as (set, points, times or None), the held-back groups left out (the fourth too
    unless ``fourth``)."""
    return [(source, points, times) for source, points, times, _ in _kept(paths, fourth)]


def _kept(paths: list[Path], fourth: bool = False) -> list[tuple[str, list[list[float]], list[float] | None, str]]:
    """`strokes`, each with where it is from: its person, file and label (for ``--list``)."""
    from bench_generalisation import held_back_set, is_held_back_new
    from stroke_sets import read_set, source_of

    out = []
    for path in paths:
        for row in read_set(path):
            group = held_back_set(row["source"])
            if (len(row["strokes"]) != 1 or (group is not None and not (fourth and group == "fourth"))
                    or is_held_back_new(source_of(row, "person"))):
                continue
            stroke = row["strokes"][0]
            times = ([p[2] / 1000 for p in stroke] if stroke and all(len(p) > 2 and p[2] is not None for p in stroke)
                     else None)
            where = f"{source_of(row, 'person')} {row.get('file', '')} \"{row.get('label', '')}\""
            out.append((str(row["source"]), [[float(v) for v in p[:2]] for p in stroke], times, where))
    return out


def _plain(value: object) -> object:
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {"type": type(value).__name__, **{k: _plain(v) for k, v in dataclasses.asdict(value).items()
                                                 if not (k == "note" and v is None)}}  # a tree without notes
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    return value


def worker(paths: list[Path], out: Path, auto: bool = False, fourth: bool = False) -> None:
    """Every reading of this tree's ``physink_tui``, one JSON line each, in `strokes` order then `MODES` order
    (``auto``: with ``noise=None``; ``fourth``: the fourth group's sets read too)."""
    import numpy as np
    from bench_recognition import resample

    from physink_tui.scene.recognition.recognize import recognize_stroke as recognize

    def recognize_stroke(points: list, times: list | None) -> object:
        return recognize(points, times, noise=None) if auto else recognize(points, times)

    with out.open("w", encoding="utf-8") as f:
        f.write(json.dumps({"package": __import__("physink_tui").__file__}) + "\n")
        for _, points, times in strokes(paths, fourth):
            f.write(json.dumps(_plain(recognize_stroke(points, times))) + "\n")
            pts = np.asarray(points, dtype=float)
            when = np.asarray(times, dtype=float) if times is not None else np.arange(len(pts)) / 100.0
            if len(pts) >= 2 and np.isfinite(pts).all() and np.isfinite(when).all():
                r_pts, r_times = resample(pts, when)
                f.write(json.dumps(_plain(recognize_stroke(r_pts.tolist(), r_times.tolist()))) + "\n")
            else:
                f.write("null\n")


def _close(a: object, b: object, tolerance: float) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return a == b or abs(a - b) <= tolerance
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k], tolerance) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_close(x, y, tolerance) for x, y in zip(a, b, strict=True))
    return a == b


def run(tree: Path, paths: list[Path], out: Path, auto: bool = False, fourth: bool = False) -> list[object]:
    env = {**os.environ, "PYTHONPATH": str(tree)}
    subprocess.run([sys.executable, __file__, "--worker", str(out), *(["--noise", "auto"] if auto else []),
                    *(["--fourth"] if fourth else []), *map(str, paths)], env=env, check=True)
    lines = out.read_text(encoding="utf-8").splitlines()
    package = json.loads(lines[0])["package"]
    if not package.startswith(str(tree)):
        raise SystemExit(f"the worker imported {package}, not the tree under {tree}")
    return [json.loads(line) for line in lines[1:]]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--baseline", default="main")
    ap.add_argument("--tolerance", type=float, default=0.0, help="geometry and confidence may differ by this much")
    ap.add_argument("--noise", choices=("default", "auto"), default="default",
                    help="auto: this tree reads with noise=None (judged from the stroke)")
    ap.add_argument("--fourth", action="store_true",
                    help="read the fourth group's sets too (opened as design material; the third and fifth never)")
    ap.add_argument("--list", action="store_true", help="name every stroke whose kind differs, and both kinds")
    ap.add_argument("--worker", type=Path, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.worker is not None:
        worker(args.sets, args.worker, args.noise == "auto", args.fourth)
        return
    from bench_side_by_side import export

    kept = _kept(args.sets, args.fourth)
    sets, wheres = [s for s, _, _, _ in kept], [w for _, _, _, w in kept]
    with tempfile.TemporaryDirectory() as tmp:
        base = run(export(args.baseline, Path(tmp)), args.sets, Path(tmp) / "baseline.jsonl", fourth=args.fourth)
        this = run(ROOT, args.sets, Path(tmp) / "this.jsonl", args.noise == "auto", args.fourth)
    if len(base) != len(this) or len(base) != len(MODES) * len(sets):
        raise SystemExit(f"{len(base)} baseline readings, {len(this)} here, for {len(sets)} strokes")
    total, kind, any_diff = Counter(), Counter(), Counter()
    changed: list[str] = []
    for i, (a, b) in enumerate(zip(base, this, strict=True)):
        key = (sets[i // len(MODES)], MODES[i % len(MODES)])
        total[key] += 1
        kind[key] += (a or {}).get("kind") != (b or {}).get("kind")
        if args.list and (a or {}).get("kind") != (b or {}).get("kind"):
            changed.append(f"- {key[0]} {wheres[i // len(MODES)]} ({key[1]}): {(a or {}).get('kind')} -> "
                           f"{(b or {}).get('kind')}")
        any_diff[key] += not _close(a, b, args.tolerance)
    print(f"Readings of this tree (noise: {args.noise}) against {args.baseline} (geometry tolerance "
          f"{args.tolerance:g}):\n")
    print("| set | mode | readings | kind differs | anything differs |\n|---|---|---:|---:|---:|")
    for key in sorted(total):
        print(f"| {key[0]} | {key[1]} | {total[key]} | {kind[key]} | {any_diff[key]} |")
    print(f"| all | both | {sum(total.values())} | {sum(kind.values())} | {sum(any_diff.values())} |")
    if changed:
        print("\nKinds changed (set, person, file, label, mode: baseline -> this tree):\n" + "\n".join(changed))
    if sum(any_diff.values()):
        raise SystemExit(1)


if __name__ == "__main__":
    main()
