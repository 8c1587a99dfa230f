"""Records a demonstration as causal events from per-step observations of the world; no physics, no clock.

Fed after every physics step with an `Observation` (every body's pose, the contacts begun, the pairs touching,
the body the pen holds, the bodies playing back their recording), it keeps one open movement per moving group
(a body and what is tied to it by ropes, springs and joints) and builds the timeline as the thesis does (3.3):

- the pen's first grab is the start (an exogenous force) and causes the grabbed body's movement; a body grabbed
  again continues its latest movement (which the last contact or end-contact involving it created);
- a contact is caused by the movements of the bodies in it and causes a new movement of each movable body in it;
  a resting or sliding contact is one contact (`touches`: reports within 15 frames, or before the bodies have
  moved apart by half the smaller one's size); the body the pen holds touching again a body it set moving, which
  nothing else has touched since, still pushes it in the same contact (the pen catching up with what it pushed:
  the egg pushed through the paddles, thesis 2.3.3, touches each paddle once); a contact with a body that is
  playing back its recording splits that body's recorded movement (concurrent movement, thesis 4.1);
- movable bodies that begin in contact are named by the start; they are in that contact until they come apart,
  which makes an end-contact caused by the movement that parted them and causing a movement of each (thesis
  figure 3-9), or until one drives into the other, which is a contact (`begun_in_contact`); their other touches
  are no events; a body that starts moving by itself is explained by the moving body it touches (a contact; only
  a jostle when that body began in contact with it and does not drive into it), else by a recent separation (an
  end-contact, the cup dispenser), else it continues its latest movement, else the start explains it;
- movements record every frame of the moving body (and of the bodies tied to it) and the regions of other bodies
  the moving body passes through (`qualitative.regions_at`); a group still for `STILL_FRAMES` ends its movement.

Re-demonstrating a body from time t (`redemonstrate`) is the assisted edit of thesis 3.3.2. When to step, seek
or play back is the session's business; the poses come from the physics world.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from physink_tui.scene.physics.contacts import ContactRecord
from physink_tui.timeline.begun_in_contact import drives_into, facing, parted
from physink_tui.timeline.edits import covering, cut_from, split_at
from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.mechanisms import Mechanisms
from physink_tui.timeline.movement_record import OpenMovement, Regions
from physink_tui.timeline.observation import Observation
from physink_tui.timeline.qualitative import BodyOutline, contact_sides
from physink_tui.timeline.touches import Touches, pushed_again

MOVING_SPEED = 5.0
"""Canvas units per second above which a body counts as moving (its centre, or its rim when it spins)."""
STILL_FRAMES = 12
"""Frames below `MOVING_SPEED` after which a movement ends."""
RECENT_SEPARATION = 1.0
"""Seconds after two bodies stop touching during which a body starting to move by itself was released by it."""


@dataclass
class Recorder:
    """Builds a `Timeline` from observations (see the module docstring); `snapshot` gives the events so far.

    Attributes:
        outlines: every body's qualitative outline, by id.
        movable: ids of the bodies that can move (fixed bodies never get movement events).
        links: the ropes, springs and joints between movable things: node -> neighbours, where nodes are movable
            body ids and rope/spring ids; a movement names the moving body, then what it reaches through links.
        initial_pairs: pairs of movable bodies touching when the demonstration began.
        reach: how far (canvas units) the regions above, below, left and right of a body extend.
        dt: the physics step in seconds (for the 15-frame rule).
        timeline: the events so far (movements being recorded are written up to date by `snapshot`).
    """

    outlines: Mapping[str, BodyOutline]
    movable: frozenset[str]
    links: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    initial_pairs: frozenset[frozenset[str]] = frozenset()
    reach: float = 250.0
    dt: float = 1 / 120
    timeline: Timeline = field(default_factory=Timeline)
    _next: int = 1
    _open: dict[str, OpenMovement] = field(default_factory=dict)
    _touches: Touches = field(init=False)
    _ended_pairs: set[frozenset[str]] = field(default_factory=set)
    _touching: frozenset[frozenset[str]] = frozenset()
    _separated_at: dict[frozenset[str], float] = field(default_factory=dict)
    _began_gap: dict[frozenset[str], float] = field(default_factory=dict)
    _start: str | None = None
    _grabbed: str | None = None
    _mechanisms: Mechanisms = field(init=False, repr=False, compare=False)
    _group: dict[str, str] = field(init=False)  # the mechanisms' keys
    _radius: dict[str, float] = field(default_factory=dict)
    _regions: Regions = field(init=False)
    _order: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        self._mechanisms = Mechanisms(self.links, self.movable, self.outlines)
        self._group = self._mechanisms.group
        for body, outline in self.outlines.items():
            self._radius[body] = max((math.hypot(x, y) for x, y in outline.hull), default=0.0)
        self._regions = Regions(self.outlines, self.reach, self._radius)
        self._order = tuple(sorted(self.movable))
        self._touches = Touches(self.outlines, self.dt)
        self._adopt(self.timeline)

    # -- the outside -----------------------------------------------------------------------------------------

    def chain(self, body: str) -> tuple[str, ...]:
        """``body`` and every movable body, rope and spring it reaches through links, nearest first."""
        return self._mechanisms.chain(body)

    def group_key(self, body: str) -> str:
        """The same key for every body of one mechanism (bodies tied together move as one)."""
        return self._mechanisms.key(body)

    def group_bodies(self, body: str) -> tuple[str, ...]:
        """The movable bodies that move with ``body`` (itself first)."""
        return self._mechanisms.bodies(body)

    @property
    def moving(self) -> bool:
        """Whether any movement is still open (timeline time runs on while bodies move)."""
        return bool(self._open)

    def observe(self, obs: Observation) -> None:
        """One physics step (see `Observation`)."""
        if obs.grabbed is not None and obs.grabbed != self._grabbed and obs.grabbed in self.movable:
            self._begin(obs.t, obs.grabbed, obs, grabbed=True)
        self._grabbed = obs.grabbed
        for pair in self._touching - obs.touching:
            self._separated_at[pair] = obs.t
        self._touching = obs.touching
        self._touches.observe(obs.poses, obs.touching)
        self._check_initial_pairs(obs)
        for contact in obs.contacts:
            self._contact(obs, contact)
        poses, playing, group, opened = obs.poses, obs.playing, self._group, self._open
        for body in self._order:
            pose = poses.get(body)
            if pose is None or body in playing or group.get(body) in opened:
                continue
            if math.hypot(pose[3], pose[4]) > MOVING_SPEED:  # spinning in place on a pin explains nothing
                self._begin(obs.t, body, obs, grabbed=False)
        if opened:
            self._regions.next_frame(poses)
            for key in sorted(opened):
                self._record_frame(obs, key)

    def snapshot(self) -> Timeline:
        """The timeline so far, movements being recorded written up to now."""
        for current in self._open.values():
            self._write(current)
        return self.timeline

    def pause(self) -> Timeline:
        """Ends every movement being recorded (before a seek, or at the end of the demonstration)."""
        for key in list(self._open):
            self._write(self._open.pop(key))
        self._grabbed = None
        self._separated_at.clear()  # what happens next follows a jump in time, not a separation
        self._touching = frozenset()
        return self.timeline

    finish = pause

    def relabel(self, timeline: Timeline) -> None:
        """Take ``timeline``: this recorder's events with other labels (narration), nothing else changed."""
        if [ev.id for ev in timeline.events] != [ev.id for ev in self.timeline.events]:
            raise ValueError("relabel: the timeline has other events than the recorder's")
        self.timeline = timeline

    def redemonstrate(self, body: str, t: float) -> Timeline:
        """The assisted edit (thesis 3.3.2): ``body`` is demonstrated again from ``t``.

        Its movement at ``t`` is cut at ``t``, and every event it caused is deleted, with every later event
        involving it or what is tied to it and what those caused; nothing else changes. The next grab of the
        body continues the cut movement.
        """
        self.pause()
        timeline, _ = cut_from(self.timeline, self.group_bodies(body), t)
        self._touches.forget()
        self._ended_pairs.clear()
        self._adopt(timeline)
        return self.timeline

    # -- events ----------------------------------------------------------------------------------------------

    def _adopt(self, timeline: Timeline) -> None:
        """Take over an existing timeline (a demonstration continued, or edited)."""
        self.timeline = timeline
        for ev in timeline.events:
            digits = ev.id[1:]
            if ev.id.startswith("e") and digits.isdigit():
                self._next = max(self._next, int(digits) + 1)
            if ev.type == "start" and self._start is None:
                self._start = ev.id
            elif ev.type in ("contact", "end_contact"):
                self._ended_pairs.add(frozenset(ev.components))  # a pair seen touching: no end-contact later
        if self._start is not None and self._start not in timeline:
            self._start = None

    def _new_id(self) -> str:
        self._next += 1
        return f"e{self._next - 1}"

    def _start_event(self, t: float) -> str:
        if self._start is None:
            self._start = self._new_id()
            in_contact = tuple(sorted((a, b) for a, b in map(sorted, self.initial_pairs)))
            self.timeline = self.timeline.add(Event(self._start, "start", (), (), t, t, in_contact=in_contact))
        return self._start

    def _begin(self, t: float, body: str, obs: Observation, *, grabbed: bool) -> None:
        """``body`` starts moving (grabbed, or by itself) with no movement of its group being recorded."""
        key = self._group[body]
        if key in self._open:
            self._open[key].still = 0
            return
        if not grabbed:
            jostled = False
            for pair in sorted(obs.touching, key=sorted):
                if body in pair and len(pair) == 2:
                    (other,) = pair - {body}
                    if self._group.get(other, other) != key and self._cause_of(other, t, obs) is not None:
                        begun = self._begun_touching(pair)
                        across = facing(self.outlines[other], obs.poses[other], obs.poses[body]) if begun else None
                        if begun and not self._drives(obs, other, body, across):
                            jostled = True  # its partner from the start moves on without pushing it
                            continue
                        ongoing = self._touches.going_on(pair)
                        if ongoing is not None and ongoing in self.timeline:
                            self._moved_on(t, body, self.timeline.event(ongoing))  # in a contact going on
                        else:  # pushed by a moving body (across the contact they began in, when they did)
                            self._add_contact(obs, body, other, None, across and (-across[0], -across[1]))
                        return
            if jostled:
                return
        latest = self._latest_movement(body)
        latest_t = latest.t1 if latest is not None else -math.inf
        for pair, when in sorted(self._separated_at.items(), key=lambda item: (-item[1], sorted(item[0]))):
            if body in pair and len(pair) == 2 and t - when <= RECENT_SEPARATION and when >= latest_t:
                (other,) = pair - {body}
                if other in self.outlines:
                    self._add_end_contact(obs, body, other)  # released by a body it stopped touching
                    return
        if latest is not None:
            self._reopen(key, latest)
            return
        self._open_movement(t, body, (self._start_event(t),))

    def _moved_on(self, t: float, body: str, contact: Event) -> None:
        """``body`` moves again in ``contact``, which goes on: its latest movement since goes on, else the
        contact moves it anew."""
        latest = self._latest_movement(body)
        if latest is not None and latest.t0 >= contact.t0:
            self._reopen(self._group[body], latest)
        else:
            self._open_movement(t, body, (contact.id,))

    def _cause_of(self, body: str, t: float, obs: Observation) -> str | None:
        """The movement explaining ``body``'s motion now: its group's open one, or the recording it plays."""
        key = self._group.get(body)
        if key is not None and key in self._open:
            return self._open[key].event_id
        if body in obs.playing:
            ev = covering(self.timeline, {body}, t)
            return ev.id if ev is not None else None
        return None

    def _begun_touching(self, pair: frozenset[str]) -> bool:
        """Whether ``pair`` began in contact and is in that contact still (no contact or end-contact since)."""
        return pair in self.initial_pairs and pair not in self._ended_pairs

    def _drives(self, obs: Observation, mover: str, other: str, normal: tuple[float, float] | None) -> bool:
        """Whether ``mover``, moving, drives into ``other`` (`begun_in_contact.drives_into`)."""
        pm, po = obs.poses.get(mover), obs.poses.get(other)
        if pm is None or po is None or self._cause_of(mover, obs.t, obs) is None:
            return False
        return drives_into(pm, po, normal)

    def _latest_movement(self, body: str) -> Event | None:
        """The latest movement of ``body``'s mechanism (open or ended), which a new grab continues."""
        return covering(self.timeline, self.group_bodies(body), math.inf)

    def _contact(self, obs: Observation, contact: ContactRecord) -> None:
        a, b = contact.a_id, contact.b_id
        pair = frozenset((a, b))
        if a == b or a not in self.outlines or b not in self.outlines:
            return
        if self._group.get(a, a) == self._group.get(b, b):
            return  # parts of one mechanism touching each other
        if self._touches.same(pair, obs.t):
            return  # the contact recorded goes on (see touches.py)
        if a in obs.playing and b in obs.playing:
            return  # both replaying what was recorded
        if self._begun_touching(pair) and not (self._drives(obs, a, b, contact.normal)
                                               or self._drives(obs, b, a, (-contact.normal[0], -contact.normal[1]))):
            return  # the contact they began in, going on
        again = None if obs.grabbed is None else pushed_again(self.timeline, pair, obs.grabbed, self.group_bodies)
        if again is not None:
            self._touches.recorded(pair, obs.t, again)
            return
        self._add_contact(obs, a, b, contact.point, contact.normal)

    def _add_contact(self, obs: Observation, a: str, b: str, point: tuple[float, float] | None,
                     normal: tuple[float, float] | None) -> None:
        t = obs.t
        pair = frozenset((a, b))
        causes = {c: self._cause_of(c, t, obs) for c in (a, b)}
        if not any(causes.values()):
            return  # two still bodies touching (drawn so): no behaviour to explain
        # the body whose movement brought them together is named first
        first, second = (a, b) if causes[a] is not None and (causes[b] is None or a <= b) else (b, a)
        pa, pb = obs.poses.get(first), obs.poses.get(second)
        if normal is None and pa is not None and pb is not None:
            d = math.hypot(pb[0] - pa[0], pb[1] - pa[1]) or 1.0
            normal = ((pb[0] - pa[0]) / d, (pb[1] - pa[1]) / d)
        elif normal is not None and first != a:
            normal = (-normal[0], -normal[1])
        sides: tuple[tuple[str, str], ...] = ()
        if normal is not None and pa is not None and pb is not None:
            sa, sb = contact_sides(self.outlines[first], pa, self.outlines[second], pb, normal)
            sides = ((first, sa), (second, sb))
        if point is None and pa is not None and pb is not None:
            point = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)
        cid = self._new_id()
        self.timeline = self.timeline.add(Event(
            cid, "contact", (first, second), tuple(dict.fromkeys(c for c in (causes[first], causes[second]) if c)),
            t, t, sides=sides, point=point))
        self._touches.recorded(pair, t, cid)
        self._ended_pairs.add(pair)
        self._moved_by(obs, cid, (first, second))

    def _add_end_contact(self, obs: Observation, a: str, b: str) -> None:
        t = obs.t
        first, second = sorted((a, b), key=lambda c: (self._cause_of(c, t, obs) is None, c))
        causes = tuple(dict.fromkeys(c for c in (self._cause_of(first, t, obs), self._cause_of(second, t, obs))
                                     if c))
        if not causes:
            latest = next((m.id for m in (self._latest_movement(a), self._latest_movement(b)) if m), None)
            causes = (latest,) if latest is not None else (self._start_event(t),)
        eid = self._new_id()
        self.timeline = self.timeline.add(Event(eid, "end_contact", (first, second), causes, t, t))
        self._ended_pairs.add(frozenset((a, b)))
        self._touches.ended(frozenset((a, b)))
        self._separated_at.pop(frozenset((a, b)), None)
        self._moved_by(obs, eid, (first, second))

    def _moved_by(self, obs: Observation, cause: str, bodies: tuple[str, str]) -> None:
        """Every movable body of a contact or end-contact gets a new movement caused by it."""
        for body in bodies:
            if body not in self.movable:
                continue
            if body in obs.playing:
                self._split(body, obs.t, cause)
            else:
                self._close(self._group[body])
                self._open_movement(obs.t, body, (cause,))

    def _check_initial_pairs(self, obs: Observation) -> None:
        for pair in sorted(self.initial_pairs - self._ended_pairs, key=sorted):
            a, b = sorted(pair)
            moving = self._cause_of(a, obs.t, obs) is not None or self._cause_of(b, obs.t, obs) is not None
            if (moving or pair not in self._began_gap) and parted(self.outlines, pair, obs.poses, self._began_gap):
                self._add_end_contact(obs, a, b)  # (neither moving, they cannot have come apart)

    # -- movements -------------------------------------------------------------------------------------------

    def _open_movement(self, t: float, body: str, causes: tuple[str, ...]) -> None:
        chain = self.chain(body)
        bodies = tuple(c for c in chain if c in self.outlines)
        mid = self._new_id()
        self.timeline = self.timeline.add(Event(mid, "movement", chain, causes, t, t))
        self._open[self._group[body]] = OpenMovement(mid, bodies, {b: [] for b in bodies})

    def _reopen(self, key: str, ev: Event) -> None:
        self._open[key] = OpenMovement.resumed(ev, tuple(c for c in ev.components if c in self.outlines))

    def _close(self, key: str) -> None:
        current = self._open.pop(key, None)
        if current is not None:
            self._write(current)

    def _record_frame(self, obs: Observation, key: str) -> None:
        current = self._open[key]
        current.record(obs.t, obs.poses, obs.grabbed in current.bodies, self._radius, self._regions, MOVING_SPEED)
        if current.still >= STILL_FRAMES:
            self._close(key)

    def _write(self, current: OpenMovement) -> None:
        event = self.timeline.event(current.event_id)
        updated = current.written(event)
        if updated is not event:
            self.timeline = self.timeline.update(updated)

    def _split(self, body: str, t: float, cause: str) -> None:
        """A contact interrupts the recorded movement ``body`` plays back (see `edits.split_at`)."""
        current = covering(self.timeline, {body}, t)
        if current is not None and current.t1 > t:
            self.timeline = split_at(self.timeline, current, t, cause, self._new_id())
