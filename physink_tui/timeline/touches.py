"""Decides whether a contact report continues a contact already recorded or is a new one; no events, no clock.

A resting or sliding contact is one contact, however often the physics reports it. Two rules, either enough:

- *time* (DESIGN.md): a report of a pair within `SAME_CONTACT_FRAMES` frames of its previous report is the same
  contact;
- *distance*: once a pair's contact is recorded, the pair stays in that contact until the two bodies have moved
  apart by more than `LEAVE_FRACTION` of the smaller one's size (its equivalent diameter, the diameter of a disc
  of its area), however long that takes. A body bouncing in place by micro-separations, a spring-held platform
  jittering under a peg that slides over it, a box pushed along a floor by a trembling pen, a ball rattling in a
  cup: each touches again before it has gone anywhere, so each is one contact. A real second bounce (the ball
  leaves the platform, travels, comes back: thesis figure 2-12's "hits B twice") carries the body well clear, so
  it is a new contact.

A third rule is about the pen: the body it holds touching again a body it set moving is still pushing it, when
nothing else has touched that body since (`pushed_again`). Demo mode has no gravity, so a paddle pushed by a slowly
dragged egg swings ahead, slows and is caught up: to the user one push through the paddles (thesis 2.3.3), and under
gravity the paddle swings away for good. A fixed body touched again (a ball dragged onto a platform twice, figure
2-12) was not set moving, so that is a second contact.

Why the smaller body's size: it is the one that bounces, rattles or slides, and whether it has *left* is judged
against itself: a ball that rises less than its radius off a platform still overlaps, to the eye, where it lay,
whatever its speed; one that rises a diameter has visibly bounced. The measured demonstrations bear this out:
micro-separations are 0.1-5 units (under a tenth of the smaller body), real second bounces 70-100 units (more
than its size). Speed enters through the time rule: a report of the same pair within 15 frames (1/8 s) is the
same contact even if the body flew off fast enough to get clear in between.

How far apart two bodies are is measured between their convex hulls (`qualitative.hull_gap`), so a body moving in
a container's hollow has not left it; the hulls are measured again only once the two bodies have moved far enough
(summed, rotation at their rims included) that the gap could have grown past the leave gap. An end-contact of a
pair ends its contact: touching again afterwards is a new one. A body that starts moving while in a contact that
goes on is moved by that contact, not by a new one (`going_on`). The recorder asks `same` and `going_on`, tells
`recorded` and `ended`, and calls `observe` every step.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from physink_tui.scene.physics.state import Motion
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.qualitative import BodyOutline, hull_gap

SAME_CONTACT_FRAMES = 15
"""Repeated reports of one pair within this many frames are one contact (DESIGN.md)."""
LEAVE_FRACTION = 0.5
"""A pair whose hulls get further apart than this share of the smaller body's size has left its contact."""
MIN_LEAVE_GAP = 4.0
"""Canvas units: the least separation that counts as leaving (thin bodies, pen tremor)."""



def body_size(outline: BodyOutline) -> float:
    """A body's size: the diameter of the disc with its hull's area (0 for a line or a point).

    >>> round(body_size(BodyOutline("b", ((-10, -10), (10, -10), (10, 10), (-10, 10)), False)), 2)
    22.57
    """
    hull = outline.hull
    area = abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(hull, hull[1:] + hull[:1], strict=True))) / 2
    return 2 * math.sqrt(area / math.pi)


