"""One movement while it is being recorded: the frames of the moving body and of what is tied to it, the regions
of other bodies the moving body passes through, and how long it has been still. The recorder decides when
movements open and close; this only accumulates and writes the event back."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

from physink_tui.scene.physics.state import Motion
from physink_tui.timeline.events import REGIONS, Event, TrajectoryPoint
from physink_tui.timeline.qualitative import BodyOutline, Strips, crossings, placed_bounds, strips


def speed(pose: Motion, radius: float) -> float:
    """How fast a body moves: its centre, or its rim when it spins faster."""
    return max(math.hypot(pose[3], pose[4]), abs(pose[5]) * radius)


@dataclass
class Regions:
    """Each body's `Strips` (bounds and how far its regions reach) at its latest pose, recomputed only when the pose
    changes; `at` gives them for one frame, which every movement being recorded then tests against."""

    outlines: Mapping[str, BodyOutline]
    reach: float
    _cache: dict[str, tuple[tuple[float, ...], Strips]] = field(default_factory=dict)

    def at(self, poses: Mapping[str, Motion]) -> list[tuple[str, Strips]]:
        """``(body, strips)`` for every body of ``poses`` with an outline, at its pose there."""
        cache, outlines, reach = self._cache, self.outlines, self.reach
        out = []
        for body, pose in poses.items():
            cached = cache.get(body)
            at = pose[:3]
            if cached is None or cached[0] != at:
                outline = outlines.get(body)
                if outline is None:
                    continue
                cached = (at, strips(placed_bounds(outline, pose), reach))
                cache[body] = cached
            out.append((body, cached[1]))
        return out


@dataclass
class OpenMovement:
    """A movement event being recorded.

    Attributes:
        event_id: the movement's event id.
        bodies: the moving body first, then the bodies tied to it.
        frames: per body, its frames so far.
        crossed: per other body, the regions of it the moving body has been in.
        still: frames in a row in which none of ``bodies`` moved.
    """

    event_id: str
    bodies: tuple[str, ...]
    frames: dict[str, list[TrajectoryPoint]]
    crossed: dict[str, set[str]] = field(default_factory=dict)
    still: int = 0

    @classmethod
    def resumed(cls, event: Event, bodies: tuple[str, ...]) -> OpenMovement:
        """Recording goes on in an existing movement (its frames and regions kept)."""
        frames: dict[str, list[TrajectoryPoint]] = {b: [] for b in bodies}
        frames[bodies[0]] = list(event.trajectory)
        for c, track in event.tracks:
            frames[c] = list(track)
        return cls(event.id, bodies, frames, {c: set(rs) for c, rs in event.regions})

    def record(self, t: float, poses: Mapping[str, Motion], held: bool, radius: Mapping[str, float],
               regions: Sequence[tuple[str, Strips]], moving_speed: float) -> None:
        """One frame: the poses of ``bodies``, the regions the moving body is in (of the other bodies of ``regions``,
        `Regions.at` this frame), and whether anything moved (``held``: the pen holds one of them)."""
        moving = held
        frames = self.frames
        for body in self.bodies:
            pose = poses.get(body)
            if pose is not None:
                frames[body].append(TrajectoryPoint(t, pose[0], pose[1], pose[2], pose[3], pose[4]))
                moving = moving or speed(pose, radius[body]) > moving_speed
        mover = poses.get(self.bodies[0])
        if mover is not None:
            crossed = self.crossed
            for other, region in crossings((mover[0], mover[1]), regions, self.bodies):
                found = crossed.get(other)
                if found is None:
                    crossed[other] = {region}
                else:
                    found.add(region)
        self.still = 0 if moving else self.still + 1

    def written(self, event: Event) -> Event:
        """``event`` brought up to date with what has been recorded."""
        mover = tuple(self.frames[self.bodies[0]])
        tracks = tuple((b, tuple(self.frames[b])) for b in self.bodies[1:] if self.frames[b])
        regions = tuple((other, tuple(r for r in REGIONS if r in found))
                        for other, found in sorted(self.crossed.items()))
        t1 = max(event.t0, mover[-1].t) if mover else event.t1
        if (event.trajectory, event.tracks, event.regions, event.t1) == (mover, tracks, regions, t1):
            return event
        return replace(event, t1=t1, trajectory=mover, tracks=tracks, regions=regions)
