"""Benchmark: where recognition's time goes — cProfile over every single stroke of the sets, resampled to 200 points.

Usage: .venv/bin/python benchmarks/profile_recognition.py SET [SET ...] [--top 25] [--sort tottime|cumtime]
       [--as-drawn]

Each single-stroke sample is resampled to 200 points with its times (`bench_recognition.resample`, as
`bench_side_by_side` times it; ``--as-drawn`` keeps the points as recorded) and recognised once under cProfile. The
second to fifth held-back groups are left out (`compare_readings.strokes`). Prints the total and the top
entries.
"""

from __future__ import annotations

import argparse
import cProfile
import io
import pstats
import time
from pathlib import Path

import numpy as np
from bench_recognition import resample
from compare_readings import strokes

from physink_tui.scene.recognition.recognize import recognize_stroke


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--sort", choices=("tottime", "cumtime"), default="tottime")
    ap.add_argument("--as-drawn", action="store_true")
    args = ap.parse_args()
    calls = []
    for _, points, times in strokes(args.sets):
        pts = np.asarray(points, dtype=float)
        when = np.asarray(times, dtype=float) if times is not None else np.arange(len(pts)) / 100.0
        if args.as_drawn:
            calls.append((points, times))
        elif len(pts) >= 2 and np.isfinite(pts).all() and np.isfinite(when).all():
            r_pts, r_times = resample(pts, when)
            calls.append((r_pts.tolist(), r_times.tolist()))
    recognize_stroke(*calls[0])  # imports and the model's first load are not recognition
    profile = cProfile.Profile()
    start = time.process_time()
    profile.enable()
    for pts, when in calls:
        recognize_stroke(pts, when)
    profile.disable()
    spent = time.process_time() - start
    out = io.StringIO()
    pstats.Stats(profile, stream=out).sort_stats(args.sort).print_stats(args.top)
    print(f"{len(calls)} strokes, {spent:.2f} s CPU under the profiler ({spent / len(calls) * 1e3:.2f} ms a stroke)")
    print(out.getvalue())


if __name__ == "__main__":
    main()
