"""Turns canvas pen samples into gestures: strokes, taps, dwells, eraser strokes; no devices, no clock.

One `GestureEngine` per pen. It follows the pen's state machine (tip hysteresis included), keeps the
stroke being drawn, and returns the gestures each sample completes. Time is the samples' own ``t``;
a ``t`` that goes backwards is held at the last value and counted, never trusted.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.state import PenState, PenStateMachine, TipThresholds


@dataclass(frozen=True, slots=True)
class StrokePoint:
    """One point of a stroke: canvas position 0..1, seconds, pressure 0..1."""

    x: float
    y: float
    t: float
    p: float


@dataclass(frozen=True, slots=True)
class Stroke:
    """A pen-down-to-pen-up movement.

    Attributes:
        points: the path, at least one point, times non-decreasing.
        eraser: drawn with the eraser end.
        dwell_t: when the pen dwelled at the stroke's start (the stroke is then a drag of what lies
            under the dwell, thesis 2.2.3), or None.
        ended_by: ``"lift"``, or ``"device-lost"`` when the device vanished mid-stroke.
    """

    points: tuple[StrokePoint, ...]
    eraser: bool = False
    dwell_t: float | None = None
    ended_by: str = "lift"

    @property
    def t0(self) -> float:
        return self.points[0].t

    @property
    def t1(self) -> float:
        return self.points[-1].t


@dataclass(frozen=True, slots=True)
class PenDown:
    """The tip (or eraser) touched at (x, y)."""

    t: float
    x: float
    y: float
    p: float
    eraser: bool


@dataclass(frozen=True, slots=True)
class PenMove:
    """The pen moved: touching (a stroke grows) or hovering (``touching`` False)."""

    t: float
    x: float
    y: float
    p: float
    touching: bool


@dataclass(frozen=True, slots=True)
class Dwell:
    """The pen has been held down within a small radius for ``DwellConfig.seconds``."""

    t: float
    x: float
    y: float


@dataclass(frozen=True, slots=True)
class Tap:
    """A short touch that barely moved (selects what lies under it)."""

    t: float
    x: float
    y: float


@dataclass(frozen=True, slots=True)
class StrokeEnded:
    """A stroke is finished (not a tap)."""

    t: float
    stroke: Stroke


@dataclass(frozen=True, slots=True)
class ProximityChanged:
    """The pen entered (``in_range``) or left the tablet's range."""

    t: float
    in_range: bool


Gesture = PenDown | PenMove | Dwell | Tap | StrokeEnded | ProximityChanged


@dataclass(frozen=True, slots=True)
class GestureConfig:
    """Gesture thresholds.

    Attributes:
        dwell_seconds: how long the pen must stay within ``dwell_radius`` to dwell (thesis: 400 ms).
        dwell_radius: canvas fraction (of the diagonal of the unit square) the pen may wander while dwelling.
        tap_seconds: the longest touch that can be a tap.
        tap_radius: how far (canvas fraction) a tap may move.
        thresholds: tip hysteresis.
    """

    dwell_seconds: float = 0.4
    dwell_radius: float = 0.01
    tap_seconds: float = 0.25
    tap_radius: float = 0.008
    thresholds: TipThresholds = field(default_factory=TipThresholds)


