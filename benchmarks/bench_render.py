"""Benchmark: rendering alone, frames per second, for the egg cracker's demonstration (issue 13: >= 300 at 1280x720).

Usage: .venv/bin/python benchmarks/bench_render.py [--runs 5] [--fps 30]

Replays ``tests/journals/egg_cracker.physink.jsonl`` through the session, builds the frame content of every frame
of its demonstration at ``--fps`` (0, 1/fps ... the end) once, then times only `Renderer.render` over all of them
in order, as a video export draws them, with one renderer per size (its caches warm after the first frame, as in an
export). Reports the median frames per second over runs; prints Markdown rows for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time
from pathlib import Path

from physink_tui.formats.journal.reader import read_journal
from physink_tui.render.frame import frame_times
from physink_tui.render.frames import Demonstration
from physink_tui.render.renderer import Renderer
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session

JOURNAL = Path(__file__).resolve().parents[1] / "tests" / "journals" / "egg_cracker.physink.jsonl"
SIZES = ((1280, 720), (1920, 1080))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--fps", type=float, default=30.0)
    parser.add_argument("--theme", default="light")
    args = parser.parse_args(argv)
    journal = read_journal(JOURNAL)
    session = replay(Session.from_header(journal.header), journal.entries)
    demo = Demonstration(session.scene, session.timeline, session.canvas)
    frames = [demo.frame(t) for t in frame_times(demo.duration, args.fps)]
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, {os.cpu_count()} cores, "
          f"{args.runs} runs, {args.theme} theme -->")
    print("| scene | size | frames | rendering, frames/s (median) | ms per frame |")
    print("|---|---|---|---|---|")
    for width, height in SIZES:
        renderer = Renderer(width, height, session.canvas, args.theme)
        renderer.render(frames[0])  # the static layer and the paths are made once per export
        rates = []
        for _ in range(args.runs):
            t0 = time.perf_counter()
            for frame in frames:
                renderer.render(frame)
            rates.append(len(frames) / (time.perf_counter() - t0))
        rate = statistics.median(rates)
        print(f"| egg cracker, {demo.duration:.2f} s at {args.fps:g} fps | {width}x{height} | {len(frames)} "
              f"| {rate:.0f} | {1000 / rate:.2f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
