"""Turns scripted strokes into realistic HID report captures for one device; reads no device and no clock.

A `VirtualPen` stands in for a tablet: given `Stroke`s (polylines in the 0..1 active area) it plays each one
as a hand would — the pen approaches in range, lands with a pressure ramp, moves with a minimum-jerk speed
profile (slow-fast-slow, stopping briefly at sharp corners) while the pressure wanders smoothly, lifts,
hovers and leaves range — and encodes every report with `report_encoder` for the pen layout the decoder
finds in the device's descriptor. Report times follow the nominal rate with Gaussian jitter and never go
backwards; the position carries a little Gaussian sensor noise. Everything random comes from one
`random.Random(seed)`, so the same inputs give a byte-identical capture. `VirtualPen.samples` returns the
intended (noise-free) states with their report times, for tests to compare decoded samples against.
Writing the capture to a file is `captures.writer.write_capture`'s job.

>>> pen = VirtualPen(REFERENCE_DEVICES["windows-ink"])
>>> capture = pen.record([Stroke.line((0.2, 0.5), (0.8, 0.5))])
>>> capture.devices[0].vid, len(capture.events) == len(pen.samples([Stroke.line((0.2, 0.5), (0.8, 0.5))]))
(4660, True)
"""

from __future__ import annotations

import bisect
import itertools
import math
import random
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Literal

from physink_tui.input.captures.capture import Capture, CaptureDevice, CaptureEvent
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.pen_layout import PenLayout
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES, ReferenceDevice
from physink_tui.input.hid.report_encoder import PenState, encode_report

__all__ = ["REFERENCE_DEVICES", "PenState", "ScriptedSample", "Stroke", "VirtualPen", "movement_seconds"]

APPROACH_REPORTS = 8
"""Hover reports while the pen comes into range, moving towards the stroke's start."""
LIFT_REPORTS = 4
"""Hover reports after the pen lifts, before the one out-of-range report."""
RAMP_S = 0.03
"""Seconds the pressure takes to build up after landing (and to fall before lifting)."""
CORNER_DEGREES = 50.0
"""A turn sharper than this splits a stroke into movements that each start and end at rest."""
DOT_S = 0.1
"""How long the tip stays down for a stroke of a single point."""
_PROTOCOL_REPORTS = {"uclogic-v1": 0x07, "huion-v2": 0x08}

Point = tuple[float, float]
Phase = Literal["approach", "touch", "lift", "leave"]


