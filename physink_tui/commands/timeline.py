"""`physink timeline FILE [--format text|json|dot]`: prints the causal timeline a project (or a timeline JSON file)
holds; no recording."""

from __future__ import annotations

import argparse
from pathlib import Path

from physink_tui.commands.timeline_source import load_timeline
from physink_tui.formats.timeline_dot import encode_timeline_dot
from physink_tui.formats.timeline_json import encode_timeline_json
from physink_tui.formats.timeline_text import encode_timeline_text


def run(args: argparse.Namespace) -> int:
    timeline, names = load_timeline(Path(args.project))
    if args.format == "json":
        text = encode_timeline_json(timeline, names)
    elif args.format == "dot":
        text = encode_timeline_dot(timeline, names)
    else:
        text = encode_timeline_text(timeline, names)
    print(text.rstrip("\n"))
    return 0
