"""Threads reading raw HID reports (hidraw, hidapi) and the --device factory; no decoding, no vendor init.

Reading through pyusb is `usb_reader`'s, reconnecting `reconnecting`'s, vendor initialisation `vendor_init`'s.

Every reader keeps the `sources` contract: `RawReport`s stamped with ``time.monotonic()`` as read, then exactly
one `SourceEnded` as the last item (``error=None`` after `stop`, a `DeviceError` saying the device disappeared or
failed otherwise), after the device has been released. Opening happens in the constructor, so a wrong path or a
missing permission raises `DeviceError` to whoever opens, never to the consumer of the queue.
"""

from __future__ import annotations

import errno
import os
import queue
import re
import select
import stat
import time
from dataclasses import replace
from typing import Any

from physink_tui.errors import DeviceError
from physink_tui.input.hid.hidraw import (
    BUS_USB,
    HidrawInfo,
    descriptor_pen_reports,
    discover_hidraw,
    hidraw_class_dir,
    info_for_path,
    is_tablet,
    permission_message,
)
from physink_tui.input.hid.threaded_reader import POLL_TIMEOUT_S, ThreadedReader
from physink_tui.input.sources import RawReport, SourceItem

READ_SIZE = 4096
"""Bytes asked of each read: more than any HID report (the kernel caps a report at 4 KiB + id)."""

_VID_PID = re.compile(r"([0-9a-fA-F]{1,4}):([0-9a-fA-F]{1,4})\Z")


class HidrawReader(ThreadedReader):
    """Reads a hidraw node (or any readable fd) with ``poll``; one report per ``read``.

    Args:
        source: a path (opened ``O_RDONLY | O_NONBLOCK``) or an open fd, which becomes the reader's (it is set
            non-blocking and closed when the reader ends).
        device_id: the id on every item.
        read_size: bytes per read. hidraw returns one report per read whatever the size; a pipe standing in for
            a device (tests) returns whatever is buffered, so such a fake reads exactly one report's length.
        info: what discovery knows of the node, kept for the caller (capture headers).
    """

    kind = "hidraw"

    def __init__(self, source: str | int, device_id: str = "tablet0", *, read_size: int = READ_SIZE,
                 info: HidrawInfo | None = None) -> None:
        if isinstance(source, int):
            fd, what = source, f"hidraw fd {source}"
        else:
            fd, what = _open_node(source), f"hidraw {source}"
        if info is not None and info.name:
            what += f" ({info.name})"
        super().__init__(device_id, what, info)
        self._fd = fd
        self._read_size = read_size
        os.set_blocking(fd, False)
        self._wake_r, self._wake_w = os.pipe()
        os.set_blocking(self._wake_w, False)

    def _wake(self) -> None:
        with self._lock:
            if not self._released:
                try:
                    os.write(self._wake_w, b"x")
                except BlockingIOError:  # already woken
                    pass

    def _read_loop(self, out: queue.Queue[SourceItem]) -> DeviceError | None:
        fd, put, monotonic, read, size = self._fd, out.put, time.monotonic, os.read, self._read_size
        poller = select.poll()
        poller.register(fd, select.POLLIN | select.POLLPRI)  # POLLERR, POLLHUP and POLLNVAL always come
        poller.register(self._wake_r, select.POLLIN)
        timeout_ms = int(POLL_TIMEOUT_S * 1000)
        while not self._stopping.is_set():
            events = poller.poll(timeout_ms)
            for which, mask in events:
                if which == self._wake_r:
                    return None
                if mask & select.POLLNVAL:
                    return DeviceError(f"{self.what} disappeared: its file descriptor was closed")
            if not events:
                continue
            try:
                data = read(fd, size)
            except (BlockingIOError, InterruptedError):
                continue
            except OSError as exc:  # ENODEV, EIO (unplugged), anything else: the device is gone for us
                name = errno.errorcode.get(exc.errno or 0, "?")
                return DeviceError(f"{self.what} disappeared: read failed: {exc.strerror or exc} ({name})")
            if not data:
                return DeviceError(f"{self.what} disappeared: end of file")
            put(RawReport(monotonic(), data, self.device_id))
        return None

    def _release_device(self) -> None:
        for fd in (self._fd, self._wake_r, self._wake_w):
            try:
                os.close(fd)
            except OSError:
                pass


