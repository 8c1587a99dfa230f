"""Scan: is there any simulation of the cup dispenser's full demonstration (issue 27)? Offline, not in CI.

Usage: nice -n 10 .venv/bin/python benchmarks/scan_cup_dispenser.py [--random 12000] [--around 12000]
       [--cma 6x800] [--push 6x800] [--end 0x0] [--workers 2] [--seed 0] [--rows FILE.jsonl]
       [--start-rows EARLIER.jsonl]

The journal is tests/journals/restored/cup_dispenser_full.physink.jsonl (the demonstration before dd04c71: the
let-go peg springs back past the platform's left end and knocks its side). Every candidate is the search's own
`Parameters` (the ball's launch velocity; mass and friction of ball, platform, cup and peg; k and natural length of
both springs), rolled out and compared exactly as SIMULATE does (`sim.evaluate.simulate`, `compare_prefixes` with the
legs of `sim.legs`). Three phases, all seeded (the rows depend only on the arguments):

- ``random``: the whole space at once: launch velocity uniform in vx -300..1500, vy -1000..1200 units/s; every mass
  and spring constant log-uniform within x1/16..x16 of the seed (thesis 3.4.3: area x 1.0, k 20); frictions 0..1;
  natural lengths 0.25..2.5 times the drawn ones.
- ``around``: the same ranges for everything but the launch, which is taken near (normal, 60 units/s) the launch
  of an anchor: the best and the furthest candidates (`Search.best`, `Search.furthest`) of the default search at seeds
  0-2 on the shorter demonstration (tests/journals/cup_dispenser, where the best of seed 0 is equivalent) and on the
  full one: launches that put the ball in the cup; half of these candidates also keep the other parameters near
  that anchor's (log-normal 0.3, friction +-0.15, natural length x N(1, 0.1)).
- ``cma``: runs of CMA-ES (pycma, seeded) on the search's objective over every coordinate at once
  (`sim.coordinates.Normalisation`), each from one of the best distinct candidates so far.
- ``push``: the same, on what decides the end (below): among candidates reproducing the demonstration up to the
  cup-peg contact, take the peg as far left as possible after it.
- ``end`` (``--end``, none by default): the same on the search's score of the seventh leg (up to the peg's end of
  contact with the platform), from candidates reproducing six legs whose peg went back past its start (those of
  ``--start-rows`` too; the farthest first).

Per candidate the row holds the parameters, the qualitative distance, the leading legs reproduced, and what decides
the demonstration's end: how far left of where it started (flush against the platform's left side) the peg goes
after its contact with the cup, before any other contact (``peg_left``; a body falling on the peg is another event).
The demonstrated ending needs the peg back past its start (``peg_left`` > 0: its right end left of the platform's
side, which it then meets), and the end of the peg's contact with the platform recorded as caused by the peg's
movement: the recorder (`timeline.recorder`, a resting body starting to move within a second of parting from
another) records it when the platform, at rest against the peg, starts moving once the peg has left it.

``--why ROWS.jsonl[,MORE.jsonl]``: runs nothing new but the candidates of earlier rows that reproduce the first six
legs (up to the cup-peg contact), and counts how their end of the peg's contact with the platform comes about.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from physink_tui.errors import SimulationError  # noqa: E402
from physink_tui.formats.journal.reader import read_journal  # noqa: E402
from physink_tui.session.session import Session  # noqa: E402
from physink_tui.sim.coordinates import Normalisation, coordinates  # noqa: E402
from physink_tui.sim.defaults import DEFAULT_BUDGET  # noqa: E402
from physink_tui.sim.evaluate import EXPLODED_SCORE, Problem, make_problem, simulate  # noqa: E402
from physink_tui.sim.legs import legs  # noqa: E402
from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters  # noqa: E402
from physink_tui.sim.rollout import Stop  # noqa: E402
from physink_tui.sim.search import Search  # noqa: E402
from physink_tui.sim.seeding import seed  # noqa: E402
from physink_tui.sim_run.driver import run_search  # noqa: E402
from physink_tui.sim_run.executors import ProcessExecutor, SerialExecutor, share, shared  # noqa: E402
from physink_tui.timeline.equivalence import compare_prefixes, prepare  # noqa: E402

JOURNALS = ROOT / "tests" / "journals"
FULL = JOURNALS / "restored" / "cup_dispenser_full.physink.jsonl"
SHORT = JOURNALS / "cup_dispenser.physink.jsonl"
BALL, PLATFORM, CUP, PEG = "b2", "b4", "b5", "b7"
VX, VY = (-300.0, 1500.0), (-1000.0, 1200.0)
SCALE = 16.0
REST = (0.25, 2.5)


Row = dict[str, Any]
"""One candidate's row (written as a JSON line)."""


