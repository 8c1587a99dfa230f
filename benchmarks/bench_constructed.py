"""Benchmark: SIMULATE on machines made by construction (tests/constructed, issue 27), possible and impossible.

Usage: .venv/bin/python benchmarks/bench_constructed.py [--possible 5000-5199] [--impossible 5000-5049]
       [--levers 5000-5019] [--springs 5000-5029] [--impossible-springs 5000-5019] [--budget 200] [--seed 0]
       [--workers 2] [--grid 0] [--grid-budget 3000] [--needle]
       [--dask 0] [--rows FILE.jsonl] [--write docs/BENCHMARKS.md]

Each case is generated (drawn and demonstrated by its pen, its witness re-checked for a possible case; not timed),
then searched as ``physink simulate`` does (`constructed.judge`: the default search with ``--seed`` and
``--budget`` on ``--workers`` local processes, the pool started once and shared; the verdict as the command words
it). Per case: found (qualitative 0) or not, the rollout it was found at, rollouts run, wall seconds of the search
and its verdict; an impossible case counts as refused with its impossibility named when the verdict names the
contact its construction made impossible (its label and demonstrated time). ``--levers`` adds lever machines
(`constructed.levers`: the ball tips a pivoted lever on its way into the basket), searched the same way;
``--springs`` and ``--impossible-springs`` spring machines (`constructed.springs`: a trampoline on a vertical spring
catches the ball; impossible: the trampoline's top and the base under it touched one right after the other), a
spring case also counting whether its spring matters (`springs.spring_matters`).

Needle-ness (``--needle``, possible cases; costly, never in CI): the share of a coarse scan of the ball's launch
velocity, `SCAN` x `SCAN` throws (``--scan``) over vx `SCAN_VX` and vy `SCAN_VY` (canvas units/s; mirrored when
the seeded throw goes left), every other parameter at its seed, that is equivalent to the demonstration; cases are
grouped by it (`BUCKETS`).

The grid (``--grid N``): the thesis's grid (`sim/grid.py`) with ``--grid-budget`` on the first N possible cases,
beside the default: rollouts to an equivalent, and their ratio where the grid finds one.

Dask (``--dask N``): the first N possible and N impossible cases (and the first spring and impossible spring cases,
with ``--springs`` and ``--impossible-springs``) searched again on a `distributed.LocalCluster`
of ``--workers`` single-threaded processes; every outcome (found, found at, rollouts, distance, verdict) must be
identical to the local one (the script says how many are).

``--rows FILE`` writes one JSON object per case; ``--write FILE`` replaces what lies between
``<!-- bench_constructed -->`` and ``<!-- /bench_constructed -->`` in FILE with the summary (``--marker NAME``:
between ``<!-- NAME -->`` and ``<!-- /NAME -->``).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import platform
import shlex
import statistics
import sys
import time
from datetime import UTC, datetime
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from constructed.impossible import impossible
from constructed.judge import Outcome, judge
from constructed.levers import lever
from constructed.possible import possible
from constructed.springs import impossible_spring, spring_case, spring_matters

from physink_tui.sim.defaults import DEFAULT_BUDGET, DEFAULT_SEED
from physink_tui.sim.evaluate import evaluate_problem, make_problem
from physink_tui.sim.seeding import seed as seed_parameters
from physink_tui.sim_run.executors import Executor, ProcessExecutor, SerialExecutor
from physink_tui.timeline.events import event_label

SCAN = 15
SCAN_VX = (-600.0, 2200.0)
SCAN_VY = (-2200.0, 600.0)
BUCKETS = ((0.0, "none in the scan"), (0.01, "< 1 %"), (0.05, "1-5 %"), (1.01, ">= 5 %"))
"""Upper bounds (exclusive, but the first: exactly 0) of the needle-ness groups, with their names."""
WALL_GOAL = 10.0


@dataclasses.dataclass
class Row:
    name: str
    kind: str
    pen: str
    platforms: int
    found: bool
    found_at: int | None
    rollouts: int
    qualitative: float
    wall: float
    verdict: str
    named: bool | None = None
    contacts: int | None = None
    needle: float | None = None
    grid_found_at: int | None = None
    grid_rollouts: int | None = None
    grid_wall: float | None = None
    spring_matters: bool | None = None


def seeds(text: str) -> range:
    if not text:
        return range(0)
    a, _, b = text.partition("-")
    return range(int(a), int(b or a) + 1)


def run_case(case, kind: str, executor: Executor, args) -> tuple[Row, Outcome]:
    s = case.session()
    start = time.perf_counter()
    outcome = judge(s, executor, seed=args.seed, budget=args.budget)
    wall = time.perf_counter() - start
    row = Row(case.name, kind, case.pen, len(case.layout.platforms), outcome.found, outcome.found_at,
              outcome.rollouts, outcome.qualitative, round(wall, 3), outcome.verdict)
    if kind == "lever":
        row.contacts = None
    elif kind == "spring":
        row.spring_matters = spring_matters(case)
    elif kind in ("impossible", "impossible-spring"):
        event = case.impossible_event()
        label = f'"{event_label(event, s.scene.names())}" (t={event.t0:.2f} s'
        row.named = not outcome.found and label in outcome.verdict
    else:
        row.contacts = len(case.platform_contacts)
    return row, outcome


def needle(case, executor: Executor, scan: int = SCAN) -> float:
    s = case.session()
    return needle_of(s.scene, s.timeline, s.canvas, executor, scan)


def needle_of(scene, timeline, canvas, executor: Executor, scan: int = SCAN) -> float | None:
    """The equivalent share of the coarse scan of the first start body's launch velocity (the module docstring);
    None when the demonstration moves no body from the start."""
    problem = make_problem(scene, timeline, canvas)
    base = seed_parameters(scene, timeline, canvas)
    if not base.start_bodies:
        return None
    ball = base.start_bodies[0]
    side = -1.0 if base.velocities[ball][0] < 0 else 1.0
    grid = [base.with_velocities({**base.velocities,
                                  ball: (side * (SCAN_VX[0] + i * (SCAN_VX[1] - SCAN_VX[0]) / (scan - 1)),
                                         SCAN_VY[0] + j * (SCAN_VY[1] - SCAN_VY[0]) / (scan - 1))})
            for i in range(scan) for j in range(scan)]
    from functools import partial
    scores = executor.map(partial(evaluate_problem, problem), grid)
    return sum(1 for sc in scores if not sc.exploded and sc.qualitative == 0) / len(grid)


def bucket(share: float | None) -> str:
    if share is None:
        return "not scanned"
    if share == 0:
        return BUCKETS[0][1]
    return next(name for bound, name in BUCKETS[1:] if share < bound)


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    if not ordered:
        return float("nan")
    k = min(len(ordered) - 1, max(0, round(q * (len(ordered) - 1))))
    return ordered[k]


def summary(rows: list[Row], args, command: str) -> str:
    poss = [r for r in rows if r.kind == "possible"]
    imp = [r for r in rows if r.kind == "impossible"]
    levers = [r for r in rows if r.kind == "lever"]
    springs = [r for r in rows if r.kind == "spring"]
    imp_springs = [r for r in rows if r.kind == "impossible-spring"]
    lines = [f"Measured {datetime.now(UTC):%Y-%m-%d %H:%M} UTC: `{command}`; {os.cpu_count()} cpus, "
             f"{args.workers} workers, CPython {platform.python_version()}; load average at the start "
             f"{args.load:.1f}.", ""]
    if poss:
        found = [r for r in poss if r.found]
        fast = [r for r in found if r.wall <= WALL_GOAL]
        lines.append(f"Possible cases {args.possible}: {len(poss)}; found at seed {args.seed} within the budget of "
                     f"{args.budget}: {len(found)} ({100 * len(found) / len(poss):.1f} %); found within "
                     f"{WALL_GOAL:.0f} s wall: {len(fast)} ({100 * len(fast) / len(poss):.1f} %).")
        lines.append("")
        lines.append("| needle-ness (equivalent share of the scan) | cases | found | rollouts to an equivalent: "
                     "median / 90th pct | wall s: median / 90th pct |")
        lines.append("|---|---:|---:|---|---|")
        groups: dict[str, list[Row]] = {}
        for r in poss:
            groups.setdefault(bucket(r.needle), []).append(r)
        order = [name for _, name in BUCKETS] + ["not scanned"]
        for name in [*order, "all"]:
            rs = poss if name == "all" else groups.get(name, [])
            if not rs:
                continue
            got = [r.found_at for r in rs if r.found_at is not None]
            walls = [r.wall for r in rs]
            lines.append(f"| {name} | {len(rs)} | {sum(r.found for r in rs)} | "
                         f"{statistics.median(got) if got else '—'} / {percentile(got, 0.9) if got else '—'} | "
                         f"{statistics.median(walls):.2f} / {percentile(walls, 0.9):.2f} |")
        by_pen = {pen: [r for r in poss if r.pen == pen] for pen in ("virtual", "hurried")}
        lines.append("")
        lines.append("By pen: " + "; ".join(f"{pen} {sum(r.found for r in rs)} of {len(rs)}"
                                            for pen, rs in by_pen.items() if rs) + ".")
        missed = [r for r in poss if not r.found]
        if missed:
            lines.append("Not found: " + "; ".join(f"{r.name} ({r.qualitative:g}: {r.verdict[:160]})"
                                                  for r in missed) + ".")
        gridded = [r for r in poss if r.grid_rollouts is not None]
        if gridded:
            both = [r for r in gridded if r.grid_found_at is not None and r.found_at is not None]
            ratios = [r.grid_found_at / r.found_at for r in both]
            lines.append("")
            lines.append(f"The grid (budget {args.grid_budget}) on {len(gridded)} of them: found "
                         f"{sum(r.grid_found_at is not None for r in gridded)}; rollouts to an equivalent, grid / "
                         f"default, where both find one ({len(both)}): median "
                         f"{statistics.median(ratios) if ratios else float('nan'):.2f}, 10th-90th pct "
                         f"{percentile(ratios, 0.1):.2f}-{percentile(ratios, 0.9):.2f}; grid wall median "
                         f"{statistics.median([r.grid_wall for r in gridded]):.2f} s.")
    if imp:
        refused = [r for r in imp if not r.found]
        named = [r for r in imp if r.named]
        lines.append("")
        lines.append(f"Impossible cases {args.impossible}: {len(imp)}; refused {len(refused)}; the verdict naming "
                     f"the constructed impossibility (the second touch of the level platform) {len(named)}; wall "
                     f"median {statistics.median([r.wall for r in imp]):.2f} s, 90th pct "
                     f"{percentile([r.wall for r in imp], 0.9):.2f} s.")
        other = [r for r in imp if not r.named]
        if other:
            lines.append("Naming another event: " + "; ".join(f"{r.name} ({r.verdict[:160]})" for r in other) + ".")
    if levers:
        walls = [r.wall for r in levers]
        got = [r.found_at for r in levers if r.found_at is not None]
        lines.append("")
        lines.append(f"Lever machines {args.levers}: {len(levers)}; found {sum(r.found for r in levers)}; rollouts to "
                     f"an equivalent median {statistics.median(got) if got else '—'}, 90th pct "
                     f"{percentile(got, 0.9) if got else '—'}; wall median {statistics.median(walls):.2f} s, 90th "
                     f"pct {percentile(walls, 0.9):.2f} s.")
    if springs:
        walls = [r.wall for r in springs]
        got = [r.found_at for r in springs if r.found_at is not None]
        matters = [r for r in springs if r.spring_matters]
        lines.append("")
        pens = {pen: sum(r.pen == pen for r in springs) for pen in ("virtual", "hurried")}
        lines.append(f"Spring machines {args.springs}: {len(springs)} (pens: virtual {pens['virtual']}, hurried "
                     f"{pens['hurried']}); "
                     f"found at seed {args.seed} within the budget of {args.budget}: {sum(r.found for r in springs)}; "
                     f"rollouts to an equivalent median {statistics.median(got) if got else '—'}, 90th pct "
                     f"{percentile(got, 0.9) if got else '—'}; wall median {statistics.median(walls):.2f} s, 90th "
                     f"pct {percentile(walls, 0.9):.2f} s. The witness's throw with the seeded spring misses the "
                     f"demonstration in {len(matters)} of them; found {sum(r.found for r in matters)} of those.")
        missed = [r for r in springs if not r.found]
        if missed:
            lines.append("Not found: " + "; ".join(f"{r.name} ({r.qualitative:g}: {r.verdict[:160]})"
                                                  for r in missed) + ".")
    if imp_springs:
        lines.append("")
        lines.append(f"Impossible spring cases {args.impossible_springs}: {len(imp_springs)}; refused "
                     f"{sum(not r.found for r in imp_springs)}; the verdict naming the constructed impossibility "
                     f"(the second of the two faces) {sum(bool(r.named) for r in imp_springs)}; "
                     f"wall median {statistics.median([r.wall for r in imp_springs]):.2f} s, 90th pct "
                     f"{percentile([r.wall for r in imp_springs], 0.9):.2f} s.")
        other = [r for r in imp_springs if not r.named]
        if other:
            lines.append("Naming another event: " + "; ".join(f"{r.name} ({r.verdict[:160]})" for r in other) + ".")
    if args.dask_line:
        lines.append("")
        lines.append(args.dask_line)
    return "\n".join(lines)


def dask_check(cases, args) -> str:
    import distributed

    from physink_tui.sim_run.dask_executor import DaskExecutor
    local = SerialExecutor()
    same = 0
    with distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=40) as cluster, \
            DaskExecutor(cluster=cluster) as remote:
        for case, kind in cases:
            a = run_case(case, kind, local, args)[1]
            b = run_case(case, kind, remote, args)[1]
            same += a == b
    return (f"Dask: {len(cases)} cases searched on a LocalCluster of {args.workers} worker processes and "
            f"serially: {same} of {len(cases)} outcomes identical (found, found at, rollouts, distance, verdict).")


def write(path: str, text: str, marker: str = "bench_constructed") -> None:
    doc = Path(path).read_text(encoding="utf-8")
    begin, end = f"<!-- {marker} -->", f"<!-- /{marker} -->"
    if begin not in doc or end not in doc:
        raise SystemExit(f"bench_constructed: {path} has no {begin} ... {end} markers")
    head, rest = doc.split(begin, 1)
    _, tail = rest.split(end, 1)
    Path(path).write_text(f"{head}{begin}\n{text}\n{end}{tail}", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--possible", default="5000-5199")
    parser.add_argument("--impossible", default="5000-5049")
    parser.add_argument("--levers", default="")
    parser.add_argument("--springs", default="")
    parser.add_argument("--impossible-springs", default="")
    parser.add_argument("--budget", type=int, default=DEFAULT_BUDGET)
    parser.add_argument("--seed", type=int, default=DEFAULT_SEED)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--grid", type=int, default=0)
    parser.add_argument("--grid-budget", type=int, default=3000)
    parser.add_argument("--needle", action="store_true")
    parser.add_argument("--scan", type=int, default=SCAN, help="throws per side of the needle-ness scan")
    parser.add_argument("--dask", type=int, default=0)
    parser.add_argument("--rows")
    parser.add_argument("--write")
    parser.add_argument("--marker", default="bench_constructed")
    args = parser.parse_args(argv)
    args.load = os.getloadavg()[0]
    args.dask_line = ""
    command = "benchmarks/bench_constructed.py " + shlex.join(argv if argv is not None else sys.argv[1:])
    executor: Executor = ProcessExecutor(args.workers) if args.workers > 1 else SerialExecutor()
    rows: list[Row] = []
    out = open(args.rows, "w", encoding="utf-8") if args.rows else None
    try:
        for kind, make, span in (("possible", possible, seeds(args.possible)),
                                 ("impossible", impossible, seeds(args.impossible)),
                                 ("lever", lever, seeds(args.levers)),
                                 ("spring", spring_case, seeds(args.springs)),
                                 ("impossible-spring", impossible_spring, seeds(args.impossible_springs))):
            for k, seed in enumerate(span):
                case = make(seed)
                row, _ = run_case(case, kind, executor, args)
                if kind in ("possible", "spring") and args.needle:
                    row.needle = needle(case, executor, args.scan)
                if kind == "possible" and k < args.grid:
                    s = case.session()
                    start = time.perf_counter()
                    g = judge(s, executor, seed=args.seed, budget=args.grid_budget, strategy="grid")
                    row.grid_found_at, row.grid_rollouts = g.found_at, g.rollouts
                    row.grid_wall = round(time.perf_counter() - start, 3)
                rows.append(row)
                print(json.dumps(dataclasses.asdict(row))[:300], flush=True)
                if out is not None:
                    out.write(json.dumps(dataclasses.asdict(row)) + "\n")
                    out.flush()
    finally:
        executor.close()
        if out is not None:
            out.close()
    if args.dask:
        cases = ([(possible(s), "possible") for s in list(seeds(args.possible))[: args.dask]]
                 + [(impossible(s), "impossible") for s in list(seeds(args.impossible))[: args.dask]]
                 + [(spring_case(s), "spring") for s in list(seeds(args.springs))[:1]]
                 + [(impossible_spring(s), "impossible-spring") for s in list(seeds(args.impossible_springs))[:1]])
        args.dask_line = dask_check(cases, args)
        print(args.dask_line)
    text = summary(rows, args, command)
    print(text)
    if args.write:
        write(args.write, text, args.marker)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
