"""A hurried hand drawing `penmodels.shapes` as timed pen reports, written apart from the virtual pen; no I/O."""

from __future__ import annotations

import bisect
import itertools
import math
import random
from dataclasses import dataclass

from penmodels.shapes import Coil, Curve, Outline, Oval, Path, Shape, XMark

Point = tuple[float, float]
TIP_DOWN, TIP_UP = 0.05, 0.01
"""The session's default tip hysteresis (libinput's): `PenPoint.tip` follows it, as the session will."""


@dataclass(frozen=True, slots=True)
class PenPoint:
    """One report: canvas pixels, seconds, pressure 0..1, whether the tip touches (after hysteresis), in range."""

    x: float
    y: float
    t: float
    p: float
    tip: bool
    in_range: bool = True


def _unit(dx: float, dy: float) -> Point:
    n = math.hypot(dx, dy) or 1.0
    return (dx / n, dy / n)


def _rot(d: Point, angle: float) -> Point:
    c, s = math.cos(angle), math.sin(angle)
    return (d[0] * c - d[1] * s, d[0] * s + d[1] * c)


def _lerp(a: Point, b: Point, f: float) -> Point:
    return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))


def _quad(a: Point, c: Point, b: Point, n: int) -> list[Point]:
    """A quadratic Bezier from ``a`` via control ``c`` to ``b``, ``n`` points after ``a``."""
    out = []
    for k in range(1, n + 1):
        u = k / n
        out.append(((1 - u) ** 2 * a[0] + 2 * u * (1 - u) * c[0] + u * u * b[0],
                    (1 - u) ** 2 * a[1] + 2 * u * (1 - u) * c[1] + u * u * b[1]))
    return out


def _size(pts: list[Point]) -> float:
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return math.hypot(max(xs) - min(xs), max(ys) - min(ys))


@dataclass(frozen=True, slots=True)
class Habits:
    """How often the hand does each thing, and how much; the defaults are the hurried hand of `HurriedPen`.

    Changing one leaves every random draw in place, so a seed draws the same strokes but for that habit (to
    find which habit a recogniser stumbles on).

    Attributes:
        corner_overshoot: share of corners run past (then cut back onto the next side), 0..1.
        corner_round: share of corners rounded; the rest are turned cleanly (the two add up to at most 1).
        close_past: share of closed shapes drawn on past their start; the rest stop a little short of it.
        mid_side: closed polygons start mid-side (else at a corner).
        hook: chance of a hook at each end of a stroke, 0..1.
        bow: the largest bow of a side longer than 30 px, as a share of its length.
        tremor: scale of the tremor and the sensor noise (1: about a pixel).
        tremor_hz: the range the tremor's frequencies are drawn from (a healthy hand's physiological tremor 7-11 Hz;
            an essential or parkinsonian tremor 4-7 Hz).
        speed: scale of the hand's speed (its power-law gain and its top speed; 1: the hurried hand's 1200-2000 px/s
            along a side, 0.15: a slow, careful or unsteady hand's 180-300 px/s, sampled by many more reports).
        drift: amplitude in pixels of a slow wander across the path (0.5-1.5 Hz: the hand correcting its course as
            it goes), 0 for none (then nothing is drawn for it, and every other draw stays in place).
    """

    corner_overshoot: float = 0.45
    corner_round: float = 0.25
    close_past: float = 0.6
    mid_side: bool = True
    hook: float = 0.75
    bow: float = 0.01
    tremor: float = 1.0
    tremor_hz: tuple[float, float] = (7.0, 11.0)
    speed: float = 1.0
    drift: float = 0.0


SHAKY_SLOW = Habits(tremor=2.5, tremor_hz=(4.0, 7.0), speed=0.15, drift=2.0)
"""A slow, unsteady hand (an older or low-vision person's, or anyone's drawing slowly to be careful): a 4-7 Hz tremor
of 1-3 px with a little more sensor noise, a slow wander across the path of 1-2 px, and a speed of 180-300 px/s along
a side, so a 200 Hz tablet sends several reports a pixel."""


