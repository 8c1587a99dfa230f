"""Circles and ovals as people draw them in a hurry or on a poor device (issue 25: held-back people read circles 93 %):
small ones, flat ovals, lumpy and wobbly ones, ones gone round again, ones with a tail, ones left open as a spiral's
turn; in canvas pixels, seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen, and the
devices of `benchmarks/bench_circle_habits.py`: a slow sampler's chords, a mouse, pointer acceleration)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point

EXPECTED = ("circle", "ellipse")
"""What every family is read as (benchmarks/label_kinds.tsv: a circle is round, a circle or an ellipse; so is an oval,
bouchal's and tutorboard's)."""


def _placed(rng: random.Random, pts: list[Point]) -> tuple[Point, ...]:
    """``pts`` (round the origin) turned a random angle and moved to a random place on the 1600 x 1000 canvas."""
    angle = rng.uniform(0, 2 * math.pi)
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x * c - y * s, cy + x * s + y * c) for x, y in pts)


def _round(rx: float, ry: float, start: float, sweep: float, radius_at: Callable[[float], float] | None = None,
           ) -> list[Point]:
    """Points every 2 degrees (at least 24) round an ellipse of half-axes ``rx``, ``ry`` from angle ``start`` turning
    by ``sweep`` (radians, signed); ``radius_at(done)`` scales the radius by how far round (radians) the pen is."""
    n = max(24, int(abs(math.degrees(sweep)) / 2))
    out = []
    for k in range(n + 1):
        done = abs(sweep) * k / n
        a = start + math.copysign(done, sweep)
        scale = radius_at(done) if radius_at else 1.0
        out.append((rx * scale * math.cos(a), ry * scale * math.sin(a)))
    return out


def _closing_sweep(rng: random.Random) -> float:
    """How far round a closed circle goes: 345-380 degrees (a little short of its start, or a little past it)."""
    return math.radians(rng.uniform(345, 380))


def _way(rng: random.Random) -> float:
    return rng.choice((-1.0, 1.0))


def small_circle(seed: int) -> Mark:
    """A circle 10-30 px across (a flowchart's connector, a dot drawn round, a wheel's hub), a little flat (up to
    15 %): a pen's few pixels of noise are a large share of it."""
    rng = random.Random(f"small-circle:{seed}")
    r = rng.uniform(5, 15)
    pts = _round(r, r * rng.uniform(0.85, 1.0), rng.uniform(0, 2 * math.pi), _way(rng) * _closing_sweep(rng))
    return Mark("small-circle", _placed(rng, pts), True)


def flat_oval(seed: int) -> Mark:
    """An oval 1.5-3.5 times as long as it is wide, 60-400 px long (a lens, an orbit, a flowchart's terminator drawn
    round): its ends turn sharply for a round shape and its sides run nearly straight."""
    rng = random.Random(f"flat-oval:{seed}")
    rx = rng.uniform(30, 200)
    pts = _round(rx, rx / rng.uniform(1.5, 3.5), rng.uniform(0, 2 * math.pi), _way(rng) * _closing_sweep(rng))
    return Mark("flat-oval", _placed(rng, pts), True)


def wobbly_circle(seed: int) -> Mark:
    """A circle drawn unevenly: its radius wanders by the 2nd to 7th harmonics round it, 6-14 % from the mean in all
    (lumps and flats a hurried hand makes, more than `closed_shape_families.lumpy_circle`'s 4-8 %), the higher
    harmonics weaker (by the square of their order: a hand's path bends smoothly), and no more than keeps it convex (a
    circle dented inwards between its lumps is a cloud or a flower); 0-30 % flat."""
    rng = random.Random(f"wobbly-circle:{seed}")
    r = rng.uniform(25, 200)
    flat = rng.uniform(0.7, 1.0)
    waves = [(m, rng.uniform(0.0, 1.0) / m ** 2, rng.uniform(0, 2 * math.pi)) for m in range(2, 8)]
    spread = sum(amp for _, amp, _ in waves) or 1.0
    want = rng.uniform(0.06, 0.14)
    waves = [(m, amp * want / spread, ph) for m, amp, ph in waves]
    bend = sum(m * m * amp for m, amp, _ in waves)  # the curvature a unit circle loses at worst
    if bend > 0.8:
        waves = [(m, amp * 0.8 / bend, ph) for m, amp, ph in waves]
    start = rng.uniform(0, 2 * math.pi)
    way = _way(rng)

    def lumps(done: float) -> float:
        a = start + way * done
        return 1.0 + sum(amp * math.cos(m * a + ph) for m, amp, ph in waves)

    pts = _round(r, r * flat, start, way * _closing_sweep(rng), lumps)
    return Mark("wobbly-circle", _placed(rng, pts), True)