@dataclass
class _Going:
    """A recorded contact that goes on: its event, the gap at which it ends, and how far the two bodies can still
    move (summed) before the gap could reach it, so the hulls are measured only when that is spent."""

    event_id: str
    leave: float
    slack: float


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
    _going: dict[frozenset[str], _Going] = field(default_factory=dict)
    _size: dict[str, float] = field(default_factory=dict)
    _radius: dict[str, float] = field(default_factory=dict)
    _seen: dict[str, Motion] = field(default_factory=dict)  # each body's pose at the last step

    def __post_init__(self) -> None:
        self._size = {body: body_size(outline) for body, outline in self.outlines.items()}
        self._radius = {body: max((math.hypot(x, y) for x, y in outline.hull), default=0.0)
                        for body, outline in self.outlines.items()}

    def leave_gap(self, pair: frozenset[str]) -> float:
        """How far apart (canvas units) the two bodies of ``pair`` must get to end their contact."""
        sizes = [self._size.get(body, 0.0) for body in pair]
        solid = [s for s in sizes if s > 0]
        return max(MIN_LEAVE_GAP, LEAVE_FRACTION * min(solid)) if solid else MIN_LEAVE_GAP

    def same(self, pair: frozenset[str], t: float) -> bool:
        """Whether a report of ``pair`` at ``t`` continues its recorded contact (and note the report)."""
        previous = self._last_report.get(pair)
        within = previous is not None and t - previous <= SAME_CONTACT_FRAMES * self.dt + 1e-9
        if within or pair in self._going:
            self._last_report[pair] = t
            return True
        return False

    def recorded(self, pair: frozenset[str], t: float, event_id: str) -> None:
        """The contact event ``event_id`` of ``pair`` was recorded at ``t``."""
        self._last_report[pair] = t
        leave = self.leave_gap(pair)
        self._going[pair] = _Going(event_id, leave, leave)

    def going_on(self, pair: frozenset[str]) -> str | None:
        """The id of the recorded contact ``pair`` is still in (it has not left it), or None."""
        going = self._going.get(pair)
        return going.event_id if going is not None else None

    def ended(self, pair: frozenset[str]) -> None:
        """An end-contact of ``pair`` was recorded: what touches next is a new contact."""
        self._going.pop(pair, None)
        self._last_report.pop(pair, None)

    def observe(self, poses: Mapping[str, Motion], touching: frozenset[frozenset[str]]) -> None:
        """One step: pairs in a recorded contact that have come apart by their leave gap have left it."""
        if not self._going:
            self._seen = {}
            return
        moved: dict[str, float] = {}
        for pair in self._going:
            for body in pair:
                if body not in moved:
                    moved[body] = self._moved(body, poses.get(body))
        for pair, going in list(self._going.items()):  # each pair on its own: their order does not matter
            a, b = sorted(pair)
            pa, pb = poses.get(a), poses.get(b)
            if pair in touching or pa is None or pb is None:  # a body not reported (fixed) is where it was
                going.slack = going.leave if pair in touching else going.slack - moved[a] - moved[b]
                continue
            going.slack -= moved[a] + moved[b]
            if going.slack > 0:
                continue  # they cannot have got further apart than the leave gap yet
            gap = hull_gap(self.outlines[a], pa, self.outlines[b], pb, going.leave)
            if gap > going.leave:
                del self._going[pair]
            else:
                going.slack = going.leave - gap
        self._seen = {body: poses[body] for body in moved if body in poses}

    def _moved(self, body: str, pose: Motion | None) -> float:
        """How far any point of ``body`` can have moved since the last step (0 when unknown)."""
        before = self._seen.get(body)
        if pose is None or before is None:
            return 0.0
        return math.hypot(pose[0] - before[0], pose[1] - before[1]) + abs(pose[2] - before[2]) * self._radius[body]

    def forget(self) -> None:
        """The timeline was edited (a body demonstrated again): no recorded contact goes on across the edit."""
        self._last_report.clear()
        self._going.clear()
        self._seen.clear()


def pushed_again(timeline: Timeline, pair: frozenset[str], held: str,
                 group_of: Callable[[str], tuple[str, ...]]) -> str | None:
    """The contact that a touch of ``pair`` by the ``held`` body continues: the pair's last contact, when it set the
    other body (or what is tied to it, ``group_of``) moving and nothing else has touched that body since; else None
    (a new contact)."""
    if held not in pair or len(pair) != 2:
        return None
    (other,) = pair - {held}
    last = next((ev for ev in reversed(timeline.events)
                 if ev.type in ("contact", "end_contact") and other in ev.components), None)
    if last is None or last.type != "contact" or frozenset(last.components) != pair:
        return None
    group = group_of(other)
    pushed = any(ev.type == "movement" and ev.components and ev.components[0] in group and last.id in ev.causes
                 for ev in timeline.events)
    return last.id if pushed else None
