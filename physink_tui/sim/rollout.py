"""Runs one candidate: the scene with its parameters under gravity, settled, then recorded as a simulated timeline
by demo mode's recorder until nothing can change it any more; no search, no comparison, no clock.

A rollout (thesis 3.4.2) is in two parts. `settled_state`: the world of ``apply(scene, parameters)`` under gravity
with the start-moved bodies held still (kinematic at their drawn pose), lightly damped, stepped unrecorded until
every body rests or `SETTLE_MAX_STEPS`; bodies drawn resting on others come flush (the golf ball on its shelf) and
that settling is no event. A body that moves further than `FLUSH_DISTANCE` while settling was not drawn at rest
under gravity (the egg cracker's knife hanging from its rope): the user meant it to stay where it is until the
machine reaches it, so it is held at its drawn pose and settling starts again, up to `SETTLE_ROUNDS` times.
`rollout_from`: a world forked from that state (`World.from_state`, warmed by `WARM_STEPS` undone steps so that
resting contacts hold as they held in the settled world), undamped, the start bodies given their initial
velocities and every other body held until touched (`World.hold_until_touched`: asleep until a moving body hits it
or a rope, spring or joint pulls it), stepped and observed exactly as demo mode observes (`step_and_observe`, the
recorder of `recorder_for`, no pen); a body starting to move by itself with nothing to explain it gets the start
event, as in a demonstration. A body that came flush onto another while settling (touching it there, not where
drawn: the golf ball drawn a little above its shelf) touches it in the record the step it is first set moving, as
the demonstration without gravity shows that contact when the body is moved onto what it was drawn above; settling
itself stays no event. `rollout` is the two in a row, so a full rollout and a fork agree bit for bit.

A settled state carries every rope link's motion too (`WorldState.links`), so a rope whose ends moved while settling
does not start the rollout stretched from where it was drawn to where its ends are.

A fork is valid for candidates whose `Parameters.structure()` equals the settled one's: settling depends on the
masses, frictions and springs and on which bodies are held, not on the initial velocities.

Speed: `World.limit_speeds` is demo mode's and is never applied here; a body faster than demo mode's limit for it is
flagged. Instead, a step in which some body on the canvas would move further than it could without passing through the
thinnest body (the two half-sizes) is divided into sub-steps (`World.substeps`, at most `MAX_SUBSTEPS`), so nothing
tunnels; a body faster than even that is flagged. NaN or a speed above `EXPLODED_SPEED` stops the rollout as
"exploded" (the search discards and counts it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

from physink_tui.scene.components import Body, Scene, Spring
from physink_tui.scene.interpretation.body_shapes import body_geometry
from physink_tui.scene.physics.build import AXES, SPRING_UNITS
from physink_tui.scene.physics.contacts import ContactRecord
from physink_tui.scene.physics.speed import MIN_SPEED_LIMIT, SPEED_LIMIT
from physink_tui.scene.physics.state import REST, Motion, WorldState
from physink_tui.scene.physics.stepping import Frame, step_and_observe
from physink_tui.scene.physics.world import GRAVITY, World
from physink_tui.sim.parameters import Parameters, apply
from physink_tui.timeline.demo_setup import TOUCHING, recorder_for, touching_pairs
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.observation import Observation
from physink_tui.timeline.recorder import MOVING_SPEED, STILL_FRAMES

SETTLE_DAMPING = 0.05
"""Share of its velocity a body keeps after one second while the scene settles (drawn bodies come to rest fast)."""
SETTLE_MAX_STEPS = 720
"""At most this many steps (6 s) of settling: a scene that never rests (a swinging pendulum, a body falling for
ever) starts anyway, its bodies moving as they were."""
SETTLE_SPEED = MOVING_SPEED / 5
"""Canvas units per second below which a body has settled: well below `MOVING_SPEED`, so that a spring creeping to
its equilibrium does not start moving again once the damping of the settling is gone."""
REST_STEPS = STILL_FRAMES
"""Consecutive steps with every body slow enough after which a world is at rest (settled, or done)."""
OFF_CANVAS_MARGIN = 0.25
"""Share of the canvas diagonal beyond the canvas's sides or bottom past which a body is gone (nothing there can
bring it back; a body thrown above the canvas falls back and is not gone)."""
FLUSH_DISTANCE = 10.0
"""Canvas units a body may move while the scene settles (coming flush with what it rests on); one that moved
further was not drawn at rest under gravity (the egg cracker's knife and egg): it is held where it was drawn until
something touches it, and the rollout flags it."""
SETTLE_ROUNDS = 4
SAG_MARGIN = 1.5
"""How many times its static sag a spring may let what it carries down while settling and still count as only
taking its load (`Settled.sagged`; the damped settling stops at rest, short of or at the static sag)."""
AXIS_SLACK = 1.0
"""Canvas units a spring-borne body may move across its spring's axis while settling (its groove allows none)."""
"""Settling rounds at most (each holds the bodies that the last one found moving too far)."""
MAX_SUBSTEPS = 8
"""Most sub-steps of one step (`World.substeps`): a body up to 8 times faster than could cross the thinnest body in
one step does not tunnel through it; a faster one is flagged."""
WARM_STEPS = 4
"""Steps a fork takes and undoes before the rollout (`World.from_state`'s ``warm``), so that the bodies held asleep
keep their contacts with the impulses that hold them: without them a sleeping group touches anew the step after
it wakes (contacts the recorder would take for new ones) and a compressed spring jolts its body for a step before
the contact pushes back (the cup dispenser's peg: 28-31 units/s at the instant the ball hits the cup, a movement
the start event would explain). Two steps already give the same rollout to 1e-6; four for margin."""
EXPLODED_SPEED = 1.0e5
"""Canvas units per second (about 75 canvas heights a second) above which the physics has blown up."""



class Stop(StrEnum):
    """Why a rollout stopped (a string, so it reads the same in JSON and in messages)."""

    AT_REST = "at rest"
    """Every body still, or gone off the canvas, none gone."""
    OFF_CANVAS = "off canvas"
    """The same, at least one body gone."""
    MAX_SECONDS = "max seconds"
    """The time allowed ran out first."""
    EXPLODED = "exploded"
    """NaN or a speed above `EXPLODED_SPEED`: discard the candidate."""


@dataclass(frozen=True, slots=True)
class RolloutResult:
    """What one rollout gave.

    Attributes:
        timeline: the simulated timeline (movements still open when it stopped are closed at the last step).
        steps: physics steps recorded (the settling steps are not counted).
        stopped_because: why it stopped (`Stop`).
        flagged: one sentence per body that moved more than `FLUSH_DISTANCE` while settling, and per body and kind
            the first time it went faster than demo mode's speed limit or than could pass through the thinnest body
            in one step; empty for a trustworthy rollout of a scene drawn at rest.
    """

    timeline: Timeline
    steps: int
    stopped_because: Stop
    flagged: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Settled:
    """A scene settled under gravity, ready to fork rollouts from.

    Attributes:
        state: the world after settling (held bodies where they were drawn).
        held: the bodies that would not stay where they were drawn (they moved more than `FLUSH_DISTANCE` while
            settling), with how far they went: held there until something touches them.
        sagged: those of ``held`` that only went down on a spring carrying them (`_sagged`): a spring is drawn at
            its natural length (thesis 4.2), so under gravity it takes its load so; held like the others, but no
            flaw of the drawing, so a rollout does not flag them.
    """

    state: WorldState
    held: tuple[tuple[str, float], ...] = ()
    sagged: tuple[str, ...] = ()


def settled_state(scene: Scene, canvas: tuple[float, float], parameters: Parameters) -> Settled:
    """The world of ``scene`` with ``parameters`` after settling (see the module docstring); ``canvas`` bounds the
    bodies that count (one gone off the canvas need not rest).

    Settling is tried up to `SETTLE_ROUNDS` times: each body that moved more than `FLUSH_DISTANCE` is held at its
    drawn pose in the next round (and, in the rollout, until touched), so that what rests on it comes flush with
    it where it was drawn rather than where it fell.
    """
    applied = apply(scene, parameters)
    drawn = {b.id: b.position for b in applied.bodies()}
    held: dict[str, float] = {}
    sagged: set[str] = set()
    for _ in range(SETTLE_ROUNDS):
        world = _settle(applied, canvas, set(parameters.start_bodies) | set(held))
        state = world.state()
        moved = {b: d for b, d in _moved(drawn, state).items() if d > FLUSH_DISTANCE and b not in held
                 and b not in parameters.start_bodies}
        if not moved:
            break
        held.update(moved)
        sagged |= _sagged(scene, applied, world, drawn, state, set(moved))
    return Settled(state, tuple(sorted(held.items())), tuple(sorted(sagged)))


def _settle(scene: Scene, canvas: tuple[float, float], held: set[str]) -> World:
    world = World.from_scene(scene, gravity=GRAVITY)
    world.damping = SETTLE_DAMPING
    poses = {b: world.pose(b) for b in sorted(held)}
    for body, pose in poses.items():
        world.follow(body, pose, REST)
    movable = [b.id for b in scene.bodies() if not scene.is_fixed(b.id) and b.id not in poses]
    bounds = _bounds(canvas)
    still = 0
    for _ in range(SETTLE_MAX_STEPS):
        world.step(1)
        world.take_contacts()
        if _exploded(world, movable):
            break
        moving = any(_speed(world, b) > SETTLE_SPEED for b in movable if _inside(world, b, bounds))
        still = 0 if moving else still + 1
        if still >= REST_STEPS:
            break
    for body, pose in poses.items():
        world.let_go(body)
        world.place(body, pose, REST)
    return world


def _moved(drawn: dict[str, tuple[float, float]], state: WorldState) -> dict[str, float]:
    return {b: math.hypot(m.x - drawn[b][0], m.y - drawn[b][1]) for b, m in state.bodies.items() if b in drawn}


def _sagged(drawn_scene: Scene, scene: Scene, world: World, drawn: dict[str, tuple[float, float]],
            state: WorldState, moved: set[str]) -> set[str]:
    """The bodies of ``moved`` that a spring from a fixed body carries (in ``scene``, the parameters applied to
    ``drawn_scene``) and that moved only along its axis, by no more than its natural length differs from the sketched
    one (the search moves it) plus `SAG_MARGIN` times its static sag (weight along the axis / stiffness) under them
    and the bodies that moved with them (by the same vector within `FLUSH_DISTANCE`: the cup on the cup dispenser's
    platform), plus `FLUSH_DISTANCE`; those riders too."""
    shift = {b: (state.bodies[b].x - drawn[b][0], state.bodies[b].y - drawn[b][1]) for b in moved}
    out: set[str] = set()
    for spring in (c for c in scene.components.values() if isinstance(c, Spring)):
        ends = [b for b in (spring.a, spring.b) if b in shift]
        if len(ends) != 1 or not any(scene.is_fixed(b) for b in (spring.a, spring.b) if b != ends[0]):
            continue
        (dx, dy), (ux, uy) = shift[ends[0]], AXES[spring.axis]
        riders = [b for b in shift if math.dist(shift[b], (dx, dy)) <= FLUSH_DISTANCE]
        load = sum(world.mass(b) for b in riders)
        sag = abs(load * (GRAVITY[0] * ux + GRAVITY[1] * uy)) / (spring.k * SPRING_UNITS)
        sketched = drawn_scene.components[spring.id]
        assert isinstance(sketched, Spring)
        reach = abs(spring.rest_length - sketched.rest_length) + SAG_MARGIN * sag + FLUSH_DISTANCE
        if abs(dx * uy - dy * ux) <= AXIS_SLACK and abs(dx * ux + dy * uy) <= reach:
            out.update(riders)
    return out


def rollout(scene: Scene, canvas: tuple[float, float], parameters: Parameters, *,
            max_seconds: float) -> RolloutResult:
    """Settle ``scene`` with ``parameters``, then record its simulated timeline (see the module docstring).

    Raises:
        SimulationError: parameters that do not fit the scene or are out of range (`parameters.apply`).
    """
    return rollout_from(scene, settled_state(scene, canvas, parameters), canvas, parameters,
                        max_seconds=max_seconds)


def rollout_from(scene: Scene, settled: Settled, canvas: tuple[float, float], parameters: Parameters, *,
                 max_seconds: float) -> RolloutResult:
    """Record the simulated timeline from ``settled`` (`settled_state` of ``scene`` with parameters of the same
    `Parameters.structure()`), the start bodies given ``parameters.velocities`` and every other body held until
    touched, for at most ``max_seconds``."""
    applied = apply(scene, parameters)
    world = World.from_state(applied, settled.state, warm=WARM_STEPS)
    start_scene = world.to_scene(applied)
    recorder = recorder_for(start_scene, canvas, world.dt, drawn=applied)
    bodies = tuple(b.id for b in applied.bodies())
    movable = [b for b in bodies if not applied.is_fixed(b)]
    came_flush = _came_flush(world, applied, movable)
    for body, (vx, vy) in sorted(parameters.velocities.items()):
        world.set_velocity(body, (vx, vy))
    held = frozenset(movable) - set(parameters.start_bodies)
    world.hold_until_touched(set(parameters.start_bodies), touching_pairs(start_scene, held))
    sleepers = set(held)
    fixed = {b for b in bodies if applied.is_fixed(b)}
    welded = {b: world.motion(b) for b in fixed}  # welded bodies never move in a rollout (nothing drags them)
    limits = _speed_limits(world, bodies, world.dt)
    bounds = _bounds(canvas)
    names = applied.names()
    flagged = {(body, "settle"): f"the {names.get(body, body)} would not stay where it is drawn (it moved {d:.0f} "
                                 "units under gravity): held there until touched"
               for body, d in settled.held if body not in settled.sagged}
    max_steps = int(max_seconds / world.dt + 1e-9)
    stopped, still, steps = Stop.MAX_SECONDS, 0, 0
    while steps < max_steps:
        asleep = {b for b in sleepers if world.is_asleep(b)}
        sleepers = asleep
        frame = step_and_observe(world, bodies, welded)
        steps += 1
        t = round(steps * world.dt, 6)
        if any(_blown(frame.motions[body]) for body in movable):
            stopped = Stop.EXPLODED
            break
        contacts = frame.contacts
        if asleep:  # pairs that rested on each other asleep touch again as they wake: no new contact
            resting = asleep | fixed
            contacts = tuple(c for c in contacts if c.a_id not in resting or c.b_id not in resting)
        if came_flush:
            contacts += _set_moving(world, frame, came_flush)
        recorder.observe(Observation(t, frame.motions, contacts, None, frame.touching))
        gone = False
        moving = False
        need = 1.0  # sub-steps the next step needs: no body on the canvas crosses the thinnest body in one
        for body in movable:
            m = frame.motions[body]
            if not _inside_xy(m.x, m.y, bounds):
                gone = True
                continue
            speed = math.hypot(m.vx, m.vy)
            moving = moving or speed > MOVING_SPEED
            need = max(need, speed / limits[body][1])
            _flag(flagged, body, names.get(body, body), speed, t, limits)
        world.substeps = min(math.ceil(need), MAX_SUBSTEPS)
        still = 0 if moving else still + 1
        if still >= REST_STEPS:  # the recorder's own stop never fires for a body falling off the canvas
            stopped = Stop.OFF_CANVAS if gone else Stop.AT_REST
            break
    timeline = recorder.finish()
    return RolloutResult(timeline, steps, stopped, tuple(flagged.values()))


# -- internals ------------------------------------------------------------------------------------------------------

def _came_flush(world: World, drawn: Scene, movable: list[str]) -> set[tuple[str, str]]:
    """(movable body, what it rests on) for the bodies touching in the settled world but not where they are drawn:
    they came flush while settling."""
    out = set()
    for pair in world.touching():
        a, b = sorted(pair, key=lambda c: (c not in movable, c)) if len(pair) == 2 else (None, None)
        if a in movable and b in drawn.components and isinstance(drawn.components[b], Body):
            gap = body_geometry(drawn.components[a]).distance(body_geometry(drawn.components[b]))
            if gap > TOUCHING:
                out.add((a, b))
    return out


def _set_moving(world: World, frame: Frame, came_flush: set[tuple[str, str]]) -> tuple[ContactRecord, ...]:
    """The contacts of bodies that came flush while settling, in the step one of them is first set moving while
    they touch (settling is no event; the demonstration shows that contact when the body is moved onto what it was
    drawn just above); pairs no longer touching are forgotten."""
    out = []
    for a, b in sorted(came_flush):
        if frozenset((a, b)) not in frame.touching:
            came_flush.discard((a, b))
        elif any(math.hypot(m.vx, m.vy) > MOVING_SPEED for m in (frame.motions[a], frame.motions[b])):
            came_flush.discard((a, b))
            record = world.contact_between(a, b, frame.step)
            if record is not None:
                out.append(record)
    return tuple(out)


def _speed(world: World, body: str) -> float:
    vx, vy, _ = world.velocity(body)
    return math.hypot(vx, vy)


def _blown(m: Motion) -> bool:
    """NaN or infinity anywhere in the motion (a sum of them is not finite), or a huge speed."""
    return not math.isfinite(m[0] + m[1] + m[2] + m[3] + m[4] + m[5]) or math.hypot(m[3], m[4]) > EXPLODED_SPEED


def _exploded(world: World, bodies: list[str]) -> bool:
    return any(_blown(world.motion(body)) for body in bodies)


def _bounds(canvas: tuple[float, float]) -> tuple[float, float, float, float]:
    margin = OFF_CANVAS_MARGIN * math.hypot(*canvas)
    return (-margin, -margin, canvas[0] + margin, canvas[1] + margin)


def _inside_xy(x: float, y: float, bounds: tuple[float, float, float, float]) -> bool:
    """Not gone: a body above the canvas falls back, one beyond its sides or below it never returns."""
    return bounds[0] <= x <= bounds[2] and y <= bounds[3]


def _inside(world: World, body: str, bounds: tuple[float, float, float, float]) -> bool:
    x, y, _ = world.pose(body)
    return _inside_xy(x, y, bounds)


def _speed_limits(world: World, bodies: tuple[str, ...], dt: float) -> dict[str, tuple[float, float]]:
    """Per body: demo mode's speed limit for it (`speed.limit_speed`) and the speed at which it could pass through
    the thinnest body of the scene in one step (its own half-size plus the thinnest one's, per step)."""
    halves = {b: world.half_size(b) for b in bodies}
    thinnest = min(halves.values(), default=math.inf)
    return {b: (max(SPEED_LIMIT * halves[b] / dt, MIN_SPEED_LIMIT), (halves[b] + thinnest) / dt) for b in bodies}


def _flag(flagged: dict[tuple[str, str], str], body: str, name: str, speed: float, t: float,
          limits: dict[str, tuple[float, float]]) -> None:
    demo, tunnel = limits[body]
    if speed > demo and (body, "demo") not in flagged:
        flagged[(body, "demo")] = f"the {name} reached {speed:.0f} units/s at {t:.3f} s, beyond demo mode's limit " \
                                  f"{demo:.0f}"
    if speed > tunnel * MAX_SUBSTEPS and (body, "tunnel") not in flagged:
        flagged[(body, "tunnel")] = f"the {name} reached {speed:.0f} units/s at {t:.3f} s: it may tunnel through the " \
                                    f"thinnest body even in {MAX_SUBSTEPS} sub-steps ({tunnel * MAX_SUBSTEPS:.0f} " \
                                    "units/s)"
