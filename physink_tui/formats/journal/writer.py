"""Appends checked entries to a new journal file in whole-line batches, fsynced often; never reads or rewrites it.

The session owns one `JournalWriter` (it is not thread-safe) and calls `JournalWriter.append` for every input
and `JournalWriter.flush` once per tick. Durability, in order of what can go wrong:

- the process dies (crash, SIGKILL): every flushed batch is in the file (it is in the kernel after one
  ``write``); at most the last line can be cut, and the reader reports it as truncated;
- the machine dies: what was fsynced survives; `flush` fsyncs whenever `FSYNC_INTERVAL` has passed since
  the last fsync, so at most that much input plus the unflushed batch is lost;
- the disk fills up (or any write or fsync fails): the writer stops journalling. It raises one
  `JournalError` saying so and how many lines are intact, refuses every later `append` and `flush` with the
  same message, and removes the part of a line it had cut (the only change it makes that is not an append),
  so the file ends with a whole line.
"""

from __future__ import annotations

import errno
import os
import time
from collections.abc import Callable
from types import TracebackType

from physink_tui.errors import JournalError
from physink_tui.formats.atomic_write import fsync_directory
from physink_tui.formats.journal.codec import encode_entry
from physink_tui.formats.journal.entries import DeviceEntry, JournalEntry, JournalHeader
from physink_tui.formats.journal.header_codec import encode_header

FSYNC_INTERVAL = 0.1
"""Seconds: `JournalWriter.flush` fsyncs when at least this long has passed since the last fsync."""

AUTO_FLUSH_BYTES = 64 * 1024
"""`JournalWriter.append` flushes by itself once this many bytes are waiting, so memory stays bounded."""

_DISK_FULL = {errno.ENOSPC, errno.EDQUOT}


