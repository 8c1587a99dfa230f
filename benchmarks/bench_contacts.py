"""Benchmark: a World's step against raw pymunk with the same bodies and no collision callbacks (issue 14).

Usage: .venv/bin/python benchmarks/bench_contacts.py [--bodies 100] [--steps 600] [--settle 240] [--repeat 3]

Two scenes: bench_world.py's pile (``--bodies`` boxes, balls and L-shapes falling onto a floor, 5 ropes) and the
egg cracker (``tests/journals/egg_cracker.physink.jsonl`` replayed through the session) under default gravity. For
each, the world as built is timed against a "raw" world: the same space, bodies, shapes and constraints, with each
shape given its material's real restitution and friction and every collision callback removed, which is what plain
pymunk would cost, and against the world with its callbacks removed (its own shapes: no elasticity, the grips of
build.py), which isolates what the callbacks cost. Each world steps ``--settle`` steps, then ``--steps`` steps are
timed one by one; the best of ``--repeat`` medians (the variants taking turns) is printed with the ratio world / raw.
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import pymunk

from physink_tui.formats.journal.reader import read_journal
from physink_tui.scene.components import Scene
from physink_tui.scene.physics.world import World
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_world import build_scene

JOURNAL = Path(__file__).resolve().parents[1] / "tests" / "journals" / "egg_cracker.physink.jsonl"


def egg_cracker() -> Scene:
    journal = read_journal(JOURNAL)
    return replay(Session.from_header(journal.header), journal.entries).scene


def raw(scene: Scene) -> World:
    """The world of ``scene`` as plain pymunk: real materials on the shapes, no collision callbacks."""
    world = World.from_scene(scene)
    for shape in world.pymunk_parts.space.shapes:
        shape.elasticity, shape.friction = world.pymunk_parts.surfaces.of(shape)
    for handler in world.pymunk_parts.space._handlers.values():
        handler.begin = handler.pre_solve = handler.post_solve = handler.separate = None
    return world


def bare(scene: Scene) -> World:
    """The world of ``scene`` as built, less its collision callbacks (contacts never bounce; some frictions are off)."""
    world = World.from_scene(scene)
    for handler in world.pymunk_parts.space._handlers.values():
        handler.begin = handler.pre_solve = handler.post_solve = handler.separate = None
    return world


def median_step(world: World, settle: int, steps: int) -> float:
    world.step(settle)
    times = []
    for _ in range(steps):
        start = time.perf_counter()
        world.step()
        times.append(time.perf_counter() - start)
    world.take_contacts()
    return statistics.median(times) * 1000


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bodies", type=int, default=100)
    parser.add_argument("--steps", type=int, default=600)
    parser.add_argument("--settle", type=int, default=240)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args(argv)
    print(f"<!-- pymunk {pymunk.version}; {args.settle} settling steps, {args.steps} timed, best of {args.repeat} -->")
    print("| scene | shapes | world step | world, no callbacks | raw pymunk step | world / raw |")
    print("|---|---:|---:|---:|---:|---:|")
    scenes = {f"pile of {args.bodies} bodies + 5 ropes": build_scene(args.bodies, 5, 1), "egg cracker": egg_cracker()}
    for label, scene in scenes.items():
        best = {World.from_scene: math.inf, bare: math.inf, raw: math.inf}
        for _ in range(args.repeat):  # interleaved, so a busy spell on the machine hits all three alike
            for make in best:
                best[make] = min(best[make], median_step(make(scene), args.settle, args.steps))
        built, quiet, plain = best.values()
        shapes = len(World.from_scene(scene).pymunk_parts.space.shapes)
        print(f"| {label} | {shapes} | {built:.3f} ms | {quiet:.3f} ms | {plain:.3f} ms | {built / plain:.2f}x |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
