"""Benchmark: whether people's strokes read the same kind drawn the other way (points and times reversed).

Usage: .venv/bin/python benchmarks/bench_reversed.py SET [SET ...] [--fourth] [--by set|person] [--list]

A person may start a shape anywhere and go either way round; a stroke's reading should not hang on which. Every scored
stroke of each SET (`bench_generalisation.scored_rows`: one stroke, a mapped label; the held-back groups left out, the
fourth group's sets read alone with ``--fourth``) is recognised as drawn and reversed (`reversed_stroke`: its points in
reverse order, its times running forward from its start), with the shipped recogniser. Prints, per source (a set, or
``--by person`` a set's person), how many strokes read another kind reversed, how many of those hold a lift the device
missed (`pen_lifts.last_attempt`, as drawn or reversed: the stroke is read by its last attempt, and which attempt is
last is the time order's, meant to change reversed), and how many are right each way and both ways; with ``--list``
every stroke whose kind differs (set, person, file, label, kind as drawn -> reversed, which way is right, "lifted").
"""

from __future__ import annotations

import argparse
from collections import Counter
from pathlib import Path

from bench_generalisation import held_back_new, scored_rows
from stroke_sets import Row, read_sets, source_of

from physink_tui.scene.recognition import pen_lifts
from physink_tui.scene.recognition.recognize import recognize_stroke

Points = list[list[float]]


def reversed_stroke(points: Points, times: list[float] | None) -> tuple[Points, list[float] | None]:
    """A stroke drawn from its other end: its points in reverse, its times (if any) running forward from its start."""
    if times is None:
        return points[::-1], None
    end = times[-1]
    return points[::-1], [end - t for t in times[::-1]]


def stroke_of(row: Row) -> tuple[Points, list[float] | None]:
    """A row's single stroke as (points, times in seconds or None), as `bench_generalisation` passes it."""
    stroke = row["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    return [[float(v) for v in p[:2]] for p in stroke], times


def readings(row: Row) -> tuple[str, str]:
    """The kind a row's stroke reads as drawn and reversed."""
    points, times = stroke_of(row)
    return recognize_stroke(points, times).kind, recognize_stroke(*reversed_stroke(points, times)).kind


def lifted(row: Row) -> bool:
    """Whether a row's stroke is read by its last attempt (`pen_lifts.last_attempt`) as drawn or reversed."""
    points, times = stroke_of(row)
    return any(pen_lifts.last_attempt(p, t) is not None for p, t in ((points, times), reversed_stroke(points, times)))


def rows_of(paths: list[Path], fourth: bool) -> list[Row]:
    """The scored rows of the sets at ``paths`` (the fourth group's alone with ``fourth``), the held back left out."""
    kept, _ = scored_rows(read_sets(paths, "bench_reversed"), fourth=fourth)
    hidden = held_back_new(kept)
    return [r for r in kept if source_of(r, "person") not in hidden]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--fourth", action="store_true", help="score the fourth group's sets (alone)")
    ap.add_argument("--by", choices=("set", "person"), default="set")
    ap.add_argument("--list", action="store_true", help="name every stroke whose kind differs reversed")
    args = ap.parse_args()
    n, differs, lifts, fwd, rev, both = Counter(), Counter(), Counter(), Counter(), Counter(), Counter()
    listed = []
    for row in rows_of(args.sets, args.fourth):
        key = source_of(row, args.by)
        ahead, back = readings(row)
        n[key] += 1
        differs[key] += ahead != back
        fwd[key] += ahead in row["accepts"]
        rev[key] += back in row["accepts"]
        both[key] += ahead in row["accepts"] and back in row["accepts"]
        if ahead != back:
            lifts[key] += lifted(row)
            which = {(True, True): "both", (True, False): "as drawn", (False, True): "reversed"}.get(
                (ahead in row["accepts"], back in row["accepts"]), "neither")
            listed.append(f"- {source_of(row, 'person')} {row.get('file', '')} \"{row['label']}\": {ahead} -> {back}"
                          f" (right: {which}{', lifted' if lifted(row) else ''})")
    print("| source | strokes | kind differs reversed | of which lifted | right as drawn | right reversed | right both "
          "ways |\n|---|---:|---:|---:|---:|---:|---:|")
    for key in sorted(n):
        print(f"| {key} | {n[key]} | {differs[key]} | {lifts[key]} | {fwd[key]} | {rev[key]} | {both[key]} |")
    total = sum(n.values())
    right, back, alike = sum(fwd.values()), sum(rev.values()), sum(both.values())
    print(f"| all | {total} | {sum(differs.values())} | {sum(lifts.values())} | {right} ({100 * right / total:.2f} %) "
          f"| {back} ({100 * back / total:.2f} %) | {alike} ({100 * alike / total:.2f} %) |")
    if args.list and listed:
        print("\nKinds that differ reversed (person, file, label: as drawn -> reversed):\n" + "\n".join(listed))


if __name__ == "__main__":
    main()
