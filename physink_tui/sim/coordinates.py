"""The searched quantities of a `Parameters` as named coordinates, read, written and normalised; no search.

A `Coordinate` names one number: a body's mass or friction, a spring's constant or natural length, or a start
body's initial velocity as (angle, speed) for the thesis grid or (vx, vy) for the optimiser. `Normalisation` maps
a set of coordinates to an unscaled vector around a centre (log mass and log k, step 1 = a factor e; friction step
0.25, clipped to [0, 1]; natural length step l0/4, at least 0; each velocity component step half the seeded speed,
at least `MIN_SPEED_SCALE`), which is what an optimiser such as CMA-ES moves in.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass

from physink_tui.sim.parameters import BodyParameters, Parameters, SpringParameters

MIN_SPEED_SCALE = 100.0
"""Units/s: the smallest step of a velocity component in the normalised coordinates."""


@dataclass(frozen=True, slots=True)
class Coordinate:
    """One searched quantity: ``kind`` is "mass", "friction", "k", "rest_length", "angle", "speed" (grid) or
    "vx", "vy" (optimiser), of component ``component``."""

    kind: str
    component: str


def speed_angle(v: tuple[float, float]) -> tuple[float, float]:
    return math.hypot(*v), math.atan2(v[1], v[0])


def get_value(p: Parameters, c: Coordinate) -> float:
    """The value of ``c`` in ``p``."""
    if c.kind == "mass":
        return p.bodies[c.component].mass
    if c.kind == "friction":
        return p.bodies[c.component].friction
    if c.kind == "k":
        return p.springs[c.component].k
    if c.kind == "rest_length":
        return p.springs[c.component].rest_length
    v = p.velocities[c.component]
    speed, angle = speed_angle(v)
    return {"angle": angle, "speed": speed, "vx": v[0], "vy": v[1]}[c.kind]


def set_value(p: Parameters, c: Coordinate, value: float) -> Parameters:
    """``p`` with ``c`` set to ``value`` (a speed set on a velocity of 0 points along +x)."""
    bodies, springs, velocities = dict(p.bodies), dict(p.springs), dict(p.velocities)
    if c.kind in ("mass", "friction"):
        b = bodies[c.component]
        bodies[c.component] = BodyParameters(value, b.friction) if c.kind == "mass" else BodyParameters(b.mass, value)
    elif c.kind in ("k", "rest_length"):
        s = springs[c.component]
        springs[c.component] = SpringParameters(value, s.rest_length) if c.kind == "k" else \
            SpringParameters(s.k, value)
    else:
        vx, vy = velocities[c.component]
        speed, angle = speed_angle((vx, vy))
        if c.kind == "angle":
            vx, vy = speed * math.cos(value), speed * math.sin(value)
        elif c.kind == "speed":
            if speed == 0:
                angle = 0.0  # a velocity of 0 has no direction: start along +x (an angle sweep turns it)
            vx, vy = value * math.cos(angle), value * math.sin(angle)
        elif c.kind == "vx":
            vx = value
        else:
            vy = value
        velocities[c.component] = (vx, vy)
    return Parameters(bodies, springs, velocities)


def coordinates(p: Parameters, velocity_kinds: tuple[str, str],
                components: Collection[str] | None = None) -> list[Coordinate]:
    """Every coordinate of ``p`` (of ``components`` only, when given): initial velocities first, then masses and
    frictions by body, then natural lengths and constants by spring."""
    def wanted(c: str) -> bool:
        return components is None or c in components

    out = [Coordinate(kind, body) for body in p.start_bodies if wanted(body) for kind in velocity_kinds]
    out += [Coordinate(kind, body) for body in sorted(p.bodies) if wanted(body) for kind in ("mass", "friction")]
    out += [Coordinate(kind, spring) for spring in sorted(p.springs) if wanted(spring)
            for kind in ("rest_length", "k")]
    return out


class Normalisation:
    """Coordinates ``coords`` as an unscaled vector around ``centre``, with scales taken from ``seeded``."""

    def __init__(self, coords: Sequence[Coordinate], centre: Parameters, seeded: Parameters) -> None:
        self.coords = tuple(coords)
        self.centre = centre
        self.scales = tuple(_scale(c, seeded) for c in self.coords)

    def decode(self, z: Iterable[float]) -> Parameters:
        """The parameters at ``z`` (0 is the centre)."""
        p = self.centre
        for c, scale, zi in zip(self.coords, self.scales, z, strict=True):
            base = get_value(self.centre, c)
            if c.kind in ("mass", "k"):
                value = base * math.exp(float(zi) * scale)
            elif c.kind == "friction":
                value = min(max(base + float(zi) * scale, 0.0), 1.0)
            elif c.kind == "rest_length":
                value = max(base + float(zi) * scale, 0.0)
            else:
                value = base + float(zi) * scale
            p = set_value(p, c, value)
        return p


def _scale(c: Coordinate, seeded: Parameters) -> float:
    if c.kind in ("mass", "k"):
        return 1.0
    if c.kind == "friction":
        return 0.25
    if c.kind == "rest_length":
        return max(get_value(seeded, c) / 4, 1.0)
    speed, _ = speed_angle(seeded.velocities[c.component])
    return max(speed / 2, MIN_SPEED_SCALE)
