"""Writes a command's results: a fresh output folder per run, every file atomic, every failure one line; no formats.

Single-run commands (`replay`, `demo`, later `export` and `simulate`) call `OutputFolder.prepare`: the folder is
made if needed, and this program's own outputs of an earlier run (only the names in `OWN_FILES`) and the hidden
temporary files a killed run left behind are removed, so the folder holds only files of this run. Other files are
never touched. Every `OSError` becomes a `PhysinkError` naming the path and the cause (exit status 1).

`StdoutGuard` wraps ``sys.stdout`` for the CLI: a reader that goes away (``| head -1``) ends the printing quietly
while the command carries on writing its files; any other write error (``> /dev/full``) also silences it, and the
CLI reports it as one line naming stdout (exit status 1) once the command has written its files.
"""

from __future__ import annotations

import errno
import os
import re
from collections.abc import Iterable
from pathlib import Path
from typing import Any, TextIO

from physink_tui.errors import PhysinkError
from physink_tui.formats.atomic_write import write_text_atomic

#: Every file name a run of this program writes into an output folder (and so removes from a reused one).
OWN_FILES = ("project.json", "timeline.json", "timeline.txt", "gestures.jsonl", "samples.jsonl", "summary.txt",
             "session.physink.jsonl", "result.json", "video.mp4", "video.gif", "video.webm", "demo.mp4", "scene.png")

#: The temporary files the atomic writers make for those names: ``.NAME.<random>.tmp`` (``.part`` for videos).
_OWN_TMP = re.compile(r"^\.(" + "|".join(re.escape(n) for n in OWN_FILES) + r")\.[^/]+\.(tmp|part)$")
#: Frame files in a frames folder: ``00000.png`` ... (and their temporary files).
FRAME_FILE = re.compile(r"^(\d{5}\.png|\.\d{5}\.png\.[^/]+\.tmp)$")


def prepare_frames_folder(path: str | os.PathLike[str]) -> Path:
    """``path`` made if needed and cleared of the frames an earlier run left there (only ``NNNNN.png`` files).

    Raises:
        PhysinkError: the folder cannot be made or cleared (path and cause named).
    """
    folder = Path(path)
    if folder.exists() and not folder.is_dir():
        raise PhysinkError(f"{folder}: cannot write frames there: it exists and is not a folder")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for old in folder.iterdir():
            if FRAME_FILE.match(old.name) and old.is_file():
                old.unlink()
    except OSError as exc:
        raise PhysinkError(f"{folder}: cannot prepare the frames folder: {reason(exc)}") from None
    return folder


def reason(exc: OSError) -> str:
    """The cause of an OS error in words: its strerror, else its text."""
    if isinstance(exc, FileExistsError | NotADirectoryError) and exc.errno in (errno.EEXIST, errno.ENOTDIR):
        return f"{exc.strerror} (a file is in the way of a folder)"
    return exc.strerror or str(exc)


class OutputFolder:
    """One run's output folder: `prepare` it, then `write` each file by name."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)

    @classmethod
    def prepare(cls, path: str | os.PathLike[str]) -> OutputFolder:
        """The folder made if needed and cleared of this program's earlier outputs and leftover temporary files.

        Raises:
            PhysinkError: the folder cannot be made or an old output cannot be removed (path and cause named).
        """
        folder = cls(path)
        out = folder.path
        if out.exists() and not out.is_dir():
            raise PhysinkError(f"{out}: cannot use as the output folder: it exists and is not a folder")
        try:
            out.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise PhysinkError(f"{out}: cannot create the output folder: {reason(exc)}") from None
        try:
            names = os.listdir(out)
        except OSError as exc:
            raise PhysinkError(f"{out}: cannot read the output folder: {reason(exc)}") from None
        for name in sorted(names):
            if (name in OWN_FILES or _OWN_TMP.match(name)) and not (out / name).is_dir():
                try:
                    (out / name).unlink()
                except FileNotFoundError:
                    pass
                except OSError as exc:
                    raise PhysinkError(f"{out / name}: cannot remove the previous run's file: {reason(exc)}") from None
        return folder

    def file(self, name: str) -> Path:
        """The path of output ``name`` in this folder."""
        return self.path / name

    def write(self, name: str, text: str) -> Path:
        """Writes ``text`` to output ``name`` atomically and returns its path.

        Raises:
            PhysinkError: the file cannot be written (read-only or full folder...): path and cause named.
        """
        target = self.path / name
        try:
            write_text_atomic(target, text)
        except OSError as exc:
            raise PhysinkError(f"{target}: cannot write: {reason(exc)}") from None
        return target


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
