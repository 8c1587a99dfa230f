"""The causal timeline's events as frozen values (thesis 3.3.1): start, movement, contact, end-contact.

A `Timeline` is a directed acyclic graph kept as a tuple of events in creation order; each event names the events
that cause it (`Event.causes`), so edges run cause -> effect. Graph algorithms (ancestors, descendants,
generations, cycle checks) are free functions in `graph`, assisted editing in `edits`; narration in `narrate`.
Times are seconds of timeline time; coordinates are canvas units with y down, angles radians (as in the scene).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace

from physink_tui.errors import PhysinkError

EVENT_TYPES = ("start", "movement", "contact", "end_contact")
SIDES = ("top", "bottom", "left", "right", "inside")
REGIONS = ("above", "below", "left", "right")


class TimelineError(PhysinkError):
    """A timeline or event that breaks the timeline's rules.

    Attributes:
        event_id: the offending event's id, or None when the problem is not tied to one event.
    """

    def __init__(self, message: str, event_id: str | None = None) -> None:
        self.event_id = event_id
        super().__init__(message)


@dataclass(frozen=True, slots=True)
class TrajectoryPoint:
    """One frame of a movement: time, position, orientation and velocity of the moving component."""

    t: float
    x: float
    y: float
    angle: float
    vx: float
    vy: float


@dataclass(frozen=True, slots=True)
class Event:
    """One node of the timeline.

    Attributes:
        id: stable event id (``e1``, ``e2`` ...), unique within a timeline.
        type: ``start``, ``movement``, ``contact`` or ``end_contact``.
        components: the component ids involved; a movement names the moving component first, then the
            components attached to it that move with it; a contact or end-contact names the bodies in it.
        causes: ids of the events that cause this one (empty only for a start event or a root).
        t0, t1: when the event begins and ends (equal for the instantaneous contact and end-contact).
        label: the user's phrase for it, or None to narrate it with `default_label`.
        sides: contact only: ``(component id, side)`` per body, side in `SIDES`.
        regions: movement only: ``(other component id, regions crossed)`` per nearby body, regions in `REGIONS`.
        trajectory: movement only: the recorded frames.
        point: contact only: the exact contact point in canvas units, when known.
        tracks: movement only: ``(body id, frames)`` for each body attached to the moving one (the knife on the
            lever's rope), so that playback can move them too; the moving body's own frames are ``trajectory``.
        in_contact: start only: the pairs of movable bodies (of different mechanisms) in contact when the
            demonstration began, each pair's ids sorted and the pairs sorted (`begun_in_contact`); separating one
            makes an end-contact (thesis figure 3-9).
    """

    id: str
    type: str
    components: tuple[str, ...] = ()
    causes: tuple[str, ...] = ()
    t0: float = 0.0
    t1: float = 0.0
    label: str | None = None
    sides: tuple[tuple[str, str], ...] = ()
    regions: tuple[tuple[str, tuple[str, ...]], ...] = ()
    trajectory: tuple[TrajectoryPoint, ...] = ()
    point: tuple[float, float] | None = None
    tracks: tuple[tuple[str, tuple[TrajectoryPoint, ...]], ...] = ()
    in_contact: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        if self.type not in EVENT_TYPES:
            raise TimelineError(f"event {self.id!r} has type {self.type!r}; expected one of {EVENT_TYPES}", self.id)
        if self.t1 < self.t0:
            raise TimelineError(f"event {self.id!r} ends at t1={self.t1!r} before it starts at t0={self.t0!r}",
                                self.id)
        for component, side in self.sides:
            if side not in SIDES:
                raise TimelineError(f"event {self.id!r}: side {side!r} of {component!r} is not one of {SIDES}",
                                    self.id)
        for other, crossed in self.regions:
            for region in crossed:
                if region not in REGIONS:
                    raise TimelineError(
                        f"event {self.id!r}: region {region!r} of {other!r} is not one of {REGIONS}", self.id)
        if self.type != "contact" and (self.sides or self.point is not None):
            raise TimelineError(f"event {self.id!r} is a {self.type}; only contacts have sides and a point", self.id)
        if self.type != "movement" and (self.regions or self.trajectory or self.tracks):
            raise TimelineError(f"event {self.id!r} is a {self.type}; only movements have regions and trajectories",
                                self.id)
        if self.type != "start" and self.in_contact:
            raise TimelineError(f"event {self.id!r} is a {self.type}; only the start names pairs in contact", self.id)
        if self.id in self.causes:
            raise TimelineError(f"event {self.id!r} names itself as a cause; events cannot cause themselves", self.id)


@dataclass(frozen=True, slots=True)
class Timeline:
    """Every event of a demonstration in creation order; changes return a new Timeline.

    Ids are unique and every cause names an event of the timeline (checked on construction); acyclicity is
    checked by `graph.check_acyclic`, since a timeline read from a file may hold a cycle.
    """

    events: tuple[Event, ...] = ()
    _index: dict[str, int] = field(init=False, repr=False, compare=False)
    _children: dict[str, tuple[str, ...]] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        index: dict[str, int] = {}
        for i, ev in enumerate(self.events):
            if ev.id in index:
                raise TimelineError(f"event id {ev.id!r} appears twice in the timeline", ev.id)
            index[ev.id] = i
        children: dict[str, list[str]] = {ev.id: [] for ev in self.events}
        for ev in self.events:
            for cause in ev.causes:
                if cause not in index:
                    raise TimelineError(f"event {ev.id!r} names unknown cause {cause!r}", ev.id)
                if ev.id not in children[cause]:
                    children[cause].append(ev.id)
        object.__setattr__(self, "_index", index)
        object.__setattr__(self, "_children", {k: tuple(v) for k, v in children.items()})

    def __contains__(self, event_id: object) -> bool:
        return event_id in self._index

    def __len__(self) -> int:
        return len(self.events)

    def ids(self) -> tuple[str, ...]:
        """Every event id in creation order."""
        return tuple(ev.id for ev in self.events)

    def position(self, event_id: str) -> int:
        """The event's index in creation order."""
        self.event(event_id)
        return self._index[event_id]

    def event(self, event_id: str) -> Event:
        """The event with this id; `TimelineError` when there is none."""
        i = self._index.get(event_id)
        if i is None:
            raise TimelineError(f"no event {event_id!r} in the timeline", event_id)
        return self.events[i]

    def children(self, event_id: str) -> tuple[str, ...]:
        """Ids of the events this one causes, in creation order."""
        self.event(event_id)
        return self._children[event_id]

    def add(self, event: Event) -> Timeline:
        """The timeline with ``event`` appended; its id must be new and its causes already present.

        The indexes are extended, not rebuilt: a recorder adds events one by one.
        """
        if event.id in self._index:
            raise TimelineError(f"event id {event.id!r} is already in the timeline", event.id)
        for cause in event.causes:
            if cause not in self._index:
                raise TimelineError(f"event {event.id!r} names unknown cause {cause!r}", event.id)
        index = dict(self._index)
        index[event.id] = len(self.events)
        children = dict(self._children)
        children[event.id] = ()
        for cause in dict.fromkeys(event.causes):
            children[cause] = (*children[cause], event.id)
        return self._with((*self.events, event), index, children)

    def update(self, event: Event) -> Timeline:
        """The timeline with the event of the same id replaced in place (e.g. a trajectory grown or truncated)."""
        i = self.position(event.id)
        events = (*self.events[:i], event, *self.events[i + 1:])
        if event.causes != self.events[i].causes:
            return Timeline(events)
        return self._with(events, self._index, self._children)  # same ids, same edges: the indexes still hold

    @classmethod
    def _with(cls, events: tuple[Event, ...], index: dict[str, int],
              children: dict[str, tuple[str, ...]]) -> Timeline:
        """A timeline of ``events`` whose indexes are known (never changed once made, so they can be shared)."""
        timeline = object.__new__(cls)
        object.__setattr__(timeline, "events", events)
        object.__setattr__(timeline, "_index", index)
        object.__setattr__(timeline, "_children", children)
        return timeline

    def remove(self, ids: Iterable[str]) -> Timeline:
        """The timeline without these events; no remaining event may name a removed one as its cause."""
        gone = set(ids)
        for event_id in sorted(gone):
            self.event(event_id)
        kept = tuple(ev for ev in self.events if ev.id not in gone)
        for ev in kept:
            orphaned = [c for c in ev.causes if c in gone]
            if orphaned:
                raise TimelineError(
                    f"cannot remove {orphaned[0]!r}: event {ev.id!r} is caused by it and would remain", ev.id)
        return Timeline(kept)

    def relabel(self, event_id: str, label: str | None) -> Timeline:
        """The timeline with the user's label of one event set (None restores the default narration)."""
        return self.update(replace(self.event(event_id), label=label))


def _name(component: str, names: Mapping[str, str]) -> str:
    return names.get(component) or component


def _join(items: list[str]) -> str:
    if len(items) <= 2:
        return " and ".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def default_label(event: Event, names: Mapping[str, str]) -> str:
    """The thesis's default narration of an event: ``Movement of ball``, ``Contact between ball and paddle`` ...

    ``names`` maps component ids to what to call them (`Scene.names`: the user's label, or ``spring`` / ``rope``
    for an unlabelled spring or rope); a component not in it is called by its id. A movement of
    several components (the moving body and what is attached to it) reads ``Movement of rotating platform
    [attached to rope, knife]``.
    """
    parts = [_name(c, names) for c in event.components]
    if event.type == "start":
        touching = [_join([_name(c, names) for c in pair]) for pair in event.in_contact]
        return f"Start ({'; '.join(touching)} in contact)" if touching else "Start"
    if event.type == "movement":
        if not parts:
            return "Movement"
        attached = f" [attached to {', '.join(parts[1:])}]" if len(parts) > 1 else ""
        return f"Movement of {parts[0]}{attached}"
    head = "Contact" if event.type == "contact" else "End of contact"
    return f"{head} between {_join(parts)}" if parts else head


def event_label(event: Event, names: Mapping[str, str]) -> str:
    """The event's narration: the user's label when given, else `default_label`."""
    return event.label if event.label is not None else default_label(event, names)
