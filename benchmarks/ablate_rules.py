"""Benchmark: which of the recogniser's hand rules generalise — each rule switched off in turn, per set and per group.

Usage: .venv/bin/python benchmarks/ablate_rules.py SET [SET ...] [--only NAME,...] [--jobs N] [--save FILE.json]

Each rule of `RULES` (a hand rule of `physink_tui.scene.recognition`, most added while designing on the first 55 design
sources, issue 25) is switched off in this process only, by monkeypatching a constant or a function (no production
flag), and every scored stroke (`bench_generalisation.scored_rows`: the third to fifth held-back groups are never read)
is recognised by the rules alone and by the shipped recogniser (the learned ranker on the rules' reading; both from one
call: the rules' reading is the one handed to the ranker). A rule's effect on a stroke is a gain when the stroke is
right with every rule on and wrong with that rule off (the rule fixes it), a loss the other way. Printed per rule and
per group — the first 55 design sources, where the rules were designed, against the second group's 37
(`bench_generalisation.in_second_group`), which no rule was designed on before it was opened (2026-12-04) — with the
net per set and the classes gained and lost. Switching a rule off leaves the ranker's own features as they are (the
model was fitted with them: `ranker.open_shapes` is held at the unpatched module), as deleting the rule from the rules'
path would until the ranker is refitted. Deterministic: the same sets give the same output.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import multiprocessing
import types
from collections import Counter, defaultdict
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from bench_generalisation import in_second_group, scored_rows
from bench_recognition import machine, table
from stroke_sets import Row, read_sets, source_of

from physink_tui.scene.recognition import (
    bracket_marks,
    closed_loops,
    open_marks,
    open_shapes,
    polygon_checks,
    ranker,
    ranking,
    rounded_corners,
)
from physink_tui.scene.recognition import recognize as rz
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Recognition

Patch = tuple[object, str, object]
"""An attribute of a module set to a value while a rule is off."""


@dataclass(frozen=True)
class Rule:
    """A hand rule and how to switch it off: ``off`` gives the patches (made when asked, so wrappers see the
    unpatched functions); ``designed_on`` says where docs/BENCHMARKS.md says it was chosen."""

    name: str
    where: str
    designed_on: str
    off: Callable[[], list[Patch]]
    shipped_only: bool = False


def _false(*_: object, **__: object) -> bool:
    return False


def _none(*_: object, **__: object) -> None:
    return None


def _no_dips() -> list[Patch]:
    find = sg.find_corners

    def find_corners(pts: np.ndarray, min_turn_deg: float = 45.0, window: int = 3, *, every_dip: bool = False,
                     ) -> list[int]:
        return find(pts, min_turn_deg, window)

    return [(sg, "find_corners", find_corners)]


def _cut_ends_without_sixths(work: np.ndarray, gap: float, d_tail: np.ndarray, d_head: np.ndarray) -> np.ndarray:
    """`loop_ends.cut_ends` without its last clause (the cut where the first and last sixths come closest)."""
    n, tail_n = len(work), len(d_tail)
    if float(d_tail.min()) < 0.5 * gap and d_tail.argmin() < tail_n - 2:
        return work[: n - tail_n + int(d_tail.argmin()) + 1]
    if float(d_head.min()) < 0.5 * gap and d_head.argmin() > 1:
        return work[int(d_head.argmin()):]
    return work


def _as_ranked(ranked: Recognition, *_: object) -> Recognition:
    return ranked


RULES: tuple[Rule, ...] = (
    # open strokes: the polyline-or-curve decision (open_shapes, open_marks, bracket_marks, stroke_geometry)
    Rule("bowed_between_corners", "open_shapes._bowed_between_corners (BOWED_SIDE)",
         "itt second pass: braces and question marks of 2 students and s03",
         lambda: [(open_shapes, "_bowed_between_corners", _false)]),
    Rule("brace_tip", "open_shapes._brace_tip (BRACE_*)",
         "itt second pass: 1 student's braces; fourth pass: tips of 1-3 sides (GixD42, shriyansnidhish)",
         lambda: [(open_shapes, "_brace_tip", _false)]),
    Rule("rounded_bracket", "open_shapes._rounded_bracket", "itt second pass: brackets of 2 students and s03",
         lambda: [(open_shapes, "_rounded_bracket", _false)]),
    Rule("every_dip", "stroke_geometry.find_corners(every_dip) (DIP_TURN_DEG)",
         "fourth pass: arrows' heads; DIP_TURN_DEG not held out for GixD42, shriyansnidhish", _no_dips),
    Rule("short_bend", "open_shapes._short_bend (SHORT_BEND; _tick_into_bend needs it)",
         "fourth pass: ahmadosama's ticks (not held out)", lambda: [(open_shapes, "_short_bend", _false)]),
    Rule("tip_in_line", "open_shapes._tip_in_line (ARMS_IN_LINE)", "fourth pass: braces; s04 not held out",
         lambda: [(open_shapes, "_tip_in_line", _false)]),
    Rule("tick_into_bend", "open_shapes._tick_into_bend", "fourth pass 2: ahmadosama, hat359/user3",
         lambda: [(open_shapes, "_tick_into_bend", _false)]),
    Rule("end_arm", "stroke_geometry.end_arm (remove_hooks, open_shapes._kept_arm; bracket arms at both ends)",
         "fourth pass 2: ahmadosama; hat359/user1, user3, klarubbio/s06; sinarest1608/Subject3",
         lambda: [(sg, "end_arm", _false)]),
    Rule("sawtooth", "open_marks.sawtooth (SAW_*)",
         "fifth pass: klarubbio/s06, pixelfac/user02, 03, 06, Nikhil-Kumar-Singh0612/user4, jonathanzhang53/s02, "
         "shriyansnidhish/s03", lambda: [(open_marks, "sawtooth", _false)]),
    Rule("retraced_ends", "open_marks.retraced_ends (RETRACE_*)", "fifth pass: mmg:10",
         lambda: [(open_marks, "retraced_ends", _none)]),
    Rule("rounded_bracket_corners", "bracket_marks.rounded_bracket_corners", "fifth pass: pixelfac/user01, "
         "klarubbio/s06", lambda: [(bracket_marks, "rounded_bracket_corners", _none)]),
    Rule("looped_point", "bracket_marks.looped_point (LOOPED_POINT)", "fifth pass: jd4386/User04, User05",
         lambda: [(bracket_marks, "looped_point", _false)]),
    Rule("brace_point", "bracket_marks.brace_point (BRACE_DEPTH, POINT_FROM_ENDS, ARMS_ALIKE ...)",
         "fifth pass: a table over the design sources' polylines; hat359/user1", lambda: [
             (bracket_marks, "brace_point", _false)]),
    # closed strokes (recognize, closed_loops, loop_ends, polygon_checks, ranking)
    Rule("spur", "polygon_checks.SPUR", "itt second pass: rectangles of 6 students",
         lambda: [(polygon_checks, "SPUR", 0.0)]),
    Rule("figure_eight", "stroke_features.figure_eight", "itt second pass: delete marks, an arrow of 4 students",
         lambda: [(sf, "figure_eight", _false)]),
    Rule("lumpy_round", "closed_loops.lumpy_round (LUMPY_SIDES, its ellipse's margin)",
         "itt first pass: the students' mouse circles; fourth pass: the margin", lambda: [
             (closed_loops, "lumpy_round", _false)]),
    Rule("loop_end_sixths", "loop_ends.cut_ends' cut in the first and last sixths (END_SHARE)",
         "fourth pass: boxes with a lead-in and an overshoot; mmg:22, DerD4n, pixelfac/user03",
         lambda: [(closed_loops, "cut_ends", _cut_ends_without_sixths)]),
    Rule("small_loop", "loop_ends.SMALL_LOOP", "fourth pass: pixelfac/user02, 03, jonathanzhang53/s05, "
         "klarubbio/s06", lambda: [(closed_loops, "SMALL_LOOP", 0.0)]),
    Rule("box_as_drawn", "rounded_corners.box_as_drawn (BOX_OVERLAP)", "fourth pass: the design sources' rectangles",
         lambda: [(rounded_corners, "box_as_drawn", _as_ranked)]),
    Rule("box_margin", "ranking.BOX_MARGIN", "fifth pass: geometry only (no source)",
         lambda: [(ranking, "BOX_MARGIN", ranking.BOUNDS_MARGIN),
                  (rounded_corners, "BOX_MARGIN", ranking.BOUNDS_MARGIN)]),
    Rule("left_open_wobble", "closed_loops.LEFT_OPEN_WOBBLE", "fifth pass: klarubbio/s06, dollar1:s03",
         lambda: [(closed_loops, "LEFT_OPEN_WOBBLE", 0.0)]),
    Rule("last_side_bow", "closed_loops.LAST_SIDE_BOW", "fifth pass: klarubbio/s06",
         lambda: [(closed_loops, "LAST_SIDE_BOW", open_shapes.STRAIGHT)]),
    Rule("star_crossings", "closed_loops.star_run_past_its_start (STAR_CROSSINGS)",
         "fifth pass: klarubbio/s06, sinarest1608/Subject3", lambda: [(closed_loops, "STAR_CROSSINGS", math.inf)]),
    # the shipped ranker's guards (the rules alone never reach them)
    Rule("checked_point", "ranker.checked_point (the hurried check is not asked of the model)",
         "third pass: s04", lambda: [(ranker, "checked_point", _false)], shipped_only=True),
    Rule("check_second_corner", "ranker.CHECK_POINT_SHARE (checked_point's second corner)", "fourth pass: s04",
         lambda: [(ranker, "CHECK_POINT_SHARE", math.inf)], shipped_only=True),
    Rule("zigzag_teeth", "ranker.zigzag_teeth", "fifth pass: pixelfac/user06 (and the zig-zags of sawtooth)",
         lambda: [(ranker, "zigzag_teeth", _false)], shipped_only=True),
    Rule("open_polygon", "ranker.open_polygon (open polygons re-ranked, OPEN_GAP)", "fourth pass: the design "
         "sources' open polygons", lambda: [(ranker, "open_polygon", _false)], shipped_only=True),
)
_UNPATCHED_OPEN_SHAPES = types.SimpleNamespace(**vars(open_shapes))
"""What the ranker's features read of `open_shapes` while a rule is off: the rules' own tests, unpatched."""


@contextlib.contextmanager
def switched_off(rule: Rule | None) -> Iterator[None]:
    """Within: ``rule`` switched off (None: every rule on), the ranker's features reading the unpatched rules."""
    patches: list[Patch] = [(ranker, "open_shapes", _UNPATCHED_OPEN_SHAPES)] + (rule.off() if rule else [])
    saved = [(target, name, getattr(target, name)) for target, name, _ in patches]
    try:
        for target, name, value in patches:
            setattr(target, name, value)
        yield
    finally:
        for target, name, value in reversed(saved):
            setattr(target, name, value)