def _open_node(path: str) -> int:
    try:
        return os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except PermissionError:
        raise DeviceError(permission_message(path)) from None
    except FileNotFoundError:
        raise DeviceError(f"{path} does not exist (unplugged? see `physink devices`)") from None
    except OSError as exc:
        raise DeviceError(f"cannot open {path}: {exc.strerror or exc}") from None


class HidapiReader(ThreadedReader):
    """Reads a device through hidapi (``hid.device``), for systems without sysfs hidraw discovery.

    Args:
        path: hidapi's path (from ``hid.enumerate()``), str or bytes.
        device_factory: makes the ``hid.device`` (tests pass a fake with ``open_path``, ``read``, ``close``).
    """

    kind = "hidapi"

    def __init__(self, path: str | bytes, device_id: str = "tablet0", *, read_size: int = READ_SIZE,
                 timeout_ms: int = int(POLL_TIMEOUT_S * 1000), info: HidrawInfo | None = None,
                 device_factory: Any = None) -> None:
        raw_path = path.encode() if isinstance(path, str) else path
        text = raw_path.decode(errors="replace")
        if device_factory is None:
            try:
                import hid
            except ImportError:
                raise DeviceError(f"cannot open {text}: hidapi (module hid) is not installed") from None
            device_factory = hid.device
        dev = device_factory()
        try:
            dev.open_path(raw_path)
        except OSError as exc:
            raise DeviceError(f"hidapi cannot open {text}: {exc} (permission? see `physink devices`)") from None
        if info is not None and not info.descriptor:
            info = replace(info, descriptor=_hidapi_descriptor(dev))
        super().__init__(device_id, f"hidapi {text}", info)
        self._dev = dev
        self._read_size = read_size
        self._timeout_ms = timeout_ms

    def _read_loop(self, out: queue.Queue[SourceItem]) -> DeviceError | None:
        dev, put, monotonic = self._dev, out.put, time.monotonic
        while not self._stopping.is_set():
            try:
                data = dev.read(self._read_size, self._timeout_ms)
            except (OSError, ValueError) as exc:  # hidapi: OSError("read error") when unplugged
                return DeviceError(f"{self.what} disappeared: {exc}")
            if data:
                put(RawReport(monotonic(), bytes(data), self.device_id))
        return None

    def _release_device(self) -> None:
        try:
            self._dev.close()
        except Exception:  # closing a vanished device may complain; there is nothing left to release
            pass


def _hidapi_descriptor(dev: Any) -> bytes:
    try:
        return bytes(dev.get_report_descriptor())
    except (OSError, ValueError, AttributeError):  # older hidapi, or a backend that cannot tell
        return b""


def parse_vid_pid(text: str) -> tuple[int, int] | None:
    """``"256c:006d"`` as ``(0x256c, 0x6d)``; None when it is not VID:PID in hex.

    >>> parse_vid_pid("256C:6d"), parse_vid_pid("/dev/hidraw0")
    ((9580, 109), None)
    """
    match = _VID_PID.match(text.strip())
    return (int(match.group(1), 16), int(match.group(2), 16)) if match else None


def _rank(info: HidrawInfo) -> tuple[int, int]:
    """Interfaces whose own descriptor describes a pen come first, then the lowest interface number."""
    return (0 if descriptor_pen_reports(info) else 1, info.interface if info.interface is not None else 99)


def choose_tablet(nodes: list[HidrawInfo]) -> HidrawInfo | None:
    """The node to read among a discovery's: a tablet (`is_tablet`), best ranked; None when there is none."""
    tablets = [n for n in nodes if is_tablet(n)]
    return min(tablets, key=_rank) if tablets else None


