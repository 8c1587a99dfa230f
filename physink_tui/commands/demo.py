"""`physink demo`: runs the part of the pipeline that exists on the bundled drawing; writes DIR outputs.

Until the Textual UI exists (a later issue) the demo is headless whatever the terminal: it decodes
the bundled egg-cracker capture (made with the virtual pen), writes the samples and the summary to
the output folder, and shows the strokes it found as braille dots.
"""

from __future__ import annotations

import argparse
import io
import sys
from pathlib import Path

from physink_tui.atomic_write import write_text_atomic
from physink_tui.commands.decode import decode_capture, summary, write_jsonl
from physink_tui.commands.recognize import recognition_json
from physink_tui.commands.replay import replay_capture
from physink_tui.demo_data import DEMO_FILE, demo_capture_text
from physink_tui.errors import PhysinkError
from physink_tui.input.capture import Capture
from physink_tui.input.gestures import StrokeEnded
from physink_tui.render.braille import braille_plot
from physink_tui.scene.recognize import recognize_strokes


def recognize_drawing(capture: Capture, path: Path) -> list[str]:
    """Follow the capture to strokes, recognise them (two lines in a row may be an X), write one JSON
    line per recognition to ``path``; return the kinds in drawing order."""
    gestures, _ = replay_capture(capture)
    strokes = [[(p.x, p.y) for p in g.stroke.points] for g in gestures if isinstance(g, StrokeEnded)]
    results = []
    i = 0
    while i < len(strokes):
        single = recognize_strokes([strokes[i]])
        if single.kind == "line" and i + 1 < len(strokes):
            pair = recognize_strokes([strokes[i], strokes[i + 1]])
            if pair.kind == "x":
                results.append(pair)
                i += 2
                continue
        results.append(single)
        i += 1
    write_text_atomic(path, "".join(recognition_json(r) + "\n" for r in results))
    return [r.kind or "nothing" for r in results]


def run(args: argparse.Namespace) -> int:
    out = Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise PhysinkError(f"{out}: cannot create the output folder: {exc.strerror or exc}") from None
    capture = Capture.from_text(demo_capture_text(), path=f"<bundled {DEMO_FILE}>")
    results = decode_capture(capture)
    _, _, cols = results[0]
    samples = io.StringIO()
    write_jsonl(cols, samples)
    text_summary = summary(capture, results)
    write_text_atomic(out / "samples.jsonl", samples.getvalue())
    write_text_atomic(out / "summary.txt", text_summary + "\n")
    tip = cols.tip.tolist()
    strokes = sum(1 for i, down in enumerate(tip) if down and (i == 0 or not tip[i - 1]))
    touching = [(x, y) for x, y, down in zip(cols.x.tolist(), cols.y.tolist(), tip, strict=True) if down]
    kinds = recognize_drawing(capture, out / "recognized.jsonl")
    print("PhysInk TUI demo: the bundled egg-cracker drawing, read as raw HID reports from a virtual")
    print("UC-Logic tablet, decoded, followed to strokes and recognised (the physical scene, the timeline")
    print("and the terminal UI come in later issues).\n")
    print(braille_plot(touching, width=64, height=20))
    print(f"\n{len(cols)} pen samples, {strokes} strokes recognised as: {', '.join(kinds)}")
    print(f"written to {out}/samples.jsonl, {out}/summary.txt and {out}/recognized.jsonl")
    if args.headless is False and sys.stdout.isatty():
        print("(the interactive TUI is not built yet; this run was headless)")
    return 0
