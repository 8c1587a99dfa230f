"""`StdoutGuard`: ``sys.stdout`` for the CLI, which never raises: a vanished reader silences it, another write error is
reported once the command is done; and `reason`, an OS error's cause in words.

A reader that goes away (``| head -1``) ends the printing quietly while the command carries on writing its files;
any other write error (``> /dev/full``) also silences it, and the CLI reports it as one line naming stdout (exit
status 1) once the command has written its files. Kept apart from `outputs` so that every command's start-up
imports only this.
"""

from __future__ import annotations

import errno
import os
from collections.abc import Iterable
from typing import Any, TextIO

from physink_tui.errors import PhysinkError


def reason(exc: OSError) -> str:
    """The cause of an OS error in words: its strerror, else its text."""
    if isinstance(exc, FileExistsError | NotADirectoryError) and exc.errno in (errno.EEXIST, errno.ENOTDIR):
        return f"{exc.strerror} (a file is in the way of a folder)"
    return exc.strerror or str(exc)


class StdoutGuard:
    """A stand-in for ``sys.stdout`` that never raises: a failed write silences it (`error` keeps any but EPIPE)."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        self.broken = False
        #: the first write error other than a broken pipe, reported by the CLI when the command has finished
        self.error: PhysinkError | None = None

    def write(self, text: str) -> int:
        if not self.broken:
            try:
                return self.stream.write(text)
            except OSError as exc:
                self._fail(exc)
        return len(text)

    def writelines(self, lines: Iterable[str]) -> None:
        for line in lines:
            self.write(line)

    def flush(self) -> None:
        if not self.broken:
            try:
                self.stream.flush()
            except OSError as exc:
                self._fail(exc)

    def _fail(self, exc: OSError) -> None:
        self.broken = True
        self._silence()
        if not isinstance(exc, BrokenPipeError):
            self.error = PhysinkError(f"<stdout>: cannot write: {reason(exc)}")

    def _silence(self) -> None:
        """Points file descriptor 1 at /dev/null so the interpreter's last flush stays quiet."""
        try:
            fd = self.stream.fileno()
        except (OSError, ValueError, AttributeError):
            return
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, fd)
        os.close(devnull)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.stream, name)
