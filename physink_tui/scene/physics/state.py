"""Where bodies are and how they move, as values: `Pose`, `Velocity`, `Motion` and a world's frozen `WorldState`;
no stepping, no pymunk."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import NamedTuple


class Pose(NamedTuple):
    """Where a body is: its origin (`Body.position`, canvas units) and its rotation in radians."""

    x: float
    y: float
    angle: float


class Velocity(NamedTuple):
    """How a body's origin moves (canvas units per second) and how fast it turns (radians per second)."""

    vx: float
    vy: float
    w: float


REST = Velocity(0.0, 0.0, 0.0)


class Motion(NamedTuple):
    """A body's pose and velocity together: what one step of the world observes of it."""

    x: float
    y: float
    angle: float
    vx: float
    vy: float
    w: float

    @property
    def pose(self) -> Pose:
        return Pose(self.x, self.y, self.angle)

    @property
    def velocity(self) -> Velocity:
        return Velocity(self.vx, self.vy, self.w)


@dataclass(frozen=True, slots=True)
class WorldState:
    """A world at one step, as a value a search can keep and fork from (`World.from_state`).

    Attributes:
        step: the steps the world had taken.
        bodies: every body's motion, by id (bodies fixed to the background included; they do not move).
        gravity: the world's gravity.
        links: every rope's links' motions, start to end, by rope id (a rope rebuilt where it was drawn would
            be stretched to wherever its bodies have gone).
    """

    step: int
    bodies: Mapping[str, Motion]
    gravity: tuple[float, float]
    links: Mapping[str, tuple[Motion, ...]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "bodies", MappingProxyType(dict(self.bodies)))
        object.__setattr__(self, "links", MappingProxyType({k: tuple(v) for k, v in self.links.items()}))