def overtraced_circle(seed: int) -> Mark:
    """A circle gone round 1.1-1.6 times, the second time round running 2-10 % inside or outside the first (the hand
    making sure it closed, or drawing it bolder), 0-20 % flat."""
    rng = random.Random(f"overtraced-circle:{seed}")
    r = rng.uniform(25, 200)
    turns = rng.uniform(1.1, 1.6)
    drift = rng.choice((-1.0, 1.0)) * rng.uniform(0.02, 0.1)
    sweep = 2 * math.pi * turns

    def drifting(done: float) -> float:
        return 1.0 + drift * min(1.0, done / sweep * turns) ** 2

    pts = _round(r, r * rng.uniform(0.8, 1.0), rng.uniform(0, 2 * math.pi), _way(rng) * sweep, drifting)
    return Mark("overtraced-circle", _placed(rng, pts), True)


def tailed_circle(seed: int) -> Mark:
    """A closed circle (350-370 degrees) whose pen, landing or lifting, runs on outwards along the tangent and away for
    0.2-0.6 of the radius (a flick off, or a lead in from outside the rim), 0-20 % flat."""
    rng = random.Random(f"tailed-circle:{seed}")
    r = rng.uniform(25, 200)
    flat = rng.uniform(0.8, 1.0)
    pts = _round(r, r * flat, rng.uniform(0, 2 * math.pi), _way(rng) * math.radians(rng.uniform(350, 370)))
    tail = rng.uniform(0.2, 0.6) * r
    (x0, y0), (x1, y1) = pts[-2], pts[-1]
    d = math.hypot(x1 - x0, y1 - y0) or 1.0
    bend = rng.uniform(0.0, 0.6)  # the tail leaves the tangent outwards (away from the centre)
    ux, uy = (x1 - x0) / d, (y1 - y0) / d
    ox, oy = x1 / (math.hypot(x1, y1) or 1.0), y1 / (math.hypot(x1, y1) or 1.0)
    dx, dy = ux + bend * ox, uy + bend * oy
    dn = math.hypot(dx, dy)
    n = max(4, int(tail / 4))
    pts += [(x1 + dx / dn * tail * k / n, y1 + dy / dn * tail * k / n) for k in range(1, n + 1)]
    if rng.random() < 0.5:
        pts = pts[::-1]
    return Mark("tailed-circle", _placed(rng, pts), True)


def open_spiral_turn(seed: int) -> Mark:
    """A circle that does not close: it goes round 330-370 degrees while its radius eases by 10-25 % in or out, so its
    end passes 0.1-0.25 of the radius inside or outside its start (a spiral's one turn; a hand that drifts)."""
    rng = random.Random(f"open-spiral-turn:{seed}")
    r = rng.uniform(25, 200)
    sweep = math.radians(rng.uniform(330, 370))
    change = rng.choice((-1.0, 1.0)) * rng.uniform(0.1, 0.25)

    def easing(done: float) -> float:
        return 1.0 + change * done / sweep

    pts = _round(r, r * rng.uniform(0.8, 1.0), rng.uniform(0, 2 * math.pi), _way(rng) * sweep, easing)
    return Mark("open-spiral-turn", _placed(rng, pts), True)


def pointed_join(seed: int) -> Mark:
    """A circle whose ends meet at a point: the pen leaves its landing 15-45 degrees outside the circle's tangent and
    comes back as far outside it (the first and last 30-70 degrees of the round pulled out to a tip 8-20 % of the
    radius beyond the rim), a teardrop's cusp where the hand started and finished (hcira sinarest1608/Subject6's
    circle 5); 0-20 % flat."""
    rng = random.Random(f"pointed-join:{seed}")
    r = rng.uniform(25, 200)
    pull = rng.uniform(0.08, 0.2)
    reach = math.radians(rng.uniform(30, 70))
    sweep = 2 * math.pi

    def tipped(done: float) -> float:
        near = min(done, sweep - done)  # how far round from the join
        return 1.0 + pull * max(0.0, 1.0 - near / reach) ** 2

    pts = _round(r, r * rng.uniform(0.8, 1.0), rng.uniform(0, 2 * math.pi), _way(rng) * sweep, tipped)
    return Mark("pointed-join", _placed(rng, pts), True)


