"""Spring machines made by construction: a ball thrown onto a trampoline (a level platform on a vertical spring
from a welded base) that catches it and throws it on into the basket; possible cases with their witness, and
impossible ones whose reason is known from their construction.

Possible (`spring_case`): a random layout (`SpringLayout`: the ball top left, the trampoline, its base and spring,
the basket right of it, and at most one welded platform), a random spring (constant log-uniform in `K_RANGE`,
natural length the drawn one times a factor in `REST_RANGE`) and a random throw aimed at the trampoline's top,
simulated under gravity; kept when the ball's first contact is the trampoline's top, the trampoline moves, and the
ball then drops into the basket (at most `MOST_CONTACTS` contacts before it) within the canvas. That path is
demonstrated by the case's pen (the virtual pen or the hurried hand, `possible.HURRIED_SHARE`) in demo mode, the
ball pressed `possible.PRESS` into each surface it touched; the demonstration pushes the trampoline down on its
spring as the throw did. The witness is the generating parameters (throw, constant, natural length), re-checked
against the demonstration (qualitative distance 0), else the next layout is drawn.

Impossible (`impossible_spring`): the ball touches the top of the base under the trampoline and then, with nothing
between, the trampoline's top (`UNDER_FIRST`: the ball starts low on the left), or the trampoline's top and then the
base's (`OVER_FIRST`: it starts top left), before it drops into the basket; the order is drawn from its own seeded
generator, so the cases of one order are the same whether or not the other is made. The base lies under the
trampoline's span more than a ball's radius in from either end (`BASE_SHARE` of its length, at least 220 long), the
trampoline moves only up and down (its spring's groove) and cannot pass through its base (a spring's two bodies
collide, `scene/physics/build.py`), so the argument of `impossible.py` holds: between the two faces the ball must
cross the trampoline's height at least a radius beyond one of its ends, and there nothing pushes it back inward
(the trampoline's corner or end only outwards, the base is out of reach, gravity has no sideways part), while a free
flight keeps its horizontal speed. (While a spring's bodies did not collide, the order `OVER_FIRST` was possible: a
trampoline struck hard sank into its base and the ball on it reached the base's top; held-back case 5001 of the first
construction was reproduced so.)
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, replace
from functools import cache

from scenarios.thesis import BACKGROUND, BodyX, Expected, JointX, SpringX, Step, _x_steps

from constructed.demonstrate import body_id, session
from constructed.layouts import CANVAS, CLEARANCE, RADIUS, Layout, Platform, _fits, _gap, frac
from constructed.possible import FLIGHT_S, HURRIED_SHARE, PRESS, THROW_SECONDS, _launch, ball_contacts, into_basket
from physink_tui.input.virtual_pen import Stroke
from physink_tui.scene.components import Scene, Spring
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import evaluate, rollout_seconds
from physink_tui.sim.parameters import Parameters, SpringParameters
from physink_tui.sim.rollout import Stop, rollout
from physink_tui.sim.seeding import seed as seed_parameters
from physink_tui.timeline.events import Event, Timeline

K_RANGE = (4.0, 80.0)
"""The witness's spring constant (thesis units, `Spring.k`; the search seeds 20), drawn log-uniformly."""
REST_RANGE = (0.8, 1.25)
"""The witness's natural length as a factor of the drawn one."""
BASE_HEIGHT = 70.0
BASE_SHARE = 0.6
"""The base's width as a share of the trampoline's length, centred under it."""
NEED_SPRING = 0.5
"""Share of possible cases that keep only a throw whose ball, with the seeded spring instead of the witness's,
touches other surfaces or sides (`spring_matters`): there the search must move the spring, or find another throw."""
LAYOUT_TRIES = 40
THROW_TRIES = 80
TRAMPOLINE = "trampoline"


