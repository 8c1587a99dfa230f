"""Edits of a recorded timeline that keep it causal: cutting a body's behaviour from time t for the assisted edit
(thesis 3.3.2) and splitting a recorded movement where a contact interrupts it (concurrent movement, thesis 4.1).
Pure functions of a `Timeline`; when to apply them is the recorder's business."""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import replace

from physink_tui.timeline.events import Event, Timeline, TrajectoryPoint
from physink_tui.timeline.graph import descendants


def covering(timeline: Timeline, bodies: Collection[str], t: float) -> Event | None:
    """The latest movement involving any of ``bodies`` begun at or before ``t`` (the later-created on a tie)."""
    best: Event | None = None
    for ev in timeline.events:
        if ev.type == "movement" and ev.t0 <= t and not set(bodies).isdisjoint(ev.components):
            if best is None or ev.t0 >= best.t0:
                best = ev
    return best


def _upto(frames: tuple[TrajectoryPoint, ...], t: float) -> tuple[TrajectoryPoint, ...]:
    return tuple(p for p in frames if p.t <= t)


def cut_from(timeline: Timeline, bodies: Collection[str], t: float) -> tuple[Timeline, Event | None]:
    """The timeline with the behaviour of ``bodies`` (a body and what is tied to it) from ``t`` on taken out.

    Their movement at ``t`` is cut at ``t``; every event it caused is deleted, with every later event involving
    them and what those caused; nothing else changes. Returns the edited timeline and the cut movement (None
    when they had not moved by ``t``).
    """
    current = covering(timeline, bodies, t)
    gone: set[str] = set()
    if current is not None:
        gone |= descendants(timeline, current.id)
    for ev in timeline.events:
        if ev.t0 > t and ev.type != "start" and not set(bodies).isdisjoint(ev.components):
            gone |= {ev.id} | descendants(timeline, ev.id)
    if current is None:
        return timeline.remove(gone), None
    gone.discard(current.id)
    kept = _upto(current.trajectory, t) or current.trajectory[:1]
    tracks = tuple((c, _upto(frames, t) or frames[:1]) for c, frames in current.tracks)
    cut = replace(current, trajectory=kept, tracks=tracks, t1=max(current.t0, kept[-1].t) if kept else current.t0)
    return timeline.remove(gone).update(cut), cut


def split_at(timeline: Timeline, movement: Event, t: float, cause: str, new_id: str) -> Timeline:
    """``movement`` interrupted at ``t`` by the event ``cause``: its frames after ``t`` become a new movement
    ``new_id`` caused by ``cause``, and what it caused from ``t`` on is caused by the new one."""
    before = _upto(movement.trajectory, t) or movement.trajectory[:1]
    after = tuple(p for p in movement.trajectory if p.t > t)
    head = replace(movement, t1=max(movement.t0, before[-1].t) if before else movement.t0, trajectory=before,
                   tracks=tuple((c, _upto(f, t)) for c, f in movement.tracks))
    tail = Event(new_id, "movement", movement.components, (cause,), t, max(t, movement.t1),
                 regions=movement.regions, trajectory=after,
                 tracks=tuple((c, tuple(p for p in f if p.t > t)) for c, f in movement.tracks))
    events = []
    for ev in timeline.events:
        if ev.id == movement.id:
            events.append(head)
        elif movement.id in ev.causes and ev.t0 >= t and ev.id != cause:
            events.append(replace(ev, causes=tuple(new_id if c == movement.id else c for c in ev.causes)))
        else:
            events.append(ev)
    return Timeline((*events, tail))
