"""Benchmark: SIMULATE's default search beside the thesis's grid on the same scenes, and the World step beside raw
pymunk (issue 14).

Usage: .venv/bin/python benchmarks/bench_simulate.py [--scenes a,b] [--budget 400] [--grid-budget 3000]
       [--seed 0] [--workers 2] [--write docs/BENCHMARKS.md] [--quick]

Scenes: every ``tests/journals/*.physink.jsonl`` (``--scenes`` takes their names without ``.physink.jsonl``),
each replayed once with ``physink replay JOURNAL --out DIR`` and read back with `load_project`, so the searches see
what ``physink simulate DIR/project.json`` would. On each scene both strategies run with the same seed on
``--workers`` local processes (`ProcessExecutor`, as ``physink simulate`` does): the grid with ``--grid-budget``
rollouts, the default (leg by leg, CMA-ES) with ``--budget``. Both stop early once a candidate is qualitatively
equivalent to the demonstration (`Search`). The wall time includes starting the worker pool.

The grid is the thesis's (3.4.5; `physink_tui.sim.grid`, whose constants the caption is printed from): every
combination, in odometer order (initial velocities first, then masses and frictions by body, then natural lengths
and spring constants by spring), of an initial velocity's angle -45°…+45° of the seeded one in 15° steps and its
speed x0.5…x2 in x0.25 steps (0…400 units/s in 100 steps when seeded at 0), a mass and a spring constant
x¼, x½, x1, x2, x4, a friction 0…1 in 0.25 steps, a natural length l0/2…2·l0 in l0/4 steps.

The headline figure, "ratio": how many times fewer rollouts the default needs than the grid to reach the grid's
best qualitative distance (issue 14: >= 20). Every rollout's score is recorded in candidate order (a wrapper round
the executor: the driver's progress callback reports once per generation, 16 grid rollouts at a time, too coarse
for counting rollouts), and:

- target: the lowest qualitative distance of any grid rollout (the quantitative distance is not part of it; it
  may be lower than the qualitative distance of the grid's best by objective, which adds the quantitative distance
  and the misses); distances are compared with a 1e-9 tolerance;
- the grid's budget caps it: the target is the lowest within ``--grid-budget`` rollouts (a longer grid could
  reach lower, later), so the ratio is the default's speed-up on what the grid achieved with that budget;
- grid needs: the 1-based number of the first grid rollout at the target; default needs: the first default
  rollout at or below it (ties count as reached); exploded rollouts count as rollouts and never reach anything;
- ratio = grid needs / default needs, when both are known and the grid needed more than one rollout;
- the grid's every rollout exploded: "n/a" (no target);
- the default never reaches the target within its budget: "n/a" (the grid did better; the default's lowest
  qualitative distance is in its column);
- the grid's best is its first candidate (the seed, rollout 1, which the default also tries first): the ratio
  would be 1 and say nothing. Then, when the default gets strictly below the target at rollout n, the grid did
  not get there in its R rollouts, so the ratio is "> R/n" (only a bound: the grid might never get there), or
  "inf" when those R rollouts were the whole grid (it stopped before its budget, nothing equivalent found); when
  the default does not get below either, "1 (seed)".

"To an equivalent": the same count to a qualitatively equivalent simulation (qualitative distance 0), which is
what a user asks SIMULATE for and which the grid's lowest distance often is not: grid "found at" / default "found
at", or, when only the default finds one, the grid's rollouts (its whole grid when it swept it) / the default's, a
lower bound written "> ...".

Each search's "best" columns are its answer (`Search.best_score`: lowest objective), as ``physink simulate``
reports it. "found at" is `Search.found_at`: the rollout at which a qualitatively equivalent candidate was found
(issue 14: each machine solved in <= 10 s wall on 2 cores). The World step overhead (goal <= 1.5x) is
bench_contacts.py's measurement, run here on its two scenes.

``--write FILE`` replaces what lies between ``<!-- bench_simulate -->`` and ``<!-- /bench_simulate -->`` in FILE
with the table, the date, the cpu count and the command line. ``--quick`` (tiny budgets, two small scenes, a short
World step measurement) is for the test of this script, not for numbers.
"""