class HurriedPen:
    """A person drawing in a hurry.

    What the hand does, all drawn from one ``random.Random`` passed in:

    - the path: closed shapes start mid-side (or at a random angle round an oval), run either way round and
      close with a small overshoot past the start or stop a little short of it; corners are overshot (the pen
      runs past the corner, then cuts back onto the next side), rounded, or turned cleanly; long straight sides
      bow a little; the pen lands with a small hook and flicks off with another; an X's strokes are tilted,
      stretched and slid along themselves, so they cross away from their middles;
    - the speed: the two-thirds power law (speed grows with the cube root of the radius of curvature), capped
      along straight sides, limited in acceleration and deceleration, so the pen slows into corners and tight
      curves and speeds up along sides; reports come at a ~200 Hz rate with jitter, so their spacing varies;
    - the sensor: a 7-11 Hz tremor of about a pixel and a little noise; pressure ramps up after landing,
      wanders, and ramps down before lifting; the pen hovers in and out of range along its direction of travel.

    Positions are canvas pixels (the 1600 x 1000 canvas), times seconds.

    Args:
        rng: every random choice comes from it (the same seed gives the same reports).
        rate_hz: the tablet's report rate.
        habits: how often the hand overshoots, rounds, hooks ... (`Habits`).
    """

    def __init__(self, rng: random.Random, rate_hz: float = 200.0, habits: Habits | None = None) -> None:
        self.rng = rng
        self.dt = 1.0 / rate_hz
        self.habits = habits or Habits()

    # -- the path the hand means to take ------------------------------------------------------------------

    def paths(self, shape: Shape) -> list[list[Point]]:
        """The pen-down paths for ``shape`` (two for an X), as keypoints before densifying and timing."""
        if isinstance(shape, Outline):
            return [self._closed(list(shape.vertices))]
        if isinstance(shape, Oval):
            return [self._oval(shape)]
        if isinstance(shape, Path):
            return [self._open(list(shape.vertices))]
        if isinstance(shape, Curve):
            return [list(shape.points)]
        if isinstance(shape, Coil):
            return [self._coil(shape)]
        if isinstance(shape, XMark):
            return [self._x_line(*shape.first), self._x_line(*shape.second)]
        raise TypeError(f"not a shape: {shape!r}")

    def _corner(self, prev: Point, v: Point, nxt: Point) -> list[Point]:
        """How the hand turns at corner ``v``: overshooting it, rounding it, or cleanly."""
        rng = self.rng
        a, b = _unit(v[0] - prev[0], v[1] - prev[1]), _unit(nxt[0] - v[0], nxt[1] - v[1])
        shortest = min(math.dist(prev, v), math.dist(v, nxt))
        roll = rng.random()
        if roll < self.habits.corner_overshoot:  # runs past the corner, then cuts back onto the next side
            d = min(rng.uniform(2.0, 6.0), 0.12 * shortest)
            back = rng.uniform(1.0, 2.0) * d
            return [(v[0] + a[0] * d, v[1] + a[1] * d), (v[0] + b[0] * back, v[1] + b[1] * back)]
        if roll < self.habits.corner_overshoot + self.habits.corner_round:  # rounded
            r = rng.uniform(0.05, 0.15) * shortest
            start = (v[0] - a[0] * r, v[1] - a[1] * r)
            return [start, *_quad(start, v, (v[0] + b[0] * r, v[1] + b[1] * r), 6)]
        return [v]

    def _closed(self, verts: list[Point]) -> list[Point]:
        rng = self.rng
        if rng.random() < 0.5:
            verts = verts[::-1]
        n = len(verts)
        i = rng.randrange(n)
        a, b = verts[i], verts[(i + 1) % n]
        start = _lerp(a, b, rng.uniform(0.25, 0.75) if self.habits.mid_side else 0.0)
        route = [start]
        for k in range(n):
            corner = verts[(i + 1 + k) % n]
            route += self._corner(verts[(i + k) % n], corner, verts[(i + 2 + k) % n])
        perimeter = sum(math.dist(verts[k], verts[(k + 1) % n]) for k in range(n))
        side = _unit(b[0] - a[0], b[1] - a[1])
        drift = rng.uniform(-1.0, 1.0) * min(3.0, 0.1 * math.dist(a, b))  # does not come back onto the same line
        normal = (-side[1] * drift, side[0] * drift)
        if rng.random() < self.habits.close_past:  # on past the start
            over = min(rng.uniform(0.03, 0.08) * perimeter, 0.8 * math.dist(start, b))
            end = (start[0] + side[0] * over + normal[0], start[1] + side[1] * over + normal[1])
            route += [(start[0] + normal[0], start[1] + normal[1]), end]
        else:  # stops short of it
            gap = min(rng.uniform(0.01, 0.035) * perimeter, 0.8 * math.dist(a, start))
            route.append((start[0] - side[0] * gap + normal[0], start[1] - side[1] * gap + normal[1]))
        return route

    def _open(self, verts: list[Point]) -> list[Point]:
        route = [verts[0]]
        for k in range(1, len(verts) - 1):
            route += self._corner(verts[k - 1], verts[k], verts[k + 1])
        return [*route, verts[-1]]

    def _oval(self, oval: Oval) -> list[Point]:
        rng = self.rng
        theta0 = rng.uniform(0.0, 2.0 * math.pi)
        turn = 1.0 if rng.random() < 0.5 else -1.0
        past = rng.random() < self.habits.close_past
        sweep = 2.0 * math.pi + (rng.uniform(0.15, 0.5) if past else -rng.uniform(0.1, 0.3))
        egg, egg_at = rng.uniform(0.0, 0.04), rng.uniform(0.0, math.pi)
        drift = rng.uniform(-0.05, 0.05)  # the closing part runs a little inside or outside the start
        n = max(24, int(sweep * max(oval.rx, oval.ry) / 1.5))
        c, s = math.cos(oval.angle), math.sin(oval.angle)
        out = []
        for k in range(n + 1):
            u = k / n
            phi = theta0 + turn * sweep * u
            scale = 1.0 + egg * math.cos(2.0 * (phi - egg_at)) + drift * u
            x, y = oval.rx * scale * math.cos(phi), oval.ry * scale * math.sin(phi)
            out.append((oval.center[0] + x * c - y * s, oval.center[1] + x * s + y * c))
        return out

    def _coil(self, coil: Coil) -> list[Point]:
        """Loops of uneven size and spacing whose centres advance along the axis."""
        rng = self.rng
        (x0, y0), (x1, y1) = coil.start, coil.end
        length = math.hypot(x1 - x0, y1 - y0) or 1.0
        ux, uy = (x1 - x0) / length, (y1 - y0) / length
        radii = [coil.radius * rng.uniform(0.85, 1.15) for _ in range(coil.loops + 1)]
        squash = rng.uniform(0.85, 1.1)
        steps = coil.loops * 36
        out = []
        for k in range(steps + 1):
            u = k / steps
            a = 2.0 * math.pi * coil.loops * u
            j = min(int(u * coil.loops), coil.loops - 1)
            f = u * coil.loops - j
            r = radii[j] + f * (radii[j + 1] - radii[j])
            progress = u + 0.03 * math.sin(2.0 * math.pi * coil.loops * u)  # loops bunch and spread
            cx, cy = x0 + progress * (x1 - x0), y0 + progress * (y1 - y0)
            along, across = -r * squash * math.cos(a), r * math.sin(a)
            out.append((cx + along * ux - across * uy, cy + along * uy + across * ux))
        return out

    def _x_line(self, a: Point, b: Point) -> list[Point]:
        """One stroke of an X: tilted, stretched and slid along itself, so the strokes cross off their middles."""
        rng = self.rng
        mid = _lerp(a, b, 0.5)
        half = _rot(((b[0] - a[0]) / 2, (b[1] - a[1]) / 2), math.radians(rng.uniform(-8.0, 8.0)))
        half = (half[0] * rng.uniform(0.85, 1.15), half[1] * rng.uniform(0.85, 1.15))
        slide = rng.choice((-1.0, 1.0)) * rng.uniform(0.08, 0.22)  # of the stroke's length
        mid = (mid[0] + 2 * half[0] * slide, mid[1] + 2 * half[1] * slide)
        return [(mid[0] - half[0], mid[1] - half[1]), (mid[0] + half[0], mid[1] + half[1])]

    # -- from keypoints to a dense path with hooks ---------------------------------------------------------

    def _dense(self, keys: list[Point]) -> list[Point]:
        """About one point per pixel along the keypoints; sides longer than 30 px bow a little."""
        out = [keys[0]]
        for a, b in itertools.pairwise(keys):
            length = math.dist(a, b)
            if length == 0.0:
                continue
            n = max(1, math.ceil(length))
            bow = self.rng.uniform(-self.habits.bow, self.habits.bow) * length if length > 30.0 else 0.0
            nx, ny = -(b[1] - a[1]) / length, (b[0] - a[0]) / length
            for k in range(1, n + 1):
                u = k / n
                off = bow * math.sin(math.pi * u)
                out.append((a[0] + u * (b[0] - a[0]) + off * nx, a[1] + u * (b[1] - a[1]) + off * ny))
        return out

    def _hooked(self, pts: list[Point]) -> list[Point]:
        """A small hook where the pen lands and another where it lifts (each most of the time)."""
        rng = self.rng
        size = _size(pts)

        def heading(a: Point, b: Point) -> Point:
            return _unit(b[0] - a[0], b[1] - a[1])

        reach = min(6, len(pts) - 1)
        d0, d1 = heading(pts[0], pts[reach]), heading(pts[-1 - reach], pts[-1])
        if rng.random() < self.habits.hook:
            h = min(rng.uniform(2.0, 5.0), 0.08 * size)
            side = rng.choice((-1.0, 1.0))
            away = _rot(d0, side * math.radians(rng.uniform(100.0, 160.0)))
            h0 = (pts[0][0] + away[0] * h, pts[0][1] + away[1] * h)
            ctrl = (pts[0][0] - d0[0] * h * 0.5, pts[0][1] - d0[1] * h * 0.5)
            pts = [h0, *_quad(h0, ctrl, pts[0], 6)[:-1], *pts]
        if rng.random() < self.habits.hook:
            h = min(rng.uniform(2.0, 5.0), 0.08 * size)
            side = rng.choice((-1.0, 1.0))
            away = _rot(d1, side * math.radians(rng.uniform(90.0, 150.0)))
            end = pts[-1]
            ctrl = (end[0] + d1[0] * h * 0.5, end[1] + d1[1] * h * 0.5)
            pts = [*pts, *_quad(end, ctrl, (end[0] + away[0] * h, end[1] + away[1] * h), 6)]
        return pts

    # -- timing, tremor, pressure ---------------------------------------------------------------------------

    def _speeds(self, pts: list[Point]) -> list[float]:
        """Speed (px/s) at each point: the two-thirds power law, capped, then acceleration-limited both ways."""
        rng = self.rng
        gain, v_max = rng.uniform(100.0, 140.0), rng.uniform(1200.0, 2000.0)
        gain, v_max = gain * self.habits.speed, v_max * self.habits.speed
        accel, decel = rng.uniform(6000.0, 12000.0), rng.uniform(6000.0, 12000.0)
        n, w = len(pts), 3
        limit = []
        for i in range(n):
            a, b, c = pts[max(i - w, 0)], pts[i], pts[min(i + w, n - 1)]
            h1, h2 = math.atan2(b[1] - a[1], b[0] - a[0]), math.atan2(c[1] - b[1], c[0] - b[0])
            turn = abs((h2 - h1 + math.pi) % (2 * math.pi) - math.pi) if a != b and b != c else 0.0
            span = math.dist(a, b) + math.dist(b, c)
            radius = span / turn if turn > 1e-6 else math.inf
            limit.append(min(v_max, max(60.0 * min(1.0, self.habits.speed), gain * radius ** (1.0 / 3.0))))
        v = list(limit)
        v[0] = min(v[0], rng.uniform(80.0, 200.0))
        v[-1] = min(v[-1], rng.uniform(100.0, 300.0))
        for i in range(1, n):
            v[i] = min(v[i], math.sqrt(v[i - 1] ** 2 + 2 * accel * math.dist(pts[i - 1], pts[i])))
        for i in range(n - 2, -1, -1):
            v[i] = min(v[i], math.sqrt(v[i + 1] ** 2 + 2 * decel * math.dist(pts[i], pts[i + 1])))
        return v

    def play(self, keys: list[Point], t_land: float) -> list[PenPoint]:
        """Every report of one pen-down along ``keys``: hovering in, touching from ``t_land``, hovering out,
        and the one report out of range."""
        rng, dt = self.rng, self.dt
        pts = self._hooked(self._dense(keys))
        v = self._speeds(pts)
        times = [0.0]
        for i in range(1, len(pts)):
            times.append(times[-1] + math.dist(pts[i - 1], pts[i]) / (0.5 * (v[i - 1] + v[i])))
        duration = times[-1]
        shaky = self.habits.tremor
        amp = rng.uniform(0.5, 0.9) * shaky
        tremor = [(rng.uniform(*self.habits.tremor_hz), rng.uniform(0.0, 2 * math.pi)) for _ in range(4)]
        base, wander = rng.uniform(0.35, 0.65), rng.uniform(0.0, 2 * math.pi)
        ramp_up, ramp_down = rng.uniform(0.015, 0.04), rng.uniform(0.015, 0.04)
        wander_by = self.habits.drift
        slow = ((rng.uniform(0.5, 1.5), rng.uniform(0.0, 2 * math.pi), rng.uniform(0.5, 1.0) * wander_by)
                if wander_by > 0 else (0.0, 0.0, 0.0))
        across = _unit(-(pts[-1][1] - pts[0][1]), pts[-1][0] - pts[0][0])

        def shake(tau: float) -> Point:
            (f1, p1), (f2, p2), (f3, p3), (f4, p4) = tremor
            return (amp * (math.sin(2 * math.pi * f1 * tau + p1) + 0.5 * math.sin(2 * math.pi * f2 * tau + p2))
                    + rng.gauss(0.0, 0.3 * shaky),
                    amp * (math.sin(2 * math.pi * f3 * tau + p3) + 0.5 * math.sin(2 * math.pi * f4 * tau + p4))
                    + rng.gauss(0.0, 0.3 * shaky))

        def at(tau: float) -> Point:
            j = min(max(bisect.bisect_right(times, tau) - 1, 0), len(pts) - 2)
            span = times[j + 1] - times[j]
            return _lerp(pts[j], pts[j + 1], (tau - times[j]) / span if span else 0.0)

        out: list[PenPoint] = []
        into = _unit(pts[min(3, len(pts) - 1)][0] - pts[0][0], pts[min(3, len(pts) - 1)][1] - pts[0][1])
        for k in range(rng.randint(4, 8), 0, -1):  # hovering in along the direction of travel
            back = v[0] * dt * k * rng.uniform(1.0, 1.6)
            out.append(PenPoint(pts[0][0] - into[0] * back, pts[0][1] - into[1] * back, t_land - k * dt, 0.0, False))
        tip = False
        steps = max(1, math.ceil(duration / dt))
        for k in range(steps + 1):
            tau = k * dt + (rng.gauss(0.0, 0.00015) if k else 0.0)  # reports come on the tablet's clock
            x, y = at(min(tau, duration))
            sx, sy = shake(t_land + tau)
            if wander_by > 0:  # the slow wander across the path, nothing at the pen-down
                off = slow[2] * (math.sin(2 * math.pi * slow[0] * tau + slow[1]) - math.sin(slow[1]))
                sx, sy = sx + across[0] * off, sy + across[1] * off
            landing = min(tau / ramp_up, 1.0) ** 2
            lifting = min(max(duration - tau, 0.0) / ramp_down, 1.0) ** 2
            envelope = 0.15 + 0.85 * min(landing, lifting)
            p = max(0.02, min(1.0, base * (1.0 + 0.12 * math.sin(2 * math.pi * 1.7 * tau + wander)) * envelope))
            tip = p > TIP_DOWN or (tip and p >= TIP_UP)
            out.append(PenPoint(x + sx, y + sy, t_land + max(tau, 0.0), p, tip))
        x1, y1 = pts[-1]
        away = _unit(x1 - pts[-min(4, len(pts))][0], y1 - pts[-min(4, len(pts))][1])
        t_lift = out[-1].t
        lift = rng.randint(3, 6)
        for k in range(1, lift + 2):  # hovering out, then out of range
            ahead = v[-1] * dt * k
            out.append(PenPoint(x1 + away[0] * ahead, y1 + away[1] * ahead, t_lift + k * dt, 0.0, False, k <= lift))
        return out

    def draw(self, shape: Shape, t_land: float) -> list[list[PenPoint]]:
        """The reports of each pen-down for ``shape``, the first landing at ``t_land``; the second stroke of an
        X lands 0.3-0.8 s after the first lifts."""
        strokes: list[list[PenPoint]] = []
        for keys in self.paths(shape):
            if strokes:
                lifted = max(p.t for p in strokes[-1] if p.tip)
                t_land = lifted + self.rng.uniform(0.3, 0.8)
            strokes.append(self.play(keys, t_land))
        return strokes


def touching(reports: list[PenPoint]) -> list[tuple[float, float, float]]:
    """The ``(x, y, t)`` of the reports where the tip touches: the stroke the gesture engine will see."""
    return [(r.x, r.y, r.t) for r in reports if r.tip]


def single_strokes(shape: Shape, seed: int = 0, habits: Habits | None = None) -> list[list[tuple[float, float, float]]]:
    """The hurried pen's strokes for one shape (`penmodels.shapes.box`, `u_container`, `circle`, `polygon` ...):
    per pen-down the ``(x, y, t)`` the tip touched, canvas pixels and seconds from the first landing. ``habits``
    changes how the hand draws (`Habits`; e.g. ``Habits(hook=0)`` for no hooks).

    >>> from penmodels.shapes import box
    >>> strokes = single_strokes(box((800, 500), 200, 80, angle=0.3), seed=1)
    >>> len(strokes), strokes[0][0][2]
    (1, 0.0)
    """
    strokes = HurriedPen(random.Random(seed), habits=habits).draw(shape, 0.0)
    out = [touching(reports) for reports in strokes]
    t0 = out[0][0][2]
    return [[(x, y, round(t - t0, 6)) for x, y, t in stroke] for stroke in out]
