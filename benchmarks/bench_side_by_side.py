"""Benchmark: this tree's recognition and pen-up latency beside another revision's (today's code), in one run.

Usage: .venv/bin/python benchmarks/bench_side_by_side.py PATH/TO/dollar1-dev.jsonl [--baseline main] [--rounds 5]
       [--bodies 200]

The baseline revision's ``physink_tui`` is exported with ``git archive`` into a temporary folder; each round runs
one worker process per tree (the order alternating between rounds), the worker importing that tree's package
through PYTHONPATH and timing, with the same code for both: recognition of every stroke of the file resampled to
200 points (`bench_recognition.resample`, `recognize_stroke`), and pen-up to the body being in the session's world
while a sketch grows to ``--bodies`` bodies (`bench_sketch.pen_up_latency`). Prints each round's p50/p95 and the
medians over rounds with this tree's ratio to the baseline.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def worker(data: Path, bodies: int) -> dict[str, float]:
    import numpy as np
    from bench_recognition import resample
    from bench_sketch import pen_up_latency

    from physink_tui.scene.recognition.recognize import recognize_stroke

    seconds = []
    for line in data.read_text(encoding="utf-8").splitlines():
        row = json.loads(line)
        if len(row["strokes"]) != 1:
            continue
        stroke = np.asarray(row["strokes"][0], dtype=float)
        pts, times = resample(stroke[:, :2], stroke[:, 2] / 1000)
        pts_list, times_list = pts.tolist(), times.tolist()
        start = time.perf_counter()
        recognize_stroke(pts_list, times_list)
        seconds.append(time.perf_counter() - start)
    p50, p95 = pen_up_latency(bodies)
    return {"recognition_p50": float(np.percentile(seconds, 50)), "recognition_p95": float(np.percentile(seconds, 95)),
            "pen_up_p50": p50, "pen_up_p95": p95, "package": __import__("physink_tui").__file__}


def export(revision: str, into: Path) -> Path:
    """``physink_tui`` as of ``revision``, unpacked under ``into``."""
    archive = into / "baseline.tar"
    with archive.open("wb") as out:
        subprocess.run(["git", "-C", str(ROOT), "archive", revision, "physink_tui"], stdout=out, check=True)
    with tarfile.open(archive) as tar:
        tar.extractall(into / "tree", filter="data")
    return into / "tree"


def run_worker(tree: Path, data: Path, bodies: int) -> dict[str, float]:
    env = {**os.environ, "PYTHONPATH": str(tree)}
    done = subprocess.run([sys.executable, __file__, "--worker", str(data), "--bodies", str(bodies)], env=env,
                          check=True, capture_output=True, text=True)
    result = json.loads(done.stdout.strip().splitlines()[-1])
    if not result["package"].startswith(str(tree)):
        raise SystemExit(f"the worker imported {result['package']}, not the tree under {tree}")
    return result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("data", type=Path)
    ap.add_argument("--baseline", default="main")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--bodies", type=int, default=200)
    ap.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.worker:
        print(json.dumps(worker(args.data, args.bodies)))
        return
    with tempfile.TemporaryDirectory() as tmp:
        trees = {f"baseline ({args.baseline})": export(args.baseline, Path(tmp)), "this tree": ROOT}
        results: dict[str, list[dict[str, float]]] = {name: [] for name in trees}
        for k in range(args.rounds):
            order = list(trees) if k % 2 == 0 else list(reversed(trees))
            for name in order:
                results[name].append(run_worker(trees[name], args.data, args.bodies))
                r = results[name][-1]
                print(f"round {k + 1}, {name}: recognition at 200 points p50 {r['recognition_p50'] * 1e3:.2f} ms "
                      f"p95 {r['recognition_p95'] * 1e3:.2f} ms; pen-up to body ({args.bodies} bodies) p50 "
                      f"{r['pen_up_p50'] * 1e3:.2f} ms p95 {r['pen_up_p95'] * 1e3:.2f} ms", flush=True)
    keys = ("recognition_p50", "recognition_p95", "pen_up_p50", "pen_up_p95")
    medians = {name: {key: statistics.median(r[key] for r in runs) for key in keys} for name, runs in results.items()}
    base, this = (medians[name] for name in trees)
    print(f"\n| measure (median of {args.rounds} rounds) | {' | '.join(trees)} | ratio |\n|---|---:|---:|---:|")
    for key in keys:
        print(f"| {key.replace('_', ' ')} | {base[key] * 1e3:.2f} ms | {this[key] * 1e3:.2f} ms | "
              f"{this[key] / base[key]:.2f}x |")


if __name__ == "__main__":
    main()
