"""Decides whether a contact report continues a contact already recorded or is a new one; no events, no clock.

A resting or sliding contact is one contact, however often the physics reports it. Two rules, either enough:

- *time* (DESIGN.md): a report of a pair within `SAME_CONTACT_FRAMES` frames of its previous report is the same
  contact;
- *distance*: once a pair's contact is recorded, the pair stays in that contact until the two bodies have moved
  apart by more than `LEAVE_FRACTION` of the smaller one's size (its equivalent diameter, the diameter of a disc
  of its area). A body bouncing in place by micro-separations, a spring-held platform jittering under a peg that
  slides over it, a box pushed along a floor by a trembling pen, a ball rattling in a cup: each touches again
  before it has gone anywhere, so each is one contact. A real second bounce (the ball leaves the platform,
  travels, comes back: thesis figure 2-12's "hits B twice") carries the body well clear, so it is a new contact.

How far apart two bodies are is measured between their convex hulls (as `qualitative.separated` does), so a body
moving in a container's hollow has not left it. An end-contact between a pair ends its contact: touching again
afterwards is a new one. A body that starts moving while in a contact that goes on is moved by that contact, not
by a new one (`going_on`). The recorder asks `same` and `going_on`, tells `recorded` and `ended`, and calls
`observe` every step.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from physink_tui.timeline.qualitative import BodyOutline, separated

SAME_CONTACT_FRAMES = 15
"""Repeated reports of one pair within this many frames are one contact (DESIGN.md)."""
LEAVE_FRACTION = 0.5
"""A pair whose hulls get further apart than this share of the smaller body's size has left its contact."""
MIN_LEAVE_GAP = 4.0
"""Canvas units: the least separation that counts as leaving (thin bodies, pen tremor)."""

Pose = tuple[float, ...]


def body_size(outline: BodyOutline) -> float:
    """A body's size: the diameter of the disc with its hull's area (0 for a line or a point).

    >>> round(body_size(BodyOutline("b", ((-10, -10), (10, -10), (10, 10), (-10, 10)), False)), 2)
    22.57
    """
    hull = outline.hull
    area = abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(hull, hull[1:] + hull[:1], strict=True))) / 2
    return 2 * math.sqrt(area / math.pi)


@dataclass
class Touches:
    """The recorded contacts still going on, and when each pair was last reported.

    Attributes:
        outlines: every body's outline, by id.
        dt: the physics step, seconds.
    """

    outlines: Mapping[str, BodyOutline]
    dt: float
    _last_report: dict[frozenset[str], float] = field(default_factory=dict)
    _resting: dict[frozenset[str], tuple[float, str]] = field(default_factory=dict)  # pair -> (leave gap, event)
    _size: dict[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self._size = {body: body_size(outline) for body, outline in self.outlines.items()}

    def leave_gap(self, pair: frozenset[str]) -> float:
        """How far apart (canvas units) the two bodies of ``pair`` must get to end their contact."""
        sizes = [self._size.get(body, 0.0) for body in pair]
        solid = [s for s in sizes if s > 0]
        return max(MIN_LEAVE_GAP, LEAVE_FRACTION * min(solid)) if solid else MIN_LEAVE_GAP

    def same(self, pair: frozenset[str], t: float) -> bool:
        """Whether a report of ``pair`` at ``t`` continues its recorded contact (and note the report)."""
        previous = self._last_report.get(pair)
        within = previous is not None and t - previous <= SAME_CONTACT_FRAMES * self.dt + 1e-9
        if within or pair in self._resting:
            self._last_report[pair] = t
            return True
        return False

    def recorded(self, pair: frozenset[str], t: float, event_id: str) -> None:
        """The contact event ``event_id`` of ``pair`` was recorded at ``t``."""
        self._last_report[pair] = t
        self._resting[pair] = (self.leave_gap(pair), event_id)

    def going_on(self, pair: frozenset[str]) -> str | None:
        """The id of the recorded contact ``pair`` is still in (it has not left it), or None."""
        resting = self._resting.get(pair)
        return resting[1] if resting is not None else None

    def ended(self, pair: frozenset[str]) -> None:
        """An end-contact of ``pair`` was recorded: what touches next is a new contact."""
        self._resting.pop(pair, None)
        self._last_report.pop(pair, None)

    def observe(self, poses: Mapping[str, Pose], touching: frozenset[frozenset[str]]) -> None:
        """One step: pairs in a recorded contact that have come apart by their leave gap have left it."""
        for pair in sorted(self._resting, key=sorted):
            if pair in touching:
                continue
            a, b = sorted(pair)
            pa, pb = poses.get(a), poses.get(b)
            if pa is None or pb is None:
                continue  # a body not reported (fixed) is where it was
            if separated(self.outlines[a], pa, self.outlines[b], pb, self._resting[pair][0]):
                del self._resting[pair]

    def forget(self) -> None:
        """The timeline was edited (a body demonstrated again): no recorded contact goes on across the edit."""
        self._last_report.clear()
        self._resting.clear()
