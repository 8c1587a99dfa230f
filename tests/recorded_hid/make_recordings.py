"""Writes the project's own recorded captures (tests/recorded_hid/*.hid) with the virtual pen; decodes none.

Run from the repository root::

    python tests/recorded_hid/make_recordings.py

Each reference device draws the same short script (a line, a box drawn as one stroke, a circle, a small
spring); ``xp-pen-style-padding.hid`` is the UC-Logic v1 device sending ones in every unused bit, as XP-Pen
tablets do. The output is deterministic, and `tests/test_virtual_pen.py` checks that regenerating gives the
committed files byte for byte: change the script or the virtual pen, run this, and review the diff.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import NamedTuple

if __name__ == "__main__":  # run as a script: make the repository's package importable
    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from physink_tui.input.captures.writer import format_capture
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.virtual_pen import Stroke, VirtualPen

HERE = Path(__file__).resolve().parent

DRAWING: tuple[Stroke, ...] = (
    Stroke.line((0.10, 0.15), (0.55, 0.22)),
    Stroke.box(0.12, 0.38, 0.38, 0.72),
    Stroke.circle((0.68, 0.42), 0.16),
    Stroke.zigzag((0.50, 0.86), (0.88, 0.80), teeth=7, amplitude=0.035),
)
"""The scripted drawing every recording shows, in the order drawn."""


class Recording(NamedTuple):
    """How one file is made: which reference device, and the virtual pen's settings."""

    device: str
    rate_hz: float
    seed: int
    padding_ones: bool = False


RECORDINGS: dict[str, Recording] = {
    "windows-ink-strokes.hid": Recording("windows-ink", 240.0, 1),
    "wacom-ff0d-strokes.hid": Recording("wacom-ff0d", 200.0, 2),
    "uclogic-v1-strokes.hid": Recording("uclogic-v1", 250.0, 3),
    "huion-v2-strokes.hid": Recording("huion-v2", 250.0, 4),
    "xp-pen-style-padding.hid": Recording("uclogic-v1", 200.0, 5, padding_ones=True),
}
"""Every recorded file, by file name."""


def pen_for(file_name: str) -> VirtualPen:
    """The virtual pen that draws ``file_name``."""
    rec = RECORDINGS[file_name]
    return VirtualPen(REFERENCE_DEVICES[rec.device], rate_hz=rec.rate_hz, seed=rec.seed,
                      padding_ones=rec.padding_ones)


def render(file_name: str) -> str:
    """The text of ``file_name``, exactly as this script writes it."""
    return format_capture(pen_for(file_name).record(DRAWING))


def main(argv: list[str] | None = None) -> int:
    """Write every recording into the directory given (default: next to this script)."""
    args = sys.argv[1:] if argv is None else argv
    out_dir = Path(args[0]) if args else HERE
    for name in RECORDINGS:
        text = render(name)
        path = out_dir / name
        # plain write (not capture.write_capture) so the bytes are exactly `render`'s, newline included
        path.write_text(text, encoding="utf-8", newline="\n")
        print(f"{path}: {text.count(chr(10) + 'E:')} reports, {len(text.encode()) // 1024} KiB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
