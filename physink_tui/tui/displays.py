"""Which display a pen display is, and where the canvas lies on it: the X monitors (``xrandr --listmonitors``), the
terminal window's place (``xwininfo -id $WINDOWID``) and the tablet area that covers the canvas drawn in it;
reads the X server through those two programs, decides no mapping itself (the settings screen fills the form).

A pen display's surface is a monitor: its tablet area is that monitor's pixels. The canvas is drawn in part of
the terminal window, so the area to use is the canvas's rectangle as fractions of the monitor it is on.
"""

from __future__ import annotations

import os
import re
import subprocess
from dataclasses import dataclass

from physink_tui.errors import PhysinkError

_MONITOR = re.compile(r"^\s*\d+:\s+[+*]*(\S+)\s+(\d+)/\d+x(\d+)/\d+\+(-?\d+)\+(-?\d+)")


@dataclass(frozen=True, slots=True)
class Rect:
    """A rectangle of the X screen, pixels: left, top, width, height (> 0)."""

    x: float
    y: float
    width: float
    height: float


@dataclass(frozen=True, slots=True)
class Monitor:
    """One monitor: its output name (``DP-1``) and where it is on the X screen."""

    name: str
    rect: Rect


def parse_monitors(text: str) -> list[Monitor]:
    """The monitors ``xrandr --listmonitors`` printed (``0: +*DP-1 2560/597x1440/336+0+0  DP-1``)."""
    out = []
    for line in text.splitlines():
        m = _MONITOR.match(line)
        if m:
            name, w, h, x, y = m.groups()
            out.append(Monitor(name, Rect(float(x), float(y), float(w), float(h))))
    return out


def parse_window(text: str) -> Rect:
    """The window ``xwininfo -id ID`` describes (absolute upper-left corner, width, height).

    Raises:
        PhysinkError: a value is missing.
    """
    values = {}
    for key, pattern in (("x", r"Absolute upper-left X:\s*(-?\d+)"), ("y", r"Absolute upper-left Y:\s*(-?\d+)"),
                         ("width", r"Width:\s*(\d+)"), ("height", r"Height:\s*(\d+)")):
        m = re.search(pattern, text)
        if m is None:
            raise PhysinkError(f"xwininfo: no {key} in its output {text[:80]!r}")
        values[key] = float(m.group(1))
    return Rect(**values)


def canvas_rect(window: Rect, cells: tuple[int, int], canvas: tuple[float, float, float, float]) -> Rect:
    """The canvas's rectangle on the X screen: ``canvas`` is (left, top, width, height) in cells (fractions
    allowed) of a terminal of ``cells`` (columns, rows) filling ``window``."""
    across, down = window.width / cells[0], window.height / cells[1]
    left, top, width, height = canvas
    return Rect(window.x + left * across, window.y + top * down, width * across, height * down)


def area_on(monitor: Monitor, rect: Rect) -> tuple[float, float, float, float]:
    """``rect`` as (x0, y0, x1, y1) fractions of ``monitor`` (a pen display's tablet area, unrotated).

    Raises:
        PhysinkError: ``rect`` is not wholly on the monitor.
    """
    m = monitor.rect
    x0, y0 = (rect.x - m.x) / m.width, (rect.y - m.y) / m.height
    x1, y1 = x0 + rect.width / m.width, y0 + rect.height / m.height
    if not (-1e-9 <= x0 < x1 <= 1 + 1e-9 and -1e-9 <= y0 < y1 <= 1 + 1e-9):
        raise PhysinkError(f"the canvas ({rect.width:g}x{rect.height:g} at {rect.x:g},{rect.y:g}) is not wholly on "
                           f"monitor {monitor.name} ({m.width:g}x{m.height:g} at {m.x:g},{m.y:g}): move the "
                           "terminal window onto the pen display")
    def fraction(v: float) -> float:
        return round(min(max(v, 0.0), 1.0), 4)

    return fraction(x0), fraction(y0), fraction(x1), fraction(y1)


def _run(args: list[str]) -> str:
    try:
        done = subprocess.run(args, capture_output=True, text=True, timeout=3, check=False)
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise PhysinkError(f"{args[0]}: cannot run it ({exc})") from None
    if done.returncode != 0:
        raise PhysinkError(f"{' '.join(args)}: exit status {done.returncode}: {done.stderr.strip()[:200]}")
    return done.stdout


def list_monitors() -> list[Monitor]:
    """The X monitors, or none (no X display, or no xrandr)."""
    if not os.environ.get("DISPLAY"):
        return []
    try:
        return parse_monitors(_run(["xrandr", "--listmonitors"]))
    except PhysinkError:
        return []


def terminal_window() -> Rect:
    """Where the terminal window (``$WINDOWID``, which X terminals set) is on the X screen.

    Raises:
        PhysinkError: no X display, no ``WINDOWID``, or xwininfo failed.
    """
    window = os.environ.get("WINDOWID", "")
    if not os.environ.get("DISPLAY") or not window.isdigit():
        raise PhysinkError("the terminal window's place is unknown (no X display, or the terminal sets no "
                           "WINDOWID): set the area by hand")
    return parse_window(_run(["xwininfo", "-id", window]))
