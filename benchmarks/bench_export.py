"""Benchmark: the whole MP4 export of the egg cracker's demonstration beside rendering alone, in one run (issue 13:
rendering >= 300 frames/s and MP4 export >= 3x real time at 1280x720, 30 fps, on 2 cores; the same at 1920x1080).

Usage: .venv/bin/python benchmarks/bench_export.py [--runs 3] [--seconds 10]

Replays ``tests/journals/egg_cracker.physink.jsonl`` through the session and exports its demonstration with
`render.export.Export` — frames drawn from the timeline's tape, converted to yuv420p and encoded by PyAV/libx264 on
the other core while the next frame is drawn. The demonstration lasts about 6 s; to time a longer video the frame
times are repeated over ``--seconds`` of video. For each size the same frames are timed three ways in one run:
rendering alone, `write_video` with drawing and encoding on one thread (``pipelined=False``) and the export as
`physink export` runs it. Reports medians over runs: frames a second and the real-time factor (video seconds per
wall second). Prints Markdown rows for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import tempfile
import time
from pathlib import Path

from physink_tui.formats.journal.reader import read_journal
from physink_tui.render.export import Export, Look
from physink_tui.render.video import write_video
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session

JOURNAL = Path(__file__).resolve().parents[1] / "tests" / "journals" / "egg_cracker.physink.jsonl"
SIZES = ((1280, 720), (1920, 1080))
FPS = 30


def one_run(session: Session, size: tuple[int, int], seconds: float, folder: Path) -> dict[str, float]:
    export = Export(session.scene, session.timeline, session.canvas, Look(*size, FPS))
    count = round(seconds * FPS)
    times = [export.times[i % len(export.times)] for i in range(count)]
    contents = [export.content(t) for t in times]

    def frame_at(i: int):
        return export.renderer.render(contents[i])

    start = time.perf_counter()
    for i in range(count):
        frame_at(i)
    render = time.perf_counter() - start
    start = time.perf_counter()
    write_video(folder / "serial.mp4", count, frame_at, FPS, pipelined=False)
    serial = time.perf_counter() - start
    start = time.perf_counter()
    write_video(folder / "pipelined.mp4", count, lambda i: export.renderer.render(export.content(times[i])), FPS)
    pipelined = time.perf_counter() - start
    video = count / FPS
    return {"render_fps": count / render, "serial_fps": count / serial, "serial_x": video / serial,
            "export_fps": count / pipelined, "export_x": video / pipelined}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=10.0)
    args = parser.parse_args(argv)
    journal = read_journal(JOURNAL)
    session = replay(Session.from_header(journal.header), journal.entries)
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, {os.cpu_count()} cores, "
          f"{args.runs} runs, {args.seconds:g} s of video at {FPS} fps -->")
    print("| size | rendering alone | MP4, one thread | MP4 export (pipelined) | export real-time factor |")
    print("|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for size in SIZES:
            runs = [one_run(session, size, args.seconds, Path(tmp)) for _ in range(args.runs)]
            med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
            print(f"| {size[0]}x{size[1]} | {med['render_fps']:.0f} frames/s | {med['serial_fps']:.0f} frames/s "
                  f"({med['serial_x']:.1f}x) | {med['export_fps']:.0f} frames/s | {med['export_x']:.1f}x |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
