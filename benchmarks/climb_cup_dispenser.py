"""Hill-climb towards a witness of the cup dispenser's full demonstration (issue 27), offline, not in CI.

Usage: nice -n 10 .venv/bin/python benchmarks/climb_cup_dispenser.py --from ROWS.jsonl[,MORE.jsonl] --rows OUT.jsonl
       [--start 80] [--evals 2000] [--seed 1] [--frictionless b4,b7] [--energy] [--kmax 4] [--workers 2]

benchmarks/scan_cup_dispenser.py samples the whole space and runs CMA-ES on the search's own scores; none of its
49,099 rollouts reproduced the seventh leg ("End of contact between peg and platform", caused by the peg's movement).
The landscape there is a cliff: a small step from a candidate reproducing six legs mostly loses one of them (the cup
bouncing on the platform is chaotic), and the search's score of the seventh leg is 0 or 1. This climbs instead on a
score shaped by what the recorder needs for that end-contact and the demonstrated ending (the peg back left of the
platform, knocking its side), read from every step of the rollout (a spy on `Recorder.observe`):

- fewer than six legs: 1e5 x the legs missing + 1000 x the next leg's qualitative distance + its quantitative one;
- six legs (up to "Contact between cup and peg"): 1000 x the seventh leg's qualitative distance + 100 x the whole's +
  3 x how far the peg's right end stays right of the platform's left side after the cup-peg contact (2.5 s) + 2 x how
  far the platform's top is below the peg's bottom when the peg's end comes within 8 units of that side + the
  platform's speed over the 0.12 s before, above 4 units/s + 0.3 x the cup's speed then, above 4, if it touches the
  platform (a moving cup on the platform explains the platform's start, not the parting) + 300 per body flagged
  faster than demo mode's limit; ``--energy`` adds 300 x (2 - G) when G < 2, G the peg's largest energy (kinetic plus
  its spring's) while moving left in the 0.6 s after the contact over the energy its spring held at the start (the peg
  starts at rest against the platform, so only the cup can give it the G > 1 that takes it back past its start, and
  its spring's damping takes about half of it per swing);
- seven legs or more: 100 x the whole's qualitative distance + 300 per flag when the peg's right end is left of the
  platform's side as the end-contact is recorded (the demonstrated parting, which the knock on that side needs);
  otherwise (the platform, pinned under the peg, parted from it for a step: a jitter) as six legs, the seventh leg's
  distance counted as 1.

Each step: 12 children of the 6 best (70 %) or the 12 best, every coordinate moved with probability 1/2 by a normal step
of 0.02-0.2 in the search's normalised coordinates (`sim.coordinates.Normalisation`); ``--frictionless`` keeps those
bodies' frictions at 0 (a pair's friction is the mean of the two, so peg and platform at 0 slide freely). The start: the
``--start`` candidates of ``--from`` reproducing six legs or more (unflagged; with ``--kmax``, the peg spring's k below
it), most legs first, then (rows of an earlier climb) lowest cost first. Rows hold the parameters, the costs' parts and
the legs; a candidate at qualitative 0 is printed as a witness.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

from scan_cup_dispenser import CUP, FULL, PEG, PLATFORM, decode, encode, load  # noqa: E402

from physink_tui.sim.coordinates import Normalisation, coordinates  # noqa: E402
from physink_tui.sim.evaluate import Problem, make_problem, simulate  # noqa: E402
from physink_tui.sim.legs import legs  # noqa: E402
from physink_tui.sim.parameters import Parameters  # noqa: E402
from physink_tui.sim.seeding import seed  # noqa: E402
from physink_tui.sim_run.executors import ProcessExecutor, share, shared  # noqa: E402
from physink_tui.timeline import recorder as recorder_module  # noqa: E402
from physink_tui.timeline.equivalence import compare_prefixes, prepare  # noqa: E402
from physink_tui.timeline.qualitative import outline_of  # noqa: E402

Row = dict[str, Any]
STEPS: list[tuple[float, dict[str, tuple[float, ...]], frozenset[frozenset[str]]]] = []
"""Every step of the rollout being scored: time, the four bodies' motions, the pairs touching."""
_observe = recorder_module.Recorder.observe


def _spying(self: recorder_module.Recorder, obs: Any) -> None:
    STEPS.append((obs.t, {b: tuple(obs.poses[b]) for b in (PLATFORM, CUP, PEG) if b in obs.poses}, obs.touching))
    _observe(self, obs)


