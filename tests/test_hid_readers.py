"""The real readers over stand-ins for devices: pipes, a pty, packet sockets, fake hidapi/pyusb devices.

A pipe is a byte stream, not a packet device: two reports written before the reader reads come out of one
``read`` joined together. So the pipe fakes write one report per ``write`` and the reader reads exactly one
report's length (``read_size``), which is right only when every report has the same length (true of the
captures used here; the test checks it). A ``SOCK_SEQPACKET`` socket pair keeps message boundaries like hidraw
does, and carries reports of different lengths with the default read size.
"""

from __future__ import annotations

import errno
import os
import pty
import queue
import socket
import threading
import time
import tty
from pathlib import Path

import pytest
from test_hidraw_discovery import KEYBOARD, make_node, make_reference_node

from physink_tui.errors import DeviceError
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.hidraw import UDEV_INSTALL, discover_hidraw, open_error
from physink_tui.input.hid.readers import HidapiReader, HidrawReader, choose_tablet, open_reader
from physink_tui.input.sources import RawReport, SourceEnded

RECORDED = Path(__file__).resolve().parent / "recorded_hid"
REPORTS = [bytes([2, 0x20 | (i & 1), i, 0, i, 0, 0, 0, 0x1D, 0x13]) for i in range(20)]
HANG_S = 60.0
"""Hang guard: the longest a test waits for an item or a state (only a stuck reader gets there)."""


def drain(q: queue.Queue, timeout: float = HANG_S) -> list:
    """Items until (and with) the first SourceEnded."""
    items = []
    deadline = time.monotonic() + timeout
    while True:
        item = q.get(timeout=max(0.01, deadline - time.monotonic()))
        items.append(item)
        if isinstance(item, SourceEnded):
            return items


def wait_until(predicate, timeout: float = HANG_S) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.005)
    return predicate()


def pipe_reader(read_size: int = len(REPORTS[0])) -> tuple[HidrawReader, int, queue.Queue]:
    r, w = os.pipe()
    reader = HidrawReader(r, "tablet0", read_size=read_size)
    q: queue.Queue = queue.Queue()
    reader.start(q)
    return reader, w, q


def test_reports_arrive_in_order_with_monotonic_times_and_stop_ends_cleanly() -> None:
    reader, w, q = pipe_reader()
    before = time.monotonic()
    for report in REPORTS:
        os.write(w, report)
    got = [q.get(timeout=HANG_S) for _ in REPORTS]
    reader.stop()
    rest = drain(q)
    os.close(w)
    assert [g.data for g in got] == REPORTS
    assert all(isinstance(g, RawReport) and g.device == "tablet0" for g in got)
    times = [g.t for g in got]
    assert times == sorted(times) and times[0] >= before
    assert len(rest) == 1 and rest[0].error is None and rest[0].device == "tablet0"
    assert not reader.running


def test_closing_the_writer_mid_stream_ends_with_a_device_error_and_the_thread_exits() -> None:
    reader, w, q = pipe_reader()
    for report in REPORTS[:5]:
        os.write(w, report)
    os.close(w)
    items = drain(q)
    assert [i.data for i in items[:-1]] == REPORTS[:5]
    end = items[-1]
    assert isinstance(end.error, DeviceError) and "disappeared" in str(end.error)
    assert wait_until(lambda: not reader.running)
    reader.stop()  # idempotent after the end
    assert q.empty()


def test_stop_on_an_idle_device_returns_with_the_thread_gone() -> None:
    reader, w, q = pipe_reader()
    reader.stop()
    assert not reader.running
    assert [type(i) for i in drain(q)] == [SourceEnded]
    reader.stop()
    os.close(w)


def test_a_pty_whose_other_end_closes_is_a_read_error_like_an_unplugged_tablet() -> None:
    master, slave = pty.openpty()
    tty.setraw(slave)
    reader = HidrawReader(master, "pen")
    q: queue.Queue = queue.Queue()
    reader.start(q)
    os.write(slave, REPORTS[0])
    first = q.get(timeout=HANG_S)
    os.close(slave)
    end = drain(q)[-1]
    assert first.data == REPORTS[0]
    assert isinstance(end.error, DeviceError) and "EIO" in str(end.error) and "disappeared" in str(end.error)


def test_a_packet_socket_keeps_reports_of_any_length_whole() -> None:
    ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    reader = HidrawReader(os.dup(ours.fileno()), "tablet0")
    ours.close()
    q: queue.Queue = queue.Queue()
    reader.start(q)
    reports = [bytes([0x07, 0x80 | i]) + bytes(i) for i in range(1, 12)]
    for report in reports:
        theirs.send(report)
    theirs.close()
    items = drain(q)
    assert [i.data for i in items[:-1]] == reports
    assert isinstance(items[-1].error, DeviceError)


