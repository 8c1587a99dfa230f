"""SIMULATE: searches parameters for a gravity timeline equivalent to the demo's; no I/O, clock or UI.

- `parameters.py`: frozen `Parameters` (per movable body mass and friction, per spring k and rest length, per
  start-moved body its initial velocity; restitution stays by shape class, ropes have none); `apply(scene,
  parameters)` writes masses as densities (mass / area), frictions and springs into a `Scene`; `structure()` is the
  key under which candidates settle alike
- `seeding.py`: `seed(scene, timeline, canvas)`: thesis 3.4.3 (mass = area x 1.0, friction 1.0/0.0 by shape class, k
  = 20, sketched rest length) and the start-moved bodies' velocity found through the timeline's causes: the
  ballistic launch under gravity to where the body made its first contact, in the demonstrated time clamped to
  0.5-2x the slowest-launch time (along the axis for a body on a spring); `seed_family(..., factors)`: the same
  destinations reached in other flight times
- `rollout.py`: `settled_state` → `Settled` (gravity, start bodies held kinematic, damped, unrecorded, until below 1
  unit/s or 6 s; a body that moves > 10 units is held at its drawn pose and settling starts again, up to 4 rounds)
  and `rollout_from` (a world forked warm from that state, start velocities given, every other body asleep until
  touched — `World.hold_until_touched`, groups tied by constraints or touching wake together —, observed and
  recorded as demo mode does, steps divided into sub-steps when a body would cross the thinnest body, stopped when
  every body rests or is gone off the canvas's sides or bottom, or at `max_seconds`; NaN or > 1e5 units/s is
  `exploded` (`RolloutResult.stopped_because` is a `Stop`); held bodies and bodies beyond demo mode's speed limit
  are flagged; a body that came flush onto another while settling touches it the step it is first set moving);
  `rollout` is the two in a row, so a fork and a full rollout agree bit for bit
- `evaluate.py`: `Score` (qualitative, quantitative, `miss`: how close the simulation came to the demonstrated contacts
  it lacks, measured on each contact's mover, `legs`: the same per leg; `objective` = 1000 x qualitative + quantitative
  + 4 x miss, inf when exploded), `Problem` (scene, demonstrated timeline, canvas, rollout length, `by_leg`, cache key),
  `evaluate` / `evaluate_problem`: rollout + `compare_prefixes` against the demonstration (prepared once per process;
  settled states cached by `structure()`); a matched contact of two movable bodies met on another side than demonstrated
  adds to `miss` how far the two bodies lay from their demonstrated placement (`side_misses`: the cup on the peg's top,
  not beside it)
- `legs.py`: `legs(timeline)`: the demonstration cut after each contact and end-contact in comparison order; each
  leg's event ids, the components they name, and those its own events name (`Leg.own`)
- `coordinates.py`: the searched numbers of a `Parameters` as `Coordinate`s (mass, friction, k, rest length;
  velocity as angle/speed or vx/vy), `get_value`/`set_value`, and `Normalisation` to the unscaled vector an
  optimiser moves in
- `grid.py`: `ThesisGrid`: every combination of the thesis's grid values (3.4.5; the steps it does not give marked)
  in odometer order, 16 at a time
- `aim.py`: aiming at surfaces (issue 27): `aim_points` samples the fixed body of the start body's first demonstrated
  contact along its edges facing the demonstrated side (ends included) and round its corners (a fan of normals), each as
  where the start body's centre is when it touches; `aimed` launches first along the clear flights (`clear_aimed`: each
  face by `clearance.py`, the low and high family apart), then at each aim point (ballistic, 4 flight times); `AimSpace`
  is two coordinates round one aimed candidate (place along its edge or round its corner, flight time) for CMA-ES to
  correct it by rollouts
- `clearance.py`: whether a ballistic flight is clear of the drawing (geometry, no stepping): `clearance_grid`
  (every aim point by every flight time, how far the body stays from everything on the way; a container aimed into
  counts only outside its hull), `clear_regions` (the deepest cell of each clear region), `nearly_clear` (the
  flight that comes nearest when none is clear: a shot that grazes a corner by a unit is often clear in the physics)
- `chain.py`: the later legs aimed (`chain_aimed`): each place along the first target's faces by each flight time
  followed through modelled bounces (`rebound`, calibrated against the physics world by benchmarks/bench_bounce.py: a
  loss to gravity while pressed, Coulomb friction, a disc starting to roll) and scored by the demonstrated contacts
  with fixed bodies it makes in order (`demonstrated_chain`); the deepest launch of each region making the most is
  tried first; `aimed_legs`: the leading legs the aims address (up to the start body meeting a movable body)
- `where.py`: `differences_in_place`: for a reproduced demonstration, the matched contacts whose simulated point lies
  far from the drawn one, in words ("the ball meets the platform a at its right corner, not at its middle as you
  showed"); `place(body, point)` reads a point in the body's own frame
- `leg_search.py`: `LegByLeg`, the default: the flight-time family of the seed first (zooming 2^(k/4), 2^(j/16),
  2^(j/64)), then the aimed candidates (`chain.py`'s, then `aim.py`'s, made only then, 16 a generation) and one CMA-ES
  run in `AimSpace` round the best of them (at most 60 rollouts), then the best one's start velocities turned and scaled
  together (the grid's velocity steps, 48 rollouts) — the aims and the scan skipped when the family's best already
  reproduces the legs they address (`chain.aimed_legs`) —, in scenes with springs the best one with its springs stiffer
  and longer (9 rollouts), then CMA-ES (pycma, seeded) on the parameters of the first leg the best so far does not
  reproduce (a later leg's first run, on machines with springs: those its own events name), against that leg's score;
  restarts with doubled steps when a run stalls; a leg given up past step 4, another round over the legs while budget is
  left; what it asked for last is its `Phase`
- `search.py`: `Search(scene, timeline, canvas, strategy=, seed=, budget=)`: `next_generation()` / `tell(scores)` /
  `done` / `best` / `found_at` / `furthest` (most leading legs reproduced, `progress`); generation 0 is the seed;
  stops at the first qualitatively equivalent candidate; deterministic for a seed and budget whatever evaluates the
  candidates
- `verdict.py`: the verdict in words: reproduced (with `where.py`'s differences in place), or the first demonstrated
  event (leg by leg) no candidate reproduces and why (nothing sets it moving; how close the body came; else the
  metric's reason): `refusal_or_verdict` tells it from `Search.furthest`, the candidate that reproduced the most
  leading legs
- `defaults.py`: the default seed and budget, shared by `physink simulate` and the session's `simulate` command
"""
