"""Running a world for the modes and for SIMULATE: the gravity-free demo world, one observed step at a time,
and putting an adjusted body down; which steps to take and what they mean is left to the caller."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from physink_tui.scene.components import Scene
from physink_tui.scene.physics.contacts import ContactRecord
from physink_tui.scene.physics.state import REST, Motion
from physink_tui.scene.physics.world import World

DEMO_DAMPING = 0.1
"""Share of its velocity a free body keeps after one second in demo mode: a released body comes to rest (DESIGN.md),
as on a table top."""
CATCH_UP_STEPS = 60
"""Steps an adjusted body gets to catch up with where the pen lifted (unless something blocks it)."""
SETTLE_STEPS = 30
"""Steps after an adjusted body is put down in which overlaps resolve, so bodies end flush (thesis figure 2-6)."""
STEP_EPSILON = 1e-9
"""Slack (in steps) when counting the steps up to an input time, so float rounding never loses a step."""


@dataclass(frozen=True, slots=True)
class Frame:
    """What one step of a world showed.

    Attributes:
        step: the world's step count after the step.
        motions: the pose and velocity of every body observed.
        contacts: contacts begun in this step between observed bodies, in the order they began.
        touching: the pairs of observed bodies touching after the step.
    """

    step: int
    motions: Mapping[str, Motion]
    contacts: tuple[ContactRecord, ...]
    touching: frozenset[frozenset[str]]


def demo_world(scene: Scene) -> World:
    """The world of demo mode: no gravity, a little damping, no tunnelling; contacts and joints still act."""
    world = World.from_scene(scene, gravity=(0.0, 0.0))
    world.damping = DEMO_DAMPING
    world.limit_speeds()
    return world


def steps_until(t: float, origin: float, dt: float) -> int:
    """The whole steps of ``dt`` from input time ``origin`` to ``t``: a mode counts its steps from where it began,
    so advancing in many small pieces or one large one takes exactly the same steps.

    >>> 1.025 / (1 / 120), steps_until(1.025, 0.0, 1 / 120)
    (122.99999999999999, 123)
    """
    return int((t - origin) / dt + STEP_EPSILON)


def step_and_observe(world: World, bodies: Iterable[str], fixed: Mapping[str, Motion] | None = None) -> Frame:
    """Advance ``world`` one step and observe ``bodies``: their motions, the contacts begun among them, and which
    of them touch. ``fixed``: motions of bodies among them that cannot move (static, and no drag can make them
    dynamic: a rollout's welded bodies), given rather than read from the world each step."""
    world.step(1)
    motions = world.motions(bodies, fixed)
    observed = motions.keys()
    contacts = tuple(c for c in world.take_contacts() if c.a_id in observed and c.b_id in observed)
    touching = world.touching()
    if not all(observed >= pair for pair in touching):
        touching = frozenset(pair for pair in touching if observed >= pair)
    return Frame(world.steps, motions, contacts, touching)


def put_down(world: World, body_id: str) -> None:
    """End a drag the way an adjustment ends: the body catches up with the pen, is let go without being thrown,
    and the world settles so what it was pushed into ends flush against it."""
    world.step(CATCH_UP_STEPS)
    world.release()
    world.set_velocity(body_id, REST[:2], REST.w)
    world.step(SETTLE_STEPS)
