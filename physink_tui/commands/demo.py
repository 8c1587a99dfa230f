"""`physink demo`: on a terminal, the TUI replaying the bundled egg cracker; headless, the pipeline and its outputs.

On a terminal (stdin and stdout, no ``--headless``) it opens the TUI (`commands.tui`) replaying the bundled
session at real speed, then leaves the user in control. Otherwise it journals the bundled
capture (the egg cracker drawn and then demonstrated with the virtual pen, `demo_data`) with what is typed in
between (labels, ``mode demo``) as a session, runs it through decoding, gestures, recognition, interpretation
and demo mode, writes the samples, the journal, the project, the timeline, the demonstration as a video
(``demo.mp4``) and its last frame (``scene.png``) to the output folder, and shows
the strokes as braille dots and the demonstration as the thesis narrates it.
"""

from __future__ import annotations

import argparse
import io
import sys
from collections import Counter

from physink_tui.commands.decode import decode_capture, summary, write_jsonl
from physink_tui.demo_data import DEMO_FILE, TABLET_ASPECT, demo_capture_text, demo_script
from physink_tui.errors import PhysinkError
from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.outputs import OutputFolder, reason
from physink_tui.formats.session_outputs import write_session_outputs
from physink_tui.input.captures.capture import Capture
from physink_tui.input.journal_compose import capture_entries, header_for_capture, write_journal
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.progress import ProgressBar
from physink_tui.render.braille import braille_plot
from physink_tui.render.export import Export, Look
from physink_tui.scene.components import Body, Joint
from physink_tui.session.session import Session
from physink_tui.timeline.narrate import timeline_text

CANVAS = (1600.0, 1000.0)
MAPPING = TabletMapping(canvas_width=CANVAS[0], canvas_height=CANVAS[1], tablet_width=TABLET_ASPECT,
                        tablet_height=1.0)
"""The bundled tablet's active area on the canvas (its proportions, the whole area used)."""
JOURNAL = "session.physink.jsonl"

PLURAL = {"body": "bodies"}


def describe(session: Session) -> list[str]:
    """One line per component, in drawing order, for the terminal."""
    lines = []
    for c in session.scene.components.values():
        if isinstance(c, Body):
            held = " (fixed)" if session.scene.is_fixed(c.id) else ""
            lines.append(f"  {c.id:4} {c.shape}{held}" + (f"  label {c.label!r}" if c.label else ""))
        elif isinstance(c, Joint):
            lines.append(f"  {c.id:4} {'rotational' if c.kind == 'pivot' else 'fixed'} joint {c.a} - {c.b}")
        else:
            lines.append(f"  {c.id:4} {type(c).__name__.lower()}")
    return lines


def bundled_capture() -> Capture:
    """The bundled capture: the egg cracker drawn and then demonstrated with the virtual pen (`demo_data`)."""
    return Capture.from_text(demo_capture_text(), path=f"<bundled {DEMO_FILE}>")


def demo_journal(capture: Capture | None = None) -> tuple[JournalHeader, list[JournalEntry]]:
    """The bundled session: the journal header of the demo capture (`bundled_capture` unless given) and its
    entries merged by time with what is typed (stable: a report before a command of the same time)."""
    capture = bundled_capture() if capture is None else capture
    entries: list[JournalEntry] = [*capture_entries(capture), *demo_script()]
    entries.sort(key=lambda e: e.t)
    return header_for_capture(capture, MAPPING), entries


def run(args: argparse.Namespace) -> int:
    if not args.headless and sys.stdout.isatty() and sys.stdin.isatty():
        from physink_tui.commands.tui import open_tui
        from physink_tui.tui.app import TuiOptions

        header, entries = demo_journal()
        return open_tui(TuiOptions(header=header, entries=tuple(entries), title="PhysInk demo", simulate_after=True))
    folder = OutputFolder.prepare(args.out)  # holds only this run's files
    out = folder.path
    capture = bundled_capture()
    results = decode_capture(capture)
    _, _, cols = results[0]
    samples = io.StringIO()
    write_jsonl(cols, samples)
    folder.write("samples.jsonl", samples.getvalue())
    folder.write("summary.txt", summary(capture, results) + "\n")

    journal_path = out / JOURNAL
    try:  # prepare removed the last run's journal: a journal is never overwritten, the demo starts a fresh one
        write_journal(journal_path, *demo_journal(capture))
    except OSError as exc:
        raise PhysinkError(f"{journal_path}: cannot write: {reason(exc)}") from None
    journal = read_journal(journal_path)
    session = Session.from_header(journal.header).run(journal.entries)
    write_session_outputs(folder, session.scene, session.timeline, session.canvas, session.vocabulary_lines(),
                          session.demonstration)
    export = Export(session.scene, session.timeline, session.canvas, Look())
    with ProgressBar("demo.mp4", "frames") as bar:
        export.video(folder.file("demo.mp4"), progress=bar)
    export.still(folder.file("scene.png"))
    narration = "" if session.timeline is None else timeline_text(session.timeline, session.scene.names())

    tip = cols.tip.tolist()
    touching = [(x, y) for x, y, down in zip(cols.x.tolist(), cols.y.tolist(), tip, strict=True) if down]
    strokes = sum(1 for i, down in enumerate(tip) if down and (i == 0 or not tip[i - 1]))
    kinds = Counter(type(c).__name__.lower() for c in session.scene.components.values())
    print("PhysInk TUI demo: the bundled egg cracker, drawn and then demonstrated on a virtual UC-Logic tablet,")
    print("read as raw HID reports, decoded, followed to strokes, recognised and interpreted into a physical scene;")
    print("in demo mode the pen pushed the ball onto the lever and carried the egg into the pan, recorded as a")
    print("causal timeline.\n")
    print(braille_plot(touching, width=64, height=20))
    print(f"\n{len(cols)} pen samples, {strokes} strokes; the sketch has "
          + ", ".join(f"{n} {PLURAL.get(k, k + 's') if n > 1 else k}" for k, n in sorted(kinds.items())) + ":")
    print("\n".join(describe(session)))
    for message in session.messages:
        print(f"  note: {message.text}")
    if narration:
        print("\nThe demonstration, as the thesis narrates it:\n" + narration)
    print(f"\nwritten to {out}/: samples.jsonl, summary.txt, {JOURNAL} (replay it with physink replay), project.json,"
          " timeline.json, timeline.txt, demo.mp4 (the demonstration as a video) and scene.png (its last frame)")
    return 0
