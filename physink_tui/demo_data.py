"""The bundled demo: the thesis's egg cracker sketched and then demonstrated with the virtual pen; no decoding.

`EGG_CRACKER` is the scripted drawing, `DEMONSTRATION` the strokes made in demo mode and `demo_script()` what is
typed in between; `write_demo_capture()` regenerates the bundled capture
``physink_tui/data/egg-cracker.hid`` (deterministic, checked byte for byte by a test), and
`demo_capture_text()` reads it back from the installed package.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.input.captures.capture import Capture
from physink_tui.input.captures.writer import format_capture, write_capture
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.virtual_pen import Stroke, VirtualPen

DEMO_FILE = "egg-cracker.hid"
SETTLE_S = 2.0
"""Seconds after the last demonstration stroke before demo mode ends."""
TABLET_ASPECT = 40000 / 25000
"""The reference UC-Logic tablet's active area is 1.6 times wider than tall: round things are drawn round on it."""

EGG_CRACKER: tuple[Stroke, ...] = (
    Stroke.line((0.06, 0.22), (0.36, 0.42)),                      # the ramp
    Stroke.line((0.18, 0.28), (0.24, 0.34)),                      # an X pinning the ramp ...
    Stroke.line((0.24, 0.28), (0.18, 0.34)),                      # ... to the background
    Stroke.circle((0.10, 0.15), 0.04, aspect=TABLET_ASPECT),      # the ball
    Stroke.box(0.38, 0.47, 0.64, 0.50),                           # the lever
    Stroke.circle((0.51, 0.485), 0.012, segments=24, aspect=TABLET_ASPECT),  # its pivot
    Stroke.circle((0.60, 0.41), 0.035, aspect=TABLET_ASPECT),     # the egg
    Stroke(((0.54, 0.78), (0.57, 0.90), (0.84, 0.90), (0.87, 0.78))),  # the frying pan
    Stroke.line((0.6825, 0.864), (0.7275, 0.936)),                # an X welding the pan ...
    Stroke.line((0.7275, 0.864), (0.6825, 0.936)),                # ... to the background
)
"""The egg cracker of the thesis (figure 2-4), drawn in the order a person would."""

LABELS: tuple[tuple[str, str], ...] = (("b2", "ball"), ("b3", "lever"), ("b4", "egg"), ("b5", "pan"))
"""What the user calls the bodies the drawing makes (typed after drawing: ``label b2 ball`` ...)."""

DEMONSTRATION: tuple[Stroke, ...] = (
    Stroke(((0.10, 0.15), (0.30, 0.14), (0.42, 0.20), (0.425, 0.46))),  # the ball over the ramp onto the lever
    Stroke(((0.588, 0.31), (0.70, 0.40), (0.70, 0.865))),         # the egg, flipped up, carried into the pan
)
"""Then, in demo mode: the ball tips the lever, which flips the egg; the egg lands in the frying pan."""


def demo_pen() -> VirtualPen:
    """A UC-Logic/Huion v1 tablet at 200 Hz: the most common kind of inexpensive tablet."""
    return VirtualPen(REFERENCE_DEVICES["uclogic-v1"], rate_hz=200.0, seed=2026)


def drawing_capture() -> Capture:
    """The drawing alone."""
    return demo_pen().record(EGG_CRACKER)


def demo_capture() -> Capture:
    """The drawing and then the demonstration, as one recording (the bundled capture)."""
    return demo_pen().record((*EGG_CRACKER, *DEMONSTRATION))


def demo_script() -> list[CommandEntry]:
    """What is typed between drawing and demonstrating: the labels, then ``mode demo``; ``mode sketch`` after
    the demonstration, once what was set moving has come to rest."""
    times: dict[int, list[float]] = {}
    for sample in demo_pen().samples((*EGG_CRACKER, *DEMONSTRATION)):
        times.setdefault(sample.stroke, []).append(sample.t)
    drawn = max(times[len(EGG_CRACKER) - 1])
    script = [CommandEntry(round(drawn + 0.05 * (i + 1), 6), "label", (cid, text))
              for i, (cid, text) in enumerate(LABELS)]
    script.append(CommandEntry(round(drawn + 0.05 * (len(LABELS) + 1), 6), "mode", ("demo",)))
    script.append(CommandEntry(round(max(times[len(times) - 1]) + SETTLE_S, 6), "mode", ("sketch",)))
    return script


def write_demo_capture(path: Path) -> None:
    write_capture(demo_capture(), path)


def demo_capture_text() -> str:
    """The bundled capture, as shipped in the package."""
    return resources.files("physink_tui.data").joinpath(DEMO_FILE).read_text(encoding="utf-8")


def expected_demo_capture_text() -> str:
    return format_capture(demo_capture())


if __name__ == "__main__":
    write_demo_capture(Path(__file__).resolve().parent / "data" / DEMO_FILE)
