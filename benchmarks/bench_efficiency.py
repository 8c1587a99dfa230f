"""Benchmark: rollouts and wall time to an equivalent simulation, the default search against the thesis's grid, by
how needle-like the case is (issue 27's "efficiency, restated").

Usage: .venv/bin/python benchmarks/bench_efficiency.py [--possible 5000-5059] [--springs 5000-5019]
       [--journals all] [--budget 200] [--grid-budget 3000] [--seed 0] [--workers 2] [--scan 10]
       [--rows FILE.jsonl] [--reuse EARLIER.jsonl] [--recheck 10] [--write docs/BENCHMARKS.md]
       .venv/bin/python benchmarks/bench_efficiency.py --from-rows A.jsonl,B.jsonl [--write docs/BENCHMARKS.md]

Cases: possible machines made by construction (`constructed.possible`, ``--possible``), spring machines
(`constructed.springs`, ``--springs``), and the thesis portfolio's journals (``--journals``: ``all`` is every
``tests/journals/*.physink.jsonl`` and ``tests/journals/restored/*.physink.jsonl``, each replayed by ``physink
replay`` and read back as ``physink simulate`` would; or names, ``restored/NAME`` for a restored one; ``''`` none).

Per case, each on a fresh pool of ``--workers`` local processes (as ``physink simulate`` starts one; the wall time
includes starting it): the default search (``--budget``, ``--seed``) and the thesis's grid (``--grid-budget``), each
stopping at its first qualitatively equivalent candidate: the rollout it was found at (`Search.found_at`), the
rollouts run and the wall seconds. The wall time to an equivalent is the search's wall time when it found one.

Needle-ness: the share of a coarse scan of the first start body's launch velocity that is equivalent
(`bench_constructed.needle_of`: ``--scan`` x ``--scan`` throws over a fixed range, every other parameter at its seed;
computed here, never in CI), grouped as bench_constructed groups it. Ratio: the default's rollouts to an equivalent
over the grid's, where both find one (below 1: the default needs fewer).

``--reuse FILE``: the grid's and the scan's figures of each case are taken from an earlier run's rows (their
commit is named in the summary) instead of measured again, only the default search is run (a case not in FILE is
measured in full): for re-measuring the default after it changed, the grid and the evaluation not. ``--recheck N``
runs the grid again on the N reused cases whose grid needed the fewest rollouts and says how many give the same
rollouts as the reused rows. ``--grid-from-table FILE``: for the thesis journals (not the restored ones), the
grid's figures are read from bench_simulate.py's table in FILE (the same grid, seed and budget; its "to an
equivalent" and "grid: rollouts, wall" columns) instead of run again. ``--from-rows`` writes the summary of rows
measured earlier (runs nothing; the load figures are then those of the runs' logs, not in the summary).

``--write FILE`` replaces what lies between ``<!-- bench_efficiency -->`` and ``<!-- /bench_efficiency -->`` in
FILE with the summary.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import platform
import shlex
import statistics
import subprocess
import sys
import time
from datetime import UTC, datetime
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_constructed import BUCKETS, bucket, needle_of, percentile, seeds
from constructed.possible import possible
from constructed.springs import spring_case
from journal_projects import JOURNALS, journal_names, replayed_projects

from physink_tui.sim.defaults import DEFAULT_BUDGET, DEFAULT_SEED
from physink_tui.sim.evaluate import make_problem
from physink_tui.sim.search import Search
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import Executor, ProcessExecutor, SerialExecutor

RESTORED = JOURNALS / "restored"


@dataclasses.dataclass
class Row:
    name: str
    group: str
    needle: float | None
    found_at: int | None
    rollouts: int
    wall: float
    grid_found_at: int | None
    grid_rollouts: int
    grid_wall: float
    commit: str = ""
    """The commit the grid and scan figures were measured on."""

    @property
    def ratio(self) -> float | None:
        if self.found_at is None or self.grid_found_at is None:
            return None
        return self.found_at / self.grid_found_at


def simulate_table(path: str) -> dict[str, tuple[int | None, int, float]]:
    """bench_simulate.py's grid figures per scene in ``path``: (found at, rollouts run, wall seconds)."""
    doc = Path(path).read_text(encoding="utf-8")
    table = doc.split("<!-- bench_simulate -->", 1)[1].split("<!-- /bench_simulate -->", 1)[0]
    out = {}
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 10 or not cells[3][:1].isdigit():
            continue
        rollouts, wall = cells[3].split(", ")
        equivalent = cells[9]
        found = int(equivalent.split("(")[1].split(" / ")[0]) if "(" in equivalent and "none" not in equivalent \
            and equivalent != "—" else None
        out[cells[0]] = (found, int(rollouts), float(wall.removesuffix(" s")))
    return out


def executor(workers: int) -> Executor:
    return ProcessExecutor(workers) if workers > 1 else SerialExecutor()


