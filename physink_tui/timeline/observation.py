"""What the recorder is fed after every physics step: the world's bodies, the contacts begun, what the pen holds and
what plays back; a plain value, built by demo mode and by SIMULATE's rollouts, read by `recorder.Recorder`."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from physink_tui.scene.physics.contacts import ContactRecord
from physink_tui.scene.physics.state import Motion


@dataclass(frozen=True, slots=True)
class Observation:
    """What the world looks like after one step.

    Attributes:
        t: timeline time of the step.
        poses: every body's pose (fixed bodies may be left out).
        contacts: contacts begun in this step, in the order they began.
        grabbed: the body the pen holds, or None.
        touching: the pairs of bodies touching now.
        playing: bodies following their recorded trajectories (concurrent movement) rather than the physics.
    """

    t: float
    poses: Mapping[str, Motion]
    contacts: Sequence[ContactRecord] = ()
    grabbed: str | None = None
    touching: frozenset[frozenset[str]] = frozenset()
    playing: frozenset[str] = frozenset()
