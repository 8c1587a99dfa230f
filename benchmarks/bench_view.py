"""Benchmark: what `Session.view()` costs while the egg cracker is being demonstrated (issue 12: under 1 ms).

Usage: .venv/bin/python benchmarks/bench_view.py [--runs 5]

Replays ``tests/journals/egg_cracker.physink.jsonl`` through the session; from the middle of the demonstration
(half of the input between ``mode demo`` and the journal's end) to its end, a view is taken at every 1/30 s of
input time, as a live driver publishes them, and each `view()` call is timed with `time.perf_counter` (the
session's own work between views is not counted). Reports the median, 95th percentile and largest call over
those views, the median over runs; prints Markdown rows for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time
from pathlib import Path

from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.session.session import Session

JOURNAL = Path(__file__).resolve().parents[1] / "tests" / "journals" / "egg_cracker.physink.jsonl"
FPS = 30.0


def one_run() -> dict[str, float]:
    journal = read_journal(JOURNAL)
    entries = journal.entries
    start = next(i for i, e in enumerate(entries) if isinstance(e, CommandEntry) and e.name == "mode"
                 and e.args == ("demo",))
    middle = start + (len(entries) - start) // 2
    session = Session.from_header(journal.header)
    for entry in entries[:middle]:
        session.handle(entry)
    timings, bodies, next_view = [], 0, entries[middle].t
    for entry in entries[middle:]:
        session.handle(entry)
        while entry.t >= next_view:
            t0 = time.perf_counter()
            view = session.view()
            timings.append(time.perf_counter() - t0)
            bodies = len(view.poses)
            next_view += 1 / FPS
    timings.sort()
    return {"views": len(timings), "bodies": bodies, "median_us": 1e6 * statistics.median(timings),
            "p95_us": 1e6 * timings[int(0.95 * (len(timings) - 1))], "max_us": 1e6 * timings[-1]}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args(argv)
    runs = [one_run() for _ in range(args.runs)]
    med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, {os.cpu_count()} cores, "
          f"{args.runs} runs -->")
    print("| session | views | bodies | view(), median | 95th percentile | largest |")
    print("|---|---:|---:|---:|---:|---:|")
    print(f"| egg cracker, second half of the demonstration | {med['views']:.0f} | {med['bodies']:.0f} | "
          f"{med['median_us']:.0f} µs | {med['p95_us']:.0f} µs | {med['max_us']:.0f} µs |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