@dataclass(frozen=True, slots=True)
class Stroke:
    """One pen-down movement.

    Attributes:
        points: the path as ``(x, y)`` pairs, each in 0..1 of the active area; one point is a dot (a tap).
        pressure: pressure profile in (0, 1], spaced evenly over the stroke's duration and interpolated
            linearly; None for a natural profile (a base near 0.5 wandering smoothly). Landing and lifting
            ramps apply to both.
        eraser: drawn with the eraser end.
        b1: first barrel button held for the whole stroke (from approach to lift).
        b2: second barrel button held likewise.
    """

    points: tuple[Point, ...]
    pressure: tuple[float, ...] | None = None
    eraser: bool = False
    b1: bool = False
    b2: bool = False

    def __post_init__(self) -> None:
        points = tuple((float(x), float(y)) for x, y in self.points)
        if not points:
            raise ValueError("a stroke needs at least one point")
        for x, y in points:
            if not (0.0 <= x <= 1.0 and 0.0 <= y <= 1.0):
                raise ValueError(f"stroke point {(x, y)!r} is outside the active area (expected 0..1)")
        object.__setattr__(self, "points", points)
        if self.pressure is not None:
            pressure = tuple(float(p) for p in self.pressure)
            if not pressure or not all(0.0 < p <= 1.0 for p in pressure):
                raise ValueError(f"pressure profile {pressure!r} must be non-empty with values in (0, 1]")
            object.__setattr__(self, "pressure", pressure)

    @classmethod
    def line(cls, start: Point, end: Point, **kwargs) -> Stroke:
        """A straight line."""
        return cls((start, end), **kwargs)

    @classmethod
    def box(cls, x0: float, y0: float, x1: float, y1: float, **kwargs) -> Stroke:
        """A rectangle drawn as one stroke, clockwise from ``(x0, y0)`` back to it."""
        return cls(((x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)), **kwargs)

    @classmethod
    def circle(cls, center: Point, radius: float, *, segments: int = 72, aspect: float = 1.0, **kwargs) -> Stroke:
        """A circle drawn clockwise from its top, closing on itself. ``radius`` is a fraction of the
        active area's height; ``aspect`` (width / height of the active area) makes it round on the
        tablet itself rather than in active-area units."""
        cx, cy = center
        angles = [2.0 * math.pi * k / segments for k in range(segments + 1)]
        pts = [(cx + radius / aspect * math.sin(a), cy - radius * math.cos(a)) for a in angles]
        return cls(tuple(pts), **kwargs)

    @classmethod
    def zigzag(cls, start: Point, end: Point, *, teeth: int = 6, amplitude: float = 0.03,
               **kwargs) -> Stroke:
        """A spring: ``teeth`` sharp turns across the line from start to end, ``amplitude`` either side."""
        (x0, y0), (x1, y1) = start, end
        length = math.hypot(x1 - x0, y1 - y0) or 1.0
        nx, ny = -(y1 - y0) / length, (x1 - x0) / length
        pts = [start]
        for k in range(teeth):
            u, side = (k + 0.5) / teeth, amplitude if k % 2 == 0 else -amplitude
            pts.append((x0 + u * (x1 - x0) + side * nx, y0 + u * (y1 - y0) + side * ny))
        pts.append(end)
        return cls(tuple(pts), **kwargs)

    @classmethod
    def coil(cls, start: Point, end: Point, *, loops: int = 5, radius: float = 0.02, segments: int = 24,
             **kwargs) -> Stroke:
        """A spring drawn as a coil (how PaleoSketch's helix looks): ``loops`` turns of ``radius``
        whose centres advance evenly from ``start`` to ``end``."""
        (x0, y0), (x1, y1) = start, end
        length = math.hypot(x1 - x0, y1 - y0) or 1.0
        ux, uy = (x1 - x0) / length, (y1 - y0) / length
        pts = []
        steps = loops * segments
        for k in range(steps + 1):
            u, a = k / steps, 2.0 * math.pi * k / segments
            cx, cy = x0 + u * (x1 - x0), y0 + u * (y1 - y0)
            along, across = -radius * math.cos(a), radius * math.sin(a)
            pts.append((cx + along * ux - across * uy, cy + along * uy + across * ux))
        return cls(tuple(pts), **kwargs)


@dataclass(frozen=True, slots=True)
class ScriptedSample:
    """The intended pen state behind one report of a recording.

    Attributes:
        t: seconds, exactly as written to the capture (whole microseconds, never decreasing).
        state: the state the pen was meant to be in, without sensor noise.
        stroke: index of the stroke in the script.
        phase: ``approach`` (hovering towards the start), ``touch``, ``lift`` (hovering after the stroke)
            or ``leave`` (the one out-of-range report).
    """

    t: float
    state: PenState
    stroke: int
    phase: Phase


def movement_seconds(length: float) -> float:
    """How long a hand takes for one movement of ``length`` active-area units (the whole width: 1.75 s).

    Longer movements are faster on average, as in Fitts-style reaching: a constant reaction time plus a
    power law of the distance. A movement across half the tablet takes 1.1 s and peaks at 0.85 width/s
    (minimum jerk peaks at 1.875 times the mean speed).

    >>> round(movement_seconds(0.5), 2)
    1.1
    """
    return 0.15 + 1.6 * length**0.75