@dataclass(frozen=True, slots=True)
class SpringLayout(Layout):
    """A layout whose last platform is the trampoline, on a vertical spring of drawn length ``spring`` from a
    welded base below it (the other platforms are welded)."""

    spring: float = 150.0

    @property
    def trampoline(self) -> Platform:
        return self.platforms[-1]

    def base(self) -> tuple[float, float, float, float]:
        """The base's box: left, top, right, bottom."""
        t = self.trampoline
        half = t.length * BASE_SHARE / 2
        top = t.bottom + self.spring
        return (t.centre[0] - half, top, t.centre[0] + half, top + BASE_HEIGHT)

    def steps(self) -> tuple[Step, ...]:
        out = list(Layout.steps(self))
        at = next(i for i, st in enumerate(out) if st.what == TRAMPOLINE)
        x0, top, x1, bottom = self.base()
        cx = self.trampoline.centre[0]
        coil = Stroke.coil(frac((cx, top + 10.0)), frac((cx, self.trampoline.bottom - 25.0)), loops=5,
                           radius=0.015)
        base = Stroke((frac((x0, top)), frac((x1, top)), frac((x1, bottom)), frac((x0, bottom)), frac((x0, top))))
        out[at + 1: at + 3] = [Step("the base", base, say=("label base",)),
                               *_x_steps("base", frac(((x0 + x1) / 2, (top + bottom) / 2)), half=0.022),
                               Step("the spring", coil, say=("label spring",))]
        return tuple(out)

    def expected(self) -> Expected:
        base = Layout.expected(self)
        bodies = tuple(b if b.name != TRAMPOLINE else BodyX(TRAMPOLINE, "box", TRAMPOLINE) for b in base.bodies)
        bodies = (*bodies, BodyX("base", "box", "base"))
        joints = (*(j for j in base.joints if j.a != TRAMPOLINE), JointX("weld", "base", BACKGROUND))
        return replace(base, bodies=bodies, joints=joints, springs=(SpringX("vertical", "base", TRAMPOLINE),),
                       fixed=(*(f for f in base.fixed if f != TRAMPOLINE), "base"))


def random_spring_layout(rng: random.Random) -> SpringLayout:
    """A layout from the spring generator's distribution (see the module docstring)."""
    while True:
        ball = (rng.uniform(110, 330), rng.uniform(90, 220))
        t = Platform(TRAMPOLINE, (rng.uniform(430, 900), rng.uniform(470, 620)), rng.uniform(220, 330))
        spring = rng.uniform(110, 190)
        width = rng.uniform(260, 360)
        rim = rng.uniform(700, 780)
        from constructed.layouts import Basket
        basket = Basket(rng.uniform(t.right + CLEARANCE, CANVAS[0] - 60 - width) if t.right + CLEARANCE
                        < CANVAS[0] - 60 - width else -1.0, width, rim, rng.uniform(920, 960))
        if basket.x < 0:
            continue
        layout = SpringLayout(ball, (t,), basket, spring)
        x0, top, x1, bottom = layout.base()
        if bottom > CANVAS[1] - 40:
            continue
        outline = basket.outline()
        if _gap((x0, top, x1, bottom), (outline[0][0], rim, outline[3][0], basket.floor)) < CLEARANCE:
            continue
        if rng.random() < 0.5:
            for _ in range(100):
                p = Platform("platform a", (rng.uniform(330, 1350), rng.uniform(280, 560)), rng.uniform(220, 360),
                             math.radians(rng.uniform(-22.0, 22.0)))
                box = (p.left, p.top, p.right, p.bottom)
                if _fits(p, ball, basket, [t]) and _gap(box, (x0, top, x1, bottom)) >= CLEARANCE:
                    return SpringLayout(ball, (p, t), basket, spring)
        return layout


@dataclass(frozen=True, slots=True)
class SpringCase:
    """A possible spring case: seed, pen, layout, demonstrated path, witness throw, constant and natural length."""

    seed: int
    pen: str
    layout: SpringLayout
    path: tuple[tuple[float, float], ...]
    witness: tuple[float, float]
    k: float
    rest_length: float

    @property
    def name(self) -> str:
        return f"spring-{self.seed}"

    def session(self) -> Session:
        return _session(self)

    def witness_parameters(self) -> Parameters:
        s = self.session()
        return _with_witness(seed_parameters(s.scene, s.timeline, s.canvas), s.scene, self.witness, self.k,
                             self.rest_length)


def _with_witness(base: Parameters, scene: Scene, v: tuple[float, float], k: float, rest: float) -> Parameters:
    spring = next(c.id for c in scene.components.values() if isinstance(c, Spring))
    springs = {**base.springs, spring: SpringParameters(k, rest)}
    return Parameters(base.bodies, springs, {body_id(scene, "ball"): v})


@cache
def _session(case: SpringCase | ImpossibleSpring) -> Session:
    return session(case.layout, case.path, case.pen, case.seed)


def recognised(layout: SpringLayout, scene: Scene) -> bool:
    """The ball, the platforms, the trampoline free on one vertical spring from the welded base, the basket."""
    got = sorted((b.shape, b.label or "", scene.is_fixed(b.id)) for b in scene.bodies())
    want = sorted([("circle", "ball", False), ("polyline", "basket", True), ("box", TRAMPOLINE, False),
                   ("box", "base", True), *(("box", p.name, True) for p in layout.platforms[:-1])])
    springs = [c for c in scene.components.values() if isinstance(c, Spring)]
    names = scene.names()
    return got == want and len(springs) == 1 and springs[0].axis == "vertical" and \
        {names[springs[0].a], names[springs[0].b]} == {"base", TRAMPOLINE}