def load(path: Path) -> Session:
    journal = read_journal(path)
    return Session.from_header(journal.header).run(journal.entries)


@dataclass(frozen=True, slots=True)
class Job:
    """What every worker shares: the problem, the demonstration prepared, its legs, the peg's start."""

    problem: Problem
    peg_x: float


def _row(job: Job, p: Parameters) -> Row:
    problem = job.problem
    names = problem.scene.names()
    row: Row = {"params": encode(p)}
    try:
        result = simulate(problem, p)
    except SimulationError as exc:  # out-of-range parameters: the search's exploded score too
        return {**row, "qualitative": EXPLODED_SCORE.qualitative, "exploded": repr(exc)[:80]}
    if result.stopped_because == Stop.EXPLODED:
        return {**row, "qualitative": math.inf, "exploded": "exploded"}
    demonstrated = prepare(problem.timeline, names)
    by_leg = tuple(leg.events for leg in legs(problem.timeline))
    whole, prefixes = compare_prefixes(demonstrated, prepare(result.timeline, names), by_leg, simulation=True)
    lead = 0
    for d in prefixes:
        if d.qualitative_distance != 0:
            break
        lead += 1
    events = result.timeline.events
    cup_peg = [ev for ev in events if ev.type == "contact" and set(ev.components) == {CUP, PEG}]
    peg_left = None
    if cup_peg:
        t = cup_peg[0].t0
        until = min((ev.t0 for ev in events if ev.type == "contact" and ev.t0 > t), default=math.inf)
        xs = [q.x for ev in events if ev.type == "movement" and ev.components and ev.components[0] == PEG
              for q in ev.trajectory if t <= q.t <= until]
        if xs:
            peg_left = job.peg_x - min(xs)
    return {**row, "qualitative": whole.qualitative_distance, "quantitative": whole.quantitative_distance,
            "legs": lead, "of": len(prefixes), "cup_peg": bool(cup_peg), "peg_left": peg_left,
            "by_leg": [[d.qualitative_distance, d.quantitative_distance] for d in prefixes]}


def evaluate_row(p: Parameters) -> Row:
    return _row(shared("scan_cup"), p)


def encode(p: Parameters) -> Row:
    return {"bodies": {k: [v.mass, v.friction] for k, v in sorted(p.bodies.items())},
            "springs": {k: [v.k, v.rest_length] for k, v in sorted(p.springs.items())},
            "velocities": {k: list(v) for k, v in sorted(p.velocities.items())}}


def decode(d: dict[str, dict[str, list[float]]]) -> Parameters:
    return Parameters({k: BodyParameters(*v) for k, v in d["bodies"].items()},
                      {k: SpringParameters(*v) for k, v in d["springs"].items()},
                      {k: (v[0], v[1]) for k, v in d["velocities"].items()})


def sample(rng: np.random.Generator, base: Parameters, launch: tuple[float, float] | None,
           near: Parameters | None) -> Parameters:
    """One candidate of the ``random`` (no ``launch``) or ``around`` phase (module docstring)."""
    if launch is None:
        v = (float(rng.uniform(*VX)), float(rng.uniform(*VY)))
    else:
        v = (launch[0] + float(rng.normal(0, 60)), launch[1] + float(rng.normal(0, 60)))
    bodies, springs = {}, {}
    for k, b in sorted(base.bodies.items()):
        if near is None:
            bodies[k] = BodyParameters(b.mass * SCALE ** float(rng.uniform(-1, 1)), float(rng.uniform(0, 1)))
        else:
            n = near.bodies[k]
            bodies[k] = BodyParameters(n.mass * math.exp(float(rng.normal(0, 0.3))),
                                       min(max(n.friction + float(rng.uniform(-0.15, 0.15)), 0.0), 1.0))
    for k, s in sorted(base.springs.items()):
        if near is None:
            springs[k] = SpringParameters(s.k * SCALE ** float(rng.uniform(-1, 1)),
                                          s.rest_length * float(rng.uniform(*REST)))
        else:
            n2 = near.springs[k]
            springs[k] = SpringParameters(n2.k * math.exp(float(rng.normal(0, 0.3))),
                                          max(n2.rest_length * float(rng.normal(1, 0.1)), 0.0))
    return Parameters(bodies, springs, {BALL: v})


