"""`physink tui [PROJECT] [--device …] [--serial PORT] [--replay FILE]` and the demo's TUI: builds the options and
opens the Textual app (imported only here, lazily), which does the rest.
"""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

from physink_tui.commands.input_file import BOM, read_bytes, regular_copy, sniff
from physink_tui.errors import PhysinkError
from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.formats.journal.reader import read_journal
from physink_tui.input.captures.capture import Capture
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.pen.mapping import TabletMapping

if TYPE_CHECKING:  # (imported only when the TUI opens: the CLI starts without Textual)
    from physink_tui.tui.app import TuiOptions

CANVAS = (1600.0, 1000.0)
"""The canvas a replayed capture is drawn on (a journal names its own)."""


def recorded(path: str) -> tuple[JournalHeader, tuple[JournalEntry, ...]]:
    """The header and entries of a journal or a capture to replay into the TUI's session."""
    data = read_bytes(path)
    if sniff(data, path, "tui --replay") == "capture":
        capture = Capture.from_text(data.removeprefix(BOM).decode("utf-8", errors="replace"), path=path)
        mapping = TabletMapping(canvas_width=CANVAS[0], canvas_height=CANVAS[1])
        return header_for_capture(capture, mapping), tuple(capture_entries(capture))
    with regular_copy(path, data) as copy:
        journal = read_journal(copy)
    return journal.header, journal.entries


def open_tui(options: TuiOptions) -> int:
    """Runs the app until the user quits; its exit status: 0, or 1 when it crashed (Textual has shown the
    traceback) or a bug stopped part of it (`PhysinkApp.failed`)."""
    if not (sys.stdout.isatty() and sys.stdin.isatty()):
        raise PhysinkError("physink tui needs a terminal (stdin and stdout); use physink replay or physink demo "
                           "--headless to run without one")
    from physink_tui.tui.app import make_app
    from physink_tui.tui.graphics import cell_pixels, choice, probe

    env = os.environ
    forced = "PHYSINK_GRAPHICS" in env or env.get("TMUX") or env.get("TERM", "").startswith(("tmux", "screen"))
    reply = None if forced else probe()  # asked before Textual owns the terminal
    options.graphics, note = choice(env, reply)
    if note:
        options.notes.append(note)
    options.cell = cell_pixels()
    app = make_app(options)
    app.run()
    return app.return_code or 0


def run(args: argparse.Namespace) -> int:
    from physink_tui.tui.app import TuiOptions

    options = TuiOptions(project=args.project, device=args.device, serial=args.serial)
    if args.replay:
        options.header, options.entries = recorded(args.replay)
    return open_tui(options)
