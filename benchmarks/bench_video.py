"""Benchmark: video export throughput and real-time factor, serial against pipelined (issue 13: MP4 >= 3x real time).

Usage: .venv/bin/python benchmarks/bench_video.py [--runs 3] [--seconds 10] [--fps 30] [--sweep]

Writes ``--seconds`` of video at ``--fps`` with `write_video` at 1280x720 and 1920x1080, from two producers:

- "encode only": a ring of 30 frames drawn beforehand, so drawing costs only the copy `write_video` makes;
- "drawn": a skia scene drawn into one reused RGBA buffer each frame (a grid, 30 moving filled and outlined
  bodies, 15 pen strokes, 5 text lines), costing about what the project's renderer costs per frame (its own
  benchmark, bench_render.py, measures 1.4 ms at 1280x720 and 3 ms at 1920x1080 on the reference machine).

Reports frames per second and the real-time factor (video seconds per second of export), the median over runs,
for MP4 serial and pipelined, and WebM and GIF pipelined for information. ``--sweep`` also compares encoder and
scaler thread counts for the pipelined MP4 (how `video_encode.ENCODER_THREADS`/`SCALER_THREADS` were chosen).
Prints Markdown rows for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import tempfile
import time
from collections.abc import Callable

import numpy as np
import skia

from physink_tui.render import video_encode
from physink_tui.render.video import write_video

SIZES = ((1280, 720), (1920, 1080))


class DrawnScene:
    """A skia scene drawn into one reused (H, W, 4) RGBA buffer, moving with the frame number."""

    def __init__(self, width: int, height: int, fps: int) -> None:
        self.width, self.height, self.fps = width, height, fps
        self.buffer = np.zeros((height, width, 4), np.uint8)
        self.surface = skia.Surface(self.buffer, colorType=skia.kRGBA_8888_ColorType,
                                    alphaType=skia.kPremul_AlphaType)
        self.canvas = self.surface.getCanvas()
        self.fill = skia.Paint(AntiAlias=True, Style=skia.Paint.kFill_Style)
        self.line = skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=2.5)
        self.grid = skia.Paint(AntiAlias=False, Style=skia.Paint.kStroke_Style, StrokeWidth=1,
                               Color=skia.Color(225, 225, 225))
        self.font = skia.Font(skia.Typeface("DejaVu Sans"), 18)
        rng = np.random.default_rng(1)
        self.bodies = rng.uniform(0, 1, (30, 4))
        self.strokes = []
        for _ in range(15):  # pen strokes: short smooth random walks
            start = rng.uniform(0.1, 0.9, 2) * (width, height)
            steps = np.cumsum(rng.normal(0, 4, (60, 2)) + rng.normal(0, 3, 2), axis=0)
            path = skia.Path()
            path.moveTo(*start)
            for dx, dy in steps:
                path.lineTo(start[0] + dx, start[1] + dy)
            self.strokes.append(path)

    def __call__(self, i: int) -> np.ndarray:
        canvas, width, height = self.canvas, self.width, self.height
        canvas.clear(skia.Color(250, 248, 240))
        for x in range(0, width, 40):
            canvas.drawLine(x, 0, x, height, self.grid)
        for y in range(0, height, 40):
            canvas.drawLine(0, y, width, y, self.grid)
        self.line.setColor(skia.Color(30, 30, 30))
        for path in self.strokes:
            canvas.drawPath(path, self.line)
        t = i / self.fps
        for k, (x, y, size, hue) in enumerate(self.bodies):
            self.fill.setColor(skia.Color4f(hue, 0.45, 1 - hue, 1.0))
            cx = (x * width + 200 * math.sin(t + k)) % width
            cy = (y * height + 60 * t) % height
            radius = 8 + size * 30
            if k % 2:
                canvas.drawCircle(cx, cy, radius, self.fill)
                canvas.drawCircle(cx, cy, radius, self.line)
            else:
                rect = skia.Rect.MakeXYWH(cx, cy, 2 * radius, radius)
                canvas.drawRect(rect, self.fill)
                canvas.drawRect(rect, self.line)
        self.fill.setColor(skia.Color(20, 20, 20))
        for k in range(5):
            canvas.drawString(f"t = {t:6.2f} s   body {k}", 20, 30 + 24 * k, self.font, self.fill)
        return self.buffer


class Ring:
    """Frames drawn beforehand and handed out in turn, so only `write_video`'s own work is timed."""

    def __init__(self, scene: DrawnScene, size: int = 30) -> None:
        self.frames = [scene(i).copy() for i in range(size)]

    def __call__(self, i: int) -> np.ndarray:
        return self.frames[i % len(self.frames)]


