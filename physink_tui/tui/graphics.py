"""Which picture the terminal can show (Kitty graphics, Sixel, or Unicode half-blocks) and how many pixels a cell
has, from the environment and the tty's window size, read before Textual owns the terminal; draws nothing.

Terminals that speak a graphics protocol say who they are in ``TERM``, ``TERM_PROGRAM`` or their own variables;
inside tmux or screen neither protocol gets through unless configured, so half-blocks are chosen there. The
choice can be forced with ``PHYSINK_GRAPHICS=kitty|sixel|halfblocks``. No escape query is sent: an unanswered
query would have to time out at every start, and a key pressed meanwhile would be lost.
"""

from __future__ import annotations

import fcntl
import os
import struct
import termios
from collections.abc import Mapping

from physink_tui.errors import RenderError

KINDS = ("kitty", "sixel", "halfblocks")
KITTY_PROGRAMS = ("ghostty",)
"""``TERM_PROGRAM`` values of terminals that show Kitty graphics with Unicode placeholders."""
SIXEL_TERMS = ("foot", "mlterm", "yaft", "contour", "xterm-sixel")
SIXEL_PROGRAMS = ("WezTerm", "iTerm.app", "mintty", "konsole")
DEFAULT_CELL = (10, 20)
"""Pixels a cell is taken to have when the terminal does not say (VT340's)."""


def choose(env: Mapping[str, str] | None = None) -> str:
    """``kitty``, ``sixel`` or ``halfblocks`` for the terminal ``env`` (default: this process's) describes.

    Raises:
        RenderError: ``PHYSINK_GRAPHICS`` names no kind.
    """
    env = os.environ if env is None else env
    forced = env.get("PHYSINK_GRAPHICS")
    if forced is not None:
        if forced not in KINDS:
            raise RenderError(f"PHYSINK_GRAPHICS={forced!r}: expected one of {', '.join(KINDS)}")
        return forced
    term, program = env.get("TERM", ""), env.get("TERM_PROGRAM", "")
    if env.get("TMUX") or term.startswith(("tmux", "screen")):
        return "halfblocks"
    if term == "xterm-kitty" or env.get("KITTY_WINDOW_ID") or program in KITTY_PROGRAMS:
        return "kitty"
    if term in SIXEL_TERMS or program in SIXEL_PROGRAMS:
        return "sixel"
    return "halfblocks"


def cell_pixels(fd: int | None = None) -> tuple[int, int]:
    """(width, height) in pixels of one cell of the terminal on ``fd`` (default: stdout), from its window size;
    `DEFAULT_CELL` when it does not say or is not a terminal."""
    fd = 1 if fd is None else fd
    try:
        rows, columns, xpixels, ypixels = struct.unpack("HHHH", fcntl.ioctl(fd, termios.TIOCGWINSZ, b"\0" * 8))
    except OSError:
        return DEFAULT_CELL
    if not (rows and columns and xpixels and ypixels):
        return DEFAULT_CELL
    return max(1, xpixels // columns), max(1, ypixels // rows)