from __future__ import annotations

import argparse
import dataclasses
import itertools
import math
import os
import platform
import shlex
import sys
import time
from collections.abc import Callable, Sequence
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import pymunk

from physink_tui.sim import grid
from physink_tui.sim.evaluate import Problem, Score, make_problem
from physink_tui.sim.search import Search
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import Executor, ProcessExecutor, SerialExecutor

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_contacts  # sibling modules, found through the path set just above
from journal_projects import journal_names, replayed_projects

ROOT = Path(__file__).resolve().parents[1]
BEGIN, END = "<!-- bench_simulate -->", "<!-- /bench_simulate -->"
QUICK_SCENES = ("bouncing_above_b", "basketball")
TOLERANCE = 1e-9
RATIO_GOAL = 20.0
WALL_GOAL = 10.0
OVERHEAD_GOAL = 1.5


# --- the grid's definition, from physink_tui.sim.grid's constants ---

def steps(values: Sequence[float], prefix: str = "", unit: str = "") -> str:
    """Evenly spaced values as "first…last in step steps", others listed.

    >>> steps((0.0, 0.25, 0.5, 0.75, 1.0))
    '0…1 in 0.25 steps'
    >>> steps((-30, -15, 0, 15, 30), unit="°")
    '-30°…+30° in 15° steps'
    >>> steps((0.25, 0.5, 1.0, 2.0, 4.0), "x")
    'x0.25, x0.5, x1, x2, x4'
    """
    def show(v: float) -> str:
        return f"{prefix}{v:+g}{unit}" if unit == "°" and v > 0 else f"{prefix}{v:g}{unit}"

    gaps = {round(b - a, 9) for a, b in itertools.pairwise(values)}
    if len(values) > 2 and len(gaps) == 1:
        return f"{show(values[0])}…{show(values[-1])} in {prefix}{gaps.pop():g}{unit} steps"
    return ", ".join(show(v) for v in values)


def grid_caption() -> str:
    """The thesis grid as the benchmark ran it (read from `physink_tui.sim.grid`)."""
    return (f"The grid (thesis 3.4.5, `sim/grid.py`): every combination, in odometer order, of an initial "
            f"velocity's angle, the seeded one {steps(grid.ANGLE_STEPS, unit='°')}, and speed, the seeded one "
            f"{steps(grid.MAGNITUDE_FACTORS, 'x')} (when seeded at 0: {steps(grid.ZERO_SPEEDS)}, units/s); "
            f"a mass and a spring constant, the seeded one {steps(grid.SCALE_FACTORS, 'x')}; a friction "
            f"{steps(grid.FRICTIONS)}; a natural length l0 {steps(grid.LENGTH_FACTORS, 'x')}; "
            f"{grid.GENERATION} candidates a generation.")


# --- the ratio ---

def first_reaching(trace: Sequence[Score], target: float, *, below: bool = False) -> int | None:
    """The 1-based number of the first rollout of ``trace`` whose qualitative distance is at most ``target``
    (strictly below it with ``below``; exploded rollouts never are), or None."""
    for i, s in enumerate(trace, 1):
        if not s.exploded and (s.qualitative < target - TOLERANCE if below else s.qualitative <= target + TOLERANCE):
            return i
    return None


def lowest(trace: Sequence[Score]) -> float | None:
    """The lowest qualitative distance of the rollouts of ``trace`` not exploded, or None."""
    return min((s.qualitative for s in trace if not s.exploded), default=None)


@dataclasses.dataclass(frozen=True, slots=True)
class Ratio:
    """The headline figure of one scene (see the module docstring for the rules).

    Attributes:
        target: the grid's lowest qualitative distance (None: every grid rollout exploded).
        grid_needs: the grid's first rollout at the target.
        default_needs: the default's first rollout at or below it (None: never).
        value: grid_needs / default_needs, or the bound when ``bound`` (None: not available).
        bound: ``value`` is a lower bound (the grid's best was the seed; the default did better).
        text: the table cell.
    """

    target: float | None
    grid_needs: int | None
    default_needs: int | None
    value: float | None
    bound: bool
    text: str


