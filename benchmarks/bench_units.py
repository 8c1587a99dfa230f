"""Benchmark: the design sources' strokes stored in other units (scaled, scaled and rounded to a device's lattice, or
as continuous floats) read with the recogniser's default noise, beside the same strokes as drawn in pixels
(transformed strokes, not people).

Usage: .venv/bin/python benchmarks/bench_units.py SET [SET ...] [--every K] [--only NAME,...]
                                                  [--noise default|stated|auto] [--pens tuning|held-back]

Reads the sets as `bench_generalisation` does (`scored_rows`: the held-back groups stay out) and keeps one stroke in
``K`` (by a hash of its file and label, as `bench_device_stress` keeps them). Each transform (`TRANSFORMS`) stores
the stroke as a device or a recorder might: scaled by 0.002 to 50 as floats; the pixel's true position within it
(``dither``: uniform over the pixel, what rounding to whole pixels hid) as continuous millimetres; as fractions of a
1000-pixel screen rounded to 1/100 or to 4 decimals; as the integers of a tablet 20 (or 5) times finer than pixels.
Times stay in seconds. ``--noise default`` reads each with `recognize_stroke`'s default noise (a pixel, whatever the
units: what the library gives a caller who does not say, and what `physink recognize` gave before ``--noise auto``);
``--noise stated`` with the noise stated in the stroke's units (one pixel scaled, or the lattice's quantum where it is
coarser): what a caller who knows the device gets; ``--noise auto`` with ``noise=None`` (`units.stroke_noise`: judged
from the stroke; what `physink recognize` does without ``--noise``). Prints Markdown: % read right per set and
transform, and how many readings differ in kind from the stroke in pixels read alike. ``--pens`` reads instead the
closed shapes of `bench_closed_shapes` drawn by the pen models of `tests/penmodels` (careful, hurried, hurried through
a coarse device; continuous floats in canvas pixels) on its tuning (0-29) or held-back (1000-1029) seeds, stored as
`PEN_STORES` keep them, against their reading in pixels with the pen's stated noise (1 px, as a session gives it).
"""

from __future__ import annotations

import argparse
import sys
import zlib
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import numpy as np
from bench_generalisation import is_held_back_new, scored_rows
from stroke_sets import Row, read_sets, source_of

import physink_tui
from physink_tui.scene.recognition.recognize import recognize_stroke

Stored = tuple[np.ndarray, float]
"""The stroke's points in the stored units and one pixel's noise in those units (the noise a caller could state)."""
SCREEN = 1000.0
"""The screen's width in pixels for the transforms storing fractions of a screen (0..1)."""
MM_PER_PIXEL = 25.4 / 96


