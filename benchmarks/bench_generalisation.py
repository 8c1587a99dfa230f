"""Benchmark: recognition on sources it was not tuned on — leave one source out, one row per source, one column per
label, with the label -> kind table fixed before scoring (benchmarks/label_kinds.tsv).

Usage: .venv/bin/python benchmarks/bench_generalisation.py SET [SET ...] [--by person|device|set] [--quick]

Each SET is a .jsonl file or a folder in a form `stroke_sets` reads (the $1 logs, the MMG set, the Drawn Shapes
set); the sets stay where they are. A source is a person of a set (``--by person``, the default; a set that names
no person is one source), a device, or a whole set. For each source held out, the ranking's weights
(`recognize.Weights`: complexity cost, relative noise floor, how round a polyline's corner may be) are chosen on a
grid by their pooled accuracy on every other source only, then the held-out source is scored with them: that is
the held-out figure. The shipped defaults are scored beside it, but they were chosen looking at the three people
of ../shared/data, so for those three the defaults column is not a held-out figure. Only single-stroke samples of
labels the table maps are scored; the rest are counted. Prints Markdown, and the issue 25 targets met or not
(every source >= 98.6 %, every label with >= 50 strokes in a source >= 97 % there).
"""

from __future__ import annotations

import argparse
import hashlib
import math
import sys
from collections import Counter, defaultdict
from pathlib import Path

import numpy as np
from bench_recognition import machine, table
from label_kinds import UNMAPPED, read_table
from stroke_sets import Row, read_set, source_of

from physink_tui.scene.recognition.recognize import DEFAULT_WEIGHTS, Weights, recognize_stroke

GRID = [Weights(c, r, k) for c in (2.0, 2.5, 3.0) for r in (0.0, 0.003) for k in (0.6, 0.8, 1.2, math.inf)]
QUICK_GRID = [DEFAULT_WEIGHTS, Weights(2.0, 0.003, 0.8), Weights(3.0, 0.003, 0.8), Weights(2.5, 0.0, 0.8)]
HELD_BACK_SEED = "physink-heldback:"
HELD_BACK_COUNT = 4
"""The students held back while the recogniser was changed for them (issue 25): the `HELD_BACK_COUNT` whose
sha256 of `HELD_BACK_SEED` + name is lowest, picked before any stroke was looked at; nobody looked at or drew their
strokes while designing. Their pooled figure is printed apart."""
SOURCE_FLOOR = 98.6
LABEL_FLOOR = 97.0
LABEL_MIN_STROKES = 50


def scored_rows(rows: list[Row]) -> tuple[list[Row], Counter]:
    """The rows scored (one stroke, a mapped label) and, for the rest, why not (counted)."""
    labels = read_table()
    kept, left = [], Counter()
    for row in rows:
        cls = labels.label_class(row["source"], row["label"])
        if cls is None:
            raise SystemExit(f"{row.get('file')}: label {row['label']!r} of set {row['source']!r} is not in "
                             "benchmarks/label_kinds.tsv: add it there before scoring")
        if cls == UNMAPPED:
            left[f"{row['source']} {row['label']}: no kind stands for it"] += 1
        elif len(row["strokes"]) != 1:
            left[f"{row['source']} {row['label']}: drawn in {len(row['strokes'])} strokes"] += 1
        else:
            kept.append({**row, "accepts": labels.accepts(row["source"], row["label"])})
    return kept, left


def held_back(rows: list[Row]) -> set[str]:
    """The sources (``itt:name``) of the held-back students among ``rows``."""
    names = sorted({str(r["subject"]) for r in rows if r["source"] == "itt" and r.get("subject")},
                   key=lambda n: hashlib.sha256((HELD_BACK_SEED + n).encode()).hexdigest())
    return {f"itt:{n}" for n in names[:HELD_BACK_COUNT]}


def right_answers(rows: list[Row], weights: Weights) -> np.ndarray:
    out = np.zeros(len(rows), dtype=bool)
    for i, row in enumerate(rows):
        stroke = row["strokes"][0]
        times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
        out[i] = recognize_stroke([p[:2] for p in stroke], times, weights=weights).kind in row["accepts"]
    return out


def closeness(w: Weights) -> float:
    return -(abs(w.complexity - DEFAULT_WEIGHTS.complexity) + abs(w.relative_noise - DEFAULT_WEIGHTS.relative_noise)
             + abs(min(w.round_corner, 9.0) - DEFAULT_WEIGHTS.round_corner))


