"""Atomic file writes (text or bytes): a complete new file or the old one untouched; knows no file format."""

from __future__ import annotations

import os


def write_text_atomic(path: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` (UTF-8, newlines as written) to ``path`` atomically; see `write_bytes_atomic`.

    Raises:
        OSError: the file cannot be written; the temporary file is removed and ``path`` is unchanged.
    """
    write_bytes_atomic(path, text.encode("utf-8"))


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file in the same folder, flushed, fsynced and renamed.

    A file already at ``path`` keeps its permission bits; a new file gets 0o644.

    Raises:
        OSError: the file cannot be written; the temporary file is removed and ``path`` is unchanged.
    """
    target = os.path.abspath(os.fspath(path))
    directory, base = os.path.split(target)
    try:
        mode = os.stat(target).st_mode & 0o777
    except FileNotFoundError:
        mode = 0o644
    import tempfile  # here, not at the top: a command that writes no file (`physink decode`) starts without it

    fd, tmp = tempfile.mkstemp(prefix=f".{base}.", suffix=".tmp", dir=directory)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fchmod(f.fileno(), mode)
            os.fsync(f.fileno())
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
    fsync_directory(directory)


def fsync_directory(directory: str) -> None:
    """Makes the rename durable where the platform allows it (best effort)."""
    try:
        dir_fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(dir_fd)
    except OSError:
        pass  # some file systems cannot fsync a directory; the rename itself is still atomic
    finally:
        os.close(dir_fd)
