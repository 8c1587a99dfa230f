"""Benchmark: pen-up to the new body being in the session's physics world, and replaying sessions of n strokes.

Pen-up latency: a scripted pen draws ``--bodies`` bodies (boxes and balls on a grid, so none overlap) into one
session; each pen-up sample is timed through the session (gesture end, recognition, interpretation, undo history)
plus bringing the session's world in step (`Session.world`, what a view shows). On a tree without a live world
(before issue 10) the world is built afresh instead, as the view then had to. Prints p50/p95.

Replay: a journal-like list of n strokes is run through a new session and timed; the sketch is a grid of boxes and
balls where every fourth stroke is a ball drawn half into the body before it (so the physics pushes it clear) and
every tenth an X welding the box before it. Timed twice: the session alone, and with the world brought in step after
every pen-up as a view showing the sketch does. Prints the median of ``--runs`` runs for each n.

Usage: .venv/bin/python benchmarks/bench_sketch.py [--bodies 60,200] [--replay 100,200,400] [--runs 3]
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

from physink_tui.formats.journal.entries import JournalHeader, PenEntry
from physink_tui.scene.physics.world import World
from physink_tui.session.session import Session

Points = list[tuple[float, float]]
HEADER = JournalHeader(1600, 1000, (), {}, 0.05, 0.01)


def stroke(t0: float, points: Points) -> list[PenEntry]:
    points = [(min(max(x, 0.0), 1.0), min(max(y, 0.0), 1.0)) for x, y in points]  # a pen line stays on the canvas
    out = [PenEntry(t0, *points[0], 0.0, False, True, False, False, False)]
    out += [PenEntry(t0 + 0.005 * i, x, y, 0.6, True, True, False, False, False) for i, (x, y) in enumerate(points, 1)]
    out.append(PenEntry(t0 + 0.005 * (len(points) + 1), *points[-1], 0.0, False, True, False, False, False))
    return out


def ball(cx: float, cy: float, r: float) -> Points:
    return [(cx + r / 1.6 * math.cos(a / 40 * 2 * math.pi), cy + r * math.sin(a / 40 * 2 * math.pi)) for a in range(41)]


def box(cx: float, cy: float, w: float, h: float) -> Points:
    corners = [(cx - w, cy - h), (cx + w, cy - h), (cx + w, cy + h), (cx - w, cy + h)]
    pts = []
    for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1], strict=True):
        pts += [(ax + (bx - ax) * i / 12, ay + (by - ay) * i / 12) for i in range(12)]
    return [*pts, corners[0]]


def cell(k: int, columns: int) -> tuple[float, float]:
    return 0.03 + (0.94 / columns) * (k % columns), 0.03 + (0.94 / columns) * (k // columns)


def grid_strokes(n: int) -> list[Points]:
    """n boxes and balls, none overlapping (the pen-up benchmark)."""
    columns = max(10, math.ceil(math.sqrt(n)))
    size = 0.3 * 0.94 / columns
    return [ball(*cell(k, columns), size) if k % 2 else box(*cell(k, columns), size * 0.7, size) for k in range(n)]


def sketch_strokes(n: int) -> list[Points]:
    """n strokes: boxes and balls on a grid, every fourth a ball drawn half into the body before it, every tenth
    an X (two strokes) on the box before it."""
    columns = max(10, math.ceil(math.sqrt(n)))
    size = 0.3 * 0.94 / columns
    out: list[Points] = []
    k = 0
    while len(out) < n:
        cx, cy = cell(k, columns)
        i = len(out)
        if i % 10 == 9 and i + 1 < n:  # an X on the box of this cell, drawn before it
            d = size * 0.5
            out += [box(cx, cy, size * 0.7, size),
                    [(cx - d + 2 * d * j / 10, cy - d + 2 * d * j / 10) for j in range(11)],
                    [(cx + d - 2 * d * j / 10, cy - d + 2 * d * j / 10) for j in range(11)]]
        elif i % 4 == 3:  # a box, then a ball half into it
            out += [box(cx, cy, size * 0.7, size), ball(cx, cy - size * 1.2, size * 0.5)]
        else:
            out.append(ball(cx, cy, size) if i % 2 else box(cx, cy, size * 0.7, size))
        k += 1
    return out[:n]


def entries_of(strokes: list[Points]) -> list[PenEntry]:
    out: list[PenEntry] = []
    t = 0.0
    for points in strokes:
        out += stroke(t, points)
        t = out[-1].t + 0.3
    return out


def pen_up_latency(n: int) -> tuple[float, float]:
    """p50 and p95 (seconds) of pen-up to the body being in the session's world, the sketch growing to n bodies."""
    session = Session.from_header(HEADER)
    live = hasattr(Session, "world")
    times, t = [], 0.0
    for points in grid_strokes(n):
        entries = stroke(t, points)
        for entry in entries[:-1]:
            session.handle(entry)
        start = time.perf_counter()
        session.handle(entries[-1])  # pen up: the stroke ends, is recognised and interpreted
        if live:
            session.world  # noqa: B018 -- brought in step with the scene, as a view asks for it
        else:
            World.from_scene(session.scene, gravity=(0.0, 0.0))
        times.append(time.perf_counter() - start)
        t = entries[-1].t + 0.3
    times.sort()
    return statistics.median(times), times[int(0.95 * (len(times) - 1))]


