"""Benchmark: the cost of comparing two 1,000-event timelines (`physink_tui.timeline.equivalence.compare`).

Usage: .venv/bin/python benchmarks/bench_equiv.py [--events 1000] [--frames 60] [--differ 0.05] [--repeat 21] [--seed 1]

Builds a demonstration-shaped timeline: 8 balls released by one start, each bouncing among 20 platforms, so every
ball is a chain movement -> contact -> movement (a ball hitting another ball makes both move on); every movement
has a ``--frames``-frame trajectory and the regions it passes relative to 2-3 platforms, every contact its sides
and point. B is the same timeline with every trajectory and contact point jittered (as a simulation would differ),
and in the second pair about ``--differ`` of its events changed besides: a third of them a contact side flipped,
a third a region above/below swapped, a third a bounce (a contact and the movement it causes) removed.
Prints Markdown rows for docs/BENCHMARKS.md: medians over ``--repeat`` timed calls of `compare` (both timelines
prepared, the reasons written), of `compare(explain=False)`, and of what a search loop pays per rollout when the
demonstration is prepared once (`prepare` of B plus `compare_prepared(explain=False)`).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import random
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from physink_tui.timeline.equivalence import compare, compare_prepared, prepare
from physink_tui.timeline.events import SIDES, Event, Timeline, TrajectoryPoint

BALLS = 8
PLATFORMS = 20


def _path(rng: random.Random, t0: float, duration: float, start: tuple[float, float], end: tuple[float, float],
          frames: int, jitter: float) -> tuple[TrajectoryPoint, ...]:
    bend = rng.uniform(-30, 30)
    points = []
    for f in range(frames):
        s = f / (frames - 1)
        x = start[0] + (end[0] - start[0]) * s + bend * math.sin(math.pi * s) + rng.gauss(0, jitter)
        y = start[1] + (end[1] - start[1]) * s + 0.5 * 300 * s * s + rng.gauss(0, jitter)
        points.append(TrajectoryPoint(t0 + duration * s, x, y, 0.1 * s, end[0] - start[0], end[1] - start[1]))
    return tuple(points)


def demonstration(n_events: int, frames: int, seed: int) -> Timeline:
    """One start, then chains of movement -> contact -> movement(s) per ball, ``n_events`` events in all."""
    rng = random.Random(seed)
    platforms = [f"p{k}" for k in range(PLATFORMS)]
    events = [Event("e1", "start")]
    # Each ball: its open movement (id, end time, position).
    open_moves: dict[str, tuple[str, float, tuple[float, float]]] = {}
    for b in range(BALLS):
        ball, at = f"ball{b}", (rng.uniform(0, 1000), rng.uniform(0, 200))
        events.append(_movement(rng, f"e{len(events) + 1}", ball, "e1", 0.0, at, frames))
        open_moves[ball] = (events[-1].id, events[-1].t1, _end(events[-1]))
    while len(events) < n_events:
        ball = min(open_moves, key=lambda k: open_moves[k][1])  # the ball whose movement ends first
        move_id, t, at = open_moves[ball]
        other = rng.choice([b for b in open_moves if b != ball]) if rng.random() < 0.1 else rng.choice(platforms)
        cid = f"e{len(events) + 1}"
        causes = (move_id, open_moves[other][0]) if other in open_moves else (move_id,)
        sides = ((ball, rng.choice(SIDES[:4])), (other, rng.choice(SIDES[:4])))
        events.append(Event(cid, "contact", (ball, other), causes, t, t, sides=sides, point=at))
        for body in (ball, other) if other in open_moves else (ball,):
            events.append(_movement(rng, f"e{len(events) + 1}", body, cid, t, at, frames))
            open_moves[body] = (events[-1].id, events[-1].t1, _end(events[-1]))
    return Timeline(tuple(events[:n_events]))


def _end(move: Event) -> tuple[float, float]:
    return move.trajectory[-1].x, move.trajectory[-1].y


def _movement(rng: random.Random, eid: str, ball: str, cause: str, t0: float, at: tuple[float, float],
              frames: int) -> Event:
    duration = rng.uniform(0.3, 1.2)
    end = (at[0] + rng.uniform(-150, 150), at[1] + rng.uniform(-50, 150))
    regions = tuple((f"p{rng.randrange(PLATFORMS)}", (rng.choice(("above", "below")), rng.choice(("left", "right"))))
                    for _ in range(rng.randint(2, 3)))
    regions = tuple(dict(regions).items())  # one entry per platform
    return Event(eid, "movement", (ball,), (cause,), t0, t0 + duration, regions=regions,
                 trajectory=_path(rng, t0, duration, at, end, frames, 0.0))


def simulated(demo: Timeline, seed: int, differ: float) -> Timeline:
    """The demonstration as a simulation might give it: paths and points jittered, ``differ`` of events changed."""
    rng = random.Random(seed)
    events = []
    for ev in demo.events:
        if ev.trajectory:
            ev = replace(ev, trajectory=tuple(replace(p, x=p.x + rng.gauss(0, 4), y=p.y + rng.gauss(0, 4))
                                              for p in ev.trajectory))
        if ev.point is not None:
            ev = replace(ev, point=(ev.point[0] + rng.gauss(0, 3), ev.point[1] + rng.gauss(0, 3)))
        events.append(ev)
    tl = Timeline(tuple(events))
    if differ <= 0:
        return tl
    changes = max(1, round(differ * len(tl) / 3))
    contacts = [ev.id for ev in tl.events if ev.type == "contact" and len(tl.children(ev.id)) == 1]
    moves = [ev.id for ev in tl.events if ev.type == "movement" and ev.regions]
    picked = rng.sample(contacts, 3 * changes)
    for cid in picked[:changes]:  # a side flipped
        ev = tl.event(cid)
        (a, sa), rest = ev.sides[0], ev.sides[1:]
        tl = tl.update(replace(ev, sides=((a, "bottom" if sa == "top" else "top"), *rest)))
    for mid in rng.sample(moves, changes):  # above <-> below relative to one platform
        ev = tl.event(mid)
        (p, rs), rest = ev.regions[0], ev.regions[1:]
        swapped = tuple({"above": "below", "below": "above"}.get(r, r) for r in rs)
        tl = tl.update(replace(ev, regions=((p, swapped), *rest)))
    for cid in picked[changes:2 * changes]:  # a bounce removed: the contact and the movement it causes
        if cid not in tl:
            continue
        (move,) = tl.children(cid)
        before = tl.event(cid).causes[0]
        rewired = [replace(tl.event(c), causes=tuple(before if x == move else x for x in tl.event(c).causes))
                   for c in tl.children(move)]
        for ev in rewired:
            tl = tl.update(ev)
        tl = tl.remove((cid, move))
    return tl


def median_ms(fn: Callable[[], object], repeat: int) -> float:
    fn()  # warm up
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--events", type=int, default=1000)
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--differ", type=float, default=0.05)
    parser.add_argument("--repeat", type=int, default=21)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)

    demo = demonstration(args.events, args.frames, args.seed)
    pairs = [("identical events (paths and points jittered)", simulated(demo, args.seed + 1, 0.0)),
             (f"~{args.differ:.0%} of events differing", simulated(demo, args.seed + 1, args.differ))]
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, numpy {np.__version__}, "
          f"{os.cpu_count()} CPUs, {platform.machine()}; {len(demo)} events, {args.frames} frames a movement, "
          f"median of {args.repeat} -->")
    print("| pair | events A / B | matched | qualitative | quantitative | reasons | compare | "
          "compare, no reasons | per rollout (A prepared once) | prepare one |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    pa = prepare(demo)
    for label, other in pairs:
        result = compare(demo, other)
        full = median_ms(lambda other=other: compare(demo, other), args.repeat)
        quiet = median_ms(lambda other=other: compare(demo, other, explain=False), args.repeat)
        loop = median_ms(lambda other=other: compare_prepared(pa, prepare(other), explain=False), args.repeat)
        prep = median_ms(lambda other=other: prepare(other), args.repeat)
        print(f"| {label} | {len(demo)} / {len(other)} | {len(result.matches)} | {result.qualitative_distance:g} | "
              f"{result.quantitative_distance:.2f} | {len(result.reasons)} | {full:.2f} ms | {quiet:.2f} ms | "
              f"{loop:.2f} ms | {prep:.2f} ms |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
