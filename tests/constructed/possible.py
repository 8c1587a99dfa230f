"""Possible cases: a random layout, a random throw of its ball that a gravity simulation carries into the basket,
and that path demonstrated by a pen in demo mode; the throw is the witness (a case is kept only if its throw
reproduces the demonstration).

The distribution (fixed, seeded by the case's seed): the pen is the hurried hand for `HURRIED_SHARE` of the cases,
else the virtual pen; the layout is `layouts.random_layout`'s; throws are aimed (`_aimed`: a random point over a
platform or the basket, a random flight time) until one lands in the basket (its first touch of the basket inside
it, nothing on the way but at most `MOST_CONTACTS` platform contacts, at least one for `WANT_CONTACT` of the
cases), within the canvas. The path is the simulated ball's, sampled every `SAMPLE_S`, with a corner `PRESS` units
into each platform at each contact, ending pressed onto the basket's floor where the ball came to rest. A layout
with no such throw in `THROW_TRIES`, or whose throw does not reproduce its demonstration, is replaced by the next
draw.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from functools import cache

from constructed.demonstrate import body_id, recognised, session
from constructed.layouts import CANVAS, RADIUS, Layout, random_layout
from physink_tui.scene.physics.world import GRAVITY
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import evaluate, rollout_seconds
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.rollout import Stop, rollout
from physink_tui.sim.seeding import seed as seed_parameters
from physink_tui.timeline.events import Event, Timeline

HURRIED_SHARE = 0.3
AIM_AT_BASKET = 0.25
"""Share of throws aimed over the basket's opening (the rest over a random platform)."""
WANT_CONTACT = 0.6
"""Share of cases whose throw must touch a platform before the basket (the rest take the first that lands)."""
MOST_CONTACTS = 3
"""Platform contacts a kept throw makes at most before it drops into the basket."""
FLIGHT_S = (0.35, 1.6)
"""A throw is aimed: at a random point over a random platform (or over the basket's opening when the case wants
no platform contact), reached in a flight time drawn uniformly from this range (seconds) under gravity."""
THROW_TRIES = 80
LAYOUT_TRIES = 40
SAMPLE_S = 0.06
PRESS = {"virtual": 12.0, "hurried": 36.0}
"""Canvas units the pen pushes the ball past touching a surface: the bouncing scenarios' 0.012 of the height for
the virtual pen; three times that for the hurried hand, whose corners cut short (tests/penmodels)."""
THROW_SECONDS = 8.0


@dataclass(frozen=True, slots=True)
class Possible:
    """A possible case: its seed, pen, layout, demonstrated path (canvas units) and witness launch velocity."""

    seed: int
    pen: str
    layout: Layout
    path: tuple[tuple[float, float], ...]
    witness: tuple[float, float]
    platform_contacts: tuple[str, ...]
    """The platforms the witness touches, in order."""

    @property
    def name(self) -> str:
        return f"possible-{self.seed}"

    def session(self) -> Session:
        return _session(self)

    def witness_parameters(self) -> Parameters:
        s = self.session()
        base = seed_parameters(s.scene, s.timeline, s.canvas)
        return base.with_velocities({body_id(s.scene, "ball"): self.witness})


@cache
def _session(case: Possible) -> Session:
    return session(case.layout, case.path, case.pen, case.seed)


@cache
def possible(seed: int) -> Possible:
    """The possible case of ``seed`` (see the module docstring)."""
    rng = random.Random(f"possible:{seed}")
    pen = "hurried" if rng.random() < HURRIED_SHARE else "virtual"
    for _ in range(LAYOUT_TRIES):
        layout = random_layout(rng)
        least = 1 if rng.random() < WANT_CONTACT else 0
        drawn = session(layout, (), pen, seed)
        if not recognised(layout, drawn.scene):
            continue
        for _ in range(THROW_TRIES):
            v = _aimed(rng, layout)
            found = _throw(drawn, v, pen, least)
            if found is None:
                continue
            path, touched = found
            case = Possible(seed, pen, layout, path, v, touched)
            if witnessed(case):
                return case
            break  # the demonstration of this layout's throw is not followed: the next layout
    raise RuntimeError(f"possible case {seed}: no layout in {LAYOUT_TRIES} gave a witnessed throw")


def witnessed(case: Possible) -> bool:
    """Whether the case's witness reproduces its demonstration (qualitative distance 0)."""
    s = case.session()
    if not recognised(case.layout, s.scene) or not any(ev.type == "contact" for ev in s.timeline.events):
        return False
    score = evaluate(s.scene, s.timeline, s.canvas, case.witness_parameters(), rollout_seconds(s.timeline))
    return not score.exploded and score.qualitative == 0


