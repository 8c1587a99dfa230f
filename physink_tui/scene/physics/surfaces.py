"""The contact materials of a world: each material a surface type whose shapes carry a grip, the bounce and the
mean friction of every pair; which callbacks act on them is world.py's and contacts.py's.

DESIGN.md wants a contact to take the larger restitution and the mean friction of its two shapes, and
`contacts.BOUNCE_THRESHOLD` a bounce only when a contact begins fast; Chipmunk multiplies the two shapes' values on
every step a contact lasts, and a Python pre-solve callback for every contact on every step made stepping four times
slower than pymunk alone. So each distinct material gets a *surface type*, a small positive ``collision_type``; a
shape's ``elasticity`` is 0.0 (Chipmunk's product is then the inelastic value every contact has after its first
step, and the world's begin callback sets the pair's restitution, `Surfaces.bounces`, on a fast first contact) and its
``friction`` is a *grip* chosen so that the product is exactly the mean friction for as many pairs of surfaces as
can be (`grip`; the project's materials come first: with boxes and balls at 1.0, freeform's 0.0 becomes 0.5, exact
against both, wrong only against itself); the pairs left are listed in `Surfaces.frictions`, and the world registers a
pre-solve callback for those pairs alone, writing the mean back. Read a shape's material values with
`Surfaces.of`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import pymunk

from physink_tui.scene.components import MATERIALS, Material

ROPE_MATERIAL = Material(0.05, 0.0, 0.5)
"""Rope links: 1/20 of a solid's density, so a rope is light next to what it holds (DESIGN.md calls ropes massless)
while its links still drag along; no bounce of their own (a contact takes the other body's); middling grip."""


@dataclass(slots=True)
class Surfaces:
    """The surface types of the materials met so far.

    Attributes:
        materials: surface type (a shape's ``collision_type``) -> its material's (restitution, friction).
        grips: surface type -> the ``friction`` its shapes carry (see the module docstring).
        bounces: (surface type, surface type), both orders -> the larger restitution of the two.
        frictions: (surface type, surface type), one order -> the mean friction, for the pairs whose product (what
            Chipmunk computes) is not the mean.
    """

    materials: dict[int, tuple[float, float]] = field(default_factory=dict)
    grips: dict[int, float] = field(default_factory=dict)
    bounces: dict[tuple[int, int], float] = field(default_factory=dict)
    frictions: dict[tuple[int, int], float] = field(default_factory=dict)
    _types: dict[tuple[float, float], int] = field(default_factory=dict)

    def __post_init__(self) -> None:
        # The project's own materials first, in a fixed order, so their grips do not depend on which a scene has
        # first (a freeform body drawn before any box would keep a grip of 0.0, inexact against boxes and balls).
        for material in (*MATERIALS.values(), ROPE_MATERIAL):
            self.type_of(material.restitution, material.friction)

    def type_of(self, restitution: float, friction: float) -> int:
        """The surface type of a material, extending `bounces` and `frictions` with its pairs when it is new."""
        kind = self._types.get((restitution, friction))
        if kind is None:
            kind = len(self._types) + 1  # collision type 0 is pymunk's default: left to shapes not built here
            self._types[(restitution, friction)] = kind
            self.materials[kind] = (restitution, friction)
            self.grips[kind] = held = grip(friction, [(f, self.grips[o]) for o, (_, f) in self.materials.items()
                                                      if o != kind])
            for other, (e, f) in self.materials.items():
                self.bounces[kind, other] = self.bounces[other, kind] = max(restitution, e)
                mean = (friction + f) / 2
                if held * self.grips[other] != mean:
                    self.frictions[other, kind] = mean
        return kind

    def of(self, shape: pymunk.Shape) -> tuple[float, float]:
        """``(restitution, friction)`` of a shape's material (its ``elasticity`` is 0.0, see the module docstring)."""
        return self.materials[shape.collision_type]

    def dress(self, shape: pymunk.Shape, restitution: float, friction: float) -> None:
        """Gives ``shape`` the surface of a material: its surface type, no elasticity of its own, the friction."""
        shape.collision_type = self.type_of(restitution, friction)
        shape.elasticity = 0.0
        shape.friction = self.grips[shape.collision_type]


def grip(friction: float, others: list[tuple[float, float]]) -> float:
    """The ``friction`` for the shapes of a new surface: of the candidates (its own friction, and for each surface
    already there the grip that would make that pair exact), the one whose product with itself and with the others'
    grips equals the mean friction exactly for the most pairs; the first such, so ties keep the material's own value.

    ``others`` holds each existing surface's (friction, grip).

    >>> grip(0.0, [(1.0, 1.0), (1.0, 1.0)])  # 0.5 makes both pairs exact (0.5 * 1.0 == (1.0 + 0.0) / 2), not itself
    0.5
    >>> grip(0.0, [(1.0, 1.0)])  # one pair either way: the material's own friction
    0.0
    """
    candidates = [friction] + [(friction + f) / 2 / g for f, g in others if g != 0.0]

    def exact(grip: float) -> int:
        pairs = [(friction, grip), *others]
        return sum(grip * g == (friction + f) / 2 for f, g in pairs)

    return max(candidates, key=exact)  # max keeps the first of equals