def flat_sided_circle(seed: int) -> Mark:
    """A circle one side of which is drawn nearly straight: 50-90 degrees of it flattened onto its chord (the hand
    sweeping across, a D or a loaf), the rest round, closing 345-380 degrees; 0-20 % flat."""
    rng = random.Random(f"flat-sided-circle:{seed}")
    r = rng.uniform(25, 200)
    half = math.radians(rng.uniform(25, 45))
    at = rng.uniform(0, 2 * math.pi)
    start = rng.uniform(0, 2 * math.pi)
    way = _way(rng)
    flatten = rng.uniform(0.7, 1.0)

    def flattened(done: float) -> float:
        off = (start + way * done - at + math.pi) % (2 * math.pi) - math.pi
        if abs(off) >= half:
            return 1.0
        onto_chord = math.cos(half) / math.cos(off)  # the chord's distance from the centre at that angle
        return 1.0 - flatten * (1.0 - onto_chord)

    pts = _round(r, r * rng.uniform(0.8, 1.0), start, way * _closing_sweep(rng), flattened)
    return Mark("flat-sided-circle", _placed(rng, pts), True)


def lopsided_long_oval(seed: int) -> Mark:
    """An oval 2.5-4.5 times as long as it is wide, 150-700 px long, as a hand draws a long one in one sweep (issue 25,
    session 26: the fourth group's pen ellipses, tutorboard captured-chromium): one end blunter than the other (the
    half width 10-30 % larger towards it, an egg laid flat), its long sides wandering by the 2nd to 4th harmonics round
    it (2-5 % of its half width each), closing 345-380 degrees. Its miss from any one ellipse is a few per cent of its
    length: measured along the ray from the centre, slantwise through its shoulders, twice what it is across."""
    rng = random.Random(f"lopsided-long-oval:{seed}")
    rx = rng.uniform(75, 350)
    ry = rx / rng.uniform(2.5, 4.5)
    egg = rng.uniform(0.1, 0.3) * rng.choice((-1.0, 1.0))
    waves = [(k, rng.uniform(0.02, 0.05), rng.uniform(0, 2 * math.pi)) for k in (2, 3, 4)]
    start, sweep = rng.uniform(0, 2 * math.pi), _way(rng) * _closing_sweep(rng)
    n = max(24, int(abs(math.degrees(sweep)) / 2))
    pts = []
    for i in range(n + 1):
        a = start + sweep * i / n
        wander = 1.0 + sum(size * math.sin(k * a + phase) for k, size, phase in waves)
        pts.append((rx * math.cos(a), ry * wander * (1.0 + egg * math.cos(a)) * math.sin(a)))
    return Mark("lopsided-long-oval", _placed(rng, pts), True)


def flicked_oval(seed: int) -> Mark:
    """An oval 16-260 px long, up to 2.2 times as long as wide, drawn 1.02-1.25 times round from anywhere on it either
    way and closed with a flick straight off the loop, bent 0-0.8 of a radian's worth outwards, of 0-1.2 of its
    half-length (a hand lifting fast: a whole note, a quick circle; issue 25, session 27, after session 26's
    `tail_runs_off` took such ovals for pigtails); drawn flick first half the time (a lead in from off the rim)."""
    rng = random.Random(f"flicked-oval:{seed}")
    rx = rng.uniform(8, 130)
    ry = rx / rng.uniform(1.0, 2.2)
    pts = _round(rx, ry, rng.uniform(0, 2 * math.pi), _way(rng) * 2 * math.pi * rng.uniform(1.02, 1.25))
    flick, bend = rng.uniform(0.0, 1.2) * rx, rng.uniform(0.0, 0.8)
    (x0, y0), (x1, y1) = pts[-2], pts[-1]
    d, r = math.hypot(x1 - x0, y1 - y0) or 1.0, math.hypot(x1, y1) or 1.0
    dx, dy = (x1 - x0) / d + bend * x1 / r, (y1 - y0) / d + bend * y1 / r
    dn = math.hypot(dx, dy)
    n = max(2, int(flick / 1.5))
    if flick > 1.0:
        pts += [(x1 + dx / dn * flick * k / n, y1 + dy / dn * flick * k / n) for k in range(1, n + 1)]
    if rng.random() < 0.5:
        pts = pts[::-1]
    return Mark("flicked-oval", _placed(rng, pts), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "small-circle": small_circle, "flat-oval": flat_oval, "wobbly-circle": wobbly_circle,
    "overtraced-circle": overtraced_circle, "tailed-circle": tailed_circle, "open-spiral-turn": open_spiral_turn,
    "pointed-join": pointed_join, "flat-sided-circle": flat_sided_circle, "lopsided-long-oval": lopsided_long_oval,
    "flicked-oval": flicked_oval}
"""Every family; each is read as a circle or an ellipse (`EXPECTED`)."""
