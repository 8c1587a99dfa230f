"""`physink timeline PROJECT [--format text|json|dot]`: prints the causal timeline a project holds; no recording."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from physink_tui.commands.timeline_formats import parse_timeline_json, timeline_dot, timeline_json
from physink_tui.errors import PhysinkError
from physink_tui.project.files import load_project
from physink_tui.timeline.narrate import timeline_text


def run(args: argparse.Namespace) -> int:
    path = Path(args.project)
    project = load_project(path)
    if project.timeline is None:
        raise PhysinkError(f"{path}: the project holds no timeline (demonstrate the machine in demo mode first)")
    timeline, labels = parse_timeline_json(json.dumps(project.timeline))
    names = {c.id: c.label for c in project.scene.components.values() if getattr(c, "label", None)}
    names = {**labels, **names}
    if args.format == "json":
        text = timeline_json(timeline, names)
    elif args.format == "dot":
        text = timeline_dot(timeline, names)
    else:
        text = timeline_text(timeline, names)
    print(text.rstrip("\n"))
    return 0
