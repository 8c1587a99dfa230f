"""Random ball-and-platform drawings: a ball, one to three platforms welded at random positions and angles, and a
basket, as pen strokes with their labels and welds (a fixed distribution, seeded; no physics).

Everything is laid out in canvas units (the 1600 x 1000 canvas the reference tablet shows one to one) and drawn in
tablet fractions. Bodies keep `CLEARANCE` between them, so a ball always fits between two of them.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

from scenarios.thesis import BACKGROUND, BodyX, Expected, JointX, Step, _x_steps, ball

from physink_tui.input.virtual_pen import Stroke

Point = tuple[float, float]

CANVAS = (1600.0, 1000.0)
RADIUS = 35.0
"""The ball's radius, canvas units."""
THICKNESS = 45.0
"""A platform's thickness, canvas units (the bouncing scenarios' 0.045 of the height)."""
CLEARANCE = 2.6 * RADIUS
"""The least gap between two bodies of a layout (a ball passes between any two)."""
LETTERS = "abc"
TRIES = 200
"""Placements tried per platform before the layout starts again with fewer."""


@dataclass(frozen=True, slots=True)
class Platform:
    """A welded box: centre, length, angle (radians, y down: positive turns clockwise on screen)."""

    name: str
    centre: Point
    length: float
    angle: float = 0.0

    def corners(self) -> tuple[Point, Point, Point, Point]:
        """Top-left, top-right, bottom-right, bottom-left (before turning), turned about the centre."""
        c, s = math.cos(self.angle), math.sin(self.angle)
        hl, ht = self.length / 2, THICKNESS / 2
        out = []
        for px, py in ((-hl, -ht), (hl, -ht), (hl, ht), (-hl, ht)):
            out.append((self.centre[0] + px * c - py * s, self.centre[1] + px * s + py * c))
        return tuple(out)  # type: ignore[return-value]

    @property
    def level(self) -> bool:
        return self.angle == 0.0

    @property
    def left(self) -> float:
        return min(x for x, _ in self.corners())

    @property
    def right(self) -> float:
        return max(x for x, _ in self.corners())

    @property
    def top(self) -> float:
        return min(y for _, y in self.corners())

    @property
    def bottom(self) -> float:
        return max(y for _, y in self.corners())


@dataclass(frozen=True, slots=True)
class Basket:
    """An open cup: the left end of its rim, its rim's width, rim and floor heights."""

    x: float
    width: float
    rim: float
    floor: float

    def outline(self) -> tuple[Point, Point, Point, Point]:
        inset = self.width * 0.1
        return ((self.x, self.rim), (self.x + inset, self.floor), (self.x + self.width - inset, self.floor),
                (self.x + self.width, self.rim))

    @property
    def inner(self) -> tuple[float, float]:
        """The floor's span a resting ball's centre lies in."""
        inset = self.width * 0.1
        return (self.x + inset + RADIUS, self.x + self.width - inset - RADIUS)


@dataclass(frozen=True, slots=True)
class Layout:
    """One drawing: the ball's centre, the platforms (named ``platform a`` ...), the basket."""

    ball: Point
    platforms: tuple[Platform, ...]
    basket: Basket

    def platform(self, name: str) -> Platform:
        return next(p for p in self.platforms if p.name == name)

    def steps(self) -> tuple[Step, ...]:
        """The drawing as pen steps: the ball, each platform and its weld, the basket and its weld."""
        out = [Step("the ball", ball(frac(self.ball), RADIUS / CANVAS[1]), say=("label ball",))]
        for p in self.platforms:
            corners = [frac(q) for q in p.corners()]
            out.append(Step(p.name, Stroke((*corners, corners[0])), say=(f"label {p.name}",)))
            out.extend(_x_steps(p.name, frac(p.centre)))
        outline = self.basket.outline()
        out.append(Step("the basket", Stroke(tuple(frac(q) for q in outline)), say=("label basket",)))
        floor_middle = ((outline[1][0] + outline[2][0]) / 2, self.basket.floor)
        out.extend(_x_steps("basket", frac(floor_middle)))
        return tuple(out)

    def expected(self) -> Expected:
        names = [p.name for p in self.platforms]
        return Expected(
            bodies=(BodyX("ball", "circle", "ball"), *(BodyX(n, "box", n) for n in names),
                    BodyX("basket", "polyline", "basket")),
            joints=tuple(JointX("weld", n, BACKGROUND) for n in (*names, "basket")),
            fixed=(*names, "basket"),
        )


def frac(p: Point) -> Point:
    """Canvas units to tablet fractions."""
    return (p[0] / CANVAS[0], p[1] / CANVAS[1])


def random_layout(rng: random.Random, *, count: int | None = None, level: int = 0,
                  ball_low: bool = False) -> Layout:
    """A layout drawn from the generator's distribution (see the module docstring).

    Args:
        count: platforms wanted (default: 1-3 at random).
        level: how many of the platforms must be level (the impossible constructions need one).
        ball_low: put the ball low on the left (below where platforms may be), not top left.
    """
    count = rng.choice((1, 2, 3)) if count is None else count
    while True:
        centre = ((rng.uniform(110, 300), rng.uniform(560, 680)) if ball_low
                  else (rng.uniform(110, 330), rng.uniform(90, 220)))
        width = rng.uniform(260, 360)
        rim = rng.uniform(690, 780)
        basket = Basket(rng.uniform(650, CANVAS[0] - 60 - width), width, rim, rng.uniform(920, 960))
        platforms: list[Platform] = []
        for k in range(count):
            for _ in range(TRIES):
                flat = k < level or rng.random() < 0.25
                angle = 0.0 if flat else math.radians(rng.uniform(-22.0, 22.0))
                y_range = (230.0, 420.0) if ball_low else (300.0, 640.0)
                p = Platform(f"platform {LETTERS[k]}", (rng.uniform(330, 1350), rng.uniform(*y_range)),
                             rng.uniform(240, 440), angle)
                if _fits(p, centre, basket, platforms):
                    platforms.append(p)
                    break
            else:
                break
        if len(platforms) == count:
            return Layout(centre, tuple(platforms), basket)


def _fits(p: Platform, ball_centre: Point, basket: Basket, others: list[Platform]) -> bool:
    box = (p.left, p.top, p.right, p.bottom)
    if box[0] < 60 or box[2] > CANVAS[0] - 60 or box[1] < 120:
        return False
    outline = basket.outline()
    basket_box = (outline[0][0], basket.rim, outline[3][0], basket.floor)
    ball_box = (ball_centre[0] - RADIUS, ball_centre[1] - RADIUS, ball_centre[0] + RADIUS, ball_centre[1] + RADIUS)
    if _gap(box, basket_box) < CLEARANCE or _gap(box, ball_box) < CLEARANCE:
        return False
    return all(_gap(box, (q.left, q.top, q.right, q.bottom)) >= CLEARANCE for q in others)


def _gap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    """The distance between two axis-aligned boxes (0 when they overlap)."""
    dx = max(b[0] - a[2], a[0] - b[2], 0.0)
    dy = max(b[1] - a[3], a[1] - b[3], 0.0)
    return math.hypot(dx, dy)
