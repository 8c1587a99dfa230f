"""Benchmark: where a seeded rollout's time goes on every thesis journal's scene: the physics, building the
observations and the recorder (issue 14: a recorder at most as costly as the physics it records).

Usage: .venv/bin/python benchmarks/bench_rollout.py [--scenes a,b] [--repeats 7] [--max-seconds 20]

Each ``tests/journals/*.physink.jsonl`` is replayed once with ``physink replay JOURNAL --out DIR`` (output
silenced) and read back with `load_project`; its parameters are the thesis's seed (`sim.seeding.seed`). The scene is
settled once (`settled_state`, not timed), then `rollout_from` is timed ``--repeats`` times. Inside it, by wrapping
the calls with `time.perf_counter` (the wrappers are this script's, installed by monkeypatching):

- physics: `World.step` inside `step_and_observe`;
- observe: the rest of `step_and_observe` (motions, contacts and touching pairs of the observed bodies);
- recorder: `Recorder.observe` and `Recorder.finish`;
- the remainder (building the world and recorder, the rollout's own checks) is in the total only.

Each column is the median over the repeats; shares are of the median total. recorder÷physics is issue 14's goal
(<= 1). The machine is shared: compare numbers from one run, not across runs.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from journal_projects import journal_names, replayed_projects  # a sibling module, through the path just set

from physink_tui.scene.physics import stepping
from physink_tui.scene.physics.world import World
from physink_tui.sim import rollout as rollout_module
from physink_tui.sim.seeding import seed


class Clock:
    """Seconds spent in each wrapped call since the last `reset`."""

    def __init__(self) -> None:
        self.spent = {"physics": 0.0, "step_and_observe": 0.0, "recorder": 0.0}

    def reset(self) -> None:
        for key in self.spent:
            self.spent[key] = 0.0

    def wrap(self, key: str, fn: Callable[..., Any]) -> Callable[..., Any]:
        spent = self.spent
        perf = time.perf_counter

        def timed(*args: Any, **kwargs: Any) -> Any:
            t0 = perf()
            try:
                return fn(*args, **kwargs)
            finally:
                spent[key] += perf() - t0

        return timed


def install(clock: Clock) -> None:
    """Wrap `World.step` (only while inside `step_and_observe`), `step_and_observe` and the recorder's calls."""
    inner_step = World.step
    inside = [False]

    def step(self: World, n: int = 1) -> None:
        if not inside[0]:
            return inner_step(self, n)
        t0 = time.perf_counter()
        try:
            return inner_step(self, n)
        finally:
            clock.spent["physics"] += time.perf_counter() - t0

    def observed(world: World, bodies: Any, fixed: Any = None) -> Any:
        inside[0] = True
        try:
            return stepping.step_and_observe(world, bodies, fixed)
        finally:
            inside[0] = False

    World.step = step  # type: ignore[method-assign]
    rollout_module.step_and_observe = clock.wrap("step_and_observe", observed)  # type: ignore[attr-defined]
    make_recorder = rollout_module.recorder_for

    def recorder_for(*args: Any, **kwargs: Any) -> Any:
        recorder = make_recorder(*args, **kwargs)
        recorder.observe = clock.wrap("recorder", recorder.observe)
        recorder.finish = clock.wrap("recorder", recorder.finish)
        return recorder

    rollout_module.recorder_for = recorder_for  # type: ignore[attr-defined]


def scenes(names: Sequence[str]) -> dict[str, Any]:
    """Each scene's project, from its journal replayed by ``physink replay`` (output silenced) and read back."""
    return replayed_projects(names, "bench_rollout")


def measure(project: Any, clock: Clock, repeats: int, max_seconds: float) -> dict[str, float]:
    """Median seconds per rollout: total, physics, observe, recorder; and the steps recorded."""
    params = seed(project.scene, project.timeline, project.canvas)
    settled = rollout_module.settled_state(project.scene, project.canvas, params)
    rows: list[dict[str, float]] = []
    steps = 0
    for _ in range(repeats):
        clock.reset()
        t0 = time.perf_counter()
        result = rollout_module.rollout_from(project.scene, settled, project.canvas, params, max_seconds=max_seconds)
        total = time.perf_counter() - t0
        steps = result.steps
        spent = dict(clock.spent)
        rows.append({"total": total, "physics": spent["physics"],
                     "observe": spent["step_and_observe"] - spent["physics"], "recorder": spent["recorder"]})
    out = {key: statistics.median(row[key] for row in rows) for key in rows[0]}
    out["ratio"] = statistics.median(row["recorder"] / row["physics"] for row in rows)
    out["steps"] = steps
    return out


def table(results: dict[str, dict[str, float]]) -> str:
    lines = ["| scene | steps | ms per rollout | physics | observe | recorder | recorder÷physics |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for name, r in results.items():
        total = r["total"]
        lines.append(f"| {name} | {int(r['steps'])} | {total * 1e3:.1f} | {r['physics'] / total:.0%} | "
                     f"{r['observe'] / total:.0%} | {r['recorder'] / total:.0%} | {r['ratio']:.2f} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default="", help="comma-separated journal names (default: all)")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--max-seconds", type=float, default=20.0)
    args = parser.parse_args(argv)
    names = ([n for n in args.scenes.split(",") if n]
             or journal_names())
    projects = scenes(names)
    clock = Clock()
    install(clock)
    results = {}
    for name, project in projects.items():
        results[name] = measure(project, clock, args.repeats, args.max_seconds)
        print(f"{name}: {results[name]['total'] * 1e3:.1f} ms", file=sys.stderr, flush=True)
    print(table(results))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