def test_a_capture_replayed_through_a_pipe_decodes_exactly_as_the_capture_does() -> None:
    capture = Capture.from_file(RECORDED / "windows-ink-strokes.hid")
    (device,) = capture.devices
    lengths = {len(e.data) for e in capture.events}
    assert len(lengths) == 1, "the pipe fake needs reports of one length"
    r, w = os.pipe()
    reader = HidrawReader(r, "tablet0", read_size=lengths.pop())
    q: queue.Queue = queue.Queue()
    reader.start(q)

    def write_all() -> None:
        for event in capture.events:
            os.write(w, event.data)
        os.close(w)

    writer = threading.Thread(target=write_all)
    writer.start()
    items = drain(q)
    writer.join()
    reports = [i for i in items if isinstance(i, RawReport)]
    assert [r.data for r in reports] == [e.data for e in capture.events]
    live = HidPenDecoder(device.descriptor, device.vid, device.pid)
    direct = HidPenDecoder(device.descriptor, device.vid, device.pid)
    from_reader = [live.decode(r.data, r.t) for r in reports]
    from_capture = [direct.decode(e.data, e.t) for e in capture.events]
    assert sum(s is not None for s in from_capture) > 100
    assert [s and s._replace(t=0.0) for s in from_reader] == [s and s._replace(t=0.0) for s in from_capture]


def test_opening_a_missing_path_is_a_device_error() -> None:
    with pytest.raises(DeviceError, match="does not exist"):
        HidrawReader("/nonexistent/hidraw9")


class FakeHid:
    """Stands in for ``hid.device``: hands out queued reports, then fails like an unplugged device."""

    def __init__(self, reports: list[bytes], fail_after: bool = True) -> None:
        self.reports = list(reports)
        self.fail_after = fail_after
        self.opened: bytes | None = None
        self.closed = False

    def open_path(self, path: bytes) -> None:
        self.opened = path

    def read(self, size: int, timeout_ms: int) -> list[int]:
        if self.reports:
            return list(self.reports.pop(0))
        if self.fail_after:
            raise OSError("read error")
        time.sleep(timeout_ms / 1000)
        return []

    def close(self) -> None:
        self.closed = True


def test_hidapi_reader_passes_reports_and_ends_when_the_device_fails() -> None:
    fake = FakeHid(REPORTS[:3])
    reader = HidapiReader("/dev/hidraw0", "tablet0", device_factory=lambda: fake)
    q: queue.Queue = queue.Queue()
    reader.start(q)
    items = drain(q)
    assert fake.opened == b"/dev/hidraw0"
    assert [i.data for i in items[:-1]] == REPORTS[:3]
    assert "disappeared" in str(items[-1].error) and fake.closed


def test_hidapi_reader_stops_cleanly_between_time_outs() -> None:
    fake = FakeHid([], fail_after=False)
    reader = HidapiReader(b"1-1:1.0", "tablet0", timeout_ms=20, device_factory=lambda: fake)
    q: queue.Queue = queue.Queue()
    reader.start(q)
    reader.stop()
    assert not reader.running and fake.closed
    assert drain(q)[-1].error is None


def test_open_reader_auto_picks_the_tablet_and_reads_it(tmp_path: Path) -> None:
    sysfs, dev = tmp_path / "sys", tmp_path / "dev"
    make_node(sysfs, dev, 0, "Boot Keyboard", 0x046D, 0xC31C, KEYBOARD)
    node = make_reference_node(sysfs, dev, 1, "windows-ink", port="1-2", node="fifo")
    reader = open_reader(None, "tablet0", sysfs_root=str(sysfs), dev_root=str(dev))
    assert reader.info.path == str(node) and reader.info.vid == 0x1234
    q: queue.Queue = queue.Queue()
    reader.start(q)
    with open(node, "wb", buffering=0) as w:
        w.write(REPORTS[0])
        assert q.get(timeout=HANG_S).data == REPORTS[0]
    assert "disappeared" in str(drain(q)[-1].error)


def test_open_reader_by_path_and_by_vid_pid(tmp_path: Path) -> None:
    sysfs, dev = tmp_path / "sys", tmp_path / "dev"
    make_reference_node(sysfs, dev, 0, "huion-v2", interface=1, port="1-1")
    make_reference_node(sysfs, dev, 1, "huion-v2", interface=0, port="1-1")
    make_reference_node(sysfs, dev, 2, "wacom-ff0d", port="1-2")
    kw = {"sysfs_root": str(sysfs), "dev_root": str(dev)}
    for spec, expected in (("256c:006d", "hidraw1"), ("056A:374", "hidraw2"), ("hidraw0", "hidraw0"),
                           (str(dev / "hidraw2"), "hidraw2"), ("auto", "hidraw2")):
        reader = open_reader(spec, **kw)
        try:
            assert reader.info.path.endswith(expected), spec
        finally:
            reader.stop()


