"""The serial reader's real code over a pty, with a fake ISDV4 tablet on the master side."""

from __future__ import annotations

import errno
import os
import queue
import select
import termios
import threading
import time
import tty
from collections.abc import Callable

import pytest
import serial

from physink_tui.errors import DeviceError
from physink_tui.input.serial_tablets import reader
from physink_tui.input.serial_tablets.isdv4 import Isdv4Query, encode_pen_packet, encode_query_reply
from physink_tui.input.serial_tablets.reader import SerialPenSource, probe_isdv4
from physink_tui.input.sources import PenSource, SampleReady, SourceEnded

QUERY = Isdv4Query(x_max=26202, y_max=16325, p_max=1023, version=0x0105)
WAIT_S = 60.0
"""Hang guard: the longest any test waits for one queue item or command (never reached unless stuck)."""
ANSWERING = {"settle_s": 0.01, "query_timeout": WAIT_S}
"""For a tablet that answers: the reply ends the wait as soon as it comes, however loaded the machine."""
SILENT = {"settle_s": 0.01, "query_timeout": 0.3}
"""For a port where nothing answers: the handshake gives up after its timeout at each rate."""

GARBAGE = b"\x01\x02\x03"
TOUCH = bytes([0x91, 1, 2, 3, 4])
STROKE = [
    encode_pen_packet(1000, 2000),  # hover in
    encode_pen_packet(1100, 2100, 300, tip=True),
    encode_pen_packet(1200, 2200, 400, tip=True, side1=True),
    encode_pen_packet(1300, 2300),  # lifted
    encode_pen_packet(1300, 2300, proximity=False),
]
STREAM = STROKE[0] + GARBAGE + STROKE[1] + TOUCH + STROKE[2][:4] + STROKE[2][4:] + STROKE[3] + STROKE[4]


class FakeTablet:
    """Answers the query (optionally only at one line speed) and writes ``stream`` once told to start."""

    def __init__(self, stream: bytes = b"", answer_at: int | None = None, answer: bool = True,
                 ignored: Callable[[], None] = lambda: None) -> None:
        self.master, self.slave = os.openpty()
        self._ignored = ignored  # called when a query comes at a speed it does not answer at
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self.commands = bytearray()
        self._stream, self._answer_at, self._answer = stream, answer_at, answer
        self._halt = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._halt.is_set():
            if not select.select([self.master], [], [], 0.02)[0]:
                continue
            try:
                data = os.read(self.master, 64)
            except OSError:
                return
            for c in data:
                self.commands.append(c)
                # the slave's termios is the port's: its speed is the baud rate the reader set
                speed_ok = self._answer_at is None or termios.tcgetattr(self.slave)[4] == self._answer_at
                if c == ord("*") and self._answer and speed_ok:
                    os.write(self.master, encode_query_reply(QUERY))
                elif c == ord("*") and self._answer:
                    self._ignored()
                elif c == ord("1"):
                    os.write(self.master, self._stream)

    def wait_for_commands(self, expected: bytes) -> bytes:
        deadline = time.monotonic() + WAIT_S
        while bytes(self.commands) != expected and time.monotonic() < deadline:
            time.sleep(0.01)
        return bytes(self.commands)

    def vanish(self) -> None:
        """The tablet goes away: the master side of the pty closes."""
        self._halt.set()
        self._thread.join()
        os.close(self.master)
        self.master = -1

    def close(self) -> None:
        self._halt.set()
        self._thread.join()
        for fd in (self.master, self.slave):
            if fd >= 0:
                os.close(fd)


@pytest.fixture
def tablets():
    made: list[FakeTablet] = []

    def make(*args, **kwargs) -> FakeTablet:
        made.append(FakeTablet(*args, **kwargs))
        return made[-1]

    yield make
    for tablet in made:
        tablet.close()


def take(out: queue.Queue, n: int) -> list:
    return [out.get(timeout=WAIT_S) for _ in range(n)]


def stops(source: SerialPenSource) -> None:
    """``source.stop()`` returns (within the hang guard)."""
    stopper = threading.Thread(target=source.stop, daemon=True)
    stopper.start()
    stopper.join(WAIT_S)
    assert not stopper.is_alive(), "stop() hung"


