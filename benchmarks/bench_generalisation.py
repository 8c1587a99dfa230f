"""Benchmark: recognition on sources it was not tuned on — leave one source out, one row per source, one column per
label, with the label -> kind table fixed before scoring (benchmarks/label_kinds.tsv).

Usage: .venv/bin/python benchmarks/bench_generalisation.py SET [SET ...] [--by person|device|set] [--quick]
       [--defaults] [--heldback] [--third | --fourth | --fifth | --sign] [--contradictions] [--rules]

Each SET is a .jsonl file or a folder in a form `stroke_sets` reads (the $1 logs, the MMG set, the Drawn Shapes set);
the sets stay where they are. A source is a person of a set (``--by person``, the default; a set that names no person is
one source), a device, or a whole set. For each source held out, the ranking's weights (`recognize.Weights`: complexity
cost, relative noise floor, how round a polyline's corner may be) are chosen on a grid by their pooled accuracy on every
other source only, then the held-out source is scored with them: that is the held-out figure. The shipped defaults are
scored beside it, but they were chosen looking at the three people of ../shared/data, so for those three the defaults
column is not a held-out figure. Only single-stroke samples of labels the table maps are scored; the rest are counted.
Sources found after the first 19 whose name draws them into the second held-back group (`in_second_group`) were left out
unless ``--heldback`` was given, until the group was opened as design material (`SECOND_GROUP_OPEN`, 2026-12-04). The
sets of the third search (`THIRD_SETS`: the third held-back group) are left out of every run but ``--third``, which
scores them alone (`scored_rows`); the sets of the fourth search (`FOURTH_SETS`) likewise, but for ``--fourth``, and
those of the fifth (`FIFTH_SETS`) for ``--fifth``, and its set ``sign``, opened (`SIGN_SETS`), for ``--sign``. Prints
Markdown, and the issue 25 targets met or not (every source >= 98.6 %, every label with >= 50 strokes in a source
>= 97 % there). With ``--contradictions`` it also prints, beside the raw figure (which stays the headline: no stroke is
dropped from it), how many strokes of each source the committed contradiction tests
(`label_contradictions.CONTRADICTIONS`) convict of a label their geometry contradicts, and the targets re-stated on the
strokes whose label agrees with their geometry.
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
from stroke_sets import Row, read_sets, source_of

from physink_tui.scene.recognition.recognize import DEFAULT_WEIGHTS, Weights, recognize_stroke

GRID = [Weights(c, r, k) for c in (2.0, 2.5, 3.0) for r in (0.0, 0.003) for k in (0.6, 0.8, 1.2, math.inf)]
QUICK_GRID = [DEFAULT_WEIGHTS, Weights(2.0, 0.003, 0.8), Weights(3.0, 0.003, 0.8), Weights(2.5, 0.0, 0.8)]
HELD_BACK_SEED = "physink-heldback:"
HELD_BACK_COUNT = 4
"""The students held back while the recogniser was changed for them (issue 25): the `HELD_BACK_COUNT` whose
sha256 of `HELD_BACK_SEED` + name is lowest, picked before any stroke was looked at; nobody looked at or drew their
strokes while designing. Their pooled figure is printed apart."""
FIRST_STUDENTS = ("Alphazerfall", "Bam33751", "Coldjack007", "DerD4n", "Ferdi-FM", "GixD42", "JonasBachmeier-UNI",
                  "LeS-crypto", "LucaEscher", "MaximilianKilger", "lvht1203", "marcel-moz", "martinarobyculasso",
                  "michaelpickl", "realdegrees", "uniUbungsAccount")
FIRST_SOURCES = frozenset({"dollar1:s02", "dollar1:s03", "dollar1:s04", *(f"itt:{n}" for n in FIRST_STUDENTS)})
"""The 19 sources scored before the second search for public sets (issue 25, 2026-12-03): the first held-back group
is drawn among these students only, so sources found later do not change it."""
HELD_BACK_SEED_NEW = "physink-heldback-2:"
"""Sources found after `FIRST_SOURCES` (the second search, issue 25): one is held back when the sha256 of
`HELD_BACK_SEED_NEW` + its source name (``set:person``, or the set where it names none) is even. Fixed before any
stroke of theirs was looked at; their strokes are never listed, drawn or looked at one by one; they are left out of
every run unless asked for (``--heldback``), then scored pooled and per source, once."""
THIRD_SETS = frozenset({"hcira3", "fc"})
"""The sets found by the third search for public sets (issue 25, 2026-12-03 from 22:30 UTC; `benchmarks/SOURCES.md`,
"The third search"): the third held-back group, held back whole, by set name, fixed before any stroke of theirs was
read. `scored_rows` leaves them out of every run (so `train_ranker.py` never fits on them, `label_contradictions` never
reads them) unless asked for their group alone (``--third``): the lead scores them once, at the end of a session."""
FOURTH_SETS = frozenset({"quickdraw", "tutorboard"})
"""The sets found by the fourth search for public sets (issue 25, 2026-12-04; `benchmarks/SOURCES.md`, "The fourth
search"): the fourth held-back group, held back whole, by set name, fixed (with their label -> kind rows, 1987277)
before any stroke of theirs was read, to be the clean measure once the third group is spent. `scored_rows` leaves them
out of every run (the default run, ``--heldback``, ``--third``, `train_ranker.py` even with ``--write``,
`label_contradictions`, `compare_readings`, `profile_recognition`) unless asked for their group alone (``--fourth``).
Opened as design material in session 19 (2026-12-04; docs/BENCHMARKS.md, "Tenth pass"): its strokes have been read
and plotted since, so its figure is no longer a held-out one; it is still scored alone, by ``--fourth``."""
FIFTH_SETS = frozenset({"lowvision", "eds", "mmgplus", "homus", "laviola", "nicicon"})
"""The sets found by the fifth search for public sets (issue 25, 2026-12-04; `benchmarks/SOURCES.md`, "The fifth
search": public 2D sets as `nmagrofuoco/Gester` republishes them): the fifth held-back group, held back whole, by set
name, fixed with their label -> kind rows (908dd97) before any stroke of theirs was read, to be the clean measure once
the third and fourth groups are spent. Left out of every run as `FOURTH_SETS` is (and of ``--third``, ``--fourth``)
unless asked for alone (``--fifth``): the lead scores them once, at the end of a session. The search's seventh set,
``sign``, was taken out of the group and opened on 2026-12-07 (`SIGN_SETS`)."""
SIGN_SETS = frozenset({"sign"})
"""The fifth search's largest set (21,450 scored strokes of 31,243; `benchmarks/SOURCES.md`), opened as design
material in session 36 (2026-12-07) after it was scored held back at the end of five sessions without being looked at
(18,960/21,450 = 88.39 % at 02d2055; docs/BENCHMARKS.md, "Twenty-seventh pass"): its per-set figure was the lowest
of the fifth group, and the clean measure stays the rest of the fifth group and the third. Its strokes are read,
plotted and designed on since; it is still scored alone, by ``--sign``, and no longer a held-out figure."""
GROUP_SETS = {"third": THIRD_SETS, "fourth": FOURTH_SETS, "fifth": FIFTH_SETS, "sign": SIGN_SETS}
"""The groups of whole sets, by name: each is scored alone, by its flag (``--third``, ``--fourth``, ``--fifth``,
``--sign``), and by no other run; the fourth and ``sign`` are opened (`OPENED_GROUPS`), the others held back."""
OPENED_GROUPS = frozenset({"fourth", "sign"})
"""The groups of whole sets opened as design material: their figures are printed apart, and not as held-out ones."""
SECOND_GROUP_OPEN = True
"""The second held-back group was scored on merged code twice without being looked at (issue 25: 97.56 % at the end
of session 13, 97.78 % at the end of session 14, docs/BENCHMARKS.md) and was opened on 2026-12-04, once the third
group (`THIRD_SETS`) could take its place as the clean measure: from then on its sources are design sources, read,
looked at and fitted on by every script (`is_held_back_new` is false for them; `in_second_group` still names them,
so the runs print their pooled figure apart). `label_contradictions` still leaves them out: its control rates were
counted without them."""
SOURCE_FLOOR = 98.6
LABEL_FLOOR = 97.0
LABEL_MIN_STROKES = 50


def in_third_group(row: Row) -> bool:
    """Whether a row is of a set found by the third search (`THIRD_SETS`), by its set's name alone."""
    return row["source"] in THIRD_SETS


def in_fourth_group(row: Row) -> bool:
    """Whether a row is of a set found by the fourth search (`FOURTH_SETS`), by its set's name alone."""
    return row["source"] in FOURTH_SETS


def in_fifth_group(row: Row) -> bool:
    """Whether a row is of a set found by the fifth search (`FIFTH_SETS`), by its set's name alone."""
    return row["source"] in FIFTH_SETS


def held_back_set(set_name: str) -> str | None:
    """Which held-back group of whole sets a set is in (``third``, ``fourth``, ``fifth``: `GROUP_SETS`), by its name;
    None for the others."""
    return next((group for group, sets in GROUP_SETS.items() if set_name in sets), None)


def scored_rows(rows: list[Row], third: bool = False, fourth: bool = False,
                fifth: bool = False, sign: bool = False) -> tuple[list[Row], Counter]:
    """The rows scored (one stroke, a mapped label) and, for the rest, why not (counted). The held-back groups of
    whole sets (`THIRD_SETS`, `FOURTH_SETS`, `FIFTH_SETS`, `SIGN_SETS`) are left out, counted, unless one of ``third``,
    ``fourth``, ``fifth``, ``sign`` asks for it: then that group alone is scored and every other row left out.

    Raises:
        SystemExit: more than one group asked for (each group is scored alone).
    """
    asked_for = [group for group, flag in (("third", third), ("fourth", fourth), ("fifth", fifth), ("sign", sign))
                 if flag]
    if len(asked_for) > 1:
        raise SystemExit(" and ".join(f"--{g}" for g in asked_for) + ": each held-back group is scored alone, once")
    asked = asked_for[0] if asked_for else None
    labels = read_table()
    kept, left = [], Counter()
    for row in rows:
        group = held_back_set(row["source"])
        if group != asked:
            left[f"of the {group} held-back group (`{group.upper()}_SETS`; --{group} scores it alone)" if group
                 else f"not of the {asked} held-back group (--{asked} scores it alone)"] += 1
            continue
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
    """The sources (``itt:name``) of the first held-back group among ``rows`` (drawn among `FIRST_STUDENTS`)."""
    names = sorted({str(r["subject"]) for r in rows if r["source"] == "itt" and r.get("subject") in FIRST_STUDENTS},
                   key=lambda n: hashlib.sha256((HELD_BACK_SEED + n).encode()).hexdigest())
    return {f"itt:{n}" for n in names[:HELD_BACK_COUNT]}


def in_second_group(source: str) -> bool:
    """Whether a source found after `FIRST_SOURCES` was drawn into the second group (`HELD_BACK_SEED_NEW`); by its
    name alone, whether or not the group is still held back (`SECOND_GROUP_OPEN`)."""
    if held_back_set(source.split(":", 1)[0]):  # the third to fifth searches' sets are groups of their own
        return False
    return source not in FIRST_SOURCES and int(hashlib.sha256((HELD_BACK_SEED_NEW + source).encode()).hexdigest(),
                                                16) % 2 == 0


def second_group(rows: list[Row]) -> set[str]:
    """The sources (``set:person``) of the second group among ``rows``, held back or opened."""
    return {s for s in {source_of(r, "person") for r in rows} if in_second_group(s)}


def is_held_back_new(source: str) -> bool:
    """Whether a source is left out of runs as the second held-back group: never since it was opened
    (`SECOND_GROUP_OPEN`)."""
    return in_second_group(source) and not SECOND_GROUP_OPEN


def held_back_new(rows: list[Row]) -> set[str]:
    """The sources (``set:person``) left out of runs as the second held-back group among ``rows``."""
    return {s for s in second_group(rows) if is_held_back_new(s)}


def group_of(source: str, first_group: set[str]) -> str:
    """Which group a person's source is pooled in: the first 19's design part or held-back part, the sources found
    by the second search, design or held back, or the third, fourth or fifth held-back group."""
    group = held_back_set(source.split(":", 1)[0])
    if group:
        return f"{group} held back"
    if source in FIRST_SOURCES:
        return "first held back" if source in first_group else "first design"
    return "new held back" if in_second_group(source) else "new design"


def right_answers(rows: list[Row], weights: Weights, learned: bool = True) -> np.ndarray:
    """Which rows are read right, with the learned ranker (the shipped recogniser) or by the rules alone."""
    out = np.zeros(len(rows), dtype=bool)
    for i, row in enumerate(rows):
        stroke = row["strokes"][0]
        times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
        out[i] = recognize_stroke([p[:2] for p in stroke], times, weights=weights,
                                  learned=learned).kind in row["accepts"]
    return out


def closeness(w: Weights) -> float:
    return -(abs(w.complexity - DEFAULT_WEIGHTS.complexity) + abs(w.relative_noise - DEFAULT_WEIGHTS.relative_noise)
             + abs(min(w.round_corner, 9.0) - DEFAULT_WEIGHTS.round_corner))


def leave_one_source_out(rows: list[Row], by: str, grid: list[Weights], contradicted: np.ndarray | None = None,
                         learned: bool = True) -> None:
    """Prints the table and the targets; ``contradicted`` (a flag a row) adds the strokes whose label contradicts
    their geometry per source and the targets re-stated without them, apart from the raw figures; ``learned`` False
    scores the rules alone, without the learned ranker."""
    sources = np.array([source_of(r, by) for r in rows])
    names = sorted(set(sources))
    if len(names) < 2:
        raise SystemExit(f"only one source ({names}): leave-one-source-out needs two or more")
    right = {w: right_answers(rows, w, learned) for w in grid}
    labels = sorted({r["label"] for r in rows})
    label_of = np.array([r["label"] for r in rows])
    table_rows, misses, pooled, agreeing = [], [], Counter(), []
    first_group = held_back(rows)
    for held in names:
        others, mine = sources != held, sources == held
        chosen = max(grid, key=lambda w: (right[w][others].mean(), closeness(w)))
        got = right[chosen]
        pooled["right"] += int(got[mine].sum())
        pooled["total"] += int(mine.sum())
        if by == "person":
            group = group_of(held, first_group)
            if group != "first design" or held.startswith("itt:"):  # the first design group's students apart
                pooled[group + " right"] += int(got[mine].sum())
                pooled[group] += int(mine.sum())
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
        extra = []
        if contradicted is not None:
            extra = _agreeing(held, mine, got, contradicted, label_of, labels, agreeing, pooled)
        table_rows.append([held, int(mine.sum()), f"{acc:.2f}", f"{100.0 * right[DEFAULT_WEIGHTS][mine].mean():.2f}"
                           if DEFAULT_WEIGHTS in right else "", _weights(chosen), *extra, *cells])
    print("### Leave one source out\n")
    print(table(["held-out source", "strokes", "held-out %", "defaults %", "weights chosen on the others",
                 *(["label contradicts geometry", "held-out % where they agree"] if contradicted is not None else []),
                 *labels], table_rows) + "\n")
    print(f"Pooled over the held-out folds: {pooled['right']}/{pooled['total']} = "
          f"{100.0 * pooled['right'] / pooled['total']:.2f} %. Cells: % right (strokes).\n")
    if by == "person" and first_group:
        print(f"Held back while designing ({', '.join(sorted(first_group))}): {_share(pooled, 'first held back')}; "
              f"the other students: {_share(pooled, 'first design')}.\n")
    if by == "person" and (pooled["new design"] or pooled["new held back"]):
        print(f"Sources found after the first 19: design {_share(pooled, 'new design')}"
              + (f"; the second group ({len(second_group(rows))} sources"
                 + (", opened 2026-12-04: no longer a held-out figure" if SECOND_GROUP_OPEN else ", held back")
                 + f"): {_share(pooled, 'new held back')}"
                 if pooled["new held back"] else "") + ".\n")
    for group in GROUP_SETS:
        if by == "person" and pooled[f"{group} held back"]:
            opened = " (opened as design material: not a held-out figure)" if group in OPENED_GROUPS else ""
            print(f"The {group} held-back group (`{group.upper()}_SETS`){opened}: "
                  f"{_share(pooled, f'{group} held back')}.\n")
    print("Issue 25 targets (every source >= 98.6 %; every label with >= 50 strokes in a source >= 97 %): "
          + ("met" if not misses else "not met: " + "; ".join(misses)) + "\n")
    if contradicted is not None:
        print(f"Not the headline: on the strokes whose label agrees with their geometry ({pooled['agree right']}/"
              f"{pooled['agree']} = {100.0 * pooled['agree right'] / max(pooled['agree'], 1):.2f} % pooled; "
              f"{int(contradicted.sum())} strokes whose label the contradiction tests convict "
              "(`label_contradictions.CONTRADICTIONS`) left out), the same targets: "
              + ("met" if not agreeing else "not met: " + "; ".join(agreeing)) + "\n")


def _agreeing(held: str, mine: np.ndarray, got: np.ndarray, contradicted: np.ndarray, label_of: np.ndarray,
              labels: list[str], misses: list[str], pooled: Counter) -> list[str | int]:
    """A source's strokes whose label its geometry contradicts (counted) and its figure without them; the targets
    missed without them are added to ``misses``."""
    agree = mine & ~contradicted
    n = int(agree.sum())
    pooled["agree right"] += int(got[agree].sum())
    pooled["agree"] += n
    acc = 100.0 * got[agree].mean() if n else float("nan")
    if n and acc < SOURCE_FLOOR:
        misses.append(f"{held}: {acc:.2f} % < {SOURCE_FLOOR} %")
    for label in labels:
        sel = agree & (label_of == label)
        if int(sel.sum()) >= LABEL_MIN_STROKES and 100.0 * got[sel].mean() < LABEL_FLOOR:
            misses.append(f"{held} {label}: {100.0 * got[sel].mean():.1f} % of {int(sel.sum())} < {LABEL_FLOOR} %")
    return [int((mine & contradicted).sum()), f"{acc:.2f}" if n else ""]


def _share(pooled: Counter, group: str) -> str:
    right, n = pooled[group + " right"], pooled[group]
    return f"{right}/{n} = {100.0 * right / max(n, 1):.2f} %"


def _weights(w: Weights) -> str:
    return f"{w.complexity:g}, {w.relative_noise:g}, {w.round_corner:g}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+", help=".jsonl files or set folders")
    ap.add_argument("--by", choices=("person", "device", "set"), default="person")
    ap.add_argument("--quick", action="store_true", help="a 4-point grid instead of 24")
    ap.add_argument("--defaults", action="store_true", help="the shipped weights only (one pass): a held-out figure "
                    "for sources found after they were set, as the second held-back group")
    ap.add_argument("--heldback", action="store_true", help="score the second held-back group too (once, at the end)")
    ap.add_argument("--third", action="store_true", help="score the third held-back group alone (`THIRD_SETS`; once, "
                    "by the lead, at the end of a session)")
    ap.add_argument("--fourth", action="store_true", help="score the fourth group alone (`FOURTH_SETS`; held back "
                    "until session 19, design material since)")
    ap.add_argument("--sign", action="store_true", help="score the sign set alone (`SIGN_SETS`; held back in the "
                    "fifth group until session 36, design material since)")
    ap.add_argument("--fifth", action="store_true", help="score the fifth held-back group alone (`FIFTH_SETS`; "
                    "once, by the lead, at the end of a session)")
    ap.add_argument("--contradictions", action="store_true", help="also count the strokes whose label the committed "
                    "contradiction tests convict, and re-state the targets without them (beside the raw figure)")
    ap.add_argument("--rules", action="store_true", help="the rules alone, without the learned ranker")
    args = ap.parse_args()
    rows = read_sets(args.sets, "bench_generalisation")
    kept, left = scored_rows(rows, third=args.third, fourth=args.fourth, fifth=args.fifth,
                             sign=args.sign)
    if not args.heldback:
        hidden = held_back_new(kept)
        n = len(kept)
        kept = [r for r in kept if source_of(r, "person") not in hidden]
        if hidden:
            left[f"of {len(hidden)} sources held back (`is_held_back_new`; --heldback scores them)"] += n - len(kept)
    print(f"## Generalisation ({machine()})\n")
    sets = Counter(r["source"] for r in kept)
    print("Scored: " + ", ".join(f"{n} strokes of {s}" for s, n in sorted(sets.items())) + ".")
    if left:
        by_set: dict[str, int] = defaultdict(int)
        for why, n in left.items():
            by_set[why] += n
        print("Not scored: " + "; ".join(f"{n} ({why})" for why, n in sorted(by_set.items())) + ".")
    print()
    contradicted = None
    if args.contradictions:
        from label_contradictions import contradiction  # it imports this module: imported when asked for

        contradicted = np.array([contradiction(r) is not None for r in kept])
    leave_one_source_out(kept, args.by, [DEFAULT_WEIGHTS] if args.defaults else QUICK_GRID if args.quick else GRID,
                         contradicted, learned=not args.rules)


if __name__ == "__main__":
    sys.exit(main())