def why(paths: list[Path]) -> None:
    """``--why``: how the candidates reproducing the first six legs end the peg's contact with the platform."""
    from collections import Counter

    session = load(FULL)
    problem = make_problem(session.scene, session.timeline, session.canvas)
    rows = [json.loads(line) for path in paths for line in path.open()]
    chosen = [r for r in rows if int(r.get("legs") or 0) >= 6]
    ends: Counter[str] = Counter()
    for r in chosen:
        timeline = simulate(problem, decode(r["params"])).timeline
        knocks = [ev.t0 for ev in timeline.events if ev.type == "contact" and set(ev.components) == {CUP, PEG}]
        parted = [ev for ev in timeline.events if ev.type == "end_contact" and set(ev.components) == {PLATFORM, PEG}
                  and knocks and ev.t0 > knocks[0]]
        if not parted:
            ends["no end of the peg's contact with the platform after the cup-peg contact"] += 1
        else:
            movers = sorted(timeline.event(c).components[0] for c in parted[0].causes)
            ends[f"the end of the peg's contact with the platform caused by the movement of {', '.join(movers)}"] += 1
    print(f"{len(chosen)} of {len(rows)} rows reproduce the first six legs:")
    for what, n in ends.most_common():
        print(f"  {n}: {what}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--random", type=int, default=12000)
    ap.add_argument("--around", type=int, default=12000)
    ap.add_argument("--cma", default="6x800", help="RUNSxEVALS")
    ap.add_argument("--push", default="6x800", help="RUNSxEVALS")
    ap.add_argument("--end", default="0x0", help="RUNSxEVALS")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--rows", type=Path, default=None)
    ap.add_argument("--start-rows", type=Path, default=None,
                    help="rows of an earlier run, among which the CMA-ES runs choose their starts (not run again)")
    ap.add_argument("--why", default=None, help="ROWS.jsonl[,MORE.jsonl]: explain earlier rows (runs nothing else)")
    args = ap.parse_args()
    if args.why:
        why([Path(p) for p in args.why.split(",")])
        return
    started = time.time()

    session = load(FULL)
    problem = make_problem(session.scene, session.timeline, session.canvas)
    base = seed(session.scene, session.timeline, session.canvas)
    share("scan_cup", Job(problem, session.scene.components[PEG].position[0]))

    anchors = []
    for demo in (load(SHORT), session):
        for s in (0, 1, 2):
            search = Search(demo.scene, demo.timeline, demo.canvas, seed=s, budget=DEFAULT_BUDGET)
            run_search(search, make_problem(demo.scene, demo.timeline, demo.canvas), SerialExecutor())
            for p in (search.best, search.furthest):
                if p is not None and p not in anchors:
                    anchors.append(p)
    print(f"anchors (the default search's best and furthest, both demonstrations, seeds 0-2): {len(anchors)}",
          flush=True)

    rng = np.random.default_rng(args.seed)
    rows: list[Row] = []
    out = args.rows.open("w") if args.rows else None

    def run(phase: str, candidates: list[Parameters], executor: ProcessExecutor) -> list[Row]:
        got = []
        for i in range(0, len(candidates), 256):
            for r in executor.map(evaluate_row, candidates[i:i + 256]):
                r["phase"] = phase
                got.append(r)
                if out is not None:
                    out.write(json.dumps(r) + "\n")
            if out is not None:
                out.flush()
            report(phase, got)
        rows.extend(got)
        return got

    if args.start_rows is not None:  # candidates of an earlier run: CMA-ES may start from them (not run again)
        rows.extend({**json.loads(line), "earlier": True} for line in args.start_rows.open())
    with ProcessExecutor(args.workers) as executor:
        run("anchors", anchors, executor)
        run("random", [sample(rng, base, None, None) for _ in range(args.random)], executor)
        around = []
        for i in range(args.around):
            anchor = anchors[i % len(anchors)]
            around.append(sample(rng, base, anchor.velocities[BALL], anchor if i % 2 else None))
        run("around", around, executor)
        runs, evals = (int(x) for x in args.cma.split("x"))
        cma_runs(rows, runs, evals, base, executor, run, args.seed, "cma", search_objective)
        runs, evals = (int(x) for x in args.push.split("x"))
        cma_runs(rows, runs, evals, base, executor, run, args.seed, "push", push_objective)
        runs, evals = (int(x) for x in args.end.split("x"))
        cma_runs([r for r in rows if r.get("legs", 0) >= 6 and (r.get("peg_left") or -1e9) > 0] or rows, runs, evals,
                 base, executor, run, args.seed, "end", lambda r: end_objective(r) if "by_leg" in r else
                 -float(r.get("peg_left") or -1e9))
    if out is not None:
        out.close()
    summary(rows, time.time() - started)


