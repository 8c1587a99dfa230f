"""`physink devices` and `physink record` against a fake sysfs tree (PHYSINK_SYSFS_ROOT / PHYSINK_DEV_ROOT).

pyusb and the serial ports of the machine running the tests are replaced where a test needs a known answer;
the hidraw part always runs for real over the fake tree. `physink record` reads a FIFO standing in for
``/dev/hidrawN``: the writer sends one report and waits until the capture file shows its ``E:`` line before
sending the next (which also proves each line is flushed as it comes), so the byte stream of the FIFO never
joins two reports.
"""

from __future__ import annotations

import argparse
import os
import queue
import threading
import time
from pathlib import Path
from types import SimpleNamespace

import pytest
from test_hidraw_discovery import KEYBOARD, make_node, make_reference_node, run_unprivileged

from physink_tui import __version__
from physink_tui.commands import devices, record
from physink_tui.errors import DeviceError
from physink_tui.input.captures.capture import Capture, CaptureDevice, CaptureEvent
from physink_tui.input.captures.writer import format_capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.hidraw import UDEV_INSTALL
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.hid.vendor_init import VendorInit, find_vendor_init
from physink_tui.input.hid.vendor_layouts import TabletParams
from physink_tui.input.sources import RawReport, SourceEnded

RECORDED = Path(__file__).resolve().parent / "recorded_hid"


@pytest.fixture
def fake_machine(tmp_path: Path, monkeypatch) -> tuple[Path, Path]:
    """Empty sysfs and /dev roots in the environment; no USB devices and no serial ports."""
    sysfs, dev = tmp_path / "sys", tmp_path / "dev"
    sysfs.mkdir()
    dev.mkdir()
    monkeypatch.setenv(devices.ENV_SYSFS_ROOT, str(sysfs))
    monkeypatch.setenv(devices.ENV_DEV_ROOT, str(dev))
    monkeypatch.setattr(devices, "list_usb", lambda: [])
    monkeypatch.setattr(devices, "serial_ports", lambda: [])
    return sysfs, dev


def run_devices(capsys) -> list[str]:
    assert devices.run(argparse.Namespace(command="devices")) == 0
    return capsys.readouterr().out.splitlines()


def test_lists_the_tablet_with_its_layouts_and_that_it_opens(fake_machine, capsys) -> None:
    sysfs, dev = fake_machine
    make_node(sysfs, dev, 0, "Boot Keyboard", 0x046D, 0xC31C, KEYBOARD)
    make_reference_node(sysfs, dev, 1, "windows-ink", port="1-2")
    out = run_devices(capsys)
    ref = REFERENCE_DEVICES["windows-ink"]
    summaries = [lay.summary() for lay in HidPenDecoder(ref.descriptor, ref.vid, ref.pid).layouts.values()]
    tablet = next(i for i, line in enumerate(out) if "hidraw1" in line)
    assert out[tablet].split() == [str(dev / "hidraw1"), *ref.name.split(), "1234:5678", "usb", "interface", "0"]
    assert out[tablet + 1:tablet + 1 + len(summaries)] == [f"      pen report {s}" for s in summaries]
    assert out[tablet + 1 + len(summaries)] == "      can open: yes"
    keyboard = next(line for line in out if "hidraw0" in line)
    assert keyboard.endswith("046d:c31c  usb interface 0  no pen report")
    assert not any("no pen tablets found" in line for line in out)


def test_a_known_model_without_a_pen_descriptor_is_listed_with_its_profile(fake_machine, capsys) -> None:
    sysfs, dev = fake_machine
    make_reference_node(sysfs, dev, 0, "huion-v2")
    out = "\n".join(run_devices(capsys))
    assert "0x08 huion-v2 12B" in out and "known model: Huion (v2 protocol) (protocol huion-v2)" in out


def test_an_unreadable_node_gets_the_permission_message(fake_machine) -> None:
    sysfs, dev = fake_machine
    node = make_reference_node(sysfs, dev, 0, "windows-ink")
    node.chmod(0o000)
    code = ("import sys; from physink_tui.commands import devices; devices.list_usb = lambda: []; "
            "devices.serial_ports = lambda: []; sys.exit(devices.run(None))")
    result = run_unprivileged(code, {devices.ENV_SYSFS_ROOT: str(sysfs), devices.ENV_DEV_ROOT: str(dev)})
    assert result.returncode == 0, result.stderr
    line = next(x for x in result.stdout.splitlines() if "cannot open" in x)
    assert line == f"      cannot open: permission denied on {node}; to allow it, install the udev rule: " \
                   f"{UDEV_INSTALL} (then replug)"


def test_nothing_found_is_one_line_saying_where_it_looked(fake_machine, capsys) -> None:
    sysfs, _ = fake_machine
    out = run_devices(capsys)
    assert out == [f"no pen tablets found (looked in {sysfs / 'class' / 'hidraw'}, USB via pyusb, serial ports)"]


def test_unusable_pyusb_is_said_in_one_line(fake_machine, monkeypatch, capsys) -> None:
    def broken():
        raise DeviceError("pyusb finds no libusb backend (install libusb-1.0)")

    monkeypatch.setattr(devices, "list_usb", broken)
    (line,) = run_devices(capsys)
    assert "USB via pyusb (pyusb finds no libusb backend (install libusb-1.0))" in line


