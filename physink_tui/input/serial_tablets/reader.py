"""Reads an ISDV4 / W8001 serial pen tablet on a thread of its own and queues its samples; decodes nothing itself.

The handshake is the one the kernel's ``wacom_w8001.c`` and xf86-input-wacom's ``wcmISDV4.c`` do: stop
sampling (``0``), wait 250 ms, discard what is on the line, ask for the query reply (``*``), and, once it
came, start sampling (``1``). A tablet answers only at its own baud rate, so without one given the query is
tried at 38400 and then 19200 baud (xf86's two rates; pass ``baudrate`` for any other, e.g. 115200). The
bytes become samples in `isdv4.Isdv4Parser`; this module only moves them from the port to the queue, with
`time.monotonic()` timestamps, following the contract of `sources`.
"""

from __future__ import annotations

import errno
import queue
import threading
import time

import serial

from physink_tui.errors import DeviceError
from physink_tui.input.serial_tablets.isdv4 import CMD_QUERY, CMD_START, CMD_STOP, Isdv4Parser, Isdv4Query
from physink_tui.input.sources import SampleReady, SourceEnded, SourceItem

__all__ = ["BAUD_RATES", "SerialPenSource", "probe_isdv4"]

BAUD_RATES = (38400, 19200)
"""Tried in this order when no baud rate is given (xf86-input-wacom accepts exactly these two)."""
READ_TIMEOUT_S = 0.05
"""How long one read waits for a byte; also how soon the thread notices `SerialPenSource.stop`."""
WRITE_TIMEOUT_S = 0.5
"""A command that cannot be written within this long means the port is stuck."""
SETTLE_S = 0.25
"""Wait after the stop command before querying (both drivers wait 250 ms)."""
QUERY_TIMEOUT_S = 0.5
"""How long to wait for the query reply at one baud rate."""


class _Stopped(Exception):
    """`SerialPenSource.stop` was called while the handshake was still running."""


def _open(port: str, baudrate: int) -> serial.Serial:
    """The port opened exclusively, raw, with short read and write timeouts; `DeviceError` says why not."""
    try:
        return serial.Serial(
            port, baudrate, timeout=READ_TIMEOUT_S, write_timeout=WRITE_TIMEOUT_S, exclusive=True
        )
    except serial.SerialException as exc:
        code = exc.errno
        if code in (errno.EACCES, errno.EPERM):
            raise DeviceError(
                f"permission denied opening serial port {port!r}: add your user to the 'dialout' group "
                "(sudo usermod -aG dialout $USER) and log in again"
            ) from exc
        if code == errno.ENOENT:
            raise DeviceError(f"serial port {port!r} does not exist") from exc
        if code in (errno.EAGAIN, errno.EBUSY):
            raise DeviceError(f"serial port {port!r} is in use by another program") from exc
        raise DeviceError(f"cannot open serial port {port!r}: {exc}") from exc
    except (OSError, ValueError) as exc:
        raise DeviceError(f"cannot open serial port {port!r}: {exc}") from exc


def _query(
    ser: serial.Serial, baudrates: tuple[int, ...], timeout: float, settle_s: float, stop: threading.Event
) -> tuple[Isdv4Query, int] | None:
    """Stop, query and read the reply at each baud rate in turn: ``(reply, baud)``, or None if none came.

    Raises `serial.SerialException` or `OSError` when the port fails, `_Stopped` when ``stop`` is set.
    """
    for baud in baudrates:
        ser.baudrate = baud
        ser.write(CMD_STOP)
        if stop.wait(settle_s):
            raise _Stopped
        ser.reset_input_buffer()  # samples sent before the stop took effect
        ser.write(CMD_QUERY)
        parser = Isdv4Parser()
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if stop.is_set():
                raise _Stopped
            chunk = ser.read(ser.in_waiting or 1)
            if chunk:
                parser.feed(chunk, 0.0)
                if parser.control_packets and parser.query is not None:
                    return parser.query, baud
    return None


def probe_isdv4(
    port: str,
    timeout: float = QUERY_TIMEOUT_S,
    *,
    baudrates: tuple[int, ...] = BAUD_RATES,
    settle_s: float = SETTLE_S,
) -> Isdv4Query | None:
    """Ask the device on ``port`` for its ISDV4 query reply (for ``physink devices``); leaves it stopped.

    Takes up to ``len(baudrates) * (settle_s + timeout)`` seconds when nothing answers.

    Returns:
        The reply, or None when nothing ISDV4-like answered at any of the baud rates.

    Raises:
        DeviceError: the port cannot be opened (missing, permission denied, busy) or fails while probing.
    """
    ser = _open(port, baudrates[0])
    try:
        found = _query(ser, baudrates, timeout, settle_s, threading.Event())
    except (serial.SerialException, OSError) as exc:
        raise DeviceError(f"serial port {port!r} failed while probing: {exc}") from exc
    finally:
        ser.close()
    return found[0] if found else None


