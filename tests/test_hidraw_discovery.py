"""hidraw discovery from a fake sysfs tree laid out as the kernel lays it out, open checks, and the udev rules.

`make_node` builds what ``/sys`` shows for one hidraw node (the class link, the HID device with its uevent and
report descriptor, the USB interface and device above it) plus the ``/dev`` node; `test_devices_command` and
`test_hid_readers` use it too. `run_unprivileged` runs Python code without the DAC override that root has, so
"permission denied" is real even when the tests run as root.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.hidraw import (
    UDEV_INSTALL,
    UDEV_RULES_FILE,
    discover_hidraw,
    info_for_path,
    is_tablet,
    open_error,
    parse_hid_id,
    pen_summaries,
)
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES

ROOT = Path(__file__).resolve().parent.parent

# The boot keyboard of the HID 1.11 specification, appendix B.1: no pen anywhere.
KEYBOARD = bytes.fromhex(
    "05010906a101050719e029e71500250175019508810295017508810195057501050819012905910295017503910195067508"
    "150025650507190029658100c0"
)


def make_node(sysfs: Path, dev: Path, n: int, name: str, vid: int, pid: int, descriptor: bytes, *,
              interface: int | None = 0, bus: int = 3, port: str = "1-1", devnum: int = 4,
              interface_file: bool = True, node: str = "file") -> Path:
    """Lays out ``/sys/class/hidraw/hidraw<n>`` and ``/dev/hidraw<n>``; returns the dev node.

    ``node``: ``"file"`` (an empty regular file), ``"fifo"`` (a named pipe a test writes reports into), or
    ``"none"`` (no dev node).
    """
    if bus == 3:
        usb_dev = sysfs / "devices" / "pci0000:00" / "0000:00:14.0" / "usb1" / port
        usb_dev.mkdir(parents=True, exist_ok=True)
        (usb_dev / "busnum").write_text("1\n")
        (usb_dev / "devnum").write_text(f"{devnum}\n")
        (usb_dev / "idVendor").write_text(f"{vid:04x}\n")
        parent = usb_dev / f"{port}:1.{interface}"
        parent.mkdir(exist_ok=True)
        if interface_file:
            (parent / "bInterfaceNumber").write_text(f"{interface:02x}\n")
        phys = f"usb-0000:00:14.0-{port.split('-', 1)[1]}/input{interface}"
    else:
        parent = sysfs / "devices" / "platform" / "AMDI0010:00" / "i2c-0" / "i2c-WACF2200:00"
        phys = "i2c-WACF2200:00"
    hid = parent / f"{bus:04X}:{vid:04X}:{pid:04X}.{n + 1:04X}"
    hid.mkdir(parents=True)
    (hid / "report_descriptor").write_bytes(descriptor)
    (hid / "uevent").write_text(
        f"DRIVER=hid-generic\nHID_ID={bus:04X}:{vid:08X}:{pid:08X}\nHID_NAME={name}\nHID_PHYS={phys}\n"
        f"HID_UNIQ=\nMODALIAS=hid:b{bus:04X}g0001v{vid:08X}p{pid:08X}\n"
    )
    node_dir = hid / "hidraw" / f"hidraw{n}"
    node_dir.mkdir(parents=True)
    (node_dir / "dev").write_text(f"243:{n}\n")
    os.symlink("../../", node_dir / "device")
    class_dir = sysfs / "class" / "hidraw"
    class_dir.mkdir(parents=True, exist_ok=True)
    os.symlink(os.path.relpath(node_dir, class_dir), class_dir / f"hidraw{n}")
    dev.mkdir(parents=True, exist_ok=True)
    path = dev / f"hidraw{n}"
    if node == "file":
        path.write_bytes(b"")
    elif node == "fifo":
        os.mkfifo(path)
    return path


def make_reference_node(sysfs: Path, dev: Path, n: int, ref_id: str, **kw) -> Path:
    ref = REFERENCE_DEVICES[ref_id]
    return make_node(sysfs, dev, n, ref.name, ref.vid, ref.pid, ref.descriptor, **kw)


def run_unprivileged(code: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    """Runs ``python -c code`` so that file permissions apply: as is when not root, else through ``setpriv``
    without CAP_DAC_OVERRIDE / CAP_DAC_READ_SEARCH (skips when setpriv is missing)."""
    cmd = [sys.executable, "-c", code]
    if os.geteuid() == 0:
        setpriv = shutil.which("setpriv")
        if setpriv is None:
            pytest.skip("running as root and setpriv (util-linux) is missing: cannot drop the DAC override")
        caps = "-dac_override,-dac_read_search"
        cmd = [setpriv, f"--inh-caps={caps}", f"--bounding-set={caps}", *cmd]
    return subprocess.run(cmd, capture_output=True, text=True, env={**os.environ, **(env or {})}, timeout=60,
                          check=False)


@pytest.fixture
def roots(tmp_path: Path) -> tuple[Path, Path]:
    return tmp_path / "sys", tmp_path / "dev"


def test_discovers_every_reference_device_with_its_ids_and_descriptor(roots) -> None:
    sysfs, dev = roots
    for n, ref_id in enumerate(REFERENCE_DEVICES):
        make_reference_node(sysfs, dev, n, ref_id, port=f"1-{n + 1}", devnum=n + 4)
    found = discover_hidraw(str(sysfs), str(dev))
    assert [f.path for f in found] == [str(dev / f"hidraw{n}") for n in range(len(REFERENCE_DEVICES))]
    for n, (info, ref) in enumerate(zip(found, REFERENCE_DEVICES.values(), strict=True)):
        assert (info.name, info.vid, info.pid, info.bus) == (ref.name, ref.vid, ref.pid, 3)
        assert info.descriptor == ref.descriptor
        assert info.interface == 0
        assert info.phys == f"usb-0000:00:14.0-{n + 1}/input0"
        assert (info.usb_bus, info.usb_address) == (1, n + 4)


def test_nodes_come_in_number_order_not_name_order(roots) -> None:
    sysfs, dev = roots
    for n in (10, 2):
        make_reference_node(sysfs, dev, n, "windows-ink", port=f"1-{n}")
    assert [f.path.rsplit("/", 1)[1] for f in discover_hidraw(str(sysfs), str(dev))] == ["hidraw2", "hidraw10"]


def test_interface_number_from_the_directory_name_and_none_off_usb(roots) -> None:
    sysfs, dev = roots
    make_reference_node(sysfs, dev, 0, "huion-v2", interface=1, interface_file=False)
    make_node(sysfs, dev, 1, "WACF2200:00 056A:5256", 0x056A, 0x5256, REFERENCE_DEVICES["windows-ink"].descriptor,
              bus=0x18)
    usb, i2c = discover_hidraw(str(sysfs), str(dev))
    assert usb.interface == 1
    assert (i2c.bus, i2c.interface, i2c.usb_bus, i2c.phys) == (0x18, None, None, "i2c-WACF2200:00")


def test_broken_entries_are_left_out_and_a_missing_class_is_no_devices(roots) -> None:
    sysfs, dev = roots
    assert discover_hidraw(str(sysfs), str(dev)) == []
    make_reference_node(sysfs, dev, 0, "windows-ink")
    make_reference_node(sysfs, dev, 1, "wacom-ff0d", port="1-2")
    uevent = next((sysfs / "devices").rglob("0003:056A:*")) / "uevent"
    uevent.write_text("DRIVER=wacom\nHID_NAME=no ids here\n")
    assert [f.vid for f in discover_hidraw(str(sysfs), str(dev))] == [0x1234]


def test_unreadable_descriptor_gives_an_empty_one(roots) -> None:
    sysfs, dev = roots
    make_reference_node(sysfs, dev, 0, "windows-ink")
    next((sysfs / "devices").rglob("report_descriptor")).unlink()
    (info,) = discover_hidraw(str(sysfs), str(dev))
    assert info.descriptor == b"" and pen_summaries(info) == []


def test_hid_id_parsing() -> None:
    assert parse_hid_id("0005:0000056A:00000357") == (5, 0x056A, 0x0357)
    assert parse_hid_id("garbage") is None and parse_hid_id("0003:zz:0001") is None


def test_pen_summaries_are_the_decoders_layouts(roots) -> None:
    sysfs, dev = roots
    make_reference_node(sysfs, dev, 0, "windows-ink")
    make_node(sysfs, dev, 1, "Boot Keyboard", 0x046D, 0xC31C, KEYBOARD, port="1-2")
    make_reference_node(sysfs, dev, 2, "huion-v2", port="1-3")
    pen, keyboard, huion = discover_hidraw(str(sysfs), str(dev))
    ref = REFERENCE_DEVICES["windows-ink"]
    expected = [lay.summary() for lay in HidPenDecoder(ref.descriptor, ref.vid, ref.pid).layouts.values()]
    assert pen_summaries(pen) == expected and expected
    assert pen_summaries(keyboard) == [] and not is_tablet(keyboard)
    assert is_tablet(pen) and is_tablet(huion)
    assert any(s.startswith("0x08 huion-v2") for s in pen_summaries(huion))


def test_info_for_path_finds_the_sysfs_entry(roots) -> None:
    sysfs, dev = roots
    node = make_reference_node(sysfs, dev, 3, "wacom-ff0d")
    info = info_for_path(str(node), str(sysfs), str(dev))
    assert info is not None and info.vid == 0x056A and info.path == str(node)
    assert info_for_path(str(dev / "hidraw9"), str(sysfs), str(dev)) is None


def test_open_error_for_missing_and_readable_nodes(tmp_path: Path) -> None:
    assert "does not exist" in open_error(str(tmp_path / "hidraw7"))
    node = tmp_path / "hidraw0"
    node.write_bytes(b"")
    assert open_error(str(node)) is None


def test_open_error_names_the_udev_rule_when_permission_is_missing(tmp_path: Path) -> None:
    node = tmp_path / "hidraw0"
    node.write_bytes(b"")
    node.chmod(0o000)
    result = run_unprivileged(f"from physink_tui.input.hid.hidraw import open_error; print(open_error({str(node)!r}))")
    assert result.returncode == 0, result.stderr
    message = result.stdout.strip()
    assert message.startswith(f"permission denied on {node}")
    assert UDEV_INSTALL in message and "\n" not in message


def test_the_udev_readme_gives_exactly_the_install_line_the_message_quotes() -> None:
    readme = (ROOT / "packaging" / "udev" / "README.md").read_text()
    rules = (ROOT / UDEV_RULES_FILE).read_text()
    assert UDEV_INSTALL in readme.splitlines()
    assert UDEV_INSTALL in rules
    assert UDEV_INSTALL.startswith(f"sudo cp {UDEV_RULES_FILE} /etc/udev/rules.d/")


@pytest.mark.parametrize("vid", ["056a", "256c", "5543", "28bd", "2feb", "0458", "172f", "08f2"])
def test_the_rules_cover_hidraw_and_usb_nodes_of_every_tablet_vendor(vid: str) -> None:
    lines = (ROOT / UDEV_RULES_FILE).read_text().splitlines()
    rules = [line for line in lines if line and not line.startswith("#")]
    hidraw = [r for r in rules if f'KERNELS=="*:{vid.upper()}:*"' in r]
    usb = [r for r in rules if f'ATTR{{idVendor}}=="{vid}"' in r]
    for found in (hidraw, usb):
        assert len(found) == 1
        assert 'TAG+="uaccess"' in found[0] and 'MODE="0660"' in found[0] and 'GROUP="plugdev"' in found[0]
