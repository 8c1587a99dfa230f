"""Possible lever machines: a ball, a lever (a level box on a pivot at its middle), sometimes a welded platform, and
a basket; a random throw of the ball that tips the lever and lands in the basket, demonstrated along its path by
the virtual pen; the throw is the witness (kept only if it reproduces the demonstration), as in `possible`.

The distribution (fixed, seeded by the case's seed): the lever's length 280-420 canvas units, its middle at x
420-1000, y 420-640; a platform as `layouts.random_layout` places it, for half of the cases; throws aimed at a
random point of the lever's top (`possible._launch`, flight 0.35-1.6 s), kept when the ball's first contact is the
lever, the lever turns, and the ball's first touch of the basket is inside it with at most `MOST_CONTACTS` other
contacts before.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, replace
from functools import cache

from scenarios.thesis import BACKGROUND, BodyX, Expected, JointX, Step, pin

from constructed.demonstrate import body_id, session
from constructed.layouts import RADIUS, THICKNESS, Layout, Platform, frac, random_layout
from constructed.possible import FLIGHT_S, PRESS, THROW_SECONDS, _launch, ball_contacts, into_basket
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import evaluate, rollout_seconds
from physink_tui.sim.parameters import Parameters
from physink_tui.sim.rollout import Stop, rollout
from physink_tui.sim.seeding import seed as seed_parameters
from physink_tui.timeline.events import Timeline

LAYOUT_TRIES = 40
THROW_TRIES = 60


@dataclass(frozen=True, slots=True)
class LeverLayout(Layout):
    """A layout whose first platform is the lever (pivoted at its middle, not welded)."""

    def steps(self) -> tuple[Step, ...]:
        out = list(Layout.steps(self))
        lever = self.platforms[0]
        at = next(i for i, st in enumerate(out) if st.what == lever.name)
        out[at + 1: at + 3] = [Step("the lever's pivot", pin(frac(lever.centre)))]
        return tuple(out)

    def expected(self) -> Expected:
        base = Layout.expected(self)
        lever = self.platforms[0].name
        joints = tuple(JointX("pivot", lever, BACKGROUND) if j.a == lever else j for j in base.joints)
        return replace(base, joints=joints, fixed=tuple(f for f in base.fixed if f != lever),
                       bodies=tuple(b if b.name != lever else BodyX(lever, "box", lever) for b in base.bodies))


@dataclass(frozen=True, slots=True)
class Lever:
    seed: int
    pen: str
    layout: LeverLayout
    path: tuple[tuple[float, float], ...]
    witness: tuple[float, float]

    @property
    def name(self) -> str:
        return f"lever-{self.seed}"

    def session(self) -> Session:
        return _session(self)

    def witness_parameters(self) -> Parameters:
        s = self.session()
        base = seed_parameters(s.scene, s.timeline, s.canvas)
        return base.with_velocities({body_id(s.scene, "ball"): self.witness})


@cache
def _session(case: Lever) -> Session:
    return session(case.layout, case.path, case.pen, case.seed)


def _recognised(layout: LeverLayout, scene) -> bool:
    got = sorted((b.shape, b.label or "", scene.is_fixed(b.id)) for b in scene.bodies())
    lever = layout.platforms[0].name
    want = sorted([("circle", "ball", False), ("polyline", "basket", True), ("box", lever, False),
                   *(("box", p.name, True) for p in layout.platforms[1:])])
    return got == want


@cache
def lever(seed: int) -> Lever:
    rng = random.Random(f"lever:{seed}")
    for _ in range(LAYOUT_TRIES):
        base = random_layout(rng, count=rng.choice((1, 2)))
        bar = Platform("lever", (rng.uniform(420, 1000), rng.uniform(420, 640)), rng.uniform(280, 420))
        layout = LeverLayout(base.ball, (bar, *(replace(p, name=f"platform {chr(97 + k)}")
                                                  for k, p in enumerate(base.platforms[1:]))), base.basket)
        if any(abs(p.centre[1] - bar.centre[1]) < THICKNESS + 2.6 * RADIUS
               and p.left < bar.right + 90 and bar.left < p.right + 90 for p in layout.platforms[1:]):
            continue
        drawn = session(layout, (), "virtual", seed)
        if not _recognised(layout, drawn.scene):
            continue
        for _ in range(THROW_TRIES):
            target = (rng.uniform(bar.left, bar.right), bar.top - RADIUS - rng.uniform(0.0, 20.0))
            d = (target[0] - layout.ball[0], target[1] - layout.ball[1])
            v = tuple(round(x, 3) for x in _launch(d, rng.uniform(*FLIGHT_S)))
            path = _throw(drawn, v)
            if path is None:
                continue
            case = Lever(seed, "virtual", layout, path, v)
            s = case.session()
            if s.timeline is not None and _recognised(layout, s.scene):
                score = evaluate(s.scene, s.timeline, s.canvas, case.witness_parameters(),
                                 rollout_seconds(s.timeline))
                if not score.exploded and score.qualitative == 0:
                    return case
            break
    raise RuntimeError(f"lever case {seed}: no layout in {LAYOUT_TRIES} gave a witnessed throw")


def _throw(drawn: Session, v):
    scene = drawn.scene
    ball, basket, bar = (body_id(scene, n) for n in ("ball", "basket", "lever"))
    parameters = seed_parameters(scene, Timeline(()), drawn.canvas)
    parameters = Parameters(parameters.bodies, parameters.springs, {ball: v})
    result = rollout(scene, drawn.canvas, parameters, max_seconds=THROW_SECONDS)
    if result.stopped_because == Stop.EXPLODED or result.flagged:
        return None
    events = result.timeline.events
    contacts = ball_contacts(events, ball)
    if not contacts or bar not in contacts[0].components:
        return None
    if not any(ev.type == "movement" and ev.components and ev.components[0] == bar for ev in events):
        return None
    found = into_basket(events, ball, basket, PRESS["virtual"])
    return None if found is None else found[0]