def _min_jerk(u: float) -> float:
    """Fraction of the distance covered at fraction ``u`` of a minimum-jerk movement."""
    return u * u * u * (10.0 - 15.0 * u + 6.0 * u * u)


def _smoothstep(u: float) -> float:
    u = 0.0 if u < 0.0 else 1.0 if u > 1.0 else u
    return u * u * (3.0 - 2.0 * u)


class _Path:
    """A stroke's polyline split at sharp corners into movements, each timed by its length."""

    def __init__(self, points: Sequence[Point]) -> None:
        pts = [points[0]]
        for p in points[1:]:
            if p != pts[-1]:
                pts.append(p)
        self.end_point = pts[-1]
        # each movement: its points, the cumulative length at each point, its duration in seconds
        self.movements: list[tuple[list[Point], list[float], float]] = []
        start = 0
        for i in range(1, len(pts)):
            if i == len(pts) - 1 or self._corner(pts[i - 1], pts[i], pts[i + 1]):
                piece = pts[start : i + 1]
                cum = [0.0]
                for a, b in itertools.pairwise(piece):
                    cum.append(cum[-1] + math.dist(a, b))
                self.movements.append((piece, cum, movement_seconds(cum[-1])))
                start = i
        self.ends = [0.0]
        for *_, seconds in self.movements:
            self.ends.append(self.ends[-1] + seconds)
        self.duration = self.ends[-1] if self.movements else DOT_S
        last = self.movements[-1][0] if self.movements else None
        self.exit_direction = (last[-1][0] - last[-2][0], last[-1][1] - last[-2][1]) if last else None

    @staticmethod
    def _corner(a: Point, b: Point, c: Point) -> bool:
        ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
        turn = math.degrees(abs(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)))
        return turn > CORNER_DEGREES

    def at(self, tau: float) -> Point:
        """Where the pen is ``tau`` seconds after landing."""
        if not self.movements:
            return self.end_point
        k = min(max(bisect.bisect_right(self.ends, tau) - 1, 0), len(self.movements) - 1)
        piece, cum, seconds = self.movements[k]
        s = _min_jerk(min(max((tau - self.ends[k]) / seconds, 0.0), 1.0)) * cum[-1]
        j = min(max(bisect.bisect_right(cum, s) - 1, 0), len(piece) - 2)
        span = cum[j + 1] - cum[j]
        f = (s - cum[j]) / span if span else 0.0
        (x0, y0), (x1, y1) = piece[j], piece[j + 1]
        return (x0 + f * (x1 - x0), y0 + f * (y1 - y0))


def _clamp01(v: float) -> float:
    return 0.0 if v < 0.0 else 1.0 if v > 1.0 else v


def _interp(profile: tuple[float, ...], u: float) -> float:
    if len(profile) == 1:
        return profile[0]
    pos = _clamp01(u) * (len(profile) - 1)
    i = min(int(pos), len(profile) - 2)
    return profile[i] + (pos - i) * (profile[i + 1] - profile[i])


