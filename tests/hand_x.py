"""Hand-drawn X symbols for the tests: bowed arms with hooks, crossing off their middles, in canvas units; seeded."""

from __future__ import annotations

import math
import random

Point = tuple[float, float]


def arm(rng: random.Random, centre: Point, length: float, heading: float, *, offset: float = 0.0,
        bow: float = 0.0, hooks: tuple[float, float] = (0.0, 0.0), jitter: float = 0.3) -> list[Point]:
    """One arm through ``centre``: ``offset`` (share of its length) moves the crossing from its middle, ``bow`` is
    its sagitta as a share of its length, ``hooks`` the lengths (shares) of the tails turned back at each end."""
    d = (math.cos(heading), math.sin(heading))
    n = (-d[1], d[0])
    body = []
    for k in range(31):
        u = k / 30
        along, side = (u - 0.5 - offset) * length, 4 * bow * length * u * (1 - u)
        body.append((centre[0] + d[0] * along + n[0] * side, centre[1] + d[1] * along + n[1] * side))

    def hook(end: Point, away: Point, share: float) -> list[Point]:
        if share <= 0:
            return []
        turn = rng.choice((-1, 1)) * math.radians(rng.uniform(110, 160))
        e = (away[0] * math.cos(turn) - away[1] * math.sin(turn), away[0] * math.sin(turn) + away[1] * math.cos(turn))
        return [(end[0] + e[0] * share * length * j / 4, end[1] + e[1] * share * length * j / 4) for j in range(1, 5)]

    path = hook(body[0], (-d[0], -d[1]), hooks[0])[::-1] + body + hook(body[-1], d, hooks[1])
    if rng.random() < 0.5:
        path.reverse()
    return [(x + rng.gauss(0, jitter), y + rng.gauss(0, jitter)) for x, y in path]


def hand_x(seed: int | str, centre: Point, size: float, *, hook: float = 0.15, bow: float = 0.1,
           offset: float = 0.3) -> tuple[list[Point], list[Point]]:
    """Two arms of about ``size`` crossing near ``centre`` at 65-115 degrees, each bowed, hooked and off-centre up to
    the shares given (drawn at random from the seed)."""
    rng = random.Random(seed)
    base = math.pi / 4 + rng.uniform(-0.5, 0.5)
    arms = []
    for heading, length in ((base, size), (base + math.radians(rng.uniform(65, 115)), size * rng.uniform(0.8, 1.2))):
        hooks = tuple(rng.choice((0.0, rng.uniform(0.03, hook))) for _ in range(2))
        arms.append(arm(rng, centre, length, heading, offset=rng.uniform(-offset, offset),
                        bow=rng.uniform(-bow, bow), hooks=hooks))
    return arms[0], arms[1]
