"""Which of the learned ranker's features lean on the way a stroke was drawn: measured on people's strokes reversed.

Usage: .venv/bin/python benchmarks/ranker_leaning.py SET [SET ...] [--every K]

Every K-th scored stroke of the SETs (`bench_generalisation.scored_rows`, the held-back groups left out as
`bench_reversed` leaves them) is described by `ranker.features` as drawn and drawn from its other end
(`bench_reversed.reversed_stroke`: points reversed, times running forward from the start). Per feature: the share of
strokes whose value moves by more than `TOLERANCE` of the feature's spread (a 0/1 feature: flips), and the mean move
over the spread. `LEANING` holds the features that move on more than `LEANING_SHARE` of the strokes measured so
(session 38); `train_ranker.py --drop-leaning` leaves them out of the fit, so that a refit scores a stroke nearly
alike from either end but for the rules' own answer (docs/BENCHMARKS.md, "The ranker refitted with unasked strokes
weighed less, and on features alike from either end").
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from bench_recognition import table
from bench_reversed import reversed_stroke, rows_of, stroke_of

from physink_tui.scene.recognition import ranker

TOLERANCE = 0.05
"""A feature's value moves when reversed by more than this share of its standard deviation over the strokes measured."""
LEANING_SHARE = 0.005
"""A feature leans on the stroke's direction when it moves on more than this share of the strokes measured."""
LEANING = ("closure", "max_roundness", "mean_roundness", "max_bend", "bent_polyline", "corner_slowdown")
"""The features that lean on direction (`LEANING_SHARE`), as this script measured them on every 4th design stroke
(session 38; the table: docs/BENCHMARKS.md)."""


def moves(rows: list) -> tuple[np.ndarray, np.ndarray]:
    """Each row's features as drawn and reversed (two arrays, one row a stroke)."""
    ahead, back = [], []
    for row in rows:
        points, times = stroke_of(row)
        ahead.append(ranker.features(points, times))
        back.append(ranker.features(*reversed_stroke(points, times)))
    return np.array(ahead), np.array(back)


def leaning(ahead: np.ndarray, back: np.ndarray) -> list[tuple[str, float, float]]:
    """Per feature: its name, the share of strokes on which it moves (`TOLERANCE`), the mean move over its spread."""
    spread = np.maximum(np.concatenate([ahead, back]).std(axis=0), 1e-9)
    move = np.abs(ahead - back) / spread
    return [(name, float((move[:, j] > TOLERANCE).mean()), float(move[:, j].mean()))
            for j, name in enumerate(ranker.FEATURES)]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--every", type=int, default=4, help="measure every K-th scored stroke")
    args = ap.parse_args()
    rows = rows_of(args.sets, False)[::args.every]
    found = leaning(*moves(rows))
    print(f"{len(rows)} strokes (every {args.every}th scored design stroke), features as drawn and reversed:\n")
    print(table(["feature", "moves on (share)", "mean move / spread", "leans"],
                [[n, f"{s:.3f}", f"{m:.4f}", "yes" if s > LEANING_SHARE else ""] for n, s, m in found]))
    measured = tuple(n for n, s, _ in found if s > LEANING_SHARE)
    print(f"\nleaning: {','.join(measured)}" + ("" if measured == LEANING else f" (LEANING says {','.join(LEANING)})"))


if __name__ == "__main__":
    main()
