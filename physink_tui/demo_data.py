"""The bundled demo drawing: the thesis's egg cracker sketched with the virtual pen; no decoding.

`EGG_CRACKER` is the scripted drawing; `write_demo_capture()` regenerates the bundled capture
``physink_tui/data/egg-cracker.hid`` (deterministic, checked byte for byte by a test), and
`demo_capture_text()` reads it back from the installed package.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from physink_tui.input.capture import Capture
from physink_tui.input.capture_writer import format_capture, write_capture
from physink_tui.input.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.virtual_pen import Stroke, VirtualPen

DEMO_FILE = "egg-cracker.hid"
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
)
"""The egg cracker of the thesis (figure 2-4), drawn in the order a person would."""


def demo_pen() -> VirtualPen:
    """A UC-Logic/Huion v1 tablet at 200 Hz: the most common kind of inexpensive tablet."""
    return VirtualPen(REFERENCE_DEVICES["uclogic-v1"], rate_hz=200.0, seed=2026)


def demo_capture() -> Capture:
    return demo_pen().record(EGG_CRACKER)


def write_demo_capture(path: Path) -> None:
    write_capture(demo_capture(), path)


def demo_capture_text() -> str:
    """The bundled capture, as shipped in the package."""
    return resources.files("physink_tui.data").joinpath(DEMO_FILE).read_text(encoding="utf-8")


def expected_demo_capture_text() -> str:
    return format_capture(demo_capture())


if __name__ == "__main__":
    write_demo_capture(Path(__file__).resolve().parent / "data" / DEMO_FILE)