def searched(scene, timeline, canvas, strategy: str, budget: int, args) -> tuple[int | None, int, float]:
    """Found at, rollouts run, wall seconds (pool start included) of one search."""
    start = time.perf_counter()
    s = Search(scene, timeline, canvas, strategy=strategy, seed=args.seed, budget=budget)
    problem = make_problem(scene, timeline, canvas, by_leg=s.by_leg)
    ex = executor(args.workers)
    try:
        run_search(s, problem, ex)
    finally:
        ex.close()
    return s.found_at, s.rollouts, round(time.perf_counter() - start, 3)


def cases(args):
    """(name, group, scene, timeline, canvas) of every case asked for, constructed ones generated as they come."""
    for seed in seeds(args.possible):
        s = possible(seed).session()
        yield f"possible-{seed}", "constructed", s.scene, s.timeline, s.canvas
    for seed in seeds(args.springs):
        s = spring_case(seed).session()
        yield f"spring-{seed}", "spring", s.scene, s.timeline, s.canvas
    if not args.journals:
        return
    if args.journals == "all":
        wanted = [*journal_names(), *(f"restored/{n}" for n in journal_names(RESTORED))]
    else:
        wanted = args.journals.split(",")
    for folder, group in ((JOURNALS, "thesis"), (RESTORED, "restored")):
        prefix = "restored/" if group == "restored" else ""
        names = [n[len(prefix):] for n in wanted if (n.startswith("restored/") == bool(prefix))]
        for name, project in replayed_projects(names, "bench_efficiency", folder).items():
            if project.timeline is None or not project.timeline.events:
                raise SystemExit(f"bench_efficiency: {prefix}{name} has no demonstration")
            yield f"{prefix}{name}", group, project.scene, project.timeline, project.canvas


def _median(values) -> str:
    values = list(values)
    return f"{statistics.median(values):.3g}" if values else "—"


def _pct(values, q: float = 0.9) -> str:
    values = list(values)
    return f"{percentile(values, q):.3g}" if values else "—"


def summary(rows: list[Row], args, command: str) -> str:
    reused = ", ".join(sorted({r.commit for r in rows}))
    load = (f"load average {args.load:.1f} at the start, {os.getloadavg()[0]:.1f} at the end (other engineers' work)"
            if not getattr(args, "from_rows", None) else "rows of earlier runs (their load is told beside)")
    lines = [f"Written {datetime.now(UTC):%Y-%m-%d %H:%M} UTC, commit {args.commit}: `{command}`; "
             f"{os.cpu_count()} cpus, {args.workers} workers, CPython {platform.python_version()}; {load}.",
             *([f"The grid's and the scan's figures are reused from a run on commit(s) {reused} (`--reuse`); "
                f"{args.rechecked}"] if args.reuse else []), "",
             f"Rollouts (R) and wall seconds (W) to an equivalent: the default (budget {args.budget}) and the grid "
             f"(budget {args.grid_budget}), median / 90th percentile (the worst decile starts there) over the cases "
             "each finds; ratio = default / grid rollouts to an equivalent where both find one.", "",
             "| needle-ness | cases | default found | grid found | default R | grid R | ratio: median (10th-90th) "
             "| default W | grid W |", "|---|---:|---:|---:|---|---|---|---|---|"]
    groups: dict[str, list[Row]] = {}
    for r in rows:
        groups.setdefault(bucket(r.needle), []).append(r)
    for name in [*(n for _, n in BUCKETS), "not scanned", "all"]:
        rs = rows if name == "all" else groups.get(name, [])
        if not rs:
            continue
        d = [r for r in rs if r.found_at is not None]
        g = [r for r in rs if r.grid_found_at is not None]
        ratios = [r.ratio for r in rs if r.ratio is not None]
        lines.append(f"| {name} | {len(rs)} | {len(d)} | {len(g)} | {_median(r.found_at for r in d)} / "
                     f"{_pct(r.found_at for r in d)} | {_median(r.grid_found_at for r in g)} / "
                     f"{_pct(r.grid_found_at for r in g)} | {_median(ratios)} ({_pct(ratios, 0.1)}-{_pct(ratios)}) | "
                     f"{_median(r.wall for r in d)} / {_pct(r.wall for r in d)} | {_median(r.grid_wall for r in g)} / "
                     f"{_pct(r.grid_wall for r in g)} |")
    lines.append("")
    by_group = {}
    for r in rows:
        by_group.setdefault(r.group, []).append(r)
    for group, rs in by_group.items():
        ratios = [r.ratio for r in rs if r.ratio is not None]
        fewer = sum(x < 1 for x in ratios)
        more = sum(x > 1 for x in ratios)
        lines.append(f"- {group}: {len(rs)} cases; default found {sum(r.found_at is not None for r in rs)}, grid "
                     f"{sum(r.grid_found_at is not None for r in rs)}, both {len(ratios)}; ratio median "
                     f"{_median(ratios)}; the default needs fewer rollouts in {fewer}, more in {more}, as many in "
                     f"{len(ratios) - fewer - more}; only the default finds one in "
                     f"{sum(r.found_at is not None and r.grid_found_at is None for r in rs)}, only the grid in "
                     f"{sum(r.found_at is None and r.grid_found_at is not None for r in rs)}.")
    lines += ["", "Per case (needle-ness as the equivalent share of the scan; found at / rollouts run / wall s; "
              "\"—\" not found):", "", "| case | needle | default | grid | ratio |", "|---|---:|---|---|---:|"]
    for r in rows:
        needle = "—" if r.needle is None else f"{100 * r.needle:.0f} %"
        ratio = "—" if r.ratio is None else f"{r.ratio:.3g}"
        lines.append(f"| {r.name} | {needle} | {r.found_at or '—'} / {r.rollouts} / {r.wall:.2f} | "
                     f"{r.grid_found_at or '—'} / {r.grid_rollouts} / {r.grid_wall:.2f} | {ratio} |")
    return "\n".join(lines)


