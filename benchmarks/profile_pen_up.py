"""Benchmark: where a pen-up's time goes outside recognition, thread CPU per step, at two sketch sizes.

Usage: PYTHONPATH=TREE:benchmarks .venv/bin/python benchmarks/profile_pen_up.py [--sketches 5]

The sketch of `bench_sketch.pen_up_latency` (boxes and balls alternating on a grid, the world brought in step after
each pen-up) is drawn ``--sketches`` times; each stroke keeps the sketch where its pen-up took the least thread CPU
(scheduler stalls and a busy neighbour inflate the rest), with what each step took in it: recognition, `x_arm` (could
it be half an X), `interpret` (and its `_inside`, whether a round stroke is a pin), settling (`clear_overlaps`, which
brings the live world in step) and `LiveWorld.sync` (adding the body's shapes). Prints medians over strokes 20-59 of a
60-body sketch and strokes 0-39 and 160-199 of a 200-body one, boxes and balls apart: the same strokes early and
late in one sketch show what grows with its size. Timing wrappers are set on the modules' names, so the numbers
include a few microseconds of wrapping; pointed at another tree through PYTHONPATH it profiles that tree.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable
from typing import Any

from bench_sketch import HEADER, grid_strokes, stroke

import physink_tui.scene.interpretation.interpret as interpret_module
import physink_tui.session.modes.sketch as sketch_module
from physink_tui.scene.physics.live import LiveWorld
from physink_tui.session.session import Session

STEPS = (("recognition", sketch_module, "recognize_stroke"), ("x_arm", sketch_module, "x_arm"),
         ("interpret", sketch_module, "interpret"), ("_inside", interpret_module, "_inside"),
         ("settle", sketch_module, "clear_overlaps"), ("sync", LiveWorld, "sync"))
SPANS = ((60, range(20, 60)), (200, range(0, 40)), (200, range(160, 200)))

tally: dict[str, float] = {}


def timed(label: str, call: Callable[..., Any]) -> Callable[..., Any]:
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        start = time.thread_time()
        try:
            return call(*args, **kwargs)
        finally:
            tally[label] = tally.get(label, 0.0) + time.thread_time() - start
    return wrapper


def least_per_stroke(n: int, sketches: int) -> list[dict[str, float]]:
    """For each stroke of an n-body sketch, the steps' thread CPU in the sketch where its pen-up took the least."""
    best: list[dict[str, float]] = [{"total": float("inf")} for _ in range(n)]
    for _ in range(sketches):
        session, t = Session.from_header(HEADER), 0.0
        for k, points in enumerate(grid_strokes(n)):
            entries = stroke(t, points)
            for entry in entries[:-1]:
                session.handle(entry)
            tally.clear()
            start = time.thread_time()
            session.handle(entries[-1])
            session.world  # noqa: B018 -- brought in step, as a view asks for it
            row = {"total": time.thread_time() - start, **tally}
            if row["total"] < best[k]["total"]:
                best[k] = row
            t = entries[-1].t + 0.3
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sketches", type=int, default=5)
    args = ap.parse_args()
    for label, owner, name in STEPS:
        setattr(owner, name, timed(label, getattr(owner, name)))
    for n, span in SPANS:
        rows = least_per_stroke(n, args.sketches)
        for parity, what in ((0, "boxes"), (1, "balls")):
            chosen = [rows[k] for k in span if k % 2 == parity]

            def ms(key: str, rows: list[dict[str, float]] = chosen) -> float:
                return statistics.median(r.get(key, 0.0) for r in rows) * 1e3

            rest = statistics.median(r["total"] - r.get("recognition", 0.0) for r in chosen) * 1e3
            print(f"{n} bodies, strokes {span.start}-{span.stop - 1}, {what}: pen-up {ms('total'):.2f} ms, "
                  f"recognition {ms('recognition'):.2f}, the rest {rest:.2f} (x_arm {ms('x_arm'):.2f}, interpret "
                  f"{ms('interpret'):.2f} of which _inside {ms('_inside'):.2f}, settle {ms('settle'):.2f}, "
                  f"sync {ms('sync'):.2f})")


if __name__ == "__main__":
    main()
