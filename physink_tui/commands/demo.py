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
from physink_tui.demo_data import DEMO_FILE, demo_capture_text
from physink_tui.errors import PhysinkError
from physink_tui.input.capture import Capture
from physink_tui.render.braille import braille_plot


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
    print("PhysInk TUI demo: the bundled egg-cracker drawing, read as raw HID reports from a virtual")
    print("UC-Logic tablet and decoded (the sketching, timeline and terminal UI come in later issues).\n")
    print(braille_plot(touching, width=64, height=20))
    print(f"\n{len(cols)} pen samples, {strokes} strokes; written to {out}/samples.jsonl and {out}/summary.txt")
    if args.headless is False and sys.stdout.isatty():
        print("(the interactive TUI is not built yet; this run was headless)")
    return 0