class GestureEngine:
    """Consumes one pen's samples (canvas coordinates) in order; returns the gestures each completes.

    >>> eng = GestureEngine()
    >>> s = PenSample(0.0, 0.5, 0.5, 0.0, False, True, False, False, False, None, None, 2)
    >>> [type(g).__name__ for g in eng.feed(s)]
    ['ProximityChanged', 'PenMove']
    """

    def __init__(self, config: GestureConfig | None = None) -> None:
        self.config = config or GestureConfig()
        self.machine = PenStateMachine(self.config.thresholds)
        self.backwards = 0
        self._last_t = float("-inf")
        self._points: list[StrokePoint] = []
        self._eraser = False
        self._dwell_t: float | None = None
        self._anchor: StrokePoint | None = None
        self._can_dwell = False

    @property
    def state(self) -> PenState:
        return self.machine.state

    @property
    def drawing(self) -> bool:
        return bool(self._points)

    def feed(self, sample: PenSample) -> list[Gesture]:
        """Advance by one sample; return the gestures it completes, in order."""
        t = sample.t
        if t < self._last_t:
            self.backwards += 1
            t = self._last_t
        self._last_t = t
        out: list[Gesture] = []
        if self._points:
            self._check_dwell(t, out)  # the pen stayed where it was until now: as if time had been ticked to t
        before = self.machine.state
        for state in self.machine.follow(sample):
            self._enter(before, state, t, sample, out)
            before = state
        if self.machine.state.in_contact:
            self._extend(t, sample, out)
        elif self.machine.state.in_range:
            out.append(PenMove(t, sample.x, sample.y, 0.0, False))
        return out

    @property
    def ink(self) -> tuple[StrokePoint, ...]:
        """The points of the stroke being drawn (empty when the pen is up)."""
        return tuple(self._points)

    def tick(self, t: float) -> list[Gesture]:
        """Let time pass without a sample (the session's clock): may complete a dwell. The dwell is stamped with
        the moment it completed, so ticking often, seldom or never before the next sample gives the same gestures."""
        if not self._points or t < self._last_t:
            return []
        out: list[Gesture] = []
        self._check_dwell(t, out)
        return out

    def device_lost(self, t: float) -> list[Gesture]:
        """The device vanished: end any stroke cleanly and leave range."""
        t = max(t, self._last_t)
        out: list[Gesture] = []
        if self._points:
            self._finish(t, "device-lost", out)
        if self.machine.state.in_range:
            self.machine.state = PenState.OUT_OF_RANGE  # no report will come to walk the states
            out.append(ProximityChanged(t, False))
        return out

    # -- internals --------------------------------------------------------------------------------

    def _enter(self, before: PenState, state: PenState, t: float, s: PenSample, out: list[Gesture]) -> None:
        if not before.in_range and state.in_range:
            out.append(ProximityChanged(t, True))
        if not before.in_contact and state.in_contact:
            self._points = [StrokePoint(s.x, s.y, t, s.p)]
            self._eraser = state.eraser
            self._dwell_t = None
            self._anchor = self._points[0]
            self._can_dwell = True
            out.append(PenDown(t, s.x, s.y, s.p, state.eraser))
        elif before.in_contact and not state.in_contact:
            self._finish(t, "lift", out)
        if before.in_range and not state.in_range:
            out.append(ProximityChanged(t, False))

    def _extend(self, t: float, s: PenSample, out: list[Gesture]) -> None:
        last = self._points[-1]
        if t != last.t or (s.x, s.y, s.p) != (last.x, last.y, last.p):
            self._points.append(StrokePoint(s.x, s.y, t, s.p))
            out.append(PenMove(t, s.x, s.y, s.p, True))
        self._check_dwell(t, out)

    def _check_dwell(self, t: float, out: list[Gesture]) -> None:
        if not self._can_dwell or self._anchor is None:
            return
        cfg = self.config
        current = self._points[-1]
        if math.hypot(current.x - self._anchor.x, current.y - self._anchor.y) > cfg.dwell_radius:
            # moved away before dwelling: only a dwell at the stroke's start makes a drag
            self._can_dwell = False
            return
        if t - self._anchor.t >= cfg.dwell_seconds:
            self._dwell_t = max(self._anchor.t + cfg.dwell_seconds, self._points[-1].t)
            self._can_dwell = False
            out.append(Dwell(self._dwell_t, self._anchor.x, self._anchor.y))

    def _finish(self, t: float, ended_by: str, out: list[Gesture]) -> None:
        points = tuple(self._points)
        self._points = []
        self._can_dwell = False
        cfg = self.config
        first = points[0]
        extent = max(math.hypot(p.x - first.x, p.y - first.y) for p in points)
        if (ended_by == "lift" and self._dwell_t is None and t - first.t <= cfg.tap_seconds
                and extent <= cfg.tap_radius and not self._eraser):
            out.append(Tap(t, first.x, first.y))
            return
        out.append(StrokeEnded(t, Stroke(points, self._eraser, self._dwell_t, ended_by)))
