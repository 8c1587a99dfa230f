"""`physink equiv A B [--json]`: are two timelines (or projects) qualitatively equivalent; the comparison itself is
`physink_tui.timeline.equivalence`'s, the file formats `timeline_formats`' and the project codec's.

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

from physink_tui.commands.timeline_formats import parse_timeline_json
from physink_tui.errors import PhysinkError
from physink_tui.project.codec import FORMAT as PROJECT_FORMAT
from physink_tui.project.files import load_project
from physink_tui.timeline.equivalence import Comparison, compare
from physink_tui.timeline.events import Timeline, TimelineError


def _is_project(text: str) -> bool:
    try:
        doc = json.loads(text)
    except ValueError:
        return False  # parse_timeline_json says what is wrong with it
    return isinstance(doc, dict) and doc.get("format") == PROJECT_FORMAT


def load_timeline(path: Path) -> tuple[Timeline, dict[str, str]]:
    """The timeline in a timeline JSON or project file, with its component labels (id -> label).

    Raises:
        PhysinkError: one line naming the file: it cannot be read, is not UTF-8, is no valid project or timeline,
            or is a project without a timeline.
    """
    try:
        text = path.read_bytes().decode("utf-8")
    except OSError as e:
        raise TimelineError(f"cannot read {path}: {e.strerror or e}") from None
    except UnicodeDecodeError as e:
        raise TimelineError(f"{path}: not UTF-8 text (byte {e.start})") from None
    if not _is_project(text):
        try:
            return parse_timeline_json(text)
        except TimelineError as e:
            raise TimelineError(f"{path}: {e}", e.event_id) from None
    project = load_project(path)  # SceneError names the file and the bad field
    if project.timeline is None:
        raise PhysinkError(f"{path}: the project holds no timeline (demonstrate the machine in demo mode first)")
    try:
        timeline, labels = parse_timeline_json(json.dumps(project.timeline))
    except TimelineError as e:
        raise TimelineError(f"{path}: timeline: {e}", e.event_id) from None
    # As `physink timeline` does: the scene's labels win over those written in the timeline.
    names = {c.id: c.label for c in project.scene.components.values() if getattr(c, "label", None)}
    return timeline, {**labels, **names}


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