def leave_one_source_out(rows: list[Row], by: str, grid: list[Weights]) -> None:
    sources = np.array([source_of(r, by) for r in rows])
    names = sorted(set(sources))
    if len(names) < 2:
        raise SystemExit(f"only one source ({names}): leave-one-source-out needs two or more")
    right = {w: right_answers(rows, w) for w in grid}
    labels = sorted({r["label"] for r in rows})
    label_of = np.array([r["label"] for r in rows])
    table_rows, misses, pooled = [], [], Counter()
    for held in names:
        others, mine = sources != held, sources == held
        chosen = max(grid, key=lambda w: (right[w][others].mean(), closeness(w)))
        got = right[chosen]
        pooled["right"] += int(got[mine].sum())
        pooled["total"] += int(mine.sum())
        if by == "person" and held in held_back(rows):
            pooled["held_right"] += int(got[mine].sum())
            pooled["held"] += int(mine.sum())
        elif held.startswith("itt:"):
            pooled["itt_right"] += int(got[mine].sum())
            pooled["itt"] += int(mine.sum())
        cells = []
        for label in labels:
            sel = mine & (label_of == label)
            n = int(sel.sum())
            if n == 0:
                cells.append("")
                continue
            acc = 100.0 * got[sel].mean()
            cells.append(f"{acc:.1f} ({n})")
            if n >= LABEL_MIN_STROKES and acc < LABEL_FLOOR:
                misses.append(f"{held} {label}: {acc:.1f} % of {n} < {LABEL_FLOOR} %")
        acc = 100.0 * got[mine].mean()
        if acc < SOURCE_FLOOR:
            misses.append(f"{held}: {acc:.2f} % < {SOURCE_FLOOR} %")
        table_rows.append([held, int(mine.sum()), f"{acc:.2f}", f"{100.0 * right[DEFAULT_WEIGHTS][mine].mean():.2f}"
                           if DEFAULT_WEIGHTS in right else "", _weights(chosen), *cells])
    print("### Leave one source out\n")
    print(table(["held-out source", "strokes", "held-out %", "defaults %", "weights chosen on the others",
                 *labels], table_rows) + "\n")
    print(f"Pooled over the held-out folds: {pooled['right']}/{pooled['total']} = "
          f"{100.0 * pooled['right'] / pooled['total']:.2f} %. Cells: % right (strokes).\n")
    group = held_back(rows) if by == "person" else set()
    if group:
        print(f"Held back while designing ({', '.join(sorted(group))}): {pooled['held_right']}/{pooled['held']} = "
              f"{100.0 * pooled['held_right'] / max(pooled['held'], 1):.2f} %; the other students: "
              f"{pooled['itt_right']}/{pooled['itt']} = {100.0 * pooled['itt_right'] / max(pooled['itt'], 1):.2f} %.\n")
    print("Issue 25 targets (every source >= 98.6 %; every label with >= 50 strokes in a source >= 97 %): "
          + ("met" if not misses else "not met: " + "; ".join(misses)) + "\n")


def _weights(w: Weights) -> str:
    return f"{w.complexity:g}, {w.relative_noise:g}, {w.round_corner:g}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+", help=".jsonl files or set folders")
    ap.add_argument("--by", choices=("person", "device", "set"), default="person")
    ap.add_argument("--quick", action="store_true", help="a 4-point grid instead of 24")
    args = ap.parse_args()
    rows: list[Row] = []
    for path in args.sets:
        try:
            rows += read_set(path)
        except (OSError, ValueError) as exc:
            raise SystemExit(f"bench_generalisation: {exc}") from None
    kept, left = scored_rows(rows)
    print(f"## Generalisation ({machine()})\n")
    sets = Counter(r["source"] for r in kept)
    print("Scored: " + ", ".join(f"{n} strokes of {s}" for s, n in sorted(sets.items())) + ".")
    if left:
        by_set: dict[str, int] = defaultdict(int)
        for why, n in left.items():
            by_set[why] += n
        print("Not scored: " + "; ".join(f"{n} ({why})" for why, n in sorted(by_set.items())) + ".")
    print()
    leave_one_source_out(kept, args.by, QUICK_GRID if args.quick else GRID)


if __name__ == "__main__":
    sys.exit(main())