def write(path: str, text: str) -> None:
    doc = Path(path).read_text(encoding="utf-8")
    begin, end = "<!-- bench_efficiency -->", "<!-- /bench_efficiency -->"
    if begin not in doc or end not in doc:
        raise SystemExit(f"bench_efficiency: {path} has no {begin} ... {end} markers")
    head, rest = doc.split(begin, 1)
    _, tail = rest.split(end, 1)
    Path(path).write_text(f"{head}{begin}\n{text}\n{end}{tail}", encoding="utf-8")


def from_rows(args, command: str) -> int:
    rows = []
    for path in args.from_rows.split(","):
        with open(path, encoding="utf-8") as f:
            rows += [Row(**r) for r in map(json.loads, f)]
    args.commit = ", ".join(sorted({r.commit for r in rows}))
    args.reuse = None
    text = summary(rows, args, command)
    print(text)
    if args.write:
        write(args.write, text)
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--possible", default="5000-5059")
    parser.add_argument("--springs", default="5000-5019")
    parser.add_argument("--journals", default="all")
    parser.add_argument("--budget", type=int, default=DEFAULT_BUDGET)
    parser.add_argument("--grid-budget", type=int, default=3000)
    parser.add_argument("--seed", type=int, default=DEFAULT_SEED)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--scan", type=int, default=10)
    parser.add_argument("--rows")
    parser.add_argument("--reuse")
    parser.add_argument("--recheck", type=int, default=10)
    parser.add_argument("--write")
    parser.add_argument("--from-rows")
    parser.add_argument("--grid-from-table")
    args = parser.parse_args(argv)
    args.load = os.getloadavg()[0]
    root = Path(__file__).resolve().parent.parent
    args.commit = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"], capture_output=True,
                                 text=True, check=False).stdout.strip() or "unknown"
    command = "benchmarks/bench_efficiency.py " + shlex.join(argv if argv is not None else sys.argv[1:])
    if args.from_rows:
        return from_rows(args, command)
    rows: list[Row] = []
    out = open(args.rows, "w", encoding="utf-8") if args.rows else None
    earlier = {}
    if args.reuse:
        with open(args.reuse, encoding="utf-8") as f:
            earlier = {r["name"]: Row(**r) for r in map(json.loads, f)}
    recheck = sorted((r for r in earlier.values()), key=lambda r: (r.grid_rollouts, r.name))[: args.recheck]
    same = 0
    tabled = simulate_table(args.grid_from_table) if args.grid_from_table else {}
    scanner = executor(args.workers)
    try:
        for name, group, scene, timeline, canvas in cases(args):
            found_at, rollouts, wall = searched(scene, timeline, canvas, "default", args.budget, args)
            if name in earlier:
                e = earlier[name]
                share, g_at, g_rollouts, g_wall, commit = (e.needle, e.grid_found_at, e.grid_rollouts, e.grid_wall,
                                                           e.commit)
                if e in recheck:
                    again = searched(scene, timeline, canvas, "grid", args.grid_budget, args)
                    same += again[:2] == (g_at, g_rollouts)
            else:
                if group == "thesis" and name in tabled:
                    g_at, g_rollouts, g_wall = tabled[name]
                else:
                    g_at, g_rollouts, g_wall = searched(scene, timeline, canvas, "grid", args.grid_budget, args)
                share = needle_of(scene, timeline, canvas, scanner, args.scan)
                commit = args.commit
            row = Row(name, group, share, found_at, rollouts, wall, g_at, g_rollouts, g_wall, commit)
            rows.append(row)
            print(json.dumps(dataclasses.asdict(row)), flush=True)
            if out is not None:
                out.write(json.dumps(dataclasses.asdict(row)) + "\n")
                out.flush()
    finally:
        scanner.close()
        if out is not None:
            out.close()
    args.rechecked = (f"the grid run again on the {len(recheck)} of them it needed the fewest rollouts for gives the "
                      f"same rollouts on {same}.")
    text = summary(rows, args, command)
    print(text)
    if args.write:
        write(args.write, text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