def search_objective(r: Row) -> float:
    """The search's own objective, without the miss term (1000 x qualitative + quantitative)."""
    q = float(r["qualitative"])
    return math.inf if not math.isfinite(q) else 1000.0 * q + float(r.get("quantitative") or 0.0)


def push_objective(r: Row) -> float:
    """Lower is better: among candidates reproducing the demonstration up to the cup-peg contact (6 legs), the peg
    taken farthest left after it; the others by how many legs they lack."""
    if not math.isfinite(float(r["qualitative"])):
        return 1e9
    lead = int(r["legs"])
    if lead >= 6 and r.get("peg_left") is not None:
        return -float(r["peg_left"])
    return 1000.0 * (6 - min(lead, 6)) + search_objective(r) / 1000.0


def end_objective(r: Row) -> float:
    """Lower is better: the search's score of the demonstration up to the peg's end of contact with the platform
    (the seventh leg: 1000 x qualitative + quantitative), for candidates reproducing the first six legs; the others
    by how many they lack."""
    if not math.isfinite(float(r["qualitative"])) or "by_leg" not in r:
        return 1e9
    lead = int(r["legs"])
    if lead >= 6:
        q, d = r["by_leg"][6]
        return 1000.0 * float(q) + float(d)
    return 1e6 * (6 - lead) + search_objective(r)


def cma_runs(rows: list[Row], runs: int, evals: int, base: Parameters, executor: ProcessExecutor,
             run: Callable[[str, list[Parameters], ProcessExecutor], list[Row]], seed_: int, phase: str,
             objective: Callable[[Row], float]) -> None:
    """CMA-ES on ``objective`` from the best distinct candidates so far by it (module docstring)."""
    import cma

    ranked = sorted((r for r in rows if math.isfinite(float(r["qualitative"]))), key=objective)
    starts: list[Parameters] = []
    for r in ranked:
        p = decode(r["params"])
        if all(abs(p.velocities[BALL][0] - s.velocities[BALL][0]) > 1 for s in starts):
            starts.append(p)
        if len(starts) == runs:
            break
    for n, start in enumerate(starts):
        norm = Normalisation(coordinates(start, ("vx", "vy")), start, base)
        es = cma.CMAEvolutionStrategy([0.0] * len(norm.coords), 0.5,
                                      {"seed": seed_ * 100 + n + 1, "popsize": 16, "verbose": -9})
        used = 0
        while used < evals and not es.stop():
            zs = es.ask()
            got = run(f"{phase}{n}", [norm.decode(z) for z in zs], executor)
            used += len(zs)
            es.tell(zs, [min(objective(r), 1e9) for r in got])


def report(phase: str, got: list[Row]) -> None:
    done = [r for r in got if math.isfinite(float(r["qualitative"]))]
    best = min((float(r["qualitative"]) for r in done), default=math.inf)
    print(f"{phase}: {len(got)} rollouts, best qualitative {best}", flush=True)


def summary(rows: list[Row], wall: float) -> None:
    rows = [r for r in rows if not r.get("earlier")]
    finite = [r for r in rows if math.isfinite(float(r["qualitative"]))]
    equivalent = [r for r in finite if float(r["qualitative"]) == 0]
    print(f"\n{len(rows)} rollouts in {wall:.0f} s; exploded or out of range {len(rows) - len(finite)}; "
          f"equivalent {len(equivalent)}")
    of = max((int(r["of"]) for r in finite), default=0)
    for phase in sorted({str(r["phase"]) for r in rows}):
        these = [r for r in finite if r["phase"] == phase]
        counts = [sum(1 for r in these if int(r["legs"]) >= k) for k in range(of + 1)]
        best = min((float(r["qualitative"]) for r in these), default=math.inf)
        print(f"{phase}: {len(these)} rollouts; best qualitative {best}; leading legs reproduced >= k, k=0..{of}: "
              f"{counts}")
    cup = [r for r in finite if r.get("peg_left") is not None]
    lead6 = [r for r in cup if int(r["legs"]) >= 6]
    for name, rs in (("with a cup-peg contact", cup), ("reproducing the demonstration up to the cup-peg contact",
                                                       lead6)):
        far = max((float(r["peg_left"]) for r in rs), default=math.nan)
        print(f"{name}: {len(rs)} rollouts; the peg's farthest travel left of its start after that contact, before "
              f"any other contact: {far:.1f} units (needed: > 0)")
    if equivalent:
        print("witness:", json.dumps(equivalent[0]["params"]))


if __name__ == "__main__":
    main()
