"""Benchmark: over which seeds the default search finds an equivalent simulation of a journal, this checkout beside
another commit (issue 27: the portfolio cup dispenser was found at a few seeds of 16).

Usage: nice -n 10 .venv/bin/python benchmarks/bench_seeds.py [--journals cup_dispenser,...] [--seeds 0-15]
       [--budget 200] [--workers 2] [--against main]

Each journal of tests/journals (``--journals``: names without ``.physink.jsonl``; ``restored/NAME`` for
tests/journals/restored) is replayed once and searched with the default strategy, the default budget and each seed,
on ``--workers`` local processes, as ``physink simulate PROJECT --seed N`` does. With ``--against REF`` the same
searches run on the code of that git commit too (``git archive REF`` into a temporary folder, this script run there
by the same Python and libraries, each reading its own tests/journals), seed by seed in turn, so both see
the same load. Per journal and seed: the rollout at which each finds an equivalent ("—" none within the budget) and
the leading legs the furthest candidate reproduces then; the counts found; the wall seconds (a search's, starting
its worker pool included; they depend on the machine's load, the rollouts do not).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CODE = Path(os.environ.get("BENCH_SEEDS_CODE", ROOT))
"""Whose code a ``--one`` search runs: this checkout, or the extracted commit of ``--against``."""
sys.path.insert(0, str(CODE))
sys.path.insert(0, str(CODE / "benchmarks"))


def seed_range(text: str) -> list[int]:
    """``"0-15"`` or ``"0,3,5-7"`` as a list of ints."""
    out: list[int] = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        out.extend(range(int(lo), int(hi or lo) + 1))
    return out


def search_one(journal: str, seed: int, budget: int, workers: int) -> dict[str, object]:
    """One default search of ``journal`` (this checkout's code) at ``seed``: found at, rollouts, legs, wall."""
    from journal_projects import JOURNALS, replayed_projects

    from physink_tui.sim.evaluate import make_problem
    from physink_tui.sim.search import Search, progress
    from physink_tui.sim_run.driver import run_search
    from physink_tui.sim_run.executors import ProcessExecutor

    folder, _, name = journal.rpartition("/")
    project = replayed_projects([name], "bench_seeds", JOURNALS / folder if folder else JOURNALS)[name]
    assert project.timeline is not None
    start = time.perf_counter()
    search = Search(project.scene, project.timeline, project.canvas, seed=seed, budget=budget)
    with ProcessExecutor(workers) as executor:
        run_search(search, make_problem(project.scene, project.timeline, project.canvas), executor)
    wall = time.perf_counter() - start
    legs = -progress(search.furthest_score)[0] if search.furthest_score is not None else 0
    best = search.best_score.qualitative if search.best_score is not None else None
    return {"journal": journal, "seed": seed, "found_at": search.found_at, "rollouts": search.rollouts,
            "legs": legs, "of": len(search.furthest_score.legs) if search.furthest_score else 0,
            "qualitative": best, "wall": round(wall, 2)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--journals", default="cup_dispenser")
    parser.add_argument("--seeds", default="0-15")
    parser.add_argument("--budget", type=int, default=None)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--against", default=None, help="a git commit to run beside this checkout")
    parser.add_argument("--one", default=None, help=argparse.SUPPRESS)  # journal:seed, run here, print a JSON row
    args = parser.parse_args(argv)
    from physink_tui.sim.defaults import DEFAULT_BUDGET

    budget = args.budget or DEFAULT_BUDGET
    if args.one:
        journal, _, seed = args.one.rpartition(":")
        print(json.dumps(search_one(journal, int(seed), budget, args.workers)))
        return 0
    journals, seeds = args.journals.split(","), seed_range(args.seeds)
    with tempfile.TemporaryDirectory() as tmp:
        codes = {"this": ROOT}
        if args.against:
            archive = Path(tmp) / "ref.tar"
            subprocess.run(["git", "-C", str(ROOT), "archive", "-o", str(archive), args.against], check=True)
            with tarfile.open(archive) as tar:
                tar.extractall(Path(tmp) / "ref", filter="data")
            codes = {args.against: Path(tmp) / "ref", "this": ROOT}
        rows: dict[tuple[str, str, int], dict] = {}
        for journal in journals:
            for seed in seeds:
                for label, code in codes.items():
                    command = [sys.executable, str(Path(__file__).resolve()), "--one", f"{journal}:{seed}",
                               "--budget", str(budget), "--workers", str(args.workers)]
                    done = subprocess.run(command, cwd=code, capture_output=True, text=True, check=True,
                                          env={**os.environ, "BENCH_SEEDS_CODE": str(code)})
                    row = rows[(label, journal, seed)] = json.loads(done.stdout.strip().splitlines()[-1])
                    print(f"{label:>8} {journal} seed {seed}: found at {row['found_at']}, legs {row['legs']}/"
                          f"{row['of']}, {row['wall']} s", file=sys.stderr, flush=True)
    labels = list(codes)
    print(f"Budget {budget}, {args.workers} workers; found at (rollout) per seed, '—' not found (leading legs "
          "reproduced / legs)\n")
    print("| journal | seed | " + " | ".join(labels) + " |")
    print("|---|---:|" + "---|" * len(labels))
    for journal in journals:
        for seed in seeds:
            cells = []
            for label in labels:
                r = rows[(label, journal, seed)]
                cells.append(str(r["found_at"]) if r["found_at"] else f"— ({r['legs']}/{r['of']})")
            print(f"| {journal} | {seed} | " + " | ".join(cells) + " |")
        for label in labels:
            found = [rows[(label, journal, s)] for s in seeds if rows[(label, journal, s)]["found_at"]]
            walls = [rows[(label, journal, s)]["wall"] for s in seeds]
            print(f"\n{journal}, {label}: found at {len(found)} of {len(seeds)} seeds "
                  f"({', '.join(str(r['seed']) for r in found) or 'none'}); wall median "
                  f"{statistics.median(walls):.1f} s, max {max(walls):.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