@cache
def spring_case(seed: int) -> SpringCase:
    """The possible spring case of ``seed`` (see the module docstring)."""
    rng = random.Random(f"spring:{seed}")
    pen = "hurried" if rng.random() < HURRIED_SHARE else "virtual"
    need = rng.random() < NEED_SPRING
    for _ in range(LAYOUT_TRIES):
        layout = random_spring_layout(rng)
        drawn = session(layout, (), pen, seed)
        if not recognised(layout, drawn.scene):
            continue
        drawn_rest = next(c.rest_length for c in drawn.scene.components.values() if isinstance(c, Spring))
        for _ in range(THROW_TRIES):
            k = round(math.exp(rng.uniform(math.log(K_RANGE[0]), math.log(K_RANGE[1]))), 3)
            rest = round(drawn_rest * rng.uniform(*REST_RANGE), 2)
            t = layout.trampoline
            target = (rng.uniform(t.left + RADIUS, t.right - RADIUS), t.top - RADIUS - rng.uniform(0.0, 20.0))
            d = (target[0] - layout.ball[0], target[1] - layout.ball[1])
            v = tuple(round(x, 3) for x in _launch(d, rng.uniform(*FLIGHT_S)))
            path = _throw(drawn, v, k, rest, PRESS[pen])
            if path is None or (need and _touches(drawn, v, None) == _touches(drawn, v, (k, rest))):
                continue
            case = SpringCase(seed, pen, layout, path, v, k, rest)
            if witnessed(case) and (not need or spring_matters(case)):
                return case
            if not need:
                break
    raise RuntimeError(f"spring case {seed}: no layout in {LAYOUT_TRIES} gave a witnessed throw")


def witnessed(case: SpringCase) -> bool:
    """Whether the case's generating parameters reproduce its demonstration (qualitative distance 0)."""
    s = case.session()
    if s.timeline is None or not recognised(case.layout, s.scene):
        return False
    score = evaluate(s.scene, s.timeline, s.canvas, case.witness_parameters(), rollout_seconds(s.timeline))
    return not score.exploded and score.qualitative == 0


def _thrown(drawn: Session, v, spring: tuple[float, float] | None):
    """The rollout of the throw ``v`` with the spring ``(k, natural length)`` (None: the seeded spring)."""
    scene = drawn.scene
    base = seed_parameters(scene, Timeline(()), drawn.canvas)
    if spring is None:
        parameters = base.with_velocities({body_id(scene, "ball"): v}) if base.velocities else \
            Parameters(base.bodies, base.springs, {body_id(scene, "ball"): v})
    else:
        parameters = _with_witness(base, scene, v, *spring)
    return rollout(scene, drawn.canvas, parameters, max_seconds=THROW_SECONDS)


def _touches(drawn: Session, v, spring: tuple[float, float] | None) -> list[tuple[str, ...]]:
    """The ball's contacts in the rollout of ``v``: each as the other body and its side, in order."""
    ball = body_id(drawn.scene, "ball")
    events = _thrown(drawn, v, spring).timeline.events
    return [tuple(sorted(ev.sides)) for ev in sorted(events, key=lambda e: e.t0)
            if ev.type == "contact" and ball in ev.components]


def _throw(drawn: Session, v, k: float, rest: float, press: float):
    scene = drawn.scene
    ball, basket, tramp = (body_id(scene, n) for n in ("ball", "basket", TRAMPOLINE))
    result = _thrown(drawn, v, (k, rest))
    if result.stopped_because == Stop.EXPLODED or any("settle" not in f and "would not stay" not in f
                                                      for f in result.flagged):
        return None
    events = result.timeline.events
    contacts = ball_contacts(events, ball)
    if not contacts or tramp not in contacts[0].components or dict(contacts[0].sides).get(tramp) != "top":
        return None
    if not any(ev.type == "movement" and ev.components and ev.components[0] == tramp for ev in events):
        return None
    found = into_basket(events, ball, basket, press)
    return None if found is None else found[0]


# -- impossible -------------------------------------------------------------------------------------------------

OVER_FIRST = "the trampoline's top, then the base's top"
UNDER_FIRST = "the base's top, then the trampoline's top"
ROUND = 2.0 * RADIUS
"""How far beyond the trampoline's end (past touching it) the pen takes the ball round it."""


@dataclass(frozen=True, slots=True)
class ImpossibleSpring:
    """An impossible spring case: the ball touches the base's top and the trampoline's top, one right after the
    other in `order`, then drops into the basket."""

    seed: int
    pen: str
    layout: SpringLayout
    order: str
    path: tuple[tuple[float, float], ...]

    @property
    def name(self) -> str:
        return f"impossible-spring-{self.seed}"

    @property
    def reason(self) -> str:
        return (f"the ball touches {self.order} with nothing between: the base lies under the trampoline, which "
                "moves only up and down on its spring and cannot pass through the base, and a free flight keeps the "
                "ball's horizontal speed, so it cannot come round the trampoline's end from one face to the other")

    @property
    def second(self) -> str:
        """The body of the contact the construction made impossible."""
        return "base" if self.order == OVER_FIRST else TRAMPOLINE

    def session(self) -> Session:
        return _session(self)

    def impossible_event(self) -> Event:
        """The demonstrated contact the construction made impossible: the ball's second contact."""
        return _ball_contacts(self.session())[1]