def read_both(rows: Sequence[Row]) -> tuple[np.ndarray, np.ndarray]:
    """Which rows the rules alone and the shipped recogniser read right (the rules' reading captured as the ranker
    is handed it: one call a stroke)."""
    handed: list[Recognition] = []
    rerank = ranker.rerank

    def capture(points: object, times: object, noise: float, found: Recognition, *rest: object) -> Recognition:
        handed.append(found)
        return rerank(points, times, noise, found, *rest)  # type: ignore[arg-type]

    rules_right, shipped_right = np.zeros(len(rows), dtype=bool), np.zeros(len(rows), dtype=bool)
    ranker.rerank = capture  # type: ignore[assignment]
    try:
        for i, row in enumerate(rows):
            stroke = row["strokes"][0]
            times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
            handed.clear()
            shipped = rz.recognize_stroke([p[:2] for p in stroke], times)
            rules = handed[0] if handed else shipped  # no geometry: the ranker is not reached
            rules_right[i] = rules.kind in row["accepts"]
            shipped_right[i] = shipped.kind in row["accepts"]
    finally:
        ranker.rerank = rerank
    return rules_right, shipped_right


def _ablated(args: tuple[Rule | None, Sequence[Row]]) -> tuple[np.ndarray, np.ndarray]:
    rule, rows = args
    with switched_off(rule):
        return read_both(rows)


