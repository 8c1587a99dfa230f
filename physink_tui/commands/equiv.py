"""`physink equiv A [B] [--up-to-demonstrated] [--json]`: are two timelines (or projects) qualitatively equivalent;
the comparison itself is `physink_tui.timeline.equivalence`'s, the file formats `timeline_json`'s and the project
codec's, the words of the simulation's rule `up_to_demonstrated`'s.

A and B are each a timeline JSON file (``physink timeline --format json``, ``physink replay``'s timeline.json)
or a project file holding a timeline; a file whose top-level ``"format"`` is ``physink-project`` is a project.
A alone is a project that adopted a simulation (the TUI's adopt, ``physink simulate``'s project.json): its kept
demonstration is compared with its simulated timeline. Prints ``equivalent`` or ``not equivalent``, the two
distances and one ``- reason`` line per mismatch; with ``--json`` one object. ``--up-to-demonstrated`` compares B
as a simulation of the demonstration A, by the rule SIMULATE uses (the TUI and ``physink simulate`` give the same
verdict and distances): the verdict names the rule, a line says what the simulation does after the last
demonstrated event, and the JSON object adds ``rule`` and ``afterwards``. Exit status 0 either way; an unreadable
or malformed file is a one-line error naming it.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from physink_tui.commands.timeline_source import load_kept_demonstration, load_timeline
from physink_tui.timeline.equivalence import Comparison, compare
from physink_tui.timeline.up_to_demonstrated import RULE, afterwards


def _number(value: float) -> float:
    r = round(value, 6)
    return 0.0 if r == 0 else r


def report_text(result: Comparison, rule: str | None = None, after: str | None = None) -> str:
    """The text report: verdict (naming ``rule`` when given), the two distances, what the simulation does
    afterwards, one ``- `` line per reason (no trailing newline)."""
    head = "equivalent" if result.equivalent else "not equivalent"
    lines = [
        head if rule is None else f"{head} {rule}",
        f"qualitative distance: {_number(result.qualitative_distance):g}",
        f"quantitative distance: {_number(result.quantitative_distance):.3f}",
        *([after] if after else []),
        *(f"- {reason}" for reason in result.reasons),
    ]
    return "\n".join(lines)


def report_json(result: Comparison, rule: str | None = None, after: str | None = None) -> str:
    """The DESIGN.md object, on one line; with a ``rule``, also ``rule`` and ``afterwards`` (null when nothing)."""
    obj: dict[str, object] = {
        "equivalent": result.equivalent,
        "qualitative_distance": _number(result.qualitative_distance),
        "quantitative_distance": _number(result.quantitative_distance),
        "reasons": list(result.reasons),
    }
    if rule is not None:
        obj["rule"] = rule
        obj["afterwards"] = after
    return json.dumps(obj, ensure_ascii=False, allow_nan=False)


def run(args: argparse.Namespace) -> int:
    if args.b is None:
        (a, names_a), (b, names_b) = load_kept_demonstration(Path(args.a))
    else:
        a, names_a = load_timeline(Path(args.a))
        b, names_b = load_timeline(Path(args.b))
    simulation = bool(getattr(args, "up_to_demonstrated", False))
    result = compare(a, b, names_a, names_b, simulation=simulation)
    rule = RULE if simulation else None
    after = afterwards(result, b, names_b) if simulation else None
    text = report_json(result, rule, after) if args.json else report_text(result, rule, after)
    sys.stdout.write(text + "\n")
    return 0