class VirtualPen:
    """A scripted pen on one device.

    Args:
        device: a `ReferenceDevice`, or ``(descriptor, vid, pid, protocol)``.
        rate_hz: nominal report rate.
        seed: seed of the one random generator (jitter, noise, approach direction, pressure wander, tilt).
        jitter_s: standard deviation of the report timestamps around the nominal rate, in seconds.
        position_noise: standard deviation of the reported x and y around the path, in active-area units.
        padding_ones: fill bits the layout does not use with ones (see `encode_report`).
        report_id: the pen report to write; None picks the protocol's report (0x07 for ``uclogic-v1``, 0x08
            for ``huion-v2``), else the descriptor's pen report with the lowest id.

    Raises:
        DescriptorError: the descriptor describes no pen report.
        ValueError: a non-positive rate, a negative jitter or noise, or a report id with no pen layout.
    """

    def __init__(
        self,
        device: ReferenceDevice | tuple[bytes, int, int, str | None],
        rate_hz: float = 200.0,
        seed: int = 0,
        jitter_s: float = 0.0003,
        position_noise: float = 0.0003,
        padding_ones: bool = False,
        report_id: int | None = None,
    ) -> None:
        if not isinstance(device, ReferenceDevice):
            descriptor, vid, pid, protocol = device
            name = f"PhysInk virtual pen {vid:04x}:{pid:04x}"
            device = ReferenceDevice(name, vid, pid, bytes(descriptor), protocol)
        if not rate_hz > 0:
            raise ValueError(f"rate_hz {rate_hz!r} must be positive")
        if not (jitter_s >= 0 and position_noise >= 0):
            raise ValueError(f"jitter_s {jitter_s!r} and position_noise {position_noise!r} must be >= 0")
        self.device = device
        self.rate_hz, self.seed, self.jitter_s = float(rate_hz), seed, float(jitter_s)
        self.position_noise, self.padding_ones = float(position_noise), padding_ones
        layouts = HidPenDecoder(device.descriptor, device.vid, device.pid, protocol=device.protocol).layouts
        if report_id is None:
            report_id = _PROTOCOL_REPORTS.get(device.protocol or "")
            if report_id not in layouts:
                described = [rid for rid, lay in layouts.items() if lay.source == "descriptor"]
                report_id = min(described or layouts)
        if report_id not in layouts:
            raise ValueError(f"report id {report_id!r} has no pen layout (pen reports: {sorted(layouts)})")
        self.layout: PenLayout = layouts[report_id]

    def encode(self, state: PenState) -> bytes:
        """One report for ``state`` in the chosen layout."""
        return encode_report(self.layout, state, padding_ones=self.padding_ones)

    def samples(
        self, strokes: Iterable[Stroke], *, start_t: float = 0.0, gap_s: float = 0.4
    ) -> tuple[ScriptedSample, ...]:
        """The intended state behind every report `record` writes for the same arguments, in order."""
        return tuple(truth for truth, _ in self._plan(strokes, start_t, gap_s))

    def record(self, strokes: Iterable[Stroke], *, start_t: float = 0.0, gap_s: float = 0.4) -> Capture:
        """A capture of the strokes, drawn one after another, ``gap_s`` seconds out of range between them."""
        strokes = tuple(strokes)
        plan = self._plan(strokes, start_t, gap_s)
        events = tuple(CaptureEvent(t=truth.t, data=self.encode(sensed)) for truth, sensed in plan)
        dev = self.device
        params = (f"report=0x{self.layout.report_id:02x} rate_hz={self.rate_hz!r} seed={self.seed!r} "
                  f"jitter_s={self.jitter_s!r} position_noise={self.position_noise!r} "
                  f"padding_ones={self.padding_ones} start_t={float(start_t)!r} gap_s={float(gap_s)!r} "
                  f"strokes={len(strokes)}")
        header = CaptureDevice(index=0, name=dev.name, phys=None, bus=3, vid=dev.vid, pid=dev.pid,
                               descriptor=dev.descriptor, comments=(f"physink virtual pen: {params}",))
        return Capture(devices=(header,), events=events)

    # -- the plan: (ground truth, sensed state) per report ----------------------------------------------

    def _plan(
        self, strokes: Iterable[Stroke], start_t: float, gap_s: float
    ) -> list[tuple[ScriptedSample, PenState]]:
        """Per report: the ground truth and the state the sensor reports (with noise)."""
        if not (start_t >= 0 and gap_s >= 0):
            raise ValueError(f"start_t {start_t!r} and gap_s {gap_s!r} must be >= 0")
        rng = random.Random(self.seed)
        dt = 1.0 / self.rate_hz
        clock = float(start_t)
        last_us = 0
        out: list[tuple[ScriptedSample, PenState]] = []
        for index, stroke in enumerate(strokes):
            for phase, state in self._stroke_states(stroke, rng, dt):
                last_us = max(round((clock + rng.gauss(0.0, self.jitter_s)) * 1e6), last_us, 0)
                sensed = state
                if phase == "leave":
                    sensed = replace(state, x=out[-1][1].x, y=out[-1][1].y)  # repeats the last position
                elif self.position_noise:
                    sensed = replace(state, x=_clamp01(state.x + rng.gauss(0.0, self.position_noise)),
                                     y=_clamp01(state.y + rng.gauss(0.0, self.position_noise)))
                out.append((ScriptedSample(last_us / 1e6, state, index, phase), sensed))
                clock += dt
            clock += gap_s - dt
        return out

    def _stroke_states(
        self, stroke: Stroke, rng: random.Random, dt: float
    ) -> Iterable[tuple[Phase, PenState]]:
        """The states of one stroke, from approaching the start to leaving range, one per report."""
        path = _Path(stroke.points)
        # per-stroke draws, always in this order so the generator's sequence depends only on the script
        angle = rng.uniform(0.0, 2.0 * math.pi)
        reach = rng.uniform(0.02, 0.04)
        base = rng.uniform(0.42, 0.58)
        phases = [rng.uniform(0.0, 2.0 * math.pi) for _ in range(3)]
        tilt = (rng.uniform(15.0, 35.0), rng.uniform(5.0, 25.0))
        drift_angle = rng.uniform(0.0, 2.0 * math.pi)
        held = {"eraser": stroke.eraser, "b1": stroke.b1, "b2": stroke.b2}

        def tilt_at(tau: float) -> tuple[float, float]:
            return (tilt[0] + 3.0 * math.sin(2.0 * math.pi * 0.7 * tau + phases[2]),
                    tilt[1] + 2.0 * math.cos(2.0 * math.pi * 0.5 * tau + phases[2]))

        x0, y0 = stroke.points[0]
        sx, sy = x0 + reach * math.cos(angle), y0 + reach * math.sin(angle)
        for k in range(APPROACH_REPORTS):
            f = 1.0 - (1.0 - (k + 1) / APPROACH_REPORTS) ** 2  # ease out: slows as it arrives
            tx, ty = tilt_at(0.0)
            yield "approach", PenState(_clamp01(sx + f * (x0 - sx)), _clamp01(sy + f * (y0 - sy)),
                                       tilt_x=tx, tilt_y=ty, **held)

        duration = path.duration
        steps = max(1, math.ceil(duration / dt - 1e-9))
        for k in range(steps + 1):
            tau = min(k * dt, duration)
            x, y = path.at(tau)
            if stroke.pressure is not None:
                p = _interp(stroke.pressure, tau / duration)
            else:
                p = (base + 0.07 * math.sin(2.0 * math.pi * 1.3 * tau + phases[0])
                     + 0.03 * math.sin(2.0 * math.pi * 3.1 * tau + phases[1]))
            envelope = 0.08 + 0.92 * _smoothstep(min(tau, duration - tau) / RAMP_S)
            tx, ty = tilt_at(tau)
            p = min(max(p * envelope, 0.01), 1.0)
            yield "touch", PenState(x, y, p, tip=True, tilt_x=tx, tilt_y=ty, **held)

        ex, ey = path.exit_direction or (math.cos(drift_angle), math.sin(drift_angle))
        norm = math.hypot(ex, ey) or 1.0
        x1, y1 = path.end_point
        tx, ty = tilt_at(duration)
        for k in range(LIFT_REPORTS):
            f = 0.012 * _smoothstep((k + 1) / LIFT_REPORTS)
            yield "lift", PenState(_clamp01(x1 + f * ex / norm), _clamp01(y1 + f * ey / norm),
                                   tilt_x=tx, tilt_y=ty, **held)
        yield "leave", PenState(_clamp01(x1 + 0.012 * ex / norm), _clamp01(y1 + 0.012 * ey / norm),
                                in_range=False, tilt_x=tx, tilt_y=ty)