class SkippingClock:
    """The monotonic clock (as the reader module's ``time``), set forward a long way by `skip`: the wait under way
    is over at once. The tablet may skip just before or just after the reader has read the clock for its
    deadline, so the clock jumps at each of the next two readings: a deadline read first is passed by the second."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self.skipped = 0.0
        self._jumps = 0

    def monotonic(self) -> float:
        with self._lock:
            if self._jumps:
                self._jumps -= 1
                self.skipped += 1e6
            return time.monotonic() + self.skipped

    def skip(self) -> None:
        with self._lock:
            self._jumps = 2


def test_reads_samples_counts_garbage_and_ends_cleanly_on_stop(tablets):
    tablet = tablets(STREAM)
    source: PenSource = SerialPenSource(tablet.path, "pen0", **ANSWERING)  # the protocol is not runtime-checkable
    out: queue.Queue = queue.Queue()
    before = time.monotonic()
    source.start(out)
    items = take(out, 5)
    assert all(isinstance(i, SampleReady) and i.device == "pen0" for i in items)
    samples = [i.sample for i in items]
    assert [(s.range, s.tip, s.b1) for s in samples] == [
        (True, False, False),
        (True, True, False),
        (True, True, True),
        (True, False, False),
        (False, False, False),
    ]
    assert samples[1].x == pytest.approx(1100 / 26202) and samples[1].y == pytest.approx(2100 / 16325)
    assert samples[2].p == pytest.approx(400 / 1023)
    assert all(before <= s.t <= time.monotonic() for s in samples)
    assert [s.t for s in samples] == sorted(s.t for s in samples)

    source.stop()
    end = out.get(timeout=WAIT_S)
    assert isinstance(end, SourceEnded) and end.error is None and end.device == "pen0"
    assert out.empty()
    assert (source.query, source.baudrate) == (QUERY, 38400)
    assert source.parser.bad_bytes == len(GARBAGE)
    assert source.parser.touch_packets == 1
    # stop, query, start; then stop again when the source stopped
    assert tablet.wait_for_commands(b"0*10") == b"0*10"
    source.stop()  # idempotent


def test_the_tablet_vanishing_mid_stroke_ends_the_source_with_a_device_error(tablets):
    tablet = tablets(STROKE[0] + STROKE[1])
    source = SerialPenSource(tablet.path, "pen0", **ANSWERING)
    out: queue.Queue = queue.Queue()
    source.start(out)
    assert [i.sample.tip for i in take(out, 2)] == [False, True]
    tablet.vanish()
    end = out.get(timeout=WAIT_S)
    assert isinstance(end, SourceEnded)
    assert isinstance(end.error, DeviceError)
    assert tablet.path in str(end.error) and "stopped answering" in str(end.error)
    stops(source)  # the thread has ended: stop has nothing to wait for


def test_the_baud_rate_falls_back_to_the_one_the_tablet_answers_at(tablets, monkeypatch):
    clock = SkippingClock()  # the unanswered query at 38400 times out at once, however generous its timeout
    monkeypatch.setattr(reader, "time", clock)
    tablet = tablets(STROKE[0], answer_at=termios.B19200, ignored=clock.skip)
    source = SerialPenSource(tablet.path, **ANSWERING)
    out: queue.Queue = queue.Queue()
    source.start(out)
    [item] = take(out, 1)
    assert isinstance(item, SampleReady) and item.device == "serial0"
    source.stop()
    assert isinstance(out.get(timeout=WAIT_S), SourceEnded)
    assert source.baudrate == 19200
    assert tablet.wait_for_commands(b"0*0*10") == b"0*0*10"


def test_open_does_the_handshake_synchronously_and_start_reuses_it(tablets):
    tablet = tablets(STROKE[0], answer_at=termios.B38400)
    source = SerialPenSource(tablet.path, baudrate=38400, **ANSWERING)
    assert source.open() == QUERY
    assert source.open() == QUERY  # idempotent: no second query
    out: queue.Queue = queue.Queue()
    source.start(out)
    assert isinstance(take(out, 1)[0], SampleReady)
    source.stop()
    assert out.get(timeout=WAIT_S).error is None
    assert tablet.wait_for_commands(b"0*10") == b"0*10"


def test_silence_is_a_device_error_from_open_and_from_the_thread(tablets):
    tablet = tablets(answer=False)
    with pytest.raises(DeviceError, match=r"no ISDV4 tablet answered .* at 38400, 19200 baud"):
        SerialPenSource(tablet.path, **SILENT).open()
    out: queue.Queue = queue.Queue()
    source = SerialPenSource(tablet.path, baudrate=115200, **SILENT)
    source.start(out)
    end = out.get(timeout=WAIT_S)
    assert isinstance(end, SourceEnded) and "at 115200 baud" in str(end.error)
    source.stop()


def test_stop_during_the_handshake_ends_it_without_waiting_for_the_query_timeout(tablets):
    tablet = tablets(answer=False)
    source = SerialPenSource(tablet.path, settle_s=0.01, query_timeout=3600.0)  # waiting it out would hang
    out: queue.Queue = queue.Queue()
    source.start(out)
    assert tablet.wait_for_commands(b"0*") == b"0*"  # the query is out: the handshake waits for a reply
    stops(source)
    end = out.get(timeout=WAIT_S)
    assert isinstance(end, SourceEnded) and end.error is None


def test_probe_finds_an_answering_tablet_and_not_a_silent_port(tablets):
    assert probe_isdv4(tablets().path, timeout=WAIT_S, settle_s=0.01) == QUERY
    assert probe_isdv4(tablets(answer=False).path, timeout=0.1, settle_s=0.01) is None


def test_a_missing_port_is_a_device_error():
    with pytest.raises(DeviceError, match="does not exist"):
        probe_isdv4("/dev/physink-no-such-port")
    out: queue.Queue = queue.Queue()
    source = SerialPenSource("/dev/physink-no-such-port")
    source.start(out)
    assert "does not exist" in str(out.get(timeout=WAIT_S).error)
    source.stop()


def test_permission_denied_says_to_join_the_dialout_group(monkeypatch):
    def denied(port, *args, **kwargs):
        raise serial.SerialException(errno.EACCES, f"could not open port {port}: [Errno 13] Permission denied")

    monkeypatch.setattr(serial, "Serial", denied)
    with pytest.raises(DeviceError, match="dialout") as caught:
        SerialPenSource("/dev/ttyS0").open()
    assert "\n" not in str(caught.value) and "'/dev/ttyS0'" in str(caught.value)
