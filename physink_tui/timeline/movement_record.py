"""One movement while it is being recorded: the frames of the moving body and of what is tied to it, the regions
of other bodies the moving body passes through (tested only when it or they may have crossed a region boundary),
and how long it has been still. The recorder decides when movements open and close; this only accumulates and
writes the event back."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace

from physink_tui.scene.physics.state import Motion
from physink_tui.timeline.events import REGIONS, Event, TrajectoryPoint
from physink_tui.timeline.qualitative import BodyOutline, Strips, placed_bounds, region_in, strips


def speed(pose: Motion, radius: float) -> float:
    """How fast a body moves: its centre, or its rim when it spins faster."""
    return max(math.hypot(pose[3], pose[4]), abs(pose[5]) * radius)


@dataclass
class Regions:
    """Every body's `Strips` (bounds and how far its regions reach), computed only for a pose that some movement
    needs tested (`strips`), and how far each body moved since the last frame (`next_frame`), so a movement can skip
    testing a body while neither could have crossed one of the other's region boundaries.

    Attributes:
        outlines: every body's outline, by id.
        reach: how far (canvas units) a body's regions extend.
        radius: every body's hull radius (how far a vertex is from its origin at most), by id.
        shifts: per body of the last frame: how far its origin moved since the frame before, across and down, then
            how far any vertex of its hull did (rotation at the radius included); infinite when it was not there.
        fastest: the most any body's hull moved in the last frame, across and down (of ``shifts``).
        top: the body that moved most in the last frame (across plus down), or None.
        rest: ``fastest`` of every body but ``top``.
    """

    outlines: Mapping[str, BodyOutline]
    reach: float
    radius: Mapping[str, float]
    shifts: dict[str, tuple[float, float, float, float]] = field(default_factory=dict)
    fastest: tuple[float, float] = (math.inf, math.inf)
    top: str | None = None
    rest: tuple[float, float] = (math.inf, math.inf)
    _last: dict[str, Motion] = field(default_factory=dict)
    _cache: dict[str, tuple[tuple[float, ...], Strips]] = field(default_factory=dict)

    def next_frame(self, poses: Mapping[str, Motion]) -> None:
        """A frame whose movements are about to be recorded: note how far each body moved since the last one."""
        last, radius, shifts = self._last, self.radius, {}
        top, tx, ty, rx, ry = None, 0.0, 0.0, 0.0, 0.0
        for body, pose in poses.items():
            before = last.get(body)
            if before is None:
                shifts[body] = UNKNOWN_SHIFT
                rx = ry = math.inf
            elif before == pose:
                shifts[body] = NO_SHIFT
            else:
                dx, dy = abs(pose[0] - before[0]), abs(pose[1] - before[1])
                turn = abs(pose[2] - before[2]) * radius.get(body, 0.0)
                bx, by = dx + turn, dy + turn
                shifts[body] = (dx, dy, bx, by)
                if not math.isfinite(bx + by):
                    rx = ry = math.inf
                elif bx + by > tx + ty:
                    top, tx, ty, rx, ry = body, bx, by, max(rx, tx), max(ry, ty)
                else:
                    rx, ry = max(rx, bx), max(ry, by)
        self.shifts = shifts
        self.top, self.rest, self.fastest = top, (rx, ry), (max(tx, rx), max(ty, ry))
        self._last = dict(poses)

    def strips(self, body: str, pose: Motion) -> Strips:
        """``body``'s strips at ``pose`` (``body`` has an outline)."""
        cached = self._cache.get(body)
        at = pose[:3]
        if cached is None or cached[0] != at:
            cached = (at, strips(placed_bounds(self.outlines[body], pose), self.reach))
            self._cache[body] = cached
        return cached[1]