def ratio(grid_trace: Sequence[Score], default_trace: Sequence[Score], *, swept: bool = False) -> Ratio:
    """How many times fewer rollouts the default needed than the grid to reach the grid's best qualitative
    distance; ``swept``: the grid tried every combination (within its budget, finding nothing equivalent)."""
    target = lowest(grid_trace)
    if target is None:
        return Ratio(None, None, None, None, False, "n/a (grid: all exploded)")
    g = first_reaching(grid_trace, target)
    d = first_reaching(default_trace, target)
    if g == 1:
        n = first_reaching(default_trace, target, below=True)
        if n is not None and swept:
            return Ratio(target, g, d, math.inf, True, f"inf (grid swept all {len(grid_trace)}; default below at {n})")
        if n is not None:
            value = len(grid_trace) / n
            return Ratio(target, g, d, value, True, f"> {value:.3g} ({len(grid_trace)}/{n}; grid: seed best)")
        return Ratio(target, g, d, None, False, "1 (seed)")
    if d is None:
        return Ratio(target, g, None, None, False, "n/a (not reached)")
    value = g / d
    return Ratio(target, g, d, value, False, f"{value:.3g}")


def to_equivalent(grid_found: int | None, grid_rollouts: int, grid_swept: bool,
                  default_found: int | None) -> tuple[float | None, str]:
    """How many times fewer rollouts the default needed than the grid to find an equivalent simulation
    (qualitative distance 0), and the table cell; a lower bound ("> ...") when only the default found one.

    >>> to_equivalent(186, 193, False, 117)[1]
    '1.59 (186 / 117)'
    >>> to_equivalent(None, 1226, True, 100)[1]
    '> 12.3 (grid: none in all 1226)'
    >>> to_equivalent(None, 3000, False, 163)[1]
    '> 18.4 (grid: none in 3000)'
    >>> to_equivalent(36, 49, False, None)
    (None, 'grid only (36)')
    """
    if default_found is None:
        return None, "—" if grid_found is None else f"grid only ({grid_found})"
    if grid_found is not None:
        value = grid_found / default_found
        return value, f"{value:.3g} ({grid_found} / {default_found})"
    value = grid_rollouts / default_found
    swept = f"none in all {grid_rollouts}" if grid_swept else f"none in {grid_rollouts}"
    return value, f"> {value:.3g} (grid: {swept})"


# --- running ---

