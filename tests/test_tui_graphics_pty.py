"""`physink tui` in a real pseudo-terminal (not Textual's headless driver): with TERM naming a Kitty or Sixel
terminal and a window size in pixels, the scene goes out as graphics escapes through Textual's own output, and
they decode to a frame of the scene view's cells at the terminal's cell size; with any other TERM, half-blocks."""

from __future__ import annotations

import fcntl
import os
import pty
import re
import select
import signal
import struct
import sys
import termios
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from terminal_graphics import kitty_image, sixel_image

from physink_tui.render import kitty
from physink_tui.tui.widgets.scene_view import KITTY_IMAGE

ROOT = Path(__file__).resolve().parent.parent
CELLS, PIXELS = (120, 40), (1200, 800)  # 10 x 20 pixels a cell
HANG_GUARD = 120.0
"""Seconds after which the test stops reading and fails (only a stuck app gets there, never a slow one)."""
KITTY_SEND = re.compile(r"\x1b_Ga=T[^\x1b]*m=(?:0[;\x1b][^\x1b]*\x1b\\|1;[^\x1b]*\x1b\\(?:\x1b_Gm=1;[^\x1b]*\x1b\\)*"
                        r"\x1b_Gm=0;[^\x1b]*\x1b\\)")
"""A whole Kitty image: its first chunk, then (if it said more) the chunks up to the last (``m=0``)."""
SIXEL_IMAGE = re.compile(r"\x1b7\x1b\[(\d+);(\d+)H(\x1bP0;1;0q.*?\x1b\\)\x1b8", re.S)


def run_tui(term: str, tmp_path: Path, until: Callable[[str], bool], colours: str | None = None) -> str:
    """What ``physink tui`` wrote to a 120x40 pty of 1200x800 pixels until ``until(written so far)``, then asked
    to quit (``colours``: ``COLORTERM``, e.g. ``truecolor``)."""
    pid, fd = pty.fork()
    if pid == 0:  # the child: the app, as a user starts it
        env = {k: v for k, v in os.environ.items() if k not in ("TMUX", "PHYSINK_GRAPHICS", "KITTY_WINDOW_ID",
                                                                 "TERM_PROGRAM", "COLORTERM")}
        env.update({"COLORTERM": colours} if colours else {})
        env.update(TERM=term, PYTHONPATH=str(ROOT), XDG_DATA_HOME=str(tmp_path / "data"),
                   XDG_CONFIG_HOME=str(tmp_path / "config"))
        os.execve(sys.executable, [sys.executable, "-m", "physink_tui", "tui"], env)
    fcntl.ioctl(fd, termios.TIOCSWINSZ, struct.pack("HHHH", CELLS[1], CELLS[0], *PIXELS))
    out = b""
    try:
        deadline = time.monotonic() + HANG_GUARD
        while not until(out.decode("utf-8", errors="replace")):
            assert time.monotonic() < deadline, f"not seen in {HANG_GUARD:g} s: {out[-500:]!r}"
            if select.select([fd], [], [], 0.1)[0]:
                try:
                    out += os.read(fd, 1 << 16)
                except OSError:
                    break
        os.write(fd, b"q")
        time.sleep(0.5)
    finally:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        os.close(fd)
    return out.decode("utf-8", errors="replace")


@pytest.mark.slow
@pytest.mark.parametrize("colours", ["truecolor", None])
def test_a_kitty_terminal_gets_the_scene_as_kitty_graphics_in_placeholder_cells(tmp_path, colours) -> None:
    out = run_tui("xterm-kitty", tmp_path, lambda out: KITTY_SEND.search(out) is not None
                  and kitty.PLACEHOLDER in out[KITTY_SEND.search(out).end():], colours=colours)
    sends = [m.group(0) for m in KITTY_SEND.finditer(out)]
    keys, pixels = kitty_image(sends[-1])
    columns, rows = int(keys["c"]), int(keys["r"])
    assert pixels.shape == (rows * 20, columns * 10, 4) and 60 < columns < 120 and 30 < rows < 40
    image = KITTY_IMAGE["truecolor" if colours else "256"]
    assert keys["i"] == str(image)
    colour = "2;" + ";".join(map(str, kitty.id_colour(image))) if colours else f"5;{image}"
    first = f"\x1b[38;{colour}m" + kitty.PLACEHOLDER + kitty.DIACRITICS[0] + kitty.DIACRITICS[0]
    assert first in out  # the first row's first cell, in the colour that names the image
    assert "\u2580" not in out


@pytest.mark.slow
def test_a_sixel_terminal_gets_the_scene_as_sixel_at_the_view(tmp_path) -> None:
    out = run_tui("foot", tmp_path, lambda out: SIXEL_IMAGE.search(out) is not None)
    row, column, data = SIXEL_IMAGE.findall(out)[-1]
    assert (int(row), int(column)) == (1, 1)  # the scene view's top left cell
    pixels = sixel_image(data)
    assert pixels.shape[0] % 20 == 0 and pixels.shape[1] % 10 == 0 and 60 < pixels.shape[1] / 10 < 120


@pytest.mark.slow
def test_another_terminal_gets_half_blocks(tmp_path) -> None:
    out = run_tui("xterm-256color", tmp_path, lambda out: "\u2580" in out)
    # no Kitty image sent (the start's graphics query, ``\x1b_Gi=31,…a=q``, is not one) and no Sixel picture
    assert "\u2580" in out and "\x1b_Ga=T" not in out and "\x1bP0;1;0q" not in out


# -- the terminal's own answers decide (issue 30) --------------------------------------------------------------------


def _tui_in(tmp_path: Path, answer: bytes):
    from pty_terminal import PtyProgram

    env = {k: v for k, v in os.environ.items() if k not in ("TMUX", "PHYSINK_GRAPHICS", "KITTY_WINDOW_ID",
                                                             "TERM_PROGRAM", "COLORTERM")}
    env.update(TERM="xterm-256color", PYTHONPATH=str(ROOT), XDG_DATA_HOME=str(tmp_path / "data"),
               XDG_CONFIG_HOME=str(tmp_path / "config"))
    return PtyProgram([sys.executable, "-m", "physink_tui", "tui"], env=env, cwd=tmp_path, answer=answer)


@pytest.mark.slow
def test_a_terminal_announcing_sixel_gets_sixel_whatever_term_says(tmp_path) -> None:
    from test_terminal_graphics import XTERM_VT340

    with _tui_in(tmp_path, XTERM_VT340) as tui:  # TERM=xterm-256color names no graphics; the DA1 answer does
        tui.wait_for(lambda s: "SKETCH" in s, "the control panel")
        tui.wait_for(lambda s: b"\x1bP0;1;0q" in tui.raw, "a Sixel picture")
        tui.send(b"q")
        assert tui.wait_exit() == 0


@pytest.mark.slow
def test_kitty_026_gets_half_blocks_and_a_note_saying_why(tmp_path) -> None:
    from test_terminal_graphics import KITTY_026

    with _tui_in(tmp_path, KITTY_026) as tui:
        screen = tui.wait_for(lambda s: "0.26.5" in s and "placeholders" in s, "the note about kitty 0.26")
        tui.wait_for(lambda s: "\u2580" in s, "half-blocks")
        assert b"\x1b_Ga=T" not in tui.raw and "SKETCH" in screen
        tui.send(b"q")
        assert tui.wait_exit() == 0
