"""Captures of people using the kiosk, drawn with the virtual pen on a UC-Logic tablet: sketches on the drawing
area below the default hot-zone strip, taps on the strip's buttons, pauses between visitors."""

from __future__ import annotations

import sys
from pathlib import Path

if __name__ == "__main__":  # run as a script: make the repository's package importable
    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from physink_tui.input.captures.capture import Capture, CaptureEvent
from physink_tui.input.captures.writer import format_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.kiosk.hot_zones import STRIP

MODE, UNDO, REDO, END = ((0.125, STRIP / 2),), ((0.375, STRIP / 2),), ((0.625, STRIP / 2),), ((0.875, STRIP / 2),)
"""Taps on the default zones (sketch/demo, undo, redo, end session)."""


def on_canvas(x: float, y: float) -> tuple[float, float]:
    """Tablet position of canvas fraction (x, y): the canvas lies below the strip."""
    return x, STRIP + (1.0 - STRIP) * y


def ball_and_platform() -> list[Stroke]:
    """A visitor draws a ball and a platform, switches to demo, drags the ball onto the platform, ends."""
    return [Stroke.circle(on_canvas(0.2, 0.2), 0.04, aspect=1.6),
            Stroke.box(*on_canvas(0.1, 0.6), *on_canvas(0.5, 0.66)),
            Stroke(MODE),
            Stroke((on_canvas(0.2, 0.2), on_canvas(0.3, 0.4), on_canvas(0.32, 0.55))),
            Stroke(END)]


def box_then_undo() -> list[Stroke]:
    """A visitor draws a box and a circle, undoes the circle and walks away (no end button)."""
    return [Stroke.box(*on_canvas(0.6, 0.3), *on_canvas(0.8, 0.4)),
            Stroke.circle(on_canvas(0.3, 0.5), 0.05, aspect=1.6),
            Stroke(UNDO)]


PadPress = tuple[int, ...]
"""Pad buttons pressed together (and released a moment later), in a visitor's list of strokes."""


def visits(*visitors: list[Stroke | PadPress], pause_s: float = 4.0, seed: int = 3,
           device: str = "uclogic-v1") -> Capture:
    """One capture of the visitors one after another, ``pause_s`` seconds without the pen between them. A
    `PadPress` among the strokes becomes Huion "v2" pad reports (``device`` must be ``huion-v2``)."""
    pen = VirtualPen(REFERENCE_DEVICES[device], seed=seed)
    devices, events, t = None, [], 0.0
    for visitor in visitors:
        strokes: list[Stroke] = []
        for item in [*visitor, None]:
            if isinstance(item, Stroke):
                strokes.append(item)
                continue
            if strokes:
                capture = pen.record(strokes, start_t=t)
                devices, strokes = capture.devices, []
                events.extend(capture.events)
                t = capture.events[-1].t
            if item is not None:  # a pad press: down, then up 0.15 s later
                t += 0.3
                mask = sum(1 << (b - 1) for b in item)
                events.append(CaptureEvent(t, bytes([0x08, 0xE0, 0x01, 0x01, mask & 0xFF, mask >> 8, *[0] * 6])))
                events.append(CaptureEvent(t + 0.15, bytes([0x08, 0xE0, 0x01, 0x01, *[0] * 8])))
                t += 0.2
        t += pause_s
    assert devices is not None
    return Capture(devices, tuple(events))


def write_capture(capture: Capture, path: Path) -> Path:
    path.write_text(format_capture(capture), encoding="utf-8")
    return path


SAMPLE = Path(__file__).resolve().parent / "visits.hid"
"""Two visitors (`ball_and_platform`, then `box_then_undo`), committed for trying the kiosk without a tablet
(``physink kiosk --out /tmp/k --replay tests/kiosk/visits.hid``); ``python tests/kiosk/captures.py`` writes it
again, byte for byte."""


def sample_text() -> str:
    return format_capture(visits(ball_and_platform(), box_then_undo()))


if __name__ == "__main__":
    SAMPLE.write_text(sample_text(), encoding="utf-8", newline="\n")
    print(f"{SAMPLE}: {SAMPLE.stat().st_size // 1024} KiB")
