"""The scene's components as frozen values: bodies, joints, ropes, springs, labels; no physics engine.

A `Scene` is the whole sketch as plain data, the thing projects save and undo restores. Coordinates
are canvas units with y down (gravity acts towards +y); angles are radians. `world.World` mirrors a
Scene into pymunk; `interpret` decides which component a recognised stroke becomes.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

Point = tuple[float, float]
BACKGROUND = "background"
"""The id that joints and springs use for the invisible background body (thesis 3.2.3)."""


@dataclass(frozen=True, slots=True)
class Material:
    """Density per unit area, restitution (0..1) and friction coefficient (>= 0)."""

    density: float
    restitution: float
    friction: float


# Thesis footnote 3 and DESIGN.md: boxes bounce fully and grip, balls bounce half, freeform solids barely bounce
# and let balls slide. A contact takes the larger restitution and the mean friction of the two bodies.
MATERIALS: dict[str, Material] = {
    "box": Material(1.0, 1.0, 1.0),
    "round": Material(1.0, 0.5, 1.0),
    "freeform": Material(1.0, 0.2, 0.0),
}


def material_class(shape: str) -> str:
    """``box`` for boxes, ``round`` for circles and ellipses, ``freeform`` for everything else."""
    return "box" if shape == "box" else "round" if shape in ("circle", "ellipse") else "freeform"


@dataclass(frozen=True, slots=True)
class Body:
    """A rigid body.

    Attributes:
        id: stable component id (``b1``, ``b2`` ...), never reused within a scene.
        shape: ``box``, ``circle``, ``ellipse``, ``polygon`` (closed freeform) or ``polyline`` (an open chain of
            thin segments, e.g. a ramp).
        outline: the shape's vertices in body coordinates (relative to ``position``, unrotated); a circle has
            none (see ``radius``); ellipses are polygons of 32 vertices; polylines are open.
        radius: a circle's radius, else 0.
        position: the body's origin in canvas units (its centroid when created).
        angle: rotation in radians.
        material: density, restitution, friction.
        label: the user's name for it, or None.
    """

    id: str
    shape: str
    outline: tuple[Point, ...]
    radius: float
    position: Point
    angle: float
    material: Material
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Joint:
    """A rotational (``pivot``) or fixed (``weld``) joint between a body and what lies under the anchor.

    Attributes:
        id: stable component id (``j1`` ...).
        kind: ``pivot`` or ``weld``.
        a: the body the symbol was drawn in.
        b: the body under it, or `BACKGROUND`.
        anchor: the joint's point in canvas units when created.
    """

    id: str
    kind: str
    a: str
    b: str
    anchor: Point


@dataclass(frozen=True, slots=True)
class Rope:
    """A rope: a chain of short links joined by pivots, ends welded to the bodies they overlap.

    Attributes:
        id: stable component id (``r1`` ...).
        points: the rope's path in canvas units, one point per link end (at least two).
        start_body, end_body: the body each end is attached to, `BACKGROUND`, or None when free.
    """

    id: str
    points: tuple[Point, ...]
    start_body: str | None = None
    end_body: str | None = None
    label: str | None = None


@dataclass(frozen=True, slots=True)
class Spring:
    """A Hooke's-law spring along one axis between two anchors.

    Attributes:
        id: stable component id (``s1`` ...).
        a, b: the bodies (or `BACKGROUND`) its ends are tethered to; at least one is fixed.
        anchor_a, anchor_b: its end points in canvas units when created.
        axis: ``horizontal`` or ``vertical``: the only direction it may stretch (a groove holds the other).
        rest_length: natural length in canvas units (the sketched length).
        k: spring constant (seeded at 20).
    """

    id: str
    a: str
    b: str
    anchor_a: Point
    anchor_b: Point
    axis: str
    rest_length: float
    k: float = 20.0
    label: str | None = None


Component = Body | Joint | Rope | Spring


@dataclass(frozen=True, slots=True)
class Scene:
    """Every component of a sketch, in creation order (later bodies lie on top of earlier ones).

    Attributes:
        components: id -> component, insertion-ordered.
        next_id: the next number for each prefix (``b``, ``j``, ``r``, ``s``), so ids are never reused.
    """

    components: dict[str, Component] = field(default_factory=dict)
    next_id: dict[str, int] = field(default_factory=lambda: {"b": 1, "j": 1, "r": 1, "s": 1})

    def new_id(self, prefix: str) -> tuple[str, Scene]:
        """A fresh id and the scene with its counter advanced."""
        n = self.next_id.get(prefix, 1)
        return f"{prefix}{n}", replace(self, next_id={**self.next_id, prefix: n + 1})

    def add(self, component: Component) -> Scene:
        return replace(self, components={**self.components, component.id: component})

    def remove(self, *ids: str) -> Scene:
        return replace(self, components={k: v for k, v in self.components.items() if k not in ids})

    def update(self, component: Component) -> Scene:
        if component.id not in self.components:
            raise KeyError(component.id)
        return replace(self, components={**self.components, component.id: component})

    def body(self, body_id: str) -> Body:
        """The body with this id (KeyError when the scene has no body of that id)."""
        c = self.components[body_id]
        if not isinstance(c, Body):
            raise KeyError(body_id)
        return c

    def bodies(self) -> list[Body]:
        return [c for c in self.components.values() if isinstance(c, Body)]

    def labels(self) -> dict[str, str]:
        """Component id -> the user's label, for every labelled component (what phrases name them by)."""
        return {c.id: label for c in self.components.values() if (label := getattr(c, "label", None))}

    def names(self) -> dict[str, str]:
        """Component id -> what narration calls it: its label; an unlabelled spring or rope by what it is.

        ``Movement of peg [attached to spring]`` rather than ``[attached to s2]``; an unlabelled body keeps its
        id, the handle ``label b2 ball`` takes.
        """
        kinds = {c.id: type(c).__name__.lower() for c in self.components.values() if isinstance(c, Spring | Rope)}
        return {**kinds, **self.labels()}

    def called(self, component_id: str) -> str:
        """How a message names a component: ``ball (b2)`` when labelled, else its id."""
        label = getattr(self.components.get(component_id), "label", None)
        return f"{label} ({component_id})" if label else component_id

    def fixed_bodies(self) -> frozenset[str]:
        """Ids of the bodies welded to the background (one pass, for questions about every body)."""
        return frozenset(end for c in self.components.values() if isinstance(c, Joint) and c.kind == "weld"
                         and BACKGROUND in (c.a, c.b) for end in (c.a, c.b)) - {BACKGROUND}

    def is_fixed(self, body_id: str) -> bool:
        """Whether a body is welded to the background (or is the background)."""
        if body_id == BACKGROUND:
            return True
        return any(isinstance(c, Joint) and c.kind == "weld" and body_id in (c.a, c.b) and BACKGROUND in (c.a, c.b)
                   for c in self.components.values())

    def attached_to(self, body_id: str) -> list[str]:
        """Ids of the joints, springs and ropes that hold on to a body (they go when it goes)."""
        out = []
        for c in self.components.values():
            if (isinstance(c, Joint) and body_id in (c.a, c.b)) or (
                isinstance(c, Spring) and body_id in (c.a, c.b)) or (
                isinstance(c, Rope) and body_id in (c.start_body, c.end_body)):
                out.append(c.id)
        return out