def drawing_ms(scene: DrawnScene, frames: int = 60) -> float:
    scene(0)
    t0 = time.perf_counter()
    for i in range(frames):
        scene(i)
    return (time.perf_counter() - t0) / frames * 1000


def timed(suffix: str, count: int, fps: int, producer: Callable[[int], np.ndarray], runs: int,
          pipelined: bool) -> tuple[float, float, int]:
    """Median frames per second over ``runs`` exports, the cores kept busy (CPU time / wall time) in the median
    run, and the file's size in bytes."""
    runs_seen, size = [], 0
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, f"bench{suffix}")
        for _ in range(runs):
            t0, cpu0 = time.perf_counter(), time.process_time()
            report = write_video(path, count, producer, fps, pipelined=pipelined)
            wall, cpu = time.perf_counter() - t0, time.process_time() - cpu0
            runs_seen.append((report.frames / wall, cpu / wall))
            size = report.bytes
    rate, cores = sorted(runs_seen)[len(runs_seen) // 2]
    return rate, cores, size


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--fps", type=int, default=30)
    parser.add_argument("--sweep", action="store_true", help="also compare encoder and scaler thread counts")
    args = parser.parse_args(argv)
    count = round(args.seconds * args.fps)
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, {os.cpu_count()} cores, "
          f"{args.runs} runs, {args.seconds:g} s at {args.fps} fps, x264 preset {video_encode.X264_PRESET}, "
          f"encoder threads {video_encode.ENCODER_THREADS}, scaler threads {video_encode.SCALER_THREADS} -->")
    print("| format | size | producer | arrangement | frames/s (median) | x real time | cores busy | file |")
    print("|---|---|---|---|---|---|---|---|")

    def row(label: str, size: str, producer_name: str, arrangement: str, measured: tuple[float, float, int],
            fps: int) -> None:
        rate, cores, nbytes = measured
        print(f"| {label} | {size} | {producer_name} | {arrangement} | {rate:.0f} | {rate / fps:.1f} "
              f"| {cores:.2f} | {nbytes / 1024:.0f} KiB |", flush=True)

    for width, height in SIZES:
        size = f"{width}x{height}"
        scene = DrawnScene(width, height, args.fps)
        print(f"<!-- drawing alone, {size}: {drawing_ms(scene):.2f} ms per frame -->")
        producers = {"encode only": Ring(scene), "drawn": scene}
        for name, producer in producers.items():
            for pipelined in (False, True):
                measured = timed(".mp4", count, args.fps, producer, args.runs, pipelined)
                row("MP4 H.264", size, name, "pipelined" if pipelined else "serial", measured, args.fps)
        for suffix, label in ((".webm", "WebM VP9"), (".gif", "GIF")):
            measured = timed(suffix, count, args.fps, scene, args.runs, True)
            row(label, size, "drawn", "pipelined", measured, min(args.fps, 30) if suffix == ".gif" else args.fps)
        if args.sweep:
            original = video_encode.ENCODER_THREADS, video_encode.SCALER_THREADS
            for encoder_threads in (1, 2, 0):
                for scaler_threads in (1, 2):
                    video_encode.ENCODER_THREADS, video_encode.SCALER_THREADS = encoder_threads, scaler_threads
                    for pipelined in (False, True):
                        measured = timed(".mp4", count, args.fps, scene, args.runs, pipelined)
                        arrangement = (f"{'pipelined' if pipelined else 'serial'}, x264 threads {encoder_threads},"
                                       f" swscale threads {scaler_threads}")
                        row("MP4 H.264", size, "drawn", arrangement, measured, args.fps)
            video_encode.ENCODER_THREADS, video_encode.SCALER_THREADS = original
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
