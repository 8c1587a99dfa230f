"""Circles and ovals as gesture sets have them drawn (issue 25, session 27: a held set's counter-clockwise circles and a
music set's whole notes read as other things): either way round, started anywhere, closed, left open by 5-30 % of the
way or run on by up to a quarter turn, 20-400 px, 1-2.5 times as long as wide at any tilt, with or without a small
hook where the pen lifts; in canvas pixels, seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the
virtual pen, and the devices of `benchmarks/bench_circle_gestures.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point

EXPECTED = ("circle", "ellipse")
"""What every family is read as (benchmarks/label_kinds.tsv: a circle gesture and a whole note are round)."""


def _sweep(rng: random.Random, ending: str) -> float:
    """How far round (radians, unsigned) a gesture of ``ending`` goes: ``closed`` 345-380 degrees, ``open`` short of
    its start by 5-30 % of the way round, ``over`` past it by up to a quarter turn (380-450 degrees)."""
    if ending == "open":
        return 2 * math.pi * (1.0 - rng.uniform(0.05, 0.30))
    if ending == "over":
        return math.radians(rng.uniform(380, 450))
    return math.radians(rng.uniform(345, 380))


def _hook(rng: random.Random, pts: list[Point], size: float, way: float) -> list[Point]:
    """A small hook where the pen lifts: the last 4-10 % of the size (its across) turned 70-150 degrees off the
    heading, inwards or outwards, over a few points (a flick as the hand leaves the paper)."""
    (x0, y0), (x1, y1) = pts[-2], pts[-1]
    heading = math.atan2(y1 - y0, x1 - x0)
    turn = math.radians(rng.uniform(70, 150)) * way * rng.choice((1.0, -1.0))
    length = rng.uniform(0.04, 0.10) * size
    out = list(pts)
    n = 5
    for k in range(1, n + 1):
        h = heading + turn * k / n
        x, y = out[-1]
        out.append((x + length / n * math.cos(h), y + length / n * math.sin(h)))
    return out


def gesture(rng: random.Random, family: str, across: tuple[float, float], aspect: tuple[float, float],
            ending: str, hooked: bool) -> Mark:
    """An ellipse ``across`` px long (its long axis; range), ``aspect`` times as long as wide (range), tilted at random,
    started at a random angle, drawn either way round (the same seed mirrored is the other way: `mirrored`) to its
    ``ending``, with a hook at the lift where ``hooked``; points every 2 degrees (at least 24)."""
    long_axis = rng.uniform(*across)
    rx = long_axis / 2
    ry = rx / rng.uniform(*aspect)
    start = rng.uniform(0, 2 * math.pi)
    way = rng.choice((-1.0, 1.0))
    sweep = _sweep(rng, ending)
    tilt = rng.uniform(0, math.pi)
    n = max(24, int(math.degrees(sweep) / 2))
    c, s = math.cos(tilt), math.sin(tilt)
    pts = []
    for k in range(n + 1):
        a = start + way * sweep * k / n
        x, y = rx * math.cos(a), ry * math.sin(a)
        pts.append((x * c - y * s, x * s + y * c))
    if hooked:
        pts = _hook(rng, pts, long_axis, way)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return Mark(family, tuple((cx + x, cy + y) for x, y in pts), True)


def _family(name: str, across: tuple[float, float], aspect: tuple[float, float], ending: str,
            hooked: bool) -> Callable[[int], Mark]:
    def make(seed: int) -> Mark:
        return gesture(random.Random(f"{name}:{seed}"), name, across, aspect, ending, hooked)
    make.__doc__ = f"A {name}: {across[0]:g}-{across[1]:g} px, {aspect[0]:g}-{aspect[1]:g} times as long as wide, " \
                   f"{ending}{', hooked at the lift' if hooked else ''}."
    return make


CIRCLE, OVAL, NOTE = (40.0, 400.0), (60.0, 400.0), (20.0, 40.0)
ROUND, LONG, NOTE_ASPECT = (1.0, 1.25), (1.25, 2.5), (1.0, 2.0)
FAMILIES: dict[str, Callable[[int], Mark]] = {
    f"{what}-{ending}{'-hooked' if hooked else ''}": _family(
        f"{what}-{ending}{'-hooked' if hooked else ''}", size, aspect, ending, hooked)
    for what, size, aspect in (("circle", CIRCLE, ROUND), ("oval", OVAL, LONG), ("whole-note", NOTE, NOTE_ASPECT))
    for ending in ("closed", "open", "over") for hooked in (False, True)}
"""Every family: circles (40-400 px, up to 1.25 times as long as wide), ovals (60-400 px, 1.25-2.5) and whole notes
(20-40 px, up to 2), each closed, left open or run on, with and without a hook at the lift; each read round
(`EXPECTED`)."""


def mirrored(points: list[tuple[float, float, float]], height: float = 1000.0) -> list[tuple[float, float, float]]:
    """A drawn stroke ``(x, y, t)`` mirrored top to bottom on the canvas: the same stroke drawn the other way round."""
    return [(x, height - y, t) for x, y, t in points]
