"""Which picture the terminal can show (Kitty graphics, Sixel, or Unicode half-blocks) and how many pixels a cell
has, asked of the terminal itself before Textual owns it; draws nothing.

`probe` sends three queries and reads the answers: Kitty's graphics query (a terminal that shows Kitty graphics
answers ``OK``), XTVERSION (the terminal's name and version) and, last, the primary device attributes (DA1), which
every terminal answers, so the wait ends as soon as it arrives (a terminal that answers nothing costs `PROBE_WAIT`).
A DA1 answer with attribute 4 announces Sixel. Kitty graphics are shown through Unicode placeholders, which kitty
has had since 0.28: an older kitty (Debian 12's is 0.26) gets half-blocks and a note saying why. Only a terminal that
answers nothing is judged by ``TERM``, ``TERM_PROGRAM`` and its own variables. Inside tmux or screen neither protocol
gets through unless configured, so half-blocks are chosen there without asking. The choice can be forced with
``PHYSINK_GRAPHICS=kitty|sixel|halfblocks``. A key pressed during the probe (a few milliseconds) is lost.
"""

from __future__ import annotations

import fcntl
import os
import re
import select
import struct
import termios
import time
from collections.abc import Mapping
from dataclasses import dataclass

from physink_tui.errors import RenderError

KINDS = ("kitty", "sixel", "halfblocks")
KITTY_PROGRAMS = ("ghostty",)
"""``TERM_PROGRAM`` values of terminals that show Kitty graphics with Unicode placeholders."""
SIXEL_TERMS = ("foot", "mlterm", "yaft", "contour", "xterm-sixel")
SIXEL_PROGRAMS = ("WezTerm", "iTerm.app", "mintty", "konsole")
DEFAULT_CELL = (10, 20)
"""Pixels a cell is taken to have when the terminal does not say (VT340's)."""


PLACEHOLDERS = (0, 28)
"""The kitty version that shows images through Unicode placeholder cells (what the scene view sends)."""
SIXEL_ATTRIBUTE = 4
"""The DA1 attribute that announces Sixel graphics."""
KITTY_QUERY_ID = 31
QUERIES = (f"\x1b_Gi={KITTY_QUERY_ID},s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\"  # Kitty graphics: a 1x1 query, not kept
           "\x1b[>0q"  # XTVERSION: name and version
           "\x1b[c").encode()  # DA1: every terminal answers; its answer ends the wait
PROBE_WAIT = 1.0
"""Seconds to wait for the DA1 answer (terminals answer within milliseconds)."""
_DA1 = re.compile(rb"\x1b\[\?([0-9;]*)c")
_XTVERSION = re.compile(rb"\x1bP>\|([^\x1b]*)\x1b\\")
_KITTY_OK = re.compile(rb"\x1b_Gi=%d;OK\x1b\\" % KITTY_QUERY_ID)


@dataclass(frozen=True, slots=True)
class TerminalReply:
    """What the terminal answered to `QUERIES`.

    Attributes:
        attributes: the DA1 parameters (``62;4;22`` → {62, 4, 22}); 4 means Sixel.
        kitty_graphics: it answered Kitty's graphics query with OK.
        version: its XTVERSION answer (``XTerm(379)``, ``kitty(0.26.5)``), or None.
    """

    attributes: frozenset[int]
    kitty_graphics: bool = False
    version: str | None = None

    @classmethod
    def parse(cls, data: bytes) -> TerminalReply | None:
        """The answers in ``data`` (what the terminal sent back), or None without a DA1 answer.

        >>> TerminalReply.parse(b"\\x1bP>|XTerm(379)\\x1b\\\\\\x1b[?63;1;2;4;6;9;15;16;22;28;29c").attributes >= {4}
        True
        """
        da1 = _DA1.search(data)
        if da1 is None:
            return None
        attributes = frozenset(int(p) for p in da1[1].split(b";") if p.isdigit())
        version = _XTVERSION.search(data)
        return cls(attributes, _KITTY_OK.search(data) is not None,
                   version[1].decode("utf-8", "replace") if version else None)

    def kitty_version(self) -> tuple[int, ...] | None:
        """kitty's version from XTVERSION (``kitty(0.26.5)`` → (0, 26, 5)); None from any other terminal."""
        match = re.fullmatch(r"kitty\(([0-9.]+)\)", self.version or "")
        return tuple(int(n) for n in match[1].split(".") if n) if match else None


def probe(fd_in: int = 0, fd_out: int = 1, wait: float = PROBE_WAIT) -> TerminalReply | None:
    """Ask the terminal on ``fd_in``/``fd_out`` (`QUERIES`) and read its answers until DA1's; None when either is
    not a terminal or nothing answered within ``wait`` seconds. The terminal's modes are restored after."""
    if not (os.isatty(fd_in) and os.isatty(fd_out)):
        return None
    saved = termios.tcgetattr(fd_in)
    quiet = termios.tcgetattr(fd_in)
    quiet[3] &= ~(termios.ICANON | termios.ECHO)  # answers come byte by byte and are not echoed
    quiet[6][termios.VMIN], quiet[6][termios.VTIME] = 0, 0
    data = b""
    try:
        termios.tcsetattr(fd_in, termios.TCSANOW, quiet)
        os.write(fd_out, QUERIES)
        deadline = time.monotonic() + wait
        while _DA1.search(data) is None:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([fd_in], [], [], left)[0]:
                break
            chunk = os.read(fd_in, 4096)
            if not chunk:
                break
            data += chunk
    except OSError:
        return None
    finally:
        termios.tcsetattr(fd_in, termios.TCSANOW, saved)
    return TerminalReply.parse(data)


def choose(env: Mapping[str, str] | None = None, reply: TerminalReply | None = None) -> str:
    """``kitty``, ``sixel`` or ``halfblocks`` for the terminal that answered ``reply`` (`probe`), or, when it
    answered nothing, the one ``env`` (default: this process's) describes.

    Raises:
        RenderError: ``PHYSINK_GRAPHICS`` names no kind.
    """
    return choice(env, reply)[0]


def choice(env: Mapping[str, str] | None = None, reply: TerminalReply | None = None) -> tuple[str, str | None]:
    """`choose`'s kind and a note for the user when the terminal could show more than it will (an old kitty)."""
    env = os.environ if env is None else env
    forced = env.get("PHYSINK_GRAPHICS")
    if forced is not None:
        if forced not in KINDS:
            raise RenderError(f"PHYSINK_GRAPHICS={forced!r}: expected one of {', '.join(KINDS)}")
        return forced, None
    term, program = env.get("TERM", ""), env.get("TERM_PROGRAM", "")
    if env.get("TMUX") or term.startswith(("tmux", "screen")):
        return "halfblocks", None
    if reply is not None:  # the terminal said what it can do
        version = reply.kitty_version()
        if reply.kitty_graphics and version is not None and version < PLACEHOLDERS:
            shown = ".".join(map(str, version))
            return "halfblocks", (f"kitty {shown} shows images, but not through Unicode placeholders (kitty 0.28 and "
                                  "later), which the scene view uses: it is drawn in half-blocks. Update kitty to see "
                                  "the scene at full resolution.")
        if reply.kitty_graphics:
            return "kitty", None
        if SIXEL_ATTRIBUTE in reply.attributes:
            return "sixel", None
        return "halfblocks", None
    if term == "xterm-kitty" or env.get("KITTY_WINDOW_ID") or program in KITTY_PROGRAMS:
        return "kitty", None
    if term in SIXEL_TERMS or program in SIXEL_PROGRAMS:
        return "sixel", None
    return "halfblocks", None


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
