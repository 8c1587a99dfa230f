"""Benchmark: time per fixed step of the pymunk world with 200 bodies (boxes, balls, polygons) and 5 ropes.

Usage: .venv/bin/python benchmarks/bench_world.py [--bodies 200] [--ropes 5] [--steps 600] [--settle 240] [--seed 1]

Builds a scene in a 1000 x 1000 canvas: a fixed floor, two walls and three fixed pegs; the bodies (a third each of
boxes, balls and concave L-shaped polygons, sizes 16-40 units) start on a grid above the floor, so after falling
they pile up and touch; each rope hangs from a peg or a wall to a ball. The world steps ``--settle`` steps first (the
pile forms), then ``--steps`` steps are timed one by one with `time.perf_counter`. Prints Markdown rows for
docs/BENCHMARKS.md: the world as built (a begin callback records contacts and gives a fast first contact the larger
restitution; a pre-solve callback gives the mean friction to the few pairs of surfaces whose product is not it, see
build.py) and, to show what recording costs, the same world without the begin callback (no records, no bounces).
bench_contacts.py sets the world beside raw pymunk.
"""

from __future__ import annotations

import argparse
import os
import platform
import random
import statistics
import sys
import time

import pymunk

from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Rope, Scene
from physink_tui.scene.physics.world import World


def _box(body_id: str, x: float, y: float, w: float, h: float, angle: float = 0.0) -> Body:
    outline = ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))
    return Body(body_id, "box", outline, 0.0, (x, y), angle, MATERIALS["box"])


def build_scene(n_bodies: int, n_ropes: int, seed: int) -> Scene:
    rng = random.Random(seed)
    scene = Scene()
    fixed = [_box("floor", 500, 980, 1000, 40), _box("wall_l", 10, 500, 20, 1000), _box("wall_r", 990, 500, 20, 1000)]
    fixed += [_box(f"peg{i}", 200 + 300 * i, 120, 30, 30) for i in range(3)]
    for body in fixed:
        scene = scene.add(body).add(Joint(f"j_{body.id}", "weld", body.id, BACKGROUND, body.position))
    ends = []
    columns = 16
    for i in range(n_bodies):
        x = 60 + (i % columns) * 55 + rng.uniform(-5, 5)
        y = 940 - (i // columns) * 55 - 30
        size = rng.uniform(16, 40)
        kind = ("box", "ball", "polygon")[i % 3]
        body_id = f"b{i}"
        if kind == "box":
            body = _box(body_id, x, y, size, size * rng.uniform(0.5, 1.0), rng.uniform(0, 1))
        elif kind == "ball":
            body = Body(body_id, "circle", (), size / 2, (x, y), 0.0, MATERIALS["round"])
        else:
            s = size / 2
            outline = ((-s, -s), (s, -s), (s, -s / 3), (-s / 3, -s / 3), (-s / 3, s), (-s, s))
            body = Body(body_id, "polygon", outline, 0.0, (x, y), 0.0, MATERIALS["freeform"])
        scene = scene.add(body)
        if kind == "ball":
            ends.append(body)
    anchors = [f"peg{i}" for i in range(3)] + ["wall_l", "wall_r"]
    for r in range(min(n_ropes, len(ends))):
        holder = next(b for b in fixed if b.id == anchors[r % len(anchors)])
        ball = ends[-1 - r]  # from the top rows, so the ropes hang over the pile
        start, end = holder.position, ball.position
        points = tuple((start[0] + (end[0] - start[0]) * k / 20, start[1] + (end[1] - start[1]) * k / 20)
                       for k in range(21))
        scene = scene.add(Rope(f"r{r}", points, holder.id, ball.id))
    return scene


def time_steps(world: World, settle: int, steps: int) -> tuple[list[float], int]:
    world.step(settle)
    world.take_contacts()
    times = []
    for _ in range(steps):
        start = time.perf_counter()
        world.step()
        times.append(time.perf_counter() - start)
    return times, len(world.take_contacts())


def row(label: str, world: World, times: list[float], began: int) -> str:
    ms = sorted(t * 1000 for t in times)
    median, p95 = statistics.median(ms), ms[int(0.95 * (len(ms) - 1))]
    shapes, constraints = len(world.pymunk_parts.space.shapes), len(world.pymunk_parts.space.constraints)
    arbiters = len(world.pymunk_parts.space._get_arbiters())  # live contact pairs, for the record
    realtime = world.dt * 1000 / median
    return (f"| {label} | {len(world.body_ids())} | {shapes} | {constraints} | {arbiters} | {began} | "
            f"{median:.3f} ms | {p95:.3f} ms | {realtime:.1f}x |")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bodies", type=int, default=200)
    parser.add_argument("--ropes", type=int, default=5)
    parser.add_argument("--steps", type=int, default=600)
    parser.add_argument("--settle", type=int, default=240)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)

    scene = build_scene(args.bodies, args.ropes, args.seed)
    print(f"<!-- {platform.python_implementation()} {platform.python_version()}, pymunk {pymunk.version}, "
          f"{os.cpu_count()} CPUs, {platform.machine()}; {args.bodies} bodies + {args.ropes} ropes, "
          f"settle {args.settle} steps, {args.steps} timed steps of 1/120 s -->")
    print("| world | bodies (incl. fixed) | shapes | constraints | contact pairs at end | contacts begun | "
          "step median | step p95 | real time |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    world = World.from_scene(scene)
    times, began = time_steps(world, args.settle, args.steps)
    print(row("as built (begin: records, bounces; pre-solve: mean friction where needed)", world, times, began))
    world = World.from_scene(scene)
    world.pymunk_parts.space.on_collision(begin=pymunk.empty_callback)
    times, _ = time_steps(world, args.settle, args.steps)
    print(row("the same without the begin callback (no records, no bounces)", world, times, 0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