def test_usb_devices_without_hidraw_nodes_are_listed(fake_machine, monkeypatch, capsys) -> None:
    sysfs, dev = fake_machine
    make_reference_node(sysfs, dev, 0, "wacom-ff0d")
    from physink_tui.input.hid.usb_reader import UsbDevice

    usb = [UsbDevice(1, 5, 0x256C, 0x006D, "Huion/Gaomon"), UsbDevice(1, 6, 0x056A, 0x0374, "Wacom")]
    monkeypatch.setattr(devices, "list_usb", lambda: usb)
    out = run_devices(capsys)
    assert "  bus 001 address 005  256c:006d  Huion (v2 protocol)" in out
    assert not any("056a:0374  Wacom" in line for line in out)  # it has a hidraw node, listed above


def test_serial_ports_are_listed_not_probed_until_the_prober_exists(fake_machine, monkeypatch, capsys) -> None:
    ports = [SimpleNamespace(device="/dev/ttyS0", description="n/a"),
             SimpleNamespace(device="/dev/ttyUSB0", description="FT232R USB UART")]
    monkeypatch.setattr(devices, "serial_ports", lambda: ports)
    monkeypatch.setattr(devices, "isdv4_prober", lambda: (None, "ISDV4 probing not available (no serial_reader)"))
    out = run_devices(capsys)
    assert "  /dev/ttyS0  not probed: ISDV4 probing not available (no serial_reader)" in out
    assert out[-1].startswith("no pen tablets found among these")

    answers = {"/dev/ttyS0": SimpleNamespace(summary=lambda: "area 26312 x 16520", has_pen=True), "/dev/ttyUSB0": None}
    calls = []

    def probe(port, timeout):
        calls.append((port, timeout))
        return answers[port]

    monkeypatch.setattr(devices, "isdv4_prober", lambda: (probe, ""))
    out = run_devices(capsys)
    assert "  /dev/ttyS0  ISDV4 tablet: area 26312 x 16520" in out
    assert "  /dev/ttyUSB0  FT232R USB UART  no ISDV4 answer" in out
    assert calls == [("/dev/ttyS0", 0.5), ("/dev/ttyUSB0", 0.5)]
    assert not any("no pen tablets found" in line for line in out)

    def refuse(port, timeout):
        raise DeviceError(f"permission denied opening serial port {port!r}: add your user to the 'dialout' group")

    monkeypatch.setattr(devices, "isdv4_prober", lambda: (refuse, ""))
    out = run_devices(capsys)
    assert "  /dev/ttyS0  cannot probe: permission denied opening serial port '/dev/ttyS0': add your user to the " \
           "'dialout' group" in out


def test_the_real_machine_listing_does_not_fail(monkeypatch, capsys) -> None:
    """Real sysfs and pyusb; serial ports are listed but not probed (a probe writes to them)."""
    monkeypatch.delenv(devices.ENV_SYSFS_ROOT, raising=False)
    monkeypatch.delenv(devices.ENV_DEV_ROOT, raising=False)
    monkeypatch.setattr(devices, "isdv4_prober", lambda: (None, "not probed in tests"))
    assert devices.run(None) == 0
    assert capsys.readouterr().out.strip()


# ---- physink record


def record_args(output: Path, device: str | None = None, serial: str | None = None) -> argparse.Namespace:
    return argparse.Namespace(command="record", device=device, serial=serial, output=str(output))


def feed(node: Path, output: Path, reports: list[bytes]) -> threading.Thread:
    """Writes reports into the FIFO one at a time, each once the previous shows in the capture, then closes."""

    def events_written() -> int:
        return output.read_text().count("\nE: ") if output.exists() else 0

    def run() -> None:
        with open(node, "wb", buffering=0) as fifo:  # blocks until the reader has opened it
            for n, report in enumerate(reports, start=1):
                fifo.write(report)
                deadline = time.monotonic() + 60  # hang guard: a FIFO would merge reports written before a read
                while events_written() < n and time.monotonic() < deadline:
                    time.sleep(0.002)

    thread = threading.Thread(target=run)
    thread.start()
    return thread


def test_record_writes_a_capture_that_decodes_like_the_reports_sent(fake_machine, tmp_path, capsys) -> None:
    sysfs, dev = fake_machine
    node = make_reference_node(sysfs, dev, 0, "windows-ink", node="fifo")
    source = Capture.from_file(RECORDED / "windows-ink-strokes.hid")
    reports = [e.data for e in source.events[:200]]
    output = tmp_path / "out.hid"
    writer = feed(node, output, reports)
    assert record.run(record_args(output)) == 0
    writer.join()
    assert capsys.readouterr().out.strip() == f"wrote {len(reports)} reports to {output} (the device went away " \
        f"(hidraw {node} (PhysInk Reference Windows Ink Pen) disappeared: end of file))"
    capture = Capture.from_file(output)
    (device,) = capture.devices
    ref = REFERENCE_DEVICES["windows-ink"]
    assert (device.descriptor, device.name, device.vid, device.pid, device.bus) == (
        ref.descriptor, ref.name, ref.vid, ref.pid, 3)
    assert device.phys == "usb-0000:00:14.0-1/input0"
    assert device.comments == (f"physink record {__version__}: {node}",)
    assert [e.data for e in capture.events] == reports and not capture.bad_lines
    times = [e.t for e in capture.events]
    assert times[0] == 0.0 and times == sorted(times)
    decoded, expected = HidPenDecoder(ref.descriptor), HidPenDecoder(ref.descriptor)
    assert [s and s._replace(t=0.0) for s in (decoded.decode(e.data, e.t) for e in capture.events)] == [
        s and s._replace(t=0.0) for s in (expected.decode(r, 0.0) for r in reports)]


