"""Benchmark: the cost of one demo-mode frame (physics step + recorder) while the egg cracker is demonstrated.

Usage: .venv/bin/python benchmarks/bench_demo.py [--runs 5]

Replays ``tests/journals/egg_cracker.physink.jsonl`` (the drawing, then the demonstration of figure 3-4) through the
session. Every call of demo mode's `DemoMode.advance` is timed with `time.perf_counter`, and so is every
`Recorder.observe` inside it; the world's step counter gives the frames stepped. A frame's cost is the time in
`DemoMode.advance` divided by the frames it stepped (pose and contact gathering, the world step, tape following and the
recorder), reported as the median over runs of the per-run mean, with the recorder's share apart and the largest
single call per frame. Prints Markdown rows for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

from physink_tui.formats.journal.reader import read_journal
from physink_tui.session.modes.demo import DemoMode
from physink_tui.session.session import Session
from physink_tui.timeline.recorder import Recorder

JOURNAL = Path(__file__).resolve().parents[1] / "tests" / "journals" / "egg_cracker.physink.jsonl"


def one_run() -> dict[str, float]:
    journal = read_journal(JOURNAL)
    session = Session.from_header(journal.header)
    advance, observe = DemoMode.advance, Recorder.observe
    totals = {"advance": 0.0, "observe": 0.0, "frames": 0, "worst": 0.0}

    def timed_advance(mode: DemoMode, t: float) -> bool:
        before = mode.world.steps
        t0 = time.perf_counter()
        stepped = advance(mode, t)
        spent = time.perf_counter() - t0
        frames = mode.world.steps - before
        totals["advance"] += spent
        totals["frames"] += frames
        if frames:
            totals["worst"] = max(totals["worst"], spent / frames)
        return stepped

    def timed_observe(self: Recorder, obs) -> None:
        t0 = time.perf_counter()
        observe(self, obs)
        totals["observe"] += time.perf_counter() - t0

    DemoMode.advance, Recorder.observe = timed_advance, timed_observe
    try:
        session.run(journal.entries)
    finally:
        DemoMode.advance, Recorder.observe = advance, observe
    frames = max(totals["frames"], 1)
    return {"frames": totals["frames"], "events": len(session.timeline),
            "frame_us": 1e6 * totals["advance"] / frames, "recorder_us": 1e6 * totals["observe"] / frames,
            "worst_us": 1e6 * totals["worst"]}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args(argv)
    runs = [one_run() for _ in range(args.runs)]
    med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
    budget_us = 1e6 / 120
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, {os.cpu_count()} cores, "
          f"{args.runs} runs -->")
    print("| demonstration | frames | events | frame (step + recorder), mean | recorder alone | "
          "worst call, per frame | share of a 1/120 s frame |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    print(f"| egg cracker, figure 3-4 | {med['frames']:.0f} | {med['events']:.0f} | {med['frame_us']:.0f} µs | "
          f"{med['recorder_us']:.0f} µs | {med['worst_us']:.0f} µs | {med['frame_us'] / budget_us:.1%} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
