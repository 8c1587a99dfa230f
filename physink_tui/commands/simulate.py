"""`physink simulate PROJECT --out DIR [--budget N] [--workers N | --scheduler ADDRESS] [--seed S]
[--strategy default|grid]`: searches physical parameters whose gravity simulation reproduces the project's
demonstrated timeline (`physink_tui.sim`); the rollouts run in local processes or, with ``--scheduler``, on a Dask
cluster (`physink_tui.sim_run.dask_executor`; the two options exclude each other).

Writes ``DIR/result.json`` (``found``, both distances, ``rollouts``, ``wall_seconds``, ``parameters``,
``verdict``, the ``rule`` compared by -- equivalent up to the last demonstrated event, as the TUI and ``physink
equiv DEMO SIM --up-to-demonstrated`` compare -- and ``afterwards``, what the simulation does after that event, or
null), ``DIR/timeline.json`` and ``timeline.txt`` (the best candidate's simulated timeline) and
``DIR/project.json`` (the scene with the parameters found applied, the simulated timeline, and the demonstration
kept beside it, so ``physink equiv DIR/project.json --up-to-demonstrated`` compares them again; the initial
velocities are in result.json only). Deterministic for a given seed and budget whatever the worker count or
executor; only ``wall_seconds`` varies. Ctrl-C writes the best result so far and says so (exit 130). The new files
are written beside the last run's and renamed over them at the end, so a run killed meanwhile (SIGTERM, SIGKILL)
leaves the last complete result; an ``--out`` whose files include the input project is refused.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

from physink_tui.errors import PhysinkError
from physink_tui.formats.outputs import OutputFolder, check_outputs
from physink_tui.formats.project.files import load_project
from physink_tui.formats.project.sanity import named
from physink_tui.formats.session_outputs import write_session_outputs
from physink_tui.progress import ProgressBar
from physink_tui.scene.components import BACKGROUND
from physink_tui.sim.defaults import DEFAULT_BUDGET, DEFAULT_SEED
from physink_tui.sim.evaluate import Problem, Score, compare_rollout, make_problem, simulate
from physink_tui.sim.parameters import Parameters, apply
from physink_tui.sim.search import Search
from physink_tui.sim.verdict import refusal_or_verdict
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import Executor, ProcessExecutor, SerialExecutor
from physink_tui.timeline.up_to_demonstrated import RULE, afterwards
from physink_tui.timeline.up_to_demonstrated import verdict as verdict_words

EXIT_INTERRUPTED = 130
OUTPUTS = ("result.json", "timeline.json", "timeline.txt", "project.json")
"""The files a run writes into ``--out``."""


def _n(v: float) -> float | None:
    if v != v or v in (float("inf"), float("-inf")):
        return None
    r = round(v, 6)
    return 0.0 if r == 0 else r


def parameters_object(p: Parameters) -> dict:
    """The parameters as JSON: per body mass and friction, per spring k and rest length, per start body velocity."""
    return {
        "bodies": {b: {"mass": _n(v.mass), "friction": _n(v.friction)} for b, v in sorted(p.bodies.items())},
        "springs": {s: {"k": _n(v.k), "rest_length": _n(v.rest_length)} for s, v in sorted(p.springs.items())},
        "velocities": {b: [_n(v[0]), _n(v[1])] for b, v in sorted(p.velocities.items())},
    }


def _problem(path: str) -> tuple[Problem, tuple[str, ...]]:
    project = load_project(path)
    if project.timeline is None or not any(ev.type != "start" for ev in project.timeline.events):
        what = "no timeline" if project.timeline is None else "a timeline with nothing after its start event"
        raise PhysinkError(f"{path}: no demonstration to reproduce ({what}): demonstrate the machine's behaviour "
                           "(demo mode) first")
    scene = project.scene
    gone = sorted(named(project.timeline) - set(scene.components) - {BACKGROUND})
    if gone:
        raise PhysinkError(f"{path}: the demonstration moves {', '.join(map(repr, gone))}, which the scene does not "
                           "have: demonstrate the machine again (or restore the body)")
    if not any(not scene.is_fixed(b.id) for b in scene.bodies()):
        raise PhysinkError(f"{path}: no movable body: draw a body that is not pinned or welded, and demonstrate "
                           "how it moves")
    return make_problem(scene, project.timeline, project.canvas), project.vocabulary


def _executor(args: argparse.Namespace) -> Executor:
    """The Dask executor with ``--scheduler`` (imported only then), else local processes (one per core by
    default; none besides this one for ``--workers 1``)."""
    scheduler = getattr(args, "scheduler", None)
    if scheduler is not None:
        from physink_tui.sim_run.dask_executor import DaskExecutor

        return DaskExecutor(scheduler)
    workers = args.workers or os.cpu_count() or 1
    return SerialExecutor() if workers == 1 else ProcessExecutor(workers)


def run(args: argparse.Namespace) -> int:
    problem, vocabulary = _problem(args.project)
    budget = args.budget or DEFAULT_BUDGET
    seed = DEFAULT_SEED if args.seed is None else args.seed
    strategy = getattr(args, "strategy", None) or "default"
    search = Search(problem.scene, problem.timeline, problem.canvas, strategy=strategy, seed=seed, budget=budget)
    check_outputs([args.project], [("--out", os.path.join(args.out, name)) for name in OUTPUTS])
    executor = _executor(args)
    try:  # the new files are written beside the last run's, which stay until the end
        folder = OutputFolder.staged(args.out)
    except PhysinkError:
        executor.close()
        raise
    start = time.monotonic()
    interrupted = False
    bar = ProgressBar(f"Simulating ({strategy})", "rollouts")

    def progress(done: int, total: int, best: Score | None) -> None:
        bar(done, total)

    try:
        run_search(search, problem, executor, progress)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        executor.close(cancel=interrupted)
        bar.close()
    wall = time.monotonic() - start
    best = search.best if search.best is not None else search.start
    result = simulate(problem, best)
    comparison = compare_rollout(problem, result, explain=True)
    score = search.best_score
    found = score is not None and not score.exploded and comparison.equivalent
    text = refusal_or_verdict(search, problem, result, comparison, found=found)
    obj = {
        "found": found,
        "qualitative_distance": _n(comparison.qualitative_distance),
        "quantitative_distance": _n(comparison.quantitative_distance),
        "rollouts": search.rollouts,
        "exploded": search.exploded,
        "strategy": strategy,
        "seed": seed,
        "budget": budget,
        "interrupted": interrupted,
        "wall_seconds": round(wall, 3),
        "parameters": parameters_object(best),
        "verdict": text,
        "rule": f"equivalent {RULE}",
        "afterwards": afterwards(comparison, result.timeline, problem.scene.names()),
        "differences": list(comparison.reasons),
    }
    try:
        write_session_outputs(folder, apply(problem.scene, best), result.timeline, problem.canvas, vocabulary,
                              problem.timeline)  # the project keeps the demonstration the simulation was found for
        folder.write("result.json", json.dumps(obj, indent=2, ensure_ascii=False, allow_nan=False) + "\n")
        folder.commit()
    finally:
        folder.discard()  # what a failure left staged (nothing after the commit)
    state = "found" if found else "not found"
    sys.stdout.write(f"{state}: qualitative distance {obj['qualitative_distance']} ({verdict_words(comparison)}), "
                     f"quantitative {obj['quantitative_distance']}, {search.rollouts} rollouts ({search.exploded} "
                     f"exploded) in {wall:.1f} s; wrote {folder.path}\n")
    if obj["afterwards"]:
        sys.stdout.write(f"{obj['afterwards']}\n")
    if interrupted:
        sys.stdout.write("interrupted: wrote the best result so far\n")
        return EXIT_INTERRUPTED
    return 0
