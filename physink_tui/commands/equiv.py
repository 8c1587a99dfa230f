"""`physink equiv A B [--json]`: are two timelines (or projects) qualitatively equivalent; the comparison itself is
`physink_tui.timeline.equivalence`'s, the file formats `timeline_json`'s and the project codec's.

A and B are each a timeline JSON file (``physink timeline --format json``, ``physink replay``'s timeline.json)
or a project file holding a timeline; a file whose top-level ``"format"`` is ``physink-project`` is a project.
Prints ``equivalent`` or ``not equivalent``, the two distances and one ``- reason`` line per mismatch; with
``--json`` one object. Exit status 0 either way; an unreadable or malformed file is a one-line error naming it.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from physink_tui.commands.timeline_source import load_timeline
from physink_tui.timeline.equivalence import Comparison, compare


def _number(value: float) -> float:
    r = round(value, 6)
    return 0.0 if r == 0 else r


def report_text(result: Comparison) -> str:
    """The text report: verdict, the two distances, one ``- `` line per reason (no trailing newline)."""
    lines = [
        "equivalent" if result.equivalent else "not equivalent",
        f"qualitative distance: {_number(result.qualitative_distance):g}",
        f"quantitative distance: {_number(result.quantitative_distance):.3f}",
        *(f"- {reason}" for reason in result.reasons),
    ]
    return "\n".join(lines)


def report_json(result: Comparison) -> str:
    """The DESIGN.md object, on one line."""
    return json.dumps({
        "equivalent": result.equivalent,
        "qualitative_distance": _number(result.qualitative_distance),
        "quantitative_distance": _number(result.quantitative_distance),
        "reasons": list(result.reasons),
    }, ensure_ascii=False, allow_nan=False)


def run(args: argparse.Namespace) -> int:
    a, names_a = load_timeline(Path(args.a))
    b, names_b = load_timeline(Path(args.b))
    result = compare(a, b, names_a, names_b)
    sys.stdout.write((report_json(result) if args.json else report_text(result)) + "\n")
    return 0