@cache
def impossible_spring(seed: int) -> ImpossibleSpring:
    """The impossible spring case of ``seed`` (see the module docstring)."""
    rng = random.Random(f"impossible-spring:{seed}")
    pen = "hurried" if rng.random() < HURRIED_SHARE else "virtual"
    order = OVER_FIRST if random.Random(f"impossible-spring-order:{seed}").random() < 0.5 else UNDER_FIRST
    for _ in range(LAYOUT_TRIES):
        layout = random_spring_layout(rng)
        layout = replace(layout, platforms=(layout.trampoline,))  # nothing else near the trampoline
        _, base_top, _, _ = layout.base()
        if order == UNDER_FIRST:
            layout = replace(layout, ball=(rng.uniform(110, 260), base_top - RADIUS - rng.uniform(30.0, 60.0)))
            if layout.ball[0] + RADIUS + CLEARANCE > layout.trampoline.left:
                continue
        path = _impossible_path(rng, layout, order, PRESS[pen])
        if not all(RADIUS < px < CANVAS[0] - RADIUS and RADIUS < py < CANVAS[1] - RADIUS / 2 for px, py in path):
            continue
        case = ImpossibleSpring(seed, pen, layout, order, path)
        if _demonstrated(case):
            return case
    raise RuntimeError(f"impossible spring case {seed}: no layout in {LAYOUT_TRIES} was demonstrated as constructed")


def _impossible_path(rng: random.Random, layout: SpringLayout, order: str, press: float):
    """`UNDER_FIRST`: in from the left under the trampoline, down onto the base (left or right of the spring) and
    up; out round the trampoline's right end, over it, down onto its top and up; round the right end again and into
    the basket. `OVER_FIRST`: down onto the trampoline's top and up; round its right end and in under it, down onto
    the base and up; out round the right end again and into the basket."""
    t = layout.trampoline
    x0, base_top, x1, _ = layout.base()
    over = t.top - RADIUS - ROUND
    on_top = t.top - RADIUS + press
    low = base_top - RADIUS - 30.0
    on_base = base_top - RADIUS + press
    end = t.right + RADIUS + ROUND
    on_t = rng.uniform(t.left + 0.2 * t.length, t.right - 0.2 * t.length)
    on_b = rng.uniform(x0 + RADIUS * 0.3, x0 + RADIUS * 0.8) if rng.random() < 0.5 else \
        rng.uniform(x1 - RADIUS * 0.8, x1 - RADIUS * 0.3)
    top = ((on_t, over), (on_t, on_top), (on_t, over))
    base = ((on_b, low), (on_b, on_base), (on_b, low))
    if order == OVER_FIRST:
        middle = (*top, (end, over), (end, low), *base, (end, low))
    else:
        middle = (*base, (end, low), (end, over), *top, (end, over))
    b = layout.basket
    drop_x = b.x + b.width / 2
    return (layout.ball, *middle, (drop_x, min(middle[-1][1], b.rim) - RADIUS - 40),
            (drop_x, b.floor - RADIUS + press))


def _demonstrated(case: ImpossibleSpring) -> bool:
    s = case.session()
    if s.timeline is None or not recognised(case.layout, s.scene):
        return False
    names = s.scene.names()
    got = [(names[_other(s, c)], dict(c.sides).get(_other(s, c))) for c in _ball_contacts(s)]
    pair = [("base", "top"), (TRAMPOLINE, "top")]
    return got == [*(pair if case.order == UNDER_FIRST else pair[::-1]), ("basket", "inside")]


def _ball_contacts(s: Session) -> list[Event]:
    return ball_contacts(s.timeline.events, body_id(s.scene, "ball"))


def _other(s: Session, contact: Event) -> str:
    ball = body_id(s.scene, "ball")
    return next(c for c in contact.components if c != ball)


def spring_matters(case: SpringCase) -> bool:
    """Whether the witness's throw with the seeded spring (`seeding.SPRING_K`, the drawn natural length) fails to
    reproduce the demonstration: then the search must move the spring (or find another throw)."""
    s = case.session()
    seeded = seed_parameters(s.scene, s.timeline, s.canvas)
    at_throw = seeded.with_velocities({body_id(s.scene, "ball"): case.witness})
    score = evaluate(s.scene, s.timeline, s.canvas, at_throw, rollout_seconds(s.timeline))
    return score.exploded or score.qualitative > 0