def _dither(pts: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Where in each whole pixel the pen was: uniform over the pixel (rounding to whole pixels hid it)."""
    return pts + rng.uniform(-0.5, 0.5, pts.shape)


def _scaled(factor: float) -> Callable[[np.ndarray, np.random.Generator], Stored]:
    return lambda pts, rng: (pts * factor, factor)


def _rounded(factor: float, quantum: float, dither: bool) -> Callable[[np.ndarray, np.random.Generator], Stored]:
    def store(pts: np.ndarray, rng: np.random.Generator) -> Stored:
        scaled = (_dither(pts, rng) if dither else pts) * factor
        return np.round(scaled / quantum) * quantum, max(factor, quantum)
    return store


def _continuous(factor: float) -> Callable[[np.ndarray, np.random.Generator], Stored]:
    return lambda pts, rng: (_dither(pts, rng) * factor, factor)


TRANSFORMS: dict[str, Callable[[np.ndarray, np.random.Generator], Stored]] = {
    "pixels": _scaled(1.0),
    "x0.002": _scaled(0.002),
    "x0.02": _scaled(0.02),
    "x0.1": _scaled(0.1),
    "x10": _scaled(10.0),
    "x50": _scaled(50.0),
    "pixels dithered": _continuous(1.0),
    "mm floats": _continuous(MM_PER_PIXEL),
    "screen 0..1 to 1/100": _rounded(1 / SCREEN, 0.01, dither=True),
    "screen 0..1 to 4 decimals": _rounded(1 / SCREEN, 1e-4, dither=True),
    "tablet x20 integers": _rounded(20.0, 1.0, dither=True),
    "tablet x5 integers": _rounded(5.0, 1.0, dither=True),
}
"""How a stroke drawn in whole pixels is stored in other units (see the module docstring)."""


PEN_STORES: dict[str, Callable[[np.ndarray], Stored]] = {
    "pixels, whole": lambda pts: (np.round(pts), 1.0),
    "canvas fractions (0..1 of 1600 px), floats": lambda pts: (pts / 1600, 1 / 1600),
    "canvas fractions to 4 decimals": lambda pts: (np.round(pts / 1600, 4), 1 / 1600),
    "millimetres, floats": lambda pts: (pts * MM_PER_PIXEL, MM_PER_PIXEL),
    "tablet x20 integers": lambda pts: (np.round(pts * 20), 20.0),
}
"""How a pen model's stroke (continuous canvas pixels) is stored in other units, with one pixel's noise in them."""


def pen_models(seeds: range, how: str) -> None:
    """Print, per pen and store, how many of the pen models' closed shapes read as in pixels and are right."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    from bench_closed_shapes import FAMILIES, PENS, class_right, shape

    same: Counter[tuple[str, str]] = Counter()
    right: Counter[tuple[str, str]] = Counter()
    count: Counter[str] = Counter()
    for family in FAMILIES:
        for pen, draw in PENS.items():
            for seed in seeds:
                drawn = np.array(draw(shape(family, seed), seed))
                pts, times = drawn[:, :2], drawn[:, 2].tolist()
                in_pixels = recognize_stroke(pts.tolist(), times, noise=1.0).kind
                count[pen] += 1
                right[(pen, "pixels, as drawn")] += class_right(family, in_pixels)
                for name, store in PEN_STORES.items():
                    stored, stated = store(pts)
                    noise = {"stated": stated, "auto": None}.get(how, 1.0)
                    kind = recognize_stroke(stored.tolist(), times, noise=noise).kind
                    same[(pen, name)] += kind == in_pixels
                    right[(pen, name)] += class_right(family, kind)
    print(f"## Pen models' closed shapes in other units (noise: {how}; seeds {seeds.start}-{seeds.stop - 1})\n")
    print("| store | " + " | ".join(f"{p} ({count[p]}): right / as in pixels" for p in PENS) + " |")
    print("|---|" + "---:|" * len(PENS))
    print("| pixels, as drawn (noise 1) | " + " | ".join(f"{right[(p, 'pixels, as drawn')]} / -" for p in PENS) + " |")
    for name in PEN_STORES:
        print(f"| {name} | " + " | ".join(f"{right[(p, name)]} / {same[(p, name)]}" for p in PENS) + " |")


def rows(paths: list[Path], every: int) -> list[Row]:
    kept, _ = scored_rows(read_sets(paths, "bench_units"))
    return [r for r in kept if not is_held_back_new(source_of(r, "person"))
            and zlib.crc32(f"{r['file']}|{r['label']}".encode()) % every == 0]


def read(row: Row, name: str, how: str) -> str | None:
    stroke = row["strokes"][0]
    pts = np.array([p[:2] for p in stroke], dtype=float)
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    rng = np.random.default_rng(zlib.crc32(f"{row['file']}|{row['label']}|{name}".encode()))
    stored, stated = TRANSFORMS[name](pts, rng)
    if how == "stated":
        return recognize_stroke(stored.tolist(), times, noise=stated).kind
    if how == "auto":
        return recognize_stroke(stored.tolist(), times, noise=None).kind
    return recognize_stroke(stored.tolist(), times).kind


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="*", help=".jsonl files or set folders (never the held-back groups')")
    ap.add_argument("--every", type=int, default=1, help="one stroke in K (by a hash of its file and label)")
    ap.add_argument("--only", default="", help="comma-separated transform names (default: all)")
    ap.add_argument("--noise", choices=("default", "stated", "auto"), default="default")
    ap.add_argument("--pens", choices=("tuning", "held-back"), help="read the pen models' closed shapes instead")
    args = ap.parse_args()
    if args.pens:
        pen_models(range(0, 30) if args.pens == "tuning" else range(1000, 1030), args.noise)
        return
    names = [n.strip() for n in args.only.split(",") if n.strip()] or list(TRANSFORMS)
    unknown = [n for n in names if n not in TRANSFORMS]
    if unknown:
        raise SystemExit(f"bench_units: no transform {unknown}; known: {', '.join(TRANSFORMS)}")
    kept = rows(args.sets, args.every)
    sets = sorted({str(r["source"]) for r in kept})
    right: dict[str, Counter[str]] = {n: Counter() for n in names}
    differ: Counter[str] = Counter()
    count = Counter(str(r["source"]) for r in kept)
    for r in kept:
        drawn = read(r, "pixels", args.noise) if "pixels" in names else None
        for n in names:
            kind = drawn if n == "pixels" else read(r, n, args.noise)
            right[n][str(r["source"])] += kind in r["accepts"]
            differ[n] += drawn is not None and kind != drawn
    print(f"## Strokes in other units ({physink_tui.__file__}; noise: {args.noise}; one stroke in {args.every})\n")
    print("| transform | " + " | ".join(f"{s} ({count[s]})" for s in sets) + " | all | differ from pixels |")
    print("|---|" + "---:|" * (len(sets) + 2))
    for n in names:
        cells = [f"{100 * right[n][s] / count[s]:.1f}" for s in sets]
        total = sum(right[n].values())
        print(f"| {n} | " + " | ".join(cells) + f" | {100 * total / len(kept):.2f} | "
              + (f"{differ[n]} |" if "pixels" in names else "- |"))
    sys.stdout.flush()


if __name__ == "__main__":
    main()
