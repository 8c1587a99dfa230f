"""The free parameters of a simulation (thesis 3.4.3) as a frozen value, and a scene carrying them; no search,
no stepping.

A `Parameters` holds, per movable body, its mass and friction; per start-moved body, its initial velocity; per
spring, its constant and natural length. Restitution is not a parameter (it stays by shape class, thesis 3.4.3) and
ropes are massless (they carry no parameters). `apply` writes masses, frictions and springs into a `Scene`; the
initial velocities are given to the world when a rollout starts (rollout.py). Seeding them is seeding.py's business.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from types import MappingProxyType

from physink_tui.errors import SimulationError
from physink_tui.scene.components import Body, Scene, Spring
from physink_tui.scene.physics.build import body_area


@dataclass(frozen=True, slots=True)
class BodyParameters:
    """A movable body's free parameters.

    Attributes:
        mass: in the world's units (canvas units² at density 1.0); > 0 and finite.
        friction: friction coefficient; >= 0 and finite.
    """

    mass: float
    friction: float


@dataclass(frozen=True, slots=True)
class SpringParameters:
    """A spring's free parameters.

    Attributes:
        k: spring constant in the thesis's units (`Spring.k`; seeded 20); > 0 and finite.
        rest_length: natural length in canvas units; >= 0 and finite.
    """

    k: float
    rest_length: float


Structure = tuple[tuple[tuple[str, BodyParameters], ...], tuple[tuple[str, SpringParameters], ...], tuple[str, ...]]
"""`Parameters.structure()`: the bodies' and springs' parameters, sorted by id, and the start bodies."""


@dataclass(frozen=True, slots=True)
class Parameters:
    """One candidate of the parameter search.

    Attributes:
        bodies: body id -> mass and friction, for every movable body (fixed bodies and ropes have none).
        springs: spring id -> k and rest length.
        velocities: body id -> initial velocity (vx, vy) in canvas units per second (y down), for the bodies the
            start event moves; these bodies are held still while the scene settles (rollout.py).
    """

    bodies: Mapping[str, BodyParameters]
    springs: Mapping[str, SpringParameters]
    velocities: Mapping[str, tuple[float, float]]

    def __post_init__(self) -> None:
        for name in ("bodies", "springs", "velocities"):
            object.__setattr__(self, name, MappingProxyType(dict(getattr(self, name))))

    def __reduce__(self) -> tuple[type[Parameters], tuple[dict[str, BodyParameters], dict[str, SpringParameters],
                                                          dict[str, tuple[float, float]]]]:
        """Pickled as plain dicts (a mapping proxy does not pickle), so candidates can go to worker processes."""
        return (Parameters, (dict(self.bodies), dict(self.springs), dict(self.velocities)))

    @property
    def start_bodies(self) -> tuple[str, ...]:
        """The bodies the start event moves, sorted."""
        return tuple(sorted(self.velocities))

    def structure(self) -> Structure:
        """Everything but the initial velocities, as a hashable key: candidates with equal keys settle alike, so a
        search may fork them all from one settled state (rollout.settled_state)."""
        return (tuple(sorted(self.bodies.items())), tuple(sorted(self.springs.items())), self.start_bodies)

    def with_velocities(self, velocities: Mapping[str, tuple[float, float]]) -> Parameters:
        """The same parameters with other initial velocities (for the same start bodies)."""
        if set(velocities) != set(self.velocities):
            raise SimulationError(f"velocities for {sorted(velocities)!r}; expected the start bodies "
                                  f"{sorted(self.velocities)!r}")
        return replace(self, velocities=velocities)


def _need(value: float, what: str, *, positive: bool) -> None:
    if not math.isfinite(value) or value < 0 or (positive and value == 0):
        bound = "> 0" if positive else ">= 0"
        raise SimulationError(f"{what} is {value!r}; expected a finite value {bound}")


def apply(scene: Scene, parameters: Parameters) -> Scene:
    """``scene`` with the parameters' masses (as material densities: mass / area), frictions, spring constants and
    natural lengths; components without parameters are left as they are.

    Raises:
        SimulationError: a parameter for a component the scene does not have (or of another kind), or a value that
            is not finite or out of range (a search must not propose it).
    """
    components = dict(scene.components)
    for body_id, p in parameters.bodies.items():
        body = components.get(body_id)
        if not isinstance(body, Body):
            raise SimulationError(f"parameters for body {body_id!r}, which the scene does not have")
        _need(p.mass, f"mass of {body_id!r}", positive=True)
        _need(p.friction, f"friction of {body_id!r}", positive=False)
        material = replace(body.material, density=p.mass / body_area(body), friction=p.friction)
        components[body_id] = replace(body, material=material)
    for spring_id, sp in parameters.springs.items():
        spring = components.get(spring_id)
        if not isinstance(spring, Spring):
            raise SimulationError(f"parameters for spring {spring_id!r}, which the scene does not have")
        _need(sp.k, f"k of {spring_id!r}", positive=True)
        _need(sp.rest_length, f"rest length of {spring_id!r}", positive=False)
        components[spring_id] = replace(spring, k=sp.k, rest_length=sp.rest_length)
    for body_id in parameters.velocities:
        if not isinstance(components.get(body_id), Body):
            raise SimulationError(f"initial velocity for body {body_id!r}, which the scene does not have")
    return replace(scene, components=components)