_ROWS: list[Row] = []


def _ablated_shared(name: str | None) -> tuple[np.ndarray, np.ndarray]:
    """`_ablated` in a worker, on the rows it inherited (`_ROWS`)."""
    return _ablated((next(r for r in RULES if r.name == name) if name else None, _ROWS))


def ablate(rows: Sequence[Row], rules: Sequence[Rule], jobs: int = 1,
           ) -> tuple[tuple[np.ndarray, np.ndarray], dict[str, tuple[np.ndarray, np.ndarray]]]:
    """The readings with every rule on, and with each of ``rules`` off: (rules alone right, shipped right) each."""
    names: list[str | None] = [None, *(r.name for r in rules)]
    if jobs > 1 and all(any(r is k for k in RULES) for r in rules):
        global _ROWS
        _ROWS = list(rows)
        with multiprocessing.get_context("fork").Pool(jobs) as pool:
            out = pool.map(_ablated_shared, names, chunksize=1)
    else:
        out = [_ablated((rule, rows)) for rule in [None, *rules]]
    return out[0], {r.name: o for r, o in zip(rules, out[1:], strict=True)}


FIRST, SECOND = "first 55", "second 37"


def group(source: str) -> str:
    return SECOND if in_second_group(source) else FIRST


@dataclass(frozen=True)
class Effect:
    """What a rule does on a group of strokes: how many it fixes (right with it, wrong without) and breaks."""

    gains: int
    losses: int

    @property
    def net(self) -> int:
        return self.gains - self.losses

    def __str__(self) -> str:
        return f"+{self.gains} -{self.losses} = {self.net:+d}"