def test_open_reader_errors_name_the_problem(tmp_path: Path) -> None:
    sysfs, dev = tmp_path / "sys", tmp_path / "dev"
    make_node(sysfs, dev, 0, "Boot Keyboard", 0x046D, 0xC31C, KEYBOARD)
    kw = {"sysfs_root": str(sysfs), "dev_root": str(dev)}
    with pytest.raises(DeviceError, match="expected 'auto'"):
        open_reader("my tablet", **kw)
    with pytest.raises(DeviceError, match="physink devices"):
        open_reader("auto", **kw)


def test_choose_tablet_prefers_an_interface_whose_descriptor_describes_a_pen(tmp_path: Path) -> None:
    sysfs, dev = tmp_path / "sys", tmp_path / "dev"
    make_reference_node(sysfs, dev, 0, "huion-v2", interface=0)
    make_reference_node(sysfs, dev, 1, "uclogic-v1", interface=1, port="1-2")
    assert choose_tablet(discover_hidraw(str(sysfs), str(dev))).path.endswith("hidraw1")


@pytest.mark.hardware
def test_the_first_real_tablet_opens_and_stops_cleanly() -> None:
    chosen = choose_tablet(discover_hidraw())
    if chosen is None:
        pytest.skip("no pen tablet among /sys/class/hidraw (plug one in to run this test)")
    problem = open_error(chosen.path)
    if problem is not None:
        pytest.skip(f"found {chosen.name} ({chosen.ids}) but cannot open it: {problem}")
    reader = open_reader(chosen.path)
    q: queue.Queue = queue.Queue()
    reader.start(q)
    time.sleep(0.5)
    reader.stop()
    items = drain(q)
    assert items[-1].error is None
    assert all(isinstance(i, RawReport) and i.data for i in items[:-1])



class FakeUsb:
    """Stands in for a ``usb.core.Device``: queued reads, time-outs, then a given USBError."""

    bus, address, iProduct = 1, 7, 0

    def __init__(self, script: list, kernel_driver: bool = True) -> None:
        self.script = list(script)
        self.kernel_driver = kernel_driver
        self.calls: list[str] = []

    def is_kernel_driver_active(self, interface: int) -> bool:
        return self.kernel_driver

    def detach_kernel_driver(self, interface: int) -> None:
        self.calls.append(f"detach {interface}")
        self.kernel_driver = False

    def attach_kernel_driver(self, interface: int) -> None:
        self.calls.append(f"attach {interface}")

    def ctrl_transfer(self, *args):
        self.calls.append(f"ctrl {args[:4]}")
        return bytes.fromhex("05010902a101c0")

    def read(self, endpoint: int, size: int, timeout: int):
        step = self.script.pop(0) if self.script else usb_core().USBTimeoutError("timeout", errno=errno.ETIMEDOUT)
        if isinstance(step, Exception):
            time.sleep(0.001)
            raise step
        return step


def usb_core():
    return pytest.importorskip("usb.core")


@pytest.fixture
def usb_util(monkeypatch):
    """pyusb's interface bookkeeping reaches into a real device's context: record the calls on the fake instead."""
    usb_util = pytest.importorskip("usb.util")
    monkeypatch.setattr(usb_util, "claim_interface", lambda dev, i: dev.calls.append(f"claim {i}"))
    monkeypatch.setattr(usb_util, "release_interface", lambda dev, i: dev.calls.append(f"release {i}"))
    monkeypatch.setattr(usb_util, "dispose_resources", lambda dev: dev.calls.append("dispose"))
    return usb_util


def test_pyusb_reader_skips_time_outs_and_ends_on_enodev(usb_util) -> None:
    from physink_tui.input.hid.usb_reader import PyusbInterruptReader

    core = usb_core()
    timeout = core.USBTimeoutError("Operation timed out", errno=errno.ETIMEDOUT)
    gone = core.USBError("No such device", errno=errno.ENODEV)
    fake = FakeUsb([REPORTS[0], timeout, timeout, REPORTS[1], gone])
    reader = PyusbInterruptReader(0x256C, 0x006D, 0, 0x81, "tablet0", packet_size=64, usb_device=fake)
    assert reader.info.path == "usb:001:007" and reader.info.descriptor == bytes.fromhex("05010902a101c0")
    q: queue.Queue = queue.Queue()
    reader.start(q)
    items = drain(q)
    assert [i.data for i in items[:-1]] == REPORTS[:2]
    assert "disappeared" in str(items[-1].error)
    assert fake.calls[0] == "detach 0" and "claim 0" in fake.calls
    assert fake.calls[-3:] == ["release 0", "attach 0", "dispose"]