def replay_seconds(n: int, view: bool) -> tuple[float, int, int, int]:
    """Seconds to run a session of n strokes, and the bodies, joints and pushes clear it ends with. With ``view`` the
    world is brought in step after every pen-up, as a view showing the sketch asks for it."""
    entries = entries_of(sketch_strokes(n))
    session = Session.from_header(HEADER)
    live = hasattr(Session, "world")
    start = time.perf_counter()
    for entry in entries:
        session.handle(entry)
        if view and not entry.tip and entry.range:
            if live:
                session.world  # noqa: B018
            else:
                World.from_scene(session.scene, gravity=(0.0, 0.0))
    session.finish()
    seconds = time.perf_counter() - start
    kinds = [type(c).__name__ for c in session.scene.components.values()]
    pushed = sum("pushed it clear" in m.text for m in session.messages)
    return seconds, kinds.count("Body"), kinds.count("Joint"), pushed


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bodies", default="60,200", help="comma-separated sketch sizes for the pen-up latency")
    ap.add_argument("--replay", default="100,200,400", help="comma-separated stroke counts to replay")
    ap.add_argument("--runs", type=int, default=3)
    args = ap.parse_args()
    for n in (int(v) for v in args.bodies.split(",") if v):
        runs = [pen_up_latency(n) for _ in range(args.runs)]
        p50 = statistics.median(r[0] for r in runs)
        p95 = statistics.median(r[1] for r in runs)
        print(f"pen-up to body in the world, sketch growing to {n} bodies: p50 {p50 * 1e3:.2f} ms, "
              f"p95 {p95 * 1e3:.2f} ms (medians of {args.runs} runs; p95s "
              f"{', '.join(f'{r[1] * 1e3:.1f}' for r in runs)})")
    for view in (False, True):
        for n in (int(v) for v in args.replay.split(",") if v):
            runs = [replay_seconds(n, view) for _ in range(args.runs)]
            seconds = statistics.median(r[0] for r in runs)
            print(f"replay of {n} strokes{' with the world shown after each' if view else ''} ({runs[0][1]} bodies, "
                  f"{runs[0][2]} joints, {runs[0][3]} pushed clear): {seconds:.2f} s median of {args.runs} "
                  f"({', '.join(f'{r[0]:.2f}' for r in runs)}), {seconds / n * 1e3:.1f} ms a stroke")


if __name__ == "__main__":
    main()
