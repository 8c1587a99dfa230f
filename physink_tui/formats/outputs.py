"""Writes a command's results: a fresh output folder per run, every file atomic, every failure one line; no formats.

Single-run commands (`replay`, `demo`, later `export` and `simulate`) call `OutputFolder.prepare`: the folder is
made if needed, and this program's own outputs of an earlier run (only the names in `OWN_FILES`) and the hidden
temporary files a killed run left behind are removed, so the folder holds only files of this run. Other files are
never touched. Every `OSError` becomes a `PhysinkError` naming the path and the cause (exit status 1).

`reason` (an OS error's cause in words) lives in `stdout_guard`, beside the CLI's ``sys.stdout`` wrapper, and is
imported here for the callers that have always found it here.
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Iterable
from pathlib import Path

from physink_tui.errors import PhysinkError
from physink_tui.formats.atomic_write import fsync_directory, write_text_atomic
from physink_tui.formats.stdout_guard import reason as reason  # (re-exported: its callers import it from here)

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


def check_outputs(inputs: Iterable[str | os.PathLike[str]],
                  outputs: Iterable[tuple[str, str | os.PathLike[str]]]) -> None:
    """Refuses a run whose outputs would destroy something: an output that is one of the run's inputs, that
    exists and is not a regular file (a device such as ``/dev/full``, a FIFO, a symlink, a folder), or that is
    another output of the same run. Call it before anything is written.

    Args:
        inputs: the files the run reads.
        outputs: ``(option, path)`` for each file the run writes (``("--still", "x.png")``).

    Raises:
        PhysinkError: one line naming the path, the option and what it would destroy.
    """
    read = {}
    for path in inputs:
        try:
            read[_identity(path)] = os.fspath(path)
        except OSError:
            continue  # an input that cannot be read says so when it is read
    written: dict[object, str] = {}
    for option, path in outputs:
        name = os.fspath(path)
        try:
            st = os.lstat(name)
        except FileNotFoundError:
            st = None
        except OSError as exc:
            raise PhysinkError(f"{name}: cannot write {option} there: {reason(exc)}") from None
        if st is not None and not stat.S_ISREG(st.st_mode):
            raise PhysinkError(f"{name}: {option} would replace {_kind(st.st_mode)}; give the path of a regular "
                               "file (or a new one)")
        key = _identity(name) if st is not None else ("new", os.path.realpath(name))
        if key in read:
            raise PhysinkError(f"{name}: {option} would replace {read[key]}, an input of this run; write it "
                               "elsewhere")
        if key in written:
            raise PhysinkError(f"{name}: {option} names the same file as {written[key]}; give each output its "
                               "own file")
        written[key] = option


def _identity(path: str | os.PathLike[str]) -> object:
    """What makes two paths the same file: device and inode when it exists."""
    st = os.stat(path)
    return ("file", st.st_dev, st.st_ino)


def _kind(mode: int) -> str:
    for test, words in ((stat.S_ISLNK, "a symbolic link"), (stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO"),
                        (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                        (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return words
    return "a file that is not a regular file"


class OutputFolder:
    """One run's output folder: `prepare` it, then `write` each file by name."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        self._staged: dict[str, Path] | None = None  # name -> staging file, for a `staged` folder
        self._token = ""

    @classmethod
    def prepare(cls, path: str | os.PathLike[str]) -> OutputFolder:
        """The folder made if needed and cleared of this program's earlier outputs and leftover temporary files.

        Raises:
            PhysinkError: the folder cannot be made or an old output cannot be removed (path and cause named).
        """
        folder = cls(path)
        out = folder.path
        for name in _made_and_listed(out):
            if (name in OWN_FILES or _OWN_TMP.match(name)) and not (out / name).is_dir():
                try:
                    (out / name).unlink()
                except FileNotFoundError:
                    pass
                except OSError as exc:
                    raise PhysinkError(f"{out / name}: cannot remove the previous run's file: {reason(exc)}") from None
        return folder

    @classmethod
    def staged(cls, path: str | os.PathLike[str]) -> OutputFolder:
        """The folder made if needed and cleared of leftover temporary files only: the previous run's outputs
        stay until `commit`. Each `write` goes to a hidden ``.NAME.<run>.tmp`` beside the old file; `commit`
        renames them over the old ones and then removes the previous run's outputs this run did not write. A run
        killed before `commit` leaves the previous complete result (and temporary files the next run removes).

        Raises:
            PhysinkError: as `prepare`.
        """
        folder = cls(path)
        out = folder.path
        for name in _made_and_listed(out):
            if _OWN_TMP.match(name) and not (out / name).is_dir():
                try:
                    (out / name).unlink()
                except OSError:
                    pass  # another run's, still being written
        folder._staged = {}
        import secrets  # here, not at the top: only a run that writes files needs it

        folder._token = f"{os.getpid()}-{secrets.token_hex(4)}"
        return folder

    def commit(self) -> None:
        """Renames every staged file over the previous run's (the outputs of a `staged` folder appear together).

        Raises:
            PhysinkError: a file cannot be renamed or an old output removed (path and cause named).
        """
        staged = self._staged
        if staged is None:
            raise RuntimeError(f"{self.path}: commit() of a folder that stages nothing (see OutputFolder.staged)")
        for name, staging in staged.items():
            try:
                os.replace(staging, self.path / name)
            except OSError as exc:
                raise PhysinkError(f"{self.path / name}: cannot write: {reason(exc)}") from None
        fsync_directory(str(self.path))
        for name in OWN_FILES:
            if name not in staged and (self.path / name).is_file():
                try:
                    (self.path / name).unlink()
                except OSError as exc:
                    raise PhysinkError(f"{self.path / name}: cannot remove the previous run's file: "
                                       f"{reason(exc)}") from None
        self._staged = {}

    def discard(self) -> None:
        """Removes the staged files (the run failed): the previous run's outputs stay as they were."""
        for staging in (self._staged or {}).values():
            try:
                os.unlink(staging)
            except OSError:
                pass
        self._staged = {}

    def file(self, name: str) -> Path:
        """The path of output ``name`` in this folder."""
        return self.path / name

    def write(self, name: str, text: str) -> Path:
        """Writes ``text`` to output ``name`` atomically and returns its path.

        Raises:
            PhysinkError: the file cannot be written (read-only or full folder...): path and cause named.
        """
        target = self.path / name
        if self._staged is not None:
            staging = self.path / f".{name}.{self._token}.tmp"
            try:
                write_text_atomic(staging, text)
            except OSError as exc:
                raise PhysinkError(f"{target}: cannot write: {reason(exc)}") from None
            self._staged[name] = staging
            return target
        try:
            write_text_atomic(target, text)
        except OSError as exc:
            raise PhysinkError(f"{target}: cannot write: {reason(exc)}") from None
        return target


def _made_and_listed(out: Path) -> list[str]:
    """The names in the output folder ``out``, sorted, the folder made first if needed.

    Raises:
        PhysinkError: ``out`` is not a folder, or cannot be made or read (path and cause named).
    """
    if out.exists() and not out.is_dir():
        raise PhysinkError(f"{out}: cannot use as the output folder: it exists and is not a folder")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise PhysinkError(f"{out}: cannot create the output folder: {reason(exc)}") from None
    try:
        return sorted(os.listdir(out))
    except OSError as exc:
        raise PhysinkError(f"{out}: cannot read the output folder: {reason(exc)}") from None