def _throw(drawn: Session, v: tuple[float, float], pen: str, least: int):
    """The demonstration path of the throw ``v`` on the drawn scene and the platforms it touches, when it is one
    the distribution keeps (see the module docstring); else None."""
    scene = drawn.scene
    ball = body_id(scene, "ball")
    basket = body_id(scene, "basket")
    names = scene.names()
    parameters = seed_parameters(scene, Timeline(()), drawn.canvas)
    parameters = Parameters(parameters.bodies, parameters.springs, {ball: v})
    result = rollout(scene, drawn.canvas, parameters, max_seconds=THROW_SECONDS)
    if result.stopped_because == Stop.EXPLODED or result.flagged:
        return None
    found = into_basket(result.timeline.events, ball, basket, PRESS[pen], least)
    if found is None:
        return None
    path, before, end = found
    if not _inside(drawn, basket, end[0], end[1]):
        return None
    touched = tuple(names[next(c for c in ev.components if c != ball)] for ev in before)
    return path, touched


def ball_contacts(events, ball: str) -> list[Event]:
    """The ball's contacts among a rollout's ``events``, in order."""
    return sorted((ev for ev in events if ev.type == "contact" and ball in ev.components), key=lambda e: e.t0)


def into_basket(events, ball: str, basket: str, press: float, least: int = 0):
    """The demonstration path of a throw whose rollout made ``events``, when the ball lands inside the basket after
    ``least`` to `MOST_CONTACTS` contacts (each with a point), all on the canvas: the path (ending pressed on the
    lowest point the ball reached, below where it came to rest), those contacts and where the ball ended; else
    None."""
    contacts = ball_contacts(events, ball)
    into = next((c for c in contacts if basket in c.components), None)
    if into is None or dict(into.sides).get(basket) != "inside":
        return None
    before = [c for c in contacts if c.t0 < into.t0]
    if not least <= len(before) <= MOST_CONTACTS or any(c.point is None for c in before):
        return None
    frames = sorted((q.t, q.x, q.y) for ev in events if ev.type == "movement" and ev.components
                    and ev.components[0] == ball for q in ev.trajectory)
    path = _path(frames, before, into.t0, press)
    if path is None:
        return None
    end = frames[-1]
    path.append((end[1], max(q[2] for q in frames) + press))
    if not all(RADIUS < x < CANVAS[0] - RADIUS and RADIUS < y < CANVAS[1] - RADIUS / 2 for x, y in path):
        return None
    return tuple(path), before, (end[1], end[2])


def _aimed(rng: random.Random, layout: Layout) -> tuple[float, float]:
    if rng.random() < AIM_AT_BASKET:
        b = layout.basket
        target = (rng.uniform(b.x, b.x + b.width), b.rim - rng.uniform(0.0, 60.0))
    else:
        p = rng.choice(layout.platforms)
        target = (rng.uniform(p.left, p.right), p.top - RADIUS - rng.uniform(0.0, 20.0))
    d = (target[0] - layout.ball[0], target[1] - layout.ball[1])
    vx, vy = _launch(d, rng.uniform(*FLIGHT_S))
    return (round(vx, 3), round(vy, 3))


def _launch(d: tuple[float, float], t: float) -> tuple[float, float]:
    """The launch velocity that carries a body by ``d`` in ``t`` seconds under gravity."""
    return (d[0] / t - GRAVITY[0] * t / 2, d[1] / t - GRAVITY[1] * t / 2)


def _inside(drawn: Session, basket: str, x: float, y: float) -> bool:
    b = next(body for body in drawn.scene.bodies() if body.id == basket)
    xs = [b.position[0] + px for px, _ in b.outline] if b.outline else []
    ys = [b.position[1] + py for _, py in b.outline] if b.outline else []
    return bool(xs) and min(xs) < x < max(xs) and min(ys) < y < max(ys)


def _path(frames, contacts: list[Event], until: float, press: float) -> list[tuple[float, float]] | None:
    """The ball's simulated path up to ``until``, one point every `SAMPLE_S`, with a pressed corner at each
    contact."""
    timed = [(t, (x, y)) for t, x, y in frames if t < until]
    if not timed:
        return None
    kept = _sample(timed, [c.t0 for c in contacts])
    for c in contacts:
        centre = _at(frames, c.t0)
        nx, ny = centre[0] - c.point[0], centre[1] - c.point[1]
        norm = math.hypot(nx, ny) or 1.0
        kept.append((c.t0, (centre[0] - press * nx / norm, centre[1] - press * ny / norm)))
    kept.sort(key=lambda item: item[0])
    return [p for _, p in kept]


def _sample(timed, contact_times) -> list:
    out = [timed[0]]
    for t, p in timed[1:]:
        if t - out[-1][0] >= SAMPLE_S and all(abs(t - tc) >= SAMPLE_S / 2 for tc in contact_times):
            out.append((t, p))
    return out


def _at(frames, t: float) -> tuple[float, float]:
    best = min(frames, key=lambda f: abs(f[0] - t))
    return (best[1], best[2])