class JournalWriter:
    """Writes one journal: the header when created, then entries in time order. Use `create`.

    Attributes:
        path: the journal file.
        header: its header.
        lines_written: lines the file holds, header included (buffered entries are not counted).
        stopped: the message of the error that stopped journalling, or None while it works.
    """

    def __init__(self, path: str, fd: int, header: JournalHeader, size: int, clock: Callable[[], float]) -> None:
        """Takes over ``fd``, an ``O_APPEND`` file holding the header line and ``size`` bytes; see `create`."""
        self.path = path
        self.header = header
        self.lines_written = 1
        self.stopped: str | None = None
        self._fd = fd
        self._size = size
        self._clock = clock
        self._devices = {d.id for d in header.devices}
        self._buffer: list[str] = []
        self._buffered_bytes = 0
        self._last_t: float | None = None
        self._last_fsync = clock()
        self._unsynced = False
        self._closed = False

    @classmethod
    def create(
        cls, path: str | os.PathLike[str], header: JournalHeader, *, clock: Callable[[], float] = time.monotonic
    ) -> JournalWriter:
        """Create the journal file at ``path`` with its header line, fsynced.

        Args:
            path: the new file; it must not exist.
            header: the header; checked before the file is created.
            clock: seconds on a monotonic clock, read to pace fsyncs (tests pass a fake one).

        Raises:
            JournalError: the file exists (a journal is never overwritten), cannot be created or written,
                or the header is invalid (naming the key).
        """
        target = os.fspath(path)
        try:
            data = (encode_header(header) + "\n").encode("utf-8")
        except JournalError as e:
            raise JournalError(f"journal {target}: {e}") from None
        flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_APPEND | getattr(os, "O_CLOEXEC", 0)
        try:
            fd = os.open(target, flags, 0o644)
        except FileExistsError:
            raise JournalError(f"journal {target} already exists; a journal is never overwritten") from None
        except OSError as e:
            raise JournalError(f"cannot create journal {target}: {e.strerror or e}") from None
        try:
            done = 0
            while done < len(data):
                done += _write(fd, data, done)
            os.fsync(fd)
        except OSError as e:
            os.close(fd)
            _remove(target)
            raise JournalError(f"cannot create journal {target}: {e.strerror or e}") from None
        fsync_directory(os.path.dirname(os.path.abspath(target)))
        return cls(target, fd, header, len(data), clock)

    def check(self, entry: JournalEntry) -> None:
        """Whether `append` would take ``entry``: raises the `JournalError` it would raise for an invalid one."""
        try:
            encode_entry(entry, previous_t=self._last_t, devices=self._devices)
        except JournalError as e:
            raise JournalError(f"journal {self.path}: {e}") from None

    def append(self, entry: JournalEntry) -> None:
        """Check and buffer one entry; flushes by itself when `AUTO_FLUSH_BYTES` are waiting.

        Raises:
            JournalError: the entry is invalid (its t is before the previous entry's, its device is not in
                the header nor an earlier device entry, a value is out of range; it is not written and the
                writer goes on), or the writer
                is closed or stopped.
        """
        self._check_usable()
        try:
            line = encode_entry(entry, previous_t=self._last_t, devices=self._devices)
        except JournalError as e:
            raise JournalError(f"journal {self.path}: {e}") from None
        self._buffer.append(line)
        self._buffered_bytes += len(line) + 1
        self._last_t = entry.t
        if isinstance(entry, DeviceEntry):
            self._devices.update(d.id for d in entry.devices)
        if self._buffered_bytes >= AUTO_FLUSH_BYTES:
            self.flush()

    def flush(self) -> None:
        """Write the buffered entries with one ``write``; fsync if `FSYNC_INTERVAL` passed since the last one.

        Call it often (every tick, even with nothing buffered): that is what bounds the time between
        fsyncs.

        Raises:
            JournalError: writing or fsyncing failed (the writer is now stopped), or it was already
                closed or stopped.
        """
        self._check_usable()
        if self._buffer:
            count = len(self._buffer)
            data = ("\n".join(self._buffer) + "\n").encode("utf-8")
            self._buffer = []
            self._buffered_bytes = 0
            self._write_batch(data)
            self.lines_written += count
            self._unsynced = True
        if self._unsynced and self._clock() - self._last_fsync >= FSYNC_INTERVAL:
            self._fsync()

    def close(self) -> None:
        """Flush, fsync what is not synced yet, and close; does nothing when already closed or stopped.

        A stopped writer raised its error once already; closing it says nothing more.

        Raises:
            JournalError: the last flush or fsync failed (the writer is now stopped and closed).
        """
        if self._closed:
            return
        try:
            if self.stopped is None:
                self.flush()
                if self._unsynced:
                    self._fsync()
        finally:
            self._closed = True
            self._close_fd()

    def __enter__(self) -> JournalWriter:
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None, tb: TracebackType | None) -> None:
        self.close()

    def _check_usable(self) -> None:
        if self.stopped is not None:
            raise JournalError(self.stopped)
        if self._closed:
            raise JournalError(f"journal {self.path} is closed")

    def _write_batch(self, data: bytes) -> None:
        done = 0
        try:
            while done < len(data):
                done += _write(self._fd, data, done)
        except OSError as e:
            self._stop(e, data, done)
        self._size += len(data)

    def _fsync(self) -> None:
        now = self._clock()
        try:
            os.fsync(self._fd)
        except OSError as e:
            self._stop(e, b"", 0)
        self._last_fsync = now
        self._unsynced = False

    def _stop(self, error: OSError, data: bytes, done: int) -> None:
        """Stop journalling after ``error``, with ``done`` bytes of the batch ``data`` written; always raises."""
        whole = data.rfind(b"\n", 0, done) + 1  # the batch's bytes up to its last complete line
        if done > whole:
            try:
                os.ftruncate(self._fd, self._size + whole)  # remove the cut line; the reader copes if this fails
            except OSError:
                pass
        self._size += whole
        self.lines_written += data.count(b"\n", 0, whole)
        reason = "disk full" if error.errno in _DISK_FULL else "write failed"
        self.stopped = (
            f"journal {self.path} stopped: {reason} ({error.strerror or error}); "
            f"the {self.lines_written} lines written so far are intact"
        )
        self._buffer = []
        self._close_fd()
        raise JournalError(self.stopped) from error

    def _close_fd(self) -> None:
        if self._fd >= 0:
            fd, self._fd = self._fd, -1
            try:
                os.close(fd)
            except OSError:
                pass  # nothing left to lose: everything was written (or the writer stopped)


def _write(fd: int, data: bytes, start: int) -> int:
    """One ``os.write`` of ``data[start:]``; the count it wrote (a write of nothing is an error)."""
    n = os.write(fd, memoryview(data)[start:])
    if n <= 0:
        raise OSError(errno.EIO, "the write wrote nothing")
    return n


def _remove(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass  # a half-created journal cannot be removed; its header line is cut and the reader says so
