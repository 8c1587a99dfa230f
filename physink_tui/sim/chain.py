"""Aiming the later legs (issue 27): launches whose modelled bounces carry the start body from its first
demonstrated contact on to the next ones, surface after surface; geometry only, no stepping.

A later contact is reached from the state after the one before: where the body left the surface and how fast. That state
is set by the first flight (where along the first surface it arrives, and in what flight time, the two coordinates
`aim.AimSpace` searches), so the later legs are aimed through it: every place along each face of the first target
(`aim.faces`) by every flight time (`clearance.CLEAR_FACTORS`) is followed through its bounces — ballistic flight, the
first body touched (`clearance.Obstacle`) and on which side, the rebound there (the plain bounce: the normal speed times
the contact's restitution, the larger of the two bodies', the tangential speed kept, or two thirds of it for a round
body that grips, which starts it rolling; `rebound` calibrated against the physics world by benchmarks/bench_bounce.py
is there too, for the benchmark) — and scored by how many of the demonstrated contacts with fixed bodies it makes in
order (`demonstrated_chain`). Of the cells that make the most (at least two), the deepest of each connected region
(`clearance.clear_regions`) is launched, for the rollouts to correct: the model ignores spin and what rolling does,
which the aim run in (place, flight time) then corrects.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from physink_tui.scene.components import MATERIALS, Body, Scene, material_class
from physink_tui.scene.physics.world import GRAVITY
from physink_tui.sim import aim as aiming
from physink_tui.sim.clearance import (
    ARRIVAL,
    CLEAR_FACTORS,
    GRAZE,
    Obstacle,
    clear_regions,
    clearance_grid,
    distances,
    in_hull,
    near_bounds,
    obstacles,
)
from physink_tui.sim.legs import Leg
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.seeding import start_movements
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.qualitative import side_along

HORIZON = 3.0
"""Seconds each modelled flight after a bounce is followed at most."""
SAMPLES = 150
"""Samples along each modelled flight after a bounce."""
GRIP = 2 / 3
"""The tangential speed a round body keeps in a bounce on a surface that grips (a disc starting to roll)."""
PLAIN_GRIP = 1.0e9
"""The friction `rebound` is given for the plain bounce on a surface that grips: enough to hold any round body to
`GRIP`. The aims bounce this way; `rebound` with `BOUNCE_LOSS` and the mean friction (calibrated against the world by
benchmarks/bench_bounce.py) was tried and dropped: within 0.2 degrees of the world on boxes, but it lost a held-back
constructed case and found none more (docs/BENCHMARKS.md)."""
BOUNCE_LOSS = {"box": 22.5, "freeform": 35.5}
"""Normal speed (units/s) a bounce on a level top loses in this world beyond the restitution, by the surface's
material class, measured (benchmarks/bench_bounce.py, 10-80 degrees, 300-3200 units/s: 21-22.6 on a box, about
three steps of gravity, 33-36 on a freeform polygon, constant in speed and angle); none on an underside (measured 0),
so it is scaled by the share of gravity pressing the body into the surface. Beside it the ratio out / in is the
restitution (1.0 for a box): the bounce modelled with restitution 1.0 alone came out 7 % too fast at 300 units/s."""
REGIONS = 2
"""Regions of the most contacts made tried per face, the largest first."""
MOST = 6
"""Chained launches tried at most (those making the most contacts, the largest regions of each face first)."""
MIN_CHAIN = 2
"""Contacts a chain must make in order, the first included, for its launches to be tried."""


def demonstrated_chain(scene: Scene, timeline: Timeline) -> tuple[str, tuple[tuple[str, str], ...]] | None:
    """The one start body and the fixed bodies it touches in the demonstration, with the side of each, in time
    order, up to its first contact with a movable body; None without one start body."""
    movements = start_movements(scene, timeline)
    if len(movements) != 1:
        return None
    body = movements[0][1]
    chain = []
    for ev in sorted((e for e in timeline.events if e.type == "contact"), key=lambda e: e.t0):
        if body.id not in ev.components or len(ev.components) != 2:
            continue
        other = next(c for c in ev.components if c != body.id)
        side = dict(ev.sides).get(other)
        if not scene.is_fixed(other) or side is None:
            break
        chain.append((other, side))
    return body.id, tuple(chain)


def aimed_legs(scene: Scene, timeline: Timeline, legs_: Sequence[Leg]) -> int:
    """How many leading legs the aims (`chain_aimed`, `aim.aimed`) and the velocity scan address: those up to the
    one start body's first demonstrated contact with a movable body, or its last with a fixed one when it meets no
    movable body; 0 without one start body or without a contact of it."""
    movements = start_movements(scene, timeline)
    if len(movements) != 1:
        return 0
    body = movements[0][1].id
    last = None
    for ev in sorted((e for e in timeline.events if e.type == "contact"), key=lambda e: e.t0):
        if body not in ev.components or len(ev.components) != 2:
            continue
        last = ev.id
        if not scene.is_fixed(next(c for c in ev.components if c != body)):
            break
    return next((k + 1 for k, leg in enumerate(legs_) if last is not None and last in leg.events), 0)


def rebound_factors(restitution: float, friction: float, angle: float, *, loss: float = 0.0,
                    speed: float = 1.0) -> tuple[float, float]:
    """(normal, tangential) speed ratios, out / in, of `rebound` for a round body arriving at ``speed`` units/s,
    ``angle`` degrees from a level top (the benchmark's table; bench_bounce.py)."""
    a = math.radians(angle)
    v = np.array([[speed * math.cos(a), speed * math.sin(a)]])
    out = rebound(v, np.array([[0.0, -1.0]]), restitution, friction, rolls=True, loss=loss)
    return float(-out[0, 1] / v[0, 1]), float(out[0, 0] / v[0, 0])


def rebound(v: np.ndarray, n: np.ndarray, restitution: float, friction: float, *, rolls: bool,
            loss: float = 0.0) -> np.ndarray:
    """Velocities ``v`` (k, 2) after bouncing off surfaces with unit normals ``n`` (k, 2) pointing at the body: the
    normal speed times ``restitution`` less ``loss`` times the share of gravity pressing the body into the surface
    (`BOUNCE_LOSS`); the tangential speed less what Coulomb friction (``friction`` times the normal impulse) takes,
    down to `GRIP` of it for a body that ``rolls`` (a disc starting to roll), to nothing for one that slides."""
    vn = (v * n).sum(axis=1, keepdims=True)
    towards = vn < 0
    g = np.asarray(GRAVITY, dtype=float)
    press = np.clip(-(n @ g) / float(np.hypot(*g)), 0.0, 1.0)[:, None]
    out_n = np.maximum(-restitution * vn - loss * press, 0.0)
    tangential = v - vn * n
    vt = np.hypot(tangential[:, :1], tangential[:, 1:])
    slip = 1.0 - friction * (-vn + out_n) / np.maximum(vt, 1e-9)
    keep = np.clip(slip, GRIP if rolls else 0.0, 1.0)
    return np.asarray(np.where(towards, keep * tangential + out_n * n, v))


def chain_aimed(scene: Scene, timeline: Timeline, start: Parameters) -> list[aiming.Aimed]:
    """Launches at the first contact's surface whose modelled bounces make the most of the demonstrated contacts
    with fixed bodies in order (at least `MIN_CHAIN`); see the module docstring."""
    found = demonstrated_chain(scene, timeline)
    first = aiming.first_target(scene, timeline)
    if found is None or first is None or len(found[1]) < MIN_CHAIN:
        return []
    body, target, side, _point = first
    chain = found[1]
    if chain[0] != (target.id, side):
        return []
    reach = aiming.reach_of(body)
    scene_obstacles = obstacles(scene, body.id)
    bodies = {b.id: b for b in scene.bodies()}
    friction = start.bodies[body.id].friction if body.id in start.bodies else body.material.friction
    ranked: list[tuple[int, int, aiming.Aimed]] = []
    for face in aiming.faces(target, side):
        aims = [aiming.face_aim(face, k / (aiming.FACE_SAMPLES - 1), reach) for k in range(aiming.FACE_SAMPLES)]
        made = _made(body, aims, chain, reach, scene_obstacles, bodies, friction)
        best = int(made.max())
        if best < MIN_CHAIN:
            continue
        for rank, (row, col) in enumerate(clear_regions(made.astype(float), best - 0.5)[:REGIONS]):
            aim, factor = aims[row], CLEAR_FACTORS[col]
            d = (aim.centre[0] - body.position[0], aim.centre[1] - body.position[1])
            ranked.append((-best, rank, aiming.Aimed(start.with_velocities({body.id: aiming.launch(d, factor)}), aim,
                                                     factor, body.id, body.position)))
    ranked.sort(key=lambda r: (r[0], r[1]))
    return [a for _, _, a in ranked][:MOST]


def _made(body: Body, aims: Sequence[aiming.Aim], chain: Sequence[tuple[str, str]], reach: float,
          scene_obstacles: Sequence[Obstacle], bodies: dict[str, Body], friction: float) -> np.ndarray:
    """For each aim (rows) and flight factor (columns): how many of ``chain``'s contacts the modelled flight makes
    in order (0 when its first flight does not arrive clear)."""
    centres = np.array([a.centre for a in aims])
    first = clearance_grid(body.position, centres, reach, chain[0][0], scene_obstacles,
                           inside=chain[0][1] == "inside")
    rows, cols = first.shape
    made = np.where(first > -GRAZE * reach, 1, 0).reshape(-1)
    g = np.asarray(GRAVITY, dtype=float)
    d = centres - np.asarray(body.position, dtype=float)[None, :]
    slowest = np.sqrt(2 * np.hypot(d[:, 0], d[:, 1]) / float(np.hypot(*g)))
    t = slowest[:, None] * np.asarray(CLEAR_FACTORS)[None, :]
    v_in = (d[:, None, :] / t[..., None] + g * t[..., None] / 2).reshape(-1, 2)
    position = np.repeat(centres, cols, axis=0)
    normal = np.repeat(np.array([a.normal for a in aims]), cols, axis=0)
    touched = chain[0][0]
    for k in range(1, len(chain)):
        live = made == k
        if not live.any():
            break
        other = bodies[touched]
        restitution = max(body.material.restitution, other.material.restitution)
        surface = material_class(other.shape)
        mean = (friction + MATERIALS[surface].friction) / 2
        rolls = body.shape == "circle"
        # the plain bounce: friction without bound holds a round body to GRIP, none lets it keep everything
        v_out = rebound(v_in[live], normal[live], restitution, PLAIN_GRIP if rolls and mean > 0 else 0.0, rolls=rolls)
        hit, where, v_hit, n_hit = _first_touch(position[live], v_out, reach, scene_obstacles, touched)
        want_body, want_side = chain[k]
        ok = np.array([h == want_body and s == want_side for h, s in hit], dtype=bool)
        index = np.flatnonzero(live)
        made[index[ok]] = k + 1
        position[index] = where
        v_in[index] = v_hit
        normal[index] = n_hit
        touched = want_body
    return made.reshape(rows, cols)


def _first_touch(start: np.ndarray, v: np.ndarray, reach: float, scene_obstacles: Sequence[Obstacle],
                 leaving: str) -> tuple[list[tuple[str | None, str | None]], np.ndarray, np.ndarray, np.ndarray]:
    """Follow each flight from ``start`` (k, 2) at ``v`` (k, 2): the first body it touches and that body's side
    (None, None when none in `HORIZON`), where and how fast the centre is then, and the surface's normal there."""
    k = len(start)
    s = np.linspace(0.0, HORIZON, SAMPLES + 1)[1:]
    g = np.asarray(GRAVITY, dtype=float)
    paths = start[:, None, :] + v[:, None, :] * s[None, :, None] + g * s[None, :, None] ** 2 / 2
    points = paths.reshape(-1, 2)
    first = np.full(k, SAMPLES, dtype=int)
    who = np.full(k, -1, dtype=int)
    away = np.hypot(paths[..., 0] - start[:, None, 0], paths[..., 1] - start[:, None, 1]) > ARRIVAL * reach
    for i, o in enumerate(scene_obstacles):
        near = near_bounds(points, o, reach)
        if o.id == leaving:
            near &= away.reshape(-1)
        if not near.any():
            continue
        dist = np.full(len(points), np.inf)
        dist[near] = distances(points[near], o)
        touching = (dist < reach).reshape(k, SAMPLES)
        hit = np.where(touching.any(axis=1), touching.argmax(axis=1), SAMPLES)
        better = hit < first
        first[better], who[better] = hit[better], i
    hits: list[tuple[str | None, str | None]] = [(None, None)] * k
    where, v_hit, normal = start.copy(), v.copy(), np.zeros_like(v)
    for i, o in enumerate(scene_obstacles):
        cells = np.flatnonzero(who == i)
        if not len(cells):
            continue
        p = paths[cells, first[cells]]
        n = _normals(p, o)
        inside = in_hull(p, o.segments.reshape(-1, 2)) if _is_open(o) else np.zeros(len(cells), dtype=bool)
        for c, nn, ins in zip(cells, n, inside, strict=True):
            hits[c] = (o.id, "inside" if ins else side_along(float(nn[0]), float(nn[1])))
        where[cells], v_hit[cells], normal[cells] = p, v[cells] + g * s[first[cells]][:, None], n
    return hits, where, v_hit, normal


def _normals(p: np.ndarray, o: Obstacle) -> np.ndarray:
    """For each point (m, 2): the unit vector from the obstacle's nearest surface point towards it."""
    a, b = o.segments[:, 0, :], o.segments[:, 1, :]
    ab = b - a
    ap = p[:, None, :] - a[None, :, :]
    u = np.clip((ap * ab[None]).sum(axis=2) / np.maximum((ab ** 2).sum(axis=1), 1e-12)[None, :], 0.0, 1.0)
    offset = p[:, None, :] - (a[None] + u[..., None] * ab[None])
    length = np.hypot(offset[..., 0], offset[..., 1])
    nearest = length.argmin(axis=1)
    n = offset[np.arange(len(p)), nearest]
    size = length[np.arange(len(p)), nearest][:, None]
    return np.asarray(np.where(size > 1e-9, n / np.maximum(size, 1e-9), np.array([0.0, -1.0])))


def _is_open(o: Obstacle) -> bool:
    """An open outline (its last segment does not end where its first begins): a container's hollow is inside."""
    return bool(not np.allclose(o.segments[0, 0], o.segments[-1, 1]))