NO_SHIFT = (0.0, 0.0, 0.0, 0.0)
UNKNOWN_SHIFT = (math.inf, math.inf, math.inf, math.inf)
SLACK_TOLERANCE = 1e-9
"""Share of the coordinates' size kept off a region's slack, far more than rounding can account for."""


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
    _slack: dict[str, list[float]] = field(default_factory=dict)
    """Per other body: how far (across, down) the moving body and it may still move before its regions are tested
    again."""
    _others: tuple[str, ...] | None = None
    """The bodies with outlines other than ``bodies`` (known at the first frame)."""
    _budget: tuple[float, float] = (-math.inf, -math.inf)
    """The least slack of any other body after the last frame that looked at them (across, down)."""
    _deferred: tuple[float, float] = (0.0, 0.0)
    """How far (across, down) the moving body and any other may have moved together since that frame: while it
    is below ``_budget``, no body needs looking at."""

    @classmethod
    def resumed(cls, event: Event, bodies: tuple[str, ...]) -> OpenMovement:
        """Recording goes on in an existing movement (its frames and regions kept)."""
        frames: dict[str, list[TrajectoryPoint]] = {b: [] for b in bodies}
        frames[bodies[0]] = list(event.trajectory)
        for c, track in event.tracks:
            frames[c] = list(track)
        return cls(event.id, bodies, frames, {c: set(rs) for c, rs in event.regions})

    def record(self, t: float, poses: Mapping[str, Motion], held: bool, radius: Mapping[str, float],
               regions: Regions, moving_speed: float) -> None:
        """One frame: the poses of ``bodies``, the regions the moving body is in (of the other bodies with outlines;
        `Regions.next_frame` has seen this frame), and whether anything moved (``held``: the pen holds one of them).

        A body's regions are tested again only once the moving body and it have together moved (across, or down)
        as far as the moving body was from the nearest boundary of those regions when they were last tested:
        until then it is in the same region as then (or in none), which ``crossed`` already has.
        """
        moving = held
        frames = self.frames
        for body in self.bodies:
            pose = poses.get(body)
            if pose is not None:
                frames[body].append(TrajectoryPoint(t, pose[0], pose[1], pose[2], pose[3], pose[4]))
                moving = moving or speed(pose, radius[body]) > moving_speed
        mover = poses.get(self.bodies[0])
        if mover is not None:
            self._regions(mover[0], mover[1], poses, regions)
        self.still = 0 if moving else self.still + 1

    def _regions(self, x: float, y: float, poses: Mapping[str, Motion], regions: Regions) -> None:
        shifts, slack = regions.shifts, self._slack
        mx, my = shifts[self.bodies[0]][:2]
        ex, ey = self._deferred
        fx, fy = regions.rest if regions.top in self.bodies else regions.fastest  # its own bodies are not tested
        dx, dy = ex + mx + fx, ey + my + fy
        if dx < self._budget[0] and dy < self._budget[1]:
            self._deferred = (dx, dy)
            return
        if self._others is None:
            self._others = tuple(b for b in regions.outlines if b not in self.bodies)
        bx = by = math.inf
        cx, cy = ex + mx, ey + my  # the moving body's share of every slack's spending
        for other in self._others:
            pose = poses.get(other)
            if pose is None:
                continue
            left = slack.get(other)
            if left is not None:
                shift = shifts[other]
                sx, sy = left[0] - cx - shift[2], left[1] - cy - shift[3]
                if sx > 0.0 and sy > 0.0:
                    left[0], left[1] = sx, sy
                    if sx < bx:
                        bx = sx
                    if sy < by:
                        by = sy
                    continue
            box = regions.strips(other, pose)
            region = region_in((x, y), box)
            if region is not None:
                found = self.crossed.get(other)
                if found is None:
                    self.crossed[other] = {region}
                else:
                    found.add(region)
            minx, miny, maxx, maxy, top, bottom, far_left, far_right = box
            margin = SLACK_TOLERANCE * (abs(x) + abs(y) + abs(minx) + abs(miny) + abs(maxx) + abs(maxy)
                                        + regions.reach + 1.0)
            sx = min(abs(x - far_left), abs(x - minx), abs(x - maxx), abs(x - far_right)) - margin
            sy = min(abs(y - top), abs(y - miny), abs(y - maxy), abs(y - bottom)) - margin
            slack[other] = [sx, sy]
            bx = bx if sx >= bx else sx  # NaN (a pose gone wrong) leaves no budget
            by = by if sy >= by else sy
        self._budget = (bx, by)
        self._deferred = (0.0, 0.0)

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