def effects(rows: Sequence[Row], on: np.ndarray, off: np.ndarray) -> tuple[dict[str, Effect], dict[str, list[str]]]:
    """A rule's effect (``on``: right with every rule on; ``off``: with it off) per group, per set and group, and per
    class and group, with the strokes it changes."""
    gained, lost = on & ~off, ~on & off
    per: dict[str, Counter] = defaultdict(Counter)
    changed: dict[str, list[str]] = defaultdict(list)
    for i, row in enumerate(rows):
        if not (gained[i] or lost[i]):
            continue
        g, sign = group(source_of(row, "person")), "gains" if gained[i] else "losses"
        per[g][sign] += 1
        per[f"{g}|set|{row['source']}"][sign] += 1
        per[f"{g}|class|{row['label']}"][sign] += 1
        changed[g].append(f"{'+' if gained[i] else '-'} {source_of(row, 'person')} {row['label']} "
                          f"{Path(str(row.get('file', ''))).name}")
    return {k: Effect(v["gains"], v["losses"]) for k, v in per.items()}, dict(changed)


def _cell(counts: dict[str, Effect], key: str) -> str:
    e = counts.get(key)
    return str(e) if e else "0"


def report(rows: Sequence[Row], rules: Sequence[Rule], base: tuple[np.ndarray, np.ndarray],
           off: dict[str, tuple[np.ndarray, np.ndarray]]) -> tuple[str, dict[str, object]]:
    """The Markdown tables, and what is saved (per rule and mode, the strokes changed)."""
    groups = np.array([group(source_of(r, "person")) for r in rows])
    lines = ["## Which hand rules generalise (each switched off in turn)\n", f"Machine: {machine()}.\n"]
    n = {g: int((groups == g).sum()) for g in (FIRST, SECOND)}
    sources = {g: len({source_of(r, "person") for r, gg in zip(rows, groups, strict=True) if gg == g})
               for g in (FIRST, SECOND)}
    lines.append("Every rule on: " + "; ".join(
        f"{mode} {g} ({sources[g]} sources) {int(right[groups == g].sum())}/{n[g]} = "
        f"{100.0 * right[groups == g].mean():.2f} %"
        for mode, right in (("rules alone", base[0]), ("shipped", base[1])) for g in (FIRST, SECOND) if n[g]) + ".\n")
    lines.append("Cells: strokes the rule fixes (+: right with it, wrong without), breaks (-), net; a rule helps where "
                 "the net is positive.\n")
    saved: dict[str, object] = {}
    head, body = ["rule", "what is switched off", "designed on (docs/BENCHMARKS.md)",
                  f"rules alone, {FIRST}", f"rules alone, {SECOND}", f"shipped, {FIRST}", f"shipped, {SECOND}"], []
    detail: list[str] = []
    for rule in rules:
        r_off, s_off = off[rule.name]
        by_mode = {"rules alone": effects(rows, base[0], r_off), "shipped": effects(rows, base[1], s_off)}
        saved[rule.name] = {m: e[1] for m, e in by_mode.items()}
        cells = [_cell(by_mode[m][0], g) if not (rule.shipped_only and m == "rules alone") else "—"
                 for m in ("rules alone", "shipped") for g in (FIRST, SECOND)]
        body.append([rule.name, rule.where, rule.designed_on, *cells])
        for mode, (counts, _) in by_mode.items():
            if not counts:
                continue
            for g in (FIRST, SECOND):
                per_set = ", ".join(f"{k.split('|')[2]} {v}" for k, v in sorted(counts.items())
                                    if k.startswith(f"{g}|set|"))
                per_class = ", ".join(f"{k.split('|')[2]} {v}" for k, v in sorted(counts.items())
                                      if k.startswith(f"{g}|class|"))
                if per_set:
                    detail.append(f"- `{rule.name}`, {mode}, {g}: by set {per_set}; by class {per_class}")
    lines.append(table(head, body) + "\n")
    lines.append("Per set and per class (only where the rule changes a stroke):\n")
    lines += detail
    return "\n".join(lines) + "\n", saved


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+", help=".jsonl files or set folders")
    ap.add_argument("--only", help="comma-separated rule names (default: every rule of RULES)")
    ap.add_argument("--jobs", type=int, default=1, help="processes (the machine is shared: run under nice)")
    ap.add_argument("--save", type=Path, help="write the strokes each rule changes, per mode and group, as JSON")
    args = ap.parse_args()
    rules = list(RULES)
    if args.only:
        wanted = args.only.split(",")
        unknown = sorted(set(wanted) - {r.name for r in RULES})
        if unknown:
            raise SystemExit(f"ablate_rules: no rule named {', '.join(unknown)} (known: "
                             f"{', '.join(r.name for r in RULES)})")
        rules = [r for r in RULES if r.name in wanted]
    rows = read_sets(args.sets, "ablate_rules")
    kept, _ = scored_rows(rows)
    base, off = ablate(kept, rules, args.jobs)
    text, saved = report(kept, rules, base, off)
    print(text)
    if args.save:
        args.save.write_text(json.dumps(saved, indent=1, sort_keys=True, ensure_ascii=False) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
