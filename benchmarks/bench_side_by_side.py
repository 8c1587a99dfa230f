"""Benchmark: this tree's recognition and pen-up latency beside another revision's (today's code), in one run.

Usage: .venv/bin/python benchmarks/bench_side_by_side.py PATH/TO/dollar1-dev.jsonl [--baseline main] [--rounds 5]
       [--bodies 200]

The baseline revision's ``physink_tui`` is exported with ``git archive`` into a temporary folder; each round runs
one worker process per tree (the order alternating between rounds), the worker importing that tree's package
through PYTHONPATH and timing, with the same code for both: recognition of every stroke of the file resampled to
200 points (`bench_recognition.resample`, `recognize_stroke`), and pen-up to the body being in the session's world
while a sketch grows to ``--bodies`` bodies (as `bench_sketch.pen_up_latency`). Each call is timed by the wall clock
and by the thread's CPU clock (on a shared, busy machine the wall clock's p95 is mostly scheduler stalls). Prints
each round's p50/p95 and the medians over rounds with this tree's ratio to the baseline.
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


def worker(data: Path, bodies: int) -> dict[str, float | str]:
    """Both measures for the ``physink_tui`` on the path, each call timed by the wall clock and by the thread's CPU
    clock (which a busy machine's scheduler stalls do not inflate)."""
    import numpy as np
    from bench_recognition import resample
    from bench_sketch import HEADER, grid_strokes, stroke

    from physink_tui.scene.recognition.recognize import recognize_stroke
    from physink_tui.session.session import Session

    wall, cpu = [], []
    for line in data.read_text(encoding="utf-8").splitlines():
        row = json.loads(line)
        if len(row["strokes"]) != 1:
            continue
        points = np.asarray(row["strokes"][0], dtype=float)
        pts, times = resample(points[:, :2], points[:, 2] / 1000)
        pts_list, times_list = pts.tolist(), times.tolist()
        w0, c0 = time.perf_counter(), time.thread_time()
        recognize_stroke(pts_list, times_list)
        cpu.append(time.thread_time() - c0)
        wall.append(time.perf_counter() - w0)
    session = Session.from_header(HEADER)
    up_wall, up_cpu, t = [], [], 0.0
    for path in grid_strokes(bodies):  # as bench_sketch.pen_up_latency: pen up, then the world in step
        entries = stroke(t, path)
        for entry in entries[:-1]:
            session.handle(entry)
        w0, c0 = time.perf_counter(), time.thread_time()
        session.handle(entries[-1])
        session.world  # noqa: B018
        up_cpu.append(time.thread_time() - c0)
        up_wall.append(time.perf_counter() - w0)
        t = entries[-1].t + 0.3
    out: dict[str, float | str] = {"package": __import__("physink_tui").__file__}
    for name, values in (("recognition", wall), ("recognition cpu", cpu), ("pen-up", up_wall),
                         ("pen-up cpu", up_cpu)):
        out[f"{name} p50"] = float(np.percentile(values, 50))
        out[f"{name} p95"] = float(np.percentile(values, 95))
    return out


def export(revision: str, into: Path) -> Path:
    """``physink_tui`` as of ``revision``, unpacked under ``into``."""
    archive = into / "baseline.tar"
    with archive.open("wb") as out:
        subprocess.run(["git", "-C", str(ROOT), "archive", revision, "physink_tui"], stdout=out, check=True)
    with tarfile.open(archive) as tar:
        tar.extractall(into / "tree", filter="data")
    return into / "tree"


KEYS = ("recognition p50", "recognition p95", "recognition cpu p50", "recognition cpu p95", "pen-up p50",
        "pen-up p95", "pen-up cpu p50", "pen-up cpu p95")


def run_worker(tree: Path, data: Path, bodies: int) -> dict:
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
        results: dict[str, list[dict]] = {name: [] for name in trees}
        for k in range(args.rounds):
            order = list(trees) if k % 2 == 0 else list(reversed(trees))
            for name in order:
                results[name].append(run_worker(trees[name], args.data, args.bodies))
                r = results[name][-1]
                print(f"round {k + 1}, {name}: " + ", ".join(f"{key} {r[key] * 1e3:.2f} ms" for key in KEYS),
                      flush=True)
    keys = KEYS
    medians = {name: {key: statistics.median(r[key] for r in runs) for key in keys} for name, runs in results.items()}
    base, this = (medians[name] for name in trees)
    print(f"\n| measure (median of {args.rounds} rounds) | {' | '.join(trees)} | ratio |\n|---|---:|---:|---:|")
    for key in keys:
        print(f"| {key} | {base[key] * 1e3:.2f} ms | {this[key] * 1e3:.2f} ms | "
              f"{this[key] / base[key]:.2f}x |")


if __name__ == "__main__":
    main()