recorder_module.Recorder.observe = _spying  # type: ignore[method-assign]  # this script's processes only


class Geometry:
    """What the score measures against, from the drawn scene: the peg's half-length and half-height, the platform's
    left side and half-height, the peg spring's drawn length and the peg's drawn x."""

    def __init__(self, problem: Problem) -> None:
        peg, platform = problem.scene.components[PEG], problem.scene.components[PLATFORM]
        peg_hull, platform_hull = outline_of(peg).hull, outline_of(platform).hull  # type: ignore[arg-type]
        self.peg_half = max(x for x, _ in peg_hull)
        self.peg_half_h = max(y for _, y in peg_hull)
        self.platform_half_h = max(y for _, y in platform_hull)
        self.platform_left = platform.position[0] + min(x for x, _ in platform_hull)  # type: ignore[union-attr]
        spring = problem.scene.components["s2"]
        self.spring_drawn = abs(spring.anchor_b[0] - spring.anchor_a[0])  # type: ignore[union-attr]
        self.peg_x = peg.position[0]  # type: ignore[union-attr]


def score(p: Parameters) -> Row:
    problem, geo, energy = shared("climb_cup")
    STEPS.clear()
    row: Row = {"params": encode(p)}
    try:
        result = simulate(problem, p)
    except Exception as exc:  # out-of-range parameters: as the search, discarded
        return {**row, "cost": 1e9, "error": repr(exc)[:80]}
    if result.stopped_because == "exploded":
        return {**row, "cost": 1e9, "error": "exploded"}
    steps = list(STEPS)
    names = problem.scene.names()
    whole, prefixes = compare_prefixes(prepare(problem.timeline, names), prepare(result.timeline, names),
                                       tuple(leg.events for leg in legs(problem.timeline)), simulation=True)
    lead = next((k for k, d in enumerate(prefixes) if d.qualitative_distance != 0), len(prefixes))
    flags = sum(1 for f in result.flagged if "limit" in f or "tunnel" in f)
    row.update(q=whole.qualitative_distance, lead=lead, legq=[d.qualitative_distance for d in prefixes], flags=flags)
    if lead < 6:
        return {**row, "cost": 1e5 * (6 - lead) + 1000 * prefixes[lead].qualitative_distance
                + prefixes[lead].quantitative_distance}
    events = result.timeline.events
    knock = min(e.t0 for e in events if e.type == "contact" and set(e.components) == {CUP, PEG})
    seventh = prefixes[6].qualitative_distance
    if lead >= 7:
        parted = min(e.t0 for e in events if e.type == "end_contact" and set(e.components) == {PLATFORM, PEG}
                     and e.t0 > knock)
        at = min(steps, key=lambda s: abs(s[0] - parted))
        row["R20"] = at[1][PEG][0] + geo.peg_half
        if row["R20"] < geo.platform_left:  # the peg slid off the platform's left end: the demonstrated parting
            return {**row, "cost": 100 * whole.qualitative_distance + 300 * flags}
        seventh = 1.0  # the platform jittering under the peg: scored as six legs
    after = [s for s in steps if knock <= s[0] <= knock + 2.5]
    farthest = min(s[1][PEG][0] for s in after) + geo.peg_half
    near = next((s for s in after if s[1][PEG][0] + geo.peg_half < geo.platform_left + 8),
                min(after, key=lambda s: s[1][PEG][0]))
    t, bodies, touching = near
    gap = (bodies[PLATFORM][1] - geo.platform_half_h) - (bodies[PEG][1] + geo.peg_half_h)
    platform_speed = max((math.hypot(s[1][PLATFORM][3], s[1][PLATFORM][4]) for s in after if t - 0.12 <= s[0] <= t),
                         default=0.0)
    cup_on = frozenset((CUP, PLATFORM)) in touching
    cup_speed = math.hypot(bodies[CUP][3], bodies[CUP][4])
    k, rest, m = p.springs["s2"].k * 1e4, p.springs["s2"].rest_length, p.bodies[PEG].mass

    def held(s: tuple[float, dict[str, tuple[float, ...]], Any]) -> float:  # the peg's energy, kinetic and spring's
        x, vx = s[1][PEG][0], s[1][PEG][3]
        return 0.5 * m * vx * vx + 0.5 * k * (rest - (x - geo.peg_x + geo.spring_drawn)) ** 2

    start = 0.5 * k * (rest - geo.spring_drawn) ** 2
    gain = max((held(s) for s in after if s[0] <= knock + 0.6 and s[1][PEG][3] < 0), default=0.0) / max(start, 1e-9)
    cost = (1000 * seventh + 100 * whole.qualitative_distance
            + 3 * max(0.0, farthest - (geo.platform_left - 1)) + 2 * max(0.0, gap - 0.5)
            + max(0.0, platform_speed - 4) + (0.3 * max(0.0, cup_speed - 4) if cup_on else 0.0) + 300 * flags)
    if energy:
        cost += 300 * max(0.0, 2.0 - gain)
    return {**row, "R": farthest, "gap": gap, "vplat": platform_speed, "vcup": cup_speed, "cup_on": cup_on,
            "gain": gain, "cost": cost}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--from", dest="sources", required=True)
    ap.add_argument("--rows", type=Path, required=True)
    ap.add_argument("--start", type=int, default=80)
    ap.add_argument("--evals", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--frictionless", default="")
    ap.add_argument("--energy", action="store_true")
    ap.add_argument("--kmax", type=float, default=math.inf)
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args()
    started = time.time()
    session = load(FULL)
    problem = make_problem(session.scene, session.timeline, session.canvas)
    base = seed(session.scene, session.timeline, session.canvas)
    share("climb_cup", (problem, Geometry(problem), args.energy))
    frictionless = [b for b in args.frictionless.split(",") if b]

    def fixed(d: Row) -> Row:
        for b in frictionless:
            d["bodies"][b][1] = 0.0
        return d

    earlier = [json.loads(line) for path in args.sources.split(",") for line in Path(path).open()]
    earlier = [r for r in earlier if int(r.get("lead") or r.get("legs") or 0) >= 6 and not r.get("flags")
               and r["params"]["springs"]["s2"][0] < args.kmax]
    earlier.sort(key=lambda r: (-int(r.get("lead") or r.get("legs") or 0), float(r.get("cost", 0.0))))
    rng = random.Random(args.seed)
    archive: list[Row] = []
    with args.rows.open("w") as out, ProcessExecutor(args.workers) as executor:
        def run(batch: list[Row]) -> None:
            for r in executor.map(score, [decode(fixed(d)) for d in batch]):
                archive.append(r)
                out.write(json.dumps(r) + "\n")
                if r.get("q") == 0:
                    print("witness:", json.dumps(r["params"]), flush=True)
            out.flush()

        run([r["params"] for r in earlier[:args.start]])
        while len(archive) < args.evals and not any(r.get("q") == 0 for r in archive):
            top = sorted(archive, key=lambda r: r["cost"])[:12]
            batch = []
            for _ in range(12):
                parent = decode(rng.choice(top[:6] if rng.random() < 0.7 else top)["params"])
                norm = Normalisation(coordinates(parent, ("vx", "vy")), parent, base)
                sigma = rng.choice((0.02, 0.05, 0.1, 0.2))
                batch.append(encode(norm.decode([rng.gauss(0, sigma) if rng.random() < 0.5 else 0.0
                                                 for _ in norm.coords])))
            run(batch)
            best = min(archive, key=lambda r: r["cost"])
            print(f"{len(archive)} rollouts, {time.time() - started:.0f} s: best cost {best['cost']:.0f}, "
                  f"qualitative {best.get('q')}, legs {best.get('lead')}", flush=True)
    leads = Counter(int(r.get("lead") or 0) for r in archive)
    done = [r for r in archive if r["cost"] < 1e9]
    print(f"\n{len(archive)} rollouts in {time.time() - started:.0f} s; leading legs reproduced: "
          f"{dict(sorted(leads.items()))}; best qualitative {min((r['q'] for r in done), default=math.inf)}")
    seven = [r for r in done if int(r.get("lead") or 0) >= 7]
    if seven:
        off = sum(1 for r in seven if r["R20"] < 767.9)
        print(f"seven legs or more: {len(seven)}; the peg's right end at the end-contact, left of the platform's "
              f"side in {off}; unflagged {sum(1 for r in seven if not r['flags'])}")
    six = [r for r in done if int(r.get("lead") or 0) == 6]
    if six:
        print(f"six legs: {len(six)}; the peg's end back past the platform's side in "
              f"{sum(1 for r in six if r['R'] < 767.9)}, and the platform then pressed under it "
              f"{sum(1 for r in six if r['R'] < 767.9 and r['gap'] < 0.5)}; the peg's energy gain above 1 in "
              f"{sum(1 for r in six if r['gain'] > 1)}")


if __name__ == "__main__":
    main()