def test_pyusb_reader_without_permission_names_the_udev_rule(usb_util, monkeypatch) -> None:
    from physink_tui.input.hid.usb_reader import PyusbInterruptReader

    core = usb_core()

    def refuse(dev, interface):
        raise core.USBError("Access denied (insufficient permissions)", errno=errno.EACCES)

    monkeypatch.setattr(usb_util, "claim_interface", refuse)
    fake = FakeUsb([], kernel_driver=False)
    with pytest.raises(DeviceError, match="no permission") as info:
        PyusbInterruptReader(0x256C, 0x006D, 0, 0x81, packet_size=64, usb_device=fake)
    assert UDEV_INSTALL in str(info.value)
    assert fake.calls[-1] == "dispose"


def test_pyusb_reader_stop_gives_the_interface_back(usb_util) -> None:
    from physink_tui.input.hid.usb_reader import PyusbInterruptReader

    fake = FakeUsb([], kernel_driver=False)
    reader = PyusbInterruptReader(0x256C, 0x006D, 0, 0x81, packet_size=64, timeout_ms=10, usb_device=fake)
    q: queue.Queue = queue.Queue()
    reader.start(q)
    reader.stop()
    assert drain(q)[-1].error is None and not reader.running
    assert fake.calls[-2:] == ["release 0", "dispose"] and "attach 0" not in fake.calls


class PipeDevice:
    """A tablet that can be unplugged and plugged back: each plug-in is a fresh pipe."""

    def __init__(self) -> None:
        self.present = threading.Event()
        self.writer: int | None = None
        self.opens = 0

    def plug(self) -> None:
        self.present.set()

    def unplug(self) -> None:
        self.present.clear()
        if self.writer is not None:
            os.close(self.writer)
            self.writer = None

    def open(self) -> HidrawReader:
        if not self.present.is_set() or self.writer is not None:
            raise DeviceError("tablet not plugged in")
        r, self.writer = os.pipe()
        self.opens += 1
        return HidrawReader(r, "inner", read_size=len(REPORTS[0]))

    def send(self, report: bytes) -> None:
        assert wait_until(lambda: self.writer is not None)
        os.write(self.writer, report)


def test_reconnecting_source_passes_the_vanishing_on_and_resumes_when_the_device_returns() -> None:
    from physink_tui.input.reconnecting import ReconnectingSource

    device = PipeDevice()
    device.plug()
    retries: list[DeviceError] = []
    source = ReconnectingSource(device.open, "tablet0", retry_s=0.01, on_retry=retries.append)
    q: queue.Queue = queue.Queue()
    source.start(q)
    device.send(REPORTS[0])
    first = q.get(timeout=HANG_S)
    assert isinstance(first, RawReport) and first.data == REPORTS[0] and first.device == "tablet0"  # relabelled
    device.unplug()
    vanished = drain(q)
    assert isinstance(vanished[-1].error, DeviceError) and vanished[-1].device == "tablet0"
    assert wait_until(lambda: len(retries) >= 2)  # polling while it is away
    assert source.running
    device.plug()
    device.send(REPORTS[1])
    back = q.get(timeout=HANG_S)
    assert isinstance(back, RawReport) and back.data == REPORTS[1] and back.device == "tablet0"
    assert device.opens == 2 and source.reconnects == 1
    source.stop()
    assert not source.running
    end = drain(q)
    assert end[-1].error is None and end[-1].device == "tablet0"
    device.unplug()


def test_reconnecting_source_stops_while_waiting_for_the_device() -> None:
    from physink_tui.input.reconnecting import ReconnectingSource

    device = PipeDevice()
    source = ReconnectingSource(device.open, "tablet0", retry_s=0.01)
    q: queue.Queue = queue.Queue()
    source.start(q)
    time.sleep(0.05)
    source.stop()
    assert not source.running
    assert [(type(i), i.error) for i in drain(q)] == [(SourceEnded, None)]


def test_hidapi_reader_fills_in_the_descriptor_hidapi_reports() -> None:
    from physink_tui.input.hid.hidraw import HidrawInfo

    fake = FakeHid([])
    fake.get_report_descriptor = lambda: [0x05, 0x0D, 0xC0]
    info = HidrawInfo("1-1:1.0", "", 3, 0x256C, 0x006D, None, "", b"")
    reader = HidapiReader("1-1:1.0", info=info, device_factory=lambda: fake)
    assert reader.info.descriptor == bytes([0x05, 0x0D, 0xC0])
    reader.stop()
    assert fake.closed
