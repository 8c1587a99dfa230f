"""Benchmark: time from pen-up to the new body being in the scene and in a physics world.

A scripted pen draws 60 bodies (boxes and balls on a grid, so none overlap) into one session; for each
stroke the pen-up sample is timed through the session (gesture end, recognition, interpretation, undo
history) plus building the pymunk World of the new scene, as the TUI will do to show it. Prints p50/p95.

Usage: .venv/bin/python benchmarks/bench_sketch.py [--strokes N]
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

from physink_tui.journal.entries import JournalHeader, PenEntry
from physink_tui.scene.world import World
from physink_tui.session.session import Session


def stroke(t0: float, points: list[tuple[float, float]]) -> list[PenEntry]:
    out = [PenEntry(t0, *points[0], 0.0, False, True, False, False, False)]
    out += [PenEntry(t0 + 0.005 * i, x, y, 0.6, True, True, False, False, False) for i, (x, y) in enumerate(points, 1)]
    out.append(PenEntry(t0 + 0.005 * (len(points) + 1), *points[-1], 0.0, False, True, False, False, False))
    return out


def shape(k: int) -> list[tuple[float, float]]:
    col, row = k % 10, k // 10
    cx, cy = 0.06 + 0.09 * col, 0.08 + 0.14 * row
    if k % 2:
        return [(cx + 0.025 / 1.6 * math.cos(a / 40 * 2 * math.pi), cy + 0.025 * math.sin(a / 40 * 2 * math.pi))
                for a in range(41)]
    corners = [(cx - 0.02, cy - 0.03), (cx + 0.02, cy - 0.03), (cx + 0.02, cy + 0.03), (cx - 0.02, cy + 0.03)]
    pts = []
    for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1], strict=True):
        pts += [(ax + (bx - ax) * i / 12, ay + (by - ay) * i / 12) for i in range(12)]
    return [*pts, corners[0]]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--strokes", type=int, default=60)
    args = ap.parse_args()
    session = Session.from_header(JournalHeader(1600, 1000, (), {}, 0.05, 0.01))
    times, t = [], 0.0
    for k in range(args.strokes):
        entries = stroke(t, shape(k))
        for entry in entries[:-1]:
            session.handle(entry)
        start = time.perf_counter()
        session.handle(entries[-1])  # pen up: the stroke ends, is recognised and interpreted
        World.from_scene(session.scene, gravity=(0.0, 0.0))
        times.append(time.perf_counter() - start)
        t = entries[-1].t + 0.3
    times.sort()
    p95 = times[int(0.95 * (len(times) - 1))]
    print(f"{len(times)} strokes, scene grows to {len(session.scene.bodies())} bodies: "
          f"pen-up to body in scene and world p50 {statistics.median(times) * 1e3:.2f} ms, p95 {p95 * 1e3:.2f} ms")


if __name__ == "__main__":
    main()