class SerialPenSource:
    """An ISDV4 / W8001 tablet on a serial port, as a `sources.PenSource` that puts `SampleReady` items.

    One use: `start` once, `stop` once. `open` may be called first to do the handshake synchronously (and
    see its `DeviceError` at once); otherwise the thread does it and a failure ends the source with
    ``SourceEnded(error=...)``. Losing the port while reading (unplugged, closed pty) ends it the same way;
    `stop` ends it with ``error=None`` after telling the tablet to stop sampling.

    Attributes:
        port: the serial device path (``/dev/ttyS0``, ``/dev/ttyUSB0``, a pty in tests).
        device_id: the id put on every item (a journal header's device key).
        query: the tablet's query reply, once the handshake is done.
        baudrate: the baud rate the tablet answered at, once the handshake is done.
        parser: the stream's parser once the handshake is done; its ``bad_bytes``, ``first_bad_reason``
            and packet counts describe the stream (read them after `stop`, or accept a racy snapshot).
    """

    def __init__(
        self,
        port: str,
        device_id: str = "serial0",
        *,
        baudrate: int | None = None,
        query_timeout: float = QUERY_TIMEOUT_S,
        settle_s: float = SETTLE_S,
    ) -> None:
        self.port = port
        self.device_id = device_id
        self.query: Isdv4Query | None = None
        self.baudrate: int | None = None
        self.parser: Isdv4Parser | None = None
        self._baudrates = (baudrate,) if baudrate else BAUD_RATES
        self._query_timeout = query_timeout
        self._settle_s = settle_s
        self._ser: serial.Serial | None = None
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._lock = threading.Lock()

    def open(self) -> Isdv4Query:
        """Open the port and do the handshake up to (not including) the start command; idempotent.

        Raises:
            DeviceError: the port cannot be opened or fails, nothing answers the query, or the tablet has no pen.
        """
        with self._lock:
            if self._ser is not None and self.query is not None:
                return self.query
            ser = _open(self.port, self._baudrates[0])
            try:
                found = _query(ser, self._baudrates, self._query_timeout, self._settle_s, self._stop)
                if found is None:
                    rates = ", ".join(str(b) for b in self._baudrates)
                    raise DeviceError(
                        f"no ISDV4 tablet answered on serial port {self.port!r} at {rates} baud "
                        "(expected an 11-byte query reply to '*')"
                    )
                query, baud = found
                if not query.has_pen:
                    raise DeviceError(f"the ISDV4 tablet on {self.port!r} has no pen (query reply {query!r})")
            except (serial.SerialException, OSError) as exc:
                ser.close()
                raise DeviceError(f"serial port {self.port!r} failed during the ISDV4 handshake: {exc}") from exc
            except BaseException:
                ser.close()
                raise
            self._ser, self.query, self.baudrate = ser, query, baud
            self.parser = Isdv4Parser(query)
            return query

    def start(self, out: queue.Queue[SourceItem]) -> None:
        """Begin the handshake (unless `open` did it) and reading on a thread of its own; return at once."""
        if self._thread is not None:
            raise RuntimeError(f"serial source {self.device_id!r} was already started")
        self._thread = threading.Thread(target=self._run, args=(out,), name=f"isdv4 {self.port}", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Ask the thread to end, wait for it (at most a read timeout once reading), release the port."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        else:
            self._close(send_stop=True)

    def _close(self, send_stop: bool) -> None:
        ser, self._ser = self._ser, None
        if ser is None:
            return
        if send_stop:
            try:
                ser.write(CMD_STOP)
            except (serial.SerialException, OSError):
                pass  # the tablet is going away anyway
        ser.close()

    def _run(self, out: queue.Queue[SourceItem]) -> None:
        error: DeviceError | None = None
        try:
            self.open()  # sets _ser and parser, or raises
            ser, parser, device = self._ser, self.parser, self.device_id
            assert ser is not None and parser is not None  # (open sets both)
            ser.write(CMD_START)
            while not self._stop.is_set():
                chunk = ser.read(ser.in_waiting or 1)
                if chunk:
                    t = time.monotonic()
                    for sample in parser.feed(chunk, t):
                        out.put(SampleReady(sample, device))
        except _Stopped:
            pass
        except DeviceError as exc:
            error = exc
        except (serial.SerialException, OSError) as exc:
            error = DeviceError(f"serial tablet on {self.port!r} stopped answering (unplugged?): {exc}")
        except BaseException as exc:  # a bug: end the source like any failure, and let the traceback show
            error = DeviceError(f"serial reader on {self.port!r} crashed: {exc!r}")
            raise
        finally:
            with self._lock:
                self._close(send_stop=error is None)
            out.put(SourceEnded(time.monotonic(), self.device_id, error))
