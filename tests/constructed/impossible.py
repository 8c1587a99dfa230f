"""Impossible cases: a random layout with a level platform X, and a demonstration whose ball touches one face of X
(top or bottom) and then, with nothing between, the opposite face, before dropping into the basket.

Why no gravity simulation follows it (the argument each case's verdict must meet): when the ball touches X's top
(bottom), its contact normal lies within 45° of straight up (down), so its centre is above X's top (below its
bottom) and within r/√2 of X's span horizontally. To reach the opposite face it must cross the height of X's
thickness, where, not touching X, its centre is at least r beyond one of X's ends; then it must come back within
r/√2 of X's span. Between the two contacts nothing but X touches it (another contact would be an event between
them), so on its last free flight before the second contact its horizontal speed is constant: it cannot go out
beyond an end and come back. Nor can it stay on X round the end: at the end's corner the contact pushes it
outwards and gravity has no inward part at the corner's height, so nothing turns it round the corner. Rolling along
the face it touched does not take it to the other face either.

The ball starts top left above X (`OVER_THEN_UNDER`: top, then bottom) or low on the left below X
(`UNDER_THEN_OVER`: bottom, then top). The demonstration's contacts must be exactly X, X, basket (checked, else the
next layout is drawn).
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from functools import cache

from constructed.demonstrate import recognised, session
from constructed.layouts import CANVAS, RADIUS, Layout, Platform, random_layout
from constructed.possible import HURRIED_SHARE, PRESS
from physink_tui.session.session import Session
from physink_tui.timeline.events import Event

OVER_THEN_UNDER = "top, then bottom"
UNDER_THEN_OVER = "bottom, then top"
LAYOUT_TRIES = 40
ROUND = 2.0 * RADIUS
"""How far beyond X's end (past touching it) the pen takes the ball round it."""


@dataclass(frozen=True, slots=True)
class Impossible:
    """An impossible case: seed, pen, layout, the platform X, which faces in which order, the demonstrated path."""

    seed: int
    pen: str
    layout: Layout
    platform: str
    order: str
    path: tuple[tuple[float, float], ...]

    @property
    def name(self) -> str:
        return f"impossible-{self.seed}"

    @property
    def sides(self) -> tuple[str, str]:
        first, second = self.order.split(", then ")
        return first, second

    @property
    def reason(self) -> str:
        first, second = self.sides
        return (f"the ball touches the {first} of {self.platform}, then its {second} with nothing between: a free "
                "flight keeps its horizontal speed, so a ball cannot come round a level platform's end from one "
                "face onto the other")

    def session(self) -> Session:
        return _session(self)

    def impossible_event(self) -> Event:
        """The demonstrated contact the construction made impossible: the ball's second touch of X."""
        s = self.session()
        return _ball_contacts(s)[1]


@cache
def _session(case: Impossible) -> Session:
    return session(case.layout, case.path, case.pen, case.seed)


@cache
def impossible(seed: int) -> Impossible:
    rng = random.Random(f"impossible:{seed}")
    pen = "hurried" if rng.random() < HURRIED_SHARE else "virtual"
    order = OVER_THEN_UNDER if rng.random() < 0.5 else UNDER_THEN_OVER
    for _ in range(LAYOUT_TRIES):
        layout = random_layout(rng, level=1, ball_low=order == UNDER_THEN_OVER)
        x = layout.platforms[0]
        path = _path(rng, layout, x, order, PRESS[pen])
        if not all(RADIUS < px < CANVAS[0] - RADIUS and RADIUS < py < CANVAS[1] - RADIUS / 2 for px, py in path):
            continue
        case = Impossible(seed, pen, layout, x.name, order, path)
        if _demonstrated(case):
            return case
    raise RuntimeError(f"impossible case {seed}: no layout in {LAYOUT_TRIES} was demonstrated as constructed")


def _path(rng: random.Random, layout: Layout, x: Platform, order: str, press: float):
    u1, u2 = rng.uniform(0.2, 0.8), rng.uniform(0.2, 0.8)
    left = rng.random() < 0.5
    end = x.left - RADIUS - ROUND if left else x.right + RADIUS + ROUND

    def along(u: float) -> float:
        return x.left + u * (x.right - x.left)

    over = x.top - RADIUS - ROUND
    under = x.bottom + RADIUS + ROUND
    on_top = x.top - RADIUS + press
    on_bottom = x.bottom + RADIUS - press
    first, second = (on_top, on_bottom) if order == OVER_THEN_UNDER else (on_bottom, on_top)
    near, far = (over, under) if order == OVER_THEN_UNDER else (under, over)
    b = layout.basket
    drop_x = b.x + b.width / 2
    return (layout.ball, (along(u1), near), (along(u1), first), (along(u1), near), (end, near), (end, far),
            (along(u2), far), (along(u2), second), (along(u2), far), (drop_x, min(far, b.rim) - RADIUS - 40),
            (drop_x, b.floor - RADIUS + press))


def _demonstrated(case: Impossible) -> bool:
    s = case.session()
    if s.timeline is None or not recognised(case.layout, s.scene):
        return False
    names = s.scene.names()
    contacts = _ball_contacts(s)
    got = [(names[_other(s, c)], dict(c.sides).get(_other(s, c))) for c in contacts]
    first, second = case.sides
    return got == [(case.platform, first), (case.platform, second), ("basket", "inside")]


def _ball_contacts(s: Session) -> list[Event]:
    ball = next(b.id for b in s.scene.bodies() if b.label == "ball")
    return sorted((ev for ev in s.timeline.events if ev.type == "contact" and ball in ev.components),
                  key=lambda e: e.t0)


def _other(s: Session, contact: Event) -> str:
    ball = next(b.id for b in s.scene.bodies() if b.label == "ball")
    return next(c for c in contact.components if c != ball)