def test_record_keeps_the_vendor_initialisation_for_decoding(fake_machine, tmp_path, monkeypatch, capsys) -> None:
    sysfs, dev = fake_machine
    node = make_reference_node(sysfs, dev, 0, "huion-v2", node="fifo", devnum=12)
    init = VendorInit("huion-v2", TabletParams(40000, 25000, 8191, 5080))
    asked = []
    monkeypatch.setattr(record, "initialise_usb", lambda *a: asked.append(a) or init)
    reports = [e.data for e in Capture.from_file(RECORDED / "huion-v2-strokes.hid").events[:20]]
    output = tmp_path / "huion.hid"
    writer = feed(node, output, reports)
    assert record.run(record_args(output, device=str(node))) == 0
    writer.join()
    assert asked == [(0x256C, 0x006D, 1, 12)]
    assert "vendor initialisation: huion-v2, x max 40000" in capsys.readouterr().err
    (device,) = Capture.from_file(output).devices
    assert f"# {init.comment()}" in output.read_text().splitlines()
    back = find_vendor_init(device.comments)
    assert (back.protocol, back.params) == ("huion-v2", init.params)


def test_a_failed_vendor_initialisation_is_a_warning(fake_machine, tmp_path, monkeypatch, capsys) -> None:
    sysfs, dev = fake_machine
    node = make_reference_node(sysfs, dev, 0, "uclogic-v1", node="fifo")

    def refuse(*args):
        raise DeviceError("no permission to talk to USB device 256c:006e")

    monkeypatch.setattr(record, "initialise_usb", refuse)
    output = tmp_path / "v1.hid"
    writer = feed(node, output, [bytes(8)])
    assert record.run(record_args(output, device="256c:006e")) == 0
    writer.join()
    assert "warning: vendor initialisation failed: no permission" in capsys.readouterr().err
    assert len(Capture.from_file(output).events) == 1


def test_record_of_a_serial_tablet_is_one_line_and_exit_2(capsys, tmp_path) -> None:
    assert record.run(record_args(tmp_path / "x.hid", serial="/dev/ttyS0")) == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and "serial capture is not in hid-recorder format" in err
    assert not (tmp_path / "x.hid").exists()


def test_record_without_a_tablet_is_a_device_error(fake_machine, tmp_path) -> None:
    with pytest.raises(DeviceError, match="no pen tablet found"):
        record.run(record_args(tmp_path / "x.hid"))


def test_event_lines_are_the_capture_writers() -> None:
    dev = CaptureDevice(0, None, None, None, None, None, b"\xa1\xc0")
    for t, data in ((0.0, b"\x02"), (1.9596984, bytes(range(10))), (12345.5, b"\x07\xff"), (3.0000004, b"")):
        written = format_capture(Capture((dev,), (CaptureEvent(t, data),))).splitlines()[-1]
        assert record.event_line(t, data) == written + "\n"


class InterruptingQueue(queue.Queue):
    """Delivers its items, but raises KeyboardInterrupt once, as Ctrl-C would, when one item is left."""

    interrupted = False

    def get(self, block=True, timeout=None):
        if self.qsize() <= 1 and not self.interrupted:
            self.interrupted = True
            raise KeyboardInterrupt
        return super().get(block, timeout)


def test_ctrl_c_stops_the_reader_and_keeps_what_it_had_queued(tmp_path) -> None:
    class Reader:
        stopped = False

        def stop(self) -> None:
            self.stopped = True

    items = InterruptingQueue()
    for n in range(3):
        items.put(RawReport(10.0 + n, bytes([2, n]), "tablet0"))
    items.put(SourceEnded(20.0, "tablet0", None))
    reader = Reader()
    with open(tmp_path / "c.hid", "w") as out:
        count, ended = record.record(reader, out, items)
    assert reader.stopped and ended is None and count == 3
    assert (tmp_path / "c.hid").read_text().splitlines()[-1] == "E: 000002.000000 2 02 02"


def test_environment_roots_default_to_the_real_ones(monkeypatch) -> None:
    monkeypatch.delenv(devices.ENV_SYSFS_ROOT, raising=False)
    monkeypatch.delenv(devices.ENV_DEV_ROOT, raising=False)
    assert devices.roots_from_env() == ("/sys", "/dev")
    assert os.environ.get(devices.ENV_SYSFS_ROOT) is None