class Recording:
    """An executor that keeps every result in the order the candidates were handed out."""

    def __init__(self, inner: Executor) -> None:
        self.inner = inner
        self.results: list[Any] = []

    def map(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> list[Any]:
        out = self.inner.map(fn, items)
        self.results.extend(out)
        return out

    def close(self, *, cancel: bool = False) -> None:
        self.inner.close(cancel=cancel)


@dataclasses.dataclass(frozen=True, slots=True)
class Run:
    """One search on one scene: its answer, its every rollout's score in order, its wall seconds."""

    best: Score | None
    rollouts: int
    found_at: int | None
    trace: tuple[Score, ...]
    wall: float
    swept: bool
    """The strategy ran out of candidates before the budget (for the grid: it tried every combination)."""


def problems(names: Sequence[str]) -> dict[str, Problem]:
    """Each scene's problem, from its journal replayed by ``physink replay`` (output silenced) and read back."""
    out = {}
    for name, project in replayed_projects(names, "bench_simulate").items():
        if project.timeline is None or not project.timeline.events:
            raise SystemExit(f"bench_simulate: {name} has no demonstration")
        out[name] = make_problem(project.scene, project.timeline, project.canvas)
    return out


def search(problem: Problem, strategy: str, budget: int, seed: int, workers: int) -> Run:
    s = Search(problem.scene, problem.timeline, problem.canvas, strategy=strategy, seed=seed, budget=budget)
    executor = Recording(ProcessExecutor(workers) if workers > 1 else SerialExecutor())
    start = time.perf_counter()
    try:
        run_search(s, problem, executor)
    finally:
        executor.close()
    wall = time.perf_counter() - start
    swept = s.rollouts < budget and s.found_at is None
    return Run(s.best_score, s.rollouts, s.found_at, tuple(executor.results), wall, swept)


def world_overhead(steps_: int, settle: int, repeat: int, bodies: int = 100) -> list[tuple[str, float, float]]:
    """bench_contacts.py's measurement: (scene, World step ms, raw pymunk step ms), best of ``repeat`` medians."""
    scenes = {f"pile of {bodies} bodies + 5 ropes": bench_contacts.build_scene(bodies, 5, 1),
              "egg cracker": bench_contacts.egg_cracker()}
    rows = []
    for label, scene in scenes.items():
        built = plain = math.inf
        for _ in range(repeat):  # taking turns, as bench_contacts.py does
            built = min(built, bench_contacts.median_step(bench_contacts.World.from_scene(scene), settle, steps_))
            plain = min(plain, bench_contacts.median_step(bench_contacts.raw(scene), settle, steps_))
        rows.append((label, built, plain))
    return rows


# --- the table ---

def _d(v: float | None) -> str:
    return "—" if v is None or math.isinf(v) else f"{v:g}" if v == round(v, 2) else f"{v:.1f}"


def _best(r: Run) -> str:
    return "all exploded" if r.best is None else f"{_d(r.best.qualitative)} / {r.best.quantitative:.1f}"


def row(name: str, g: Run, d: Run) -> tuple[str, Ratio, float | None]:
    r = ratio(g.trace, d.trace, swept=g.swept)
    equivalent, equivalent_text = to_equivalent(g.found_at, g.rollouts, g.swept, d.found_at)
    reached = "—" if r.target is None else "never" if r.default_needs is None else str(r.default_needs)
    at = "—" if r.target is None else f"{_d(r.target)} at {r.grid_needs}"
    found = "—" if d.found_at is None else str(d.found_at)
    cells = (name, _best(g), at, f"{g.rollouts}, {g.wall:.1f} s", _best(d), reached, found,
             f"{d.rollouts}, {d.wall:.1f} s", r.text, equivalent_text)
    return "| " + " | ".join(cells) + " |", r, equivalent


HEADER = ("| scene | grid: best qual / quant | grid: lowest qual, at rollout | grid: rollouts, wall "
          "| default: best qual / quant | default: reaches the grid's lowest at | default: found at "
          "| default: rollouts, wall | ratio (grid / default rollouts) "
          "| to an equivalent (grid / default rollouts) |\n|---|---|---|---|---|---|---|---|---|---|")


def section(rows: list[str], ratios: list[Ratio], runs: list[Run], overhead: list[tuple[str, float, float]],
            argv: Sequence[str], workers: int, quick: bool = False,
            equivalents: Sequence[float | None] = ()) -> str:
    """The Markdown written between the markers (and printed)."""
    now = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    command = shlex.join(["benchmarks/bench_simulate.py", *argv])
    met = sum(1 for r in ratios if r.value is not None and r.value >= RATIO_GOAL)
    known = sum(1 for r in ratios if r.value is not None)
    fast = sum(1 for r in runs if r.found_at is not None and r.wall <= WALL_GOAL)
    solved = [e for e in equivalents if e is not None]
    to_zero = sum(1 for e in solved if e >= RATIO_GOAL)
    worst = max((b / p for _, b, p in overhead), default=math.nan)
    lines = [
        f"Measured {now}: `{command}`; {os.cpu_count()} cpus (`os.cpu_count()`), {workers} workers, "
        f"{platform.python_implementation()} {platform.python_version()}, pymunk {pymunk.version}.",
        "",
        grid_caption() + " Ratio rules: the module docstring of `benchmarks/bench_simulate.py`.",
        "",
        HEADER,
        *rows,
        "",
        f"Default >= {RATIO_GOAL:g}x fewer rollouts than the grid: {met} of {len(ratios)} scenes "
        f"({len(ratios) - known} without a ratio). Default solved (qualitative 0) in <= {WALL_GOAL:g} s wall: "
        f"{fast} of {len(runs)}. To an equivalent simulation, the default >= {RATIO_GOAL:g}x fewer rollouts than "
        f"the grid: {to_zero} of the {len(solved)} scenes the default solves (lower bounds counted).",
        "",
        *(["`--quick`: budgets and World step measurement too small to mean anything.", ""] if quick else []),
        "World step vs raw pymunk: " + "; ".join(f"{label} {b:.3f} / {p:.3f} ms = {b / p:.2f}x"
                                                 for label, b, p in overhead)
        + f" (bench_contacts.py; worst {worst:.2f}x, goal <= {OVERHEAD_GOAL:g}x: "
        + ("met" if worst <= OVERHEAD_GOAL else "not met") + ").",
    ]
    return "\n".join(lines) + "\n"


def replace_section(text: str, body: str) -> str:
    """``text`` with what lies between the markers replaced by ``body``.

    >>> replace_section("a\\n<!-- bench_simulate -->\\nold\\n<!-- /bench_simulate -->\\nb\\n", "new\\n")
    'a\\n<!-- bench_simulate -->\\nnew\\n<!-- /bench_simulate -->\\nb\\n'
    """
    start, end = text.find(BEGIN), text.find(END)
    if start < 0 or end < start:
        raise ValueError(f"no {BEGIN} ... {END} section")
    return text[: start + len(BEGIN)] + "\n" + body + text[end:]


def scene_names(selected: str | None, quick: bool) -> list[str]:
    available = journal_names()
    if selected is None:
        return list(QUICK_SCENES) if quick else available
    names = [n.strip() for n in selected.split(",") if n.strip()]
    unknown = [n for n in names if n not in available]
    if unknown:
        raise SystemExit(f"bench_simulate: unknown scene {unknown[0]!r}; expected some of {', '.join(available)}")
    return names


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", help="comma-separated journal names (default: every tests/journals one)")
    parser.add_argument("--budget", type=int, default=400, help="rollouts for the default strategy")
    parser.add_argument("--grid-budget", type=int, default=3000, help="rollouts for the grid")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--write", metavar="FILE", help="replace the bench_simulate section of FILE")
    parser.add_argument("--quick", action="store_true", help="tiny budgets, two scenes: checks the script runs")
    argv = sys.argv[1:] if argv is None else argv
    args = parser.parse_args(argv)
    if args.quick:
        args.budget, args.grid_budget = min(args.budget, 6), min(args.grid_budget, 20)
    if args.budget < 1 or args.grid_budget < 1 or args.workers < 1:
        parser.error("budgets and workers must be at least 1")
    if args.write is not None and BEGIN not in Path(args.write).read_text(encoding="utf-8"):
        parser.error(f"{args.write} has no {BEGIN} marker")
    rows, ratios, defaults, equivalents = [], [], [], []
    for name, problem in problems(scene_names(args.scenes, args.quick)).items():
        g = search(problem, "grid", args.grid_budget, args.seed, args.workers)
        d = search(problem, "default", args.budget, args.seed, args.workers)
        line, r, equivalent = row(name, g, d)
        rows.append(line)
        ratios.append(r)
        equivalents.append(equivalent)
        defaults.append(d)
        print(f"bench_simulate: {name}: grid {g.rollouts} rollouts in {g.wall:.1f} s "
              f"({g.rollouts / g.wall:.1f}/s), default {d.rollouts} in {d.wall:.1f} s ({d.rollouts / d.wall:.1f}/s)",
              file=sys.stderr, flush=True)
    overhead = world_overhead(60, 20, 1) if args.quick else world_overhead(600, 240, 3)
    body = section(rows, ratios, defaults, overhead, argv, args.workers, args.quick, equivalents)
    sys.stdout.write(body)
    if args.write is not None:
        path = Path(args.write)
        path.write_text(replace_section(path.read_text(encoding="utf-8"), body), encoding="utf-8")
        print(f"bench_simulate: wrote {path}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