def check_device_spec(spec: str | None) -> None:
    """Refuses a ``--device`` value that names no device however long one waits: none of `open_reader`'s forms, or
    a path to a regular file or a folder (a node that does not exist yet may appear when the tablet is plugged in).

    >>> check_device_spec("zzzz:yyyy")
    Traceback (most recent call last):
    ...
    physink_tui.errors.DeviceError: --device 'zzzz:yyyy': expected 'auto', a hidraw path such as /dev/hidraw3, or \
VID:PID in hex such as 256c:006d
    """
    spec = (spec or "auto").strip()
    if "/" in spec:
        try:
            mode = os.stat(spec).st_mode
        except FileNotFoundError:
            return  # a node that may appear when the tablet is plugged in
        except OSError as exc:
            raise DeviceError(f"--device {spec!r}: {exc.strerror or exc}") from None
        if stat.S_ISREG(mode) or stat.S_ISDIR(mode):
            raise DeviceError(f"--device {spec!r}: not a device node; expected a hidraw node such as /dev/hidraw3")
        return
    if spec == "auto" or parse_vid_pid(spec) is not None or spec.startswith("hidraw"):
        return
    raise DeviceError(f"--device {spec!r}: expected 'auto', a hidraw path such as /dev/hidraw3, or VID:PID in hex "
                      "such as 256c:006d")


def open_reader(spec: str | None, device_id: str = "tablet0", *, sysfs_root: str = "/sys",
                dev_root: str = "/dev") -> ThreadedReader:
    """Opens the reader ``--device`` names; the reader's ``info`` describes the device.

    Args:
        spec: ``None`` or ``"auto"`` (the first tablet found), a hidraw path (``/dev/hidraw3``, or ``hidraw3``),
            or ``VID:PID`` in hex (that device's hidraw node when it has one, else pyusb; hidapi where sysfs has
            no hidraw class at all).

    Raises:
        DeviceError: a spec that is none of these, no such device, or one that cannot be opened (permission).
    """
    spec = (spec or "auto").strip()
    if spec == "auto":
        return _open_auto(device_id, sysfs_root, dev_root)
    ids = parse_vid_pid(spec)
    if ids is not None:
        return _open_vid_pid(*ids, device_id, sysfs_root, dev_root)
    if not ("/" in spec or spec.startswith("hidraw")):
        raise DeviceError(f"--device {spec!r}: expected 'auto', a hidraw path such as /dev/hidraw3, or VID:PID in "
                          "hex such as 256c:006d")
    path = spec if "/" in spec else os.path.join(dev_root, spec)
    return HidrawReader(path, device_id, info=info_for_path(path, sysfs_root, dev_root))


def _open_auto(device_id: str, sysfs_root: str, dev_root: str) -> ThreadedReader:
    nodes = discover_hidraw(sysfs_root, dev_root)
    chosen = choose_tablet(nodes)
    if chosen is not None:
        return HidrawReader(chosen.path, device_id, info=chosen)
    if not nodes:
        from physink_tui.input.hid.usb_reader import list_usb_tablets

        try:
            usb = list_usb_tablets()
        except DeviceError:  # no pyusb or no libusb: there is nothing more to look at
            usb = []
        if usb:
            return _open_vid_pid(usb[0].vid, usb[0].pid, device_id, sysfs_root, dev_root)
    where = f"{len(nodes)} hidraw nodes in {hidraw_class_dir(sysfs_root)}"
    raise DeviceError(f"no pen tablet found ({where}, none with a pen report or a known tablet id); "
                      "run `physink devices` to see what is there")


def _open_vid_pid(vid: int, pid: int, device_id: str, sysfs_root: str, dev_root: str) -> ThreadedReader:
    ids = f"{vid:04x}:{pid:04x}"
    nodes = [n for n in discover_hidraw(sysfs_root, dev_root) if (n.vid, n.pid) == (vid, pid)]
    if nodes:
        chosen = choose_tablet(nodes) or min(nodes, key=_rank)
        return HidrawReader(chosen.path, device_id, info=chosen)
    if not hidraw_class_dir(sysfs_root).is_dir():
        path = _hidapi_path(vid, pid)
        if path is not None:
            info = HidrawInfo(path.decode(errors="replace"), "", BUS_USB, vid, pid, None, "", b"")
            return HidapiReader(path, device_id, info=info)
    from physink_tui.input.hid.usb_reader import PyusbInterruptReader

    try:
        return PyusbInterruptReader(vid, pid, 0, None, device_id)
    except DeviceError as exc:
        raise DeviceError(f"{ids} has no hidraw node, and pyusb cannot read it either: {exc}") from None


def _hidapi_path(vid: int, pid: int) -> bytes | None:
    try:
        import hid

        found = hid.enumerate(vid, pid)
    except Exception:  # no hidapi, or its backend failed: fall through to pyusb
        return None
    found.sort(key=lambda d: d.get("interface_number", 0))
    return found[0]["path"] if found else None

