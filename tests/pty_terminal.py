"""A program run in a pseudo-terminal whose output goes through a terminal emulator (pyte), so a test reads the screen
a person would see and waits until it shows something, never for a fixed time. Like a real terminal it answers the
primary device-attributes query (as a VT102: no graphics)."""

from __future__ import annotations

import fcntl
import os
import pty
import select
import signal
import struct
import termios
import time
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import pyte

HANG_GUARD = 90.0
"""Seconds after which a wait gives up: only a hung program gets there (a guard, not a timing)."""


class _Screen(pyte.Screen):
    """pyte's screen, answering the program's device-attributes query as a VT102 does (``CSI ? 6 c``)."""

    def __init__(self, columns: int, rows: int, answer: Callable[[bytes], object]) -> None:
        super().__init__(columns, rows)
        self._answer = answer

    def write_process_input(self, data: str) -> None:
        self._answer(data.encode())


class PtyProgram:
    """``argv`` started in a ``columns`` x ``rows`` pty (``cwd``, ``env``); its screen in ``self.screen``."""

    def __init__(self, argv: Sequence[str], *, env: Mapping[str, str], cwd: Path, size: tuple[int, int] = (120, 40),
                 pixels: tuple[int, int] = (1200, 800), answer: bytes | None = None) -> None:
        """``answer``: what the terminal says to the program's first device-attributes query (the answers of
        another terminal, e.g. kitty's to its graphics query, XTVERSION and DA1), instead of a VT102's."""
        self.columns, self.rows = size
        self.answer = answer
        self.screen = _Screen(*size, answer=lambda data: None if answer else os.write(self.fd, data))
        self.stream = pyte.ByteStream(self.screen)
        self.raw = b""
        self.status: int | None = None
        pid, fd = pty.fork()
        if pid == 0:  # the child: the program, as a person starts it
            try:
                os.chdir(cwd)
                os.execvpe(argv[0], list(argv), dict(env))
            finally:
                os._exit(127)
        self.pid, self.fd = pid, fd
        fcntl.ioctl(fd, termios.TIOCSWINSZ, struct.pack("HHHH", size[1], size[0], *pixels))

    def text(self) -> str:
        """The screen as lines of text."""
        return "\n".join(self.screen.display)

    def _read(self, wait: float) -> bool:
        """Feeds what the program wrote within ``wait`` s to the screen; False once the pty is closed."""
        if not select.select([self.fd], [], [], wait)[0]:
            return True
        try:
            data = os.read(self.fd, 1 << 16)
        except OSError:  # EIO: the program and every child closed the terminal
            return False
        if not data:
            return False
        self.raw += data
        if self.answer is not None and b"\x1b[c" in self.raw:
            os.write(self.fd, self.answer)
            self.answer = None
        self.stream.feed(data)
        return True

    def wait_for(self, condition: Callable[[str], bool], what: str, guard: float = HANG_GUARD) -> str:
        """Reads until ``condition(screen text)`` holds; fails saying ``what`` and showing the screen after ``guard``
        seconds or when the program ends first."""
        deadline = time.monotonic() + guard
        while time.monotonic() < deadline:
            if condition(self.text()):
                return self.text()
            if not self._read(0.1):
                break
        raise AssertionError(f"the screen never showed {what}; it shows:\n{self.text()}")

    def send(self, data: bytes) -> None:
        os.write(self.fd, data)

    def wait_exit(self, guard: float = HANG_GUARD) -> int:
        """The exit status once the program ends (its output read meanwhile); fails after ``guard`` seconds."""
        deadline = time.monotonic() + guard
        while time.monotonic() < deadline:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                self.status = os.waitstatus_to_exitcode(status)
                while self._read(0):
                    if not select.select([self.fd], [], [], 0)[0]:
                        break
                return self.status
            self._read(0.05)
        raise AssertionError(f"the program did not end within {guard:g} s; its screen:\n{self.text()}")

    def close(self) -> None:
        """Ends the program if it still runs; closes the pty."""
        if self.status is None:
            try:
                os.kill(self.pid, signal.SIGKILL)
                os.waitpid(self.pid, 0)
            except (ProcessLookupError, ChildProcessError):
                pass
        os.close(self.fd)

    def __enter__(self) -> PtyProgram:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
