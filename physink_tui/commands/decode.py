"""`physink decode`: a capture file to pen samples on stdout and a summary on stderr; no device I/O."""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, TextIO

from physink_tui.commands.decode_plain import write_plain
from physink_tui.errors import CaptureFormatError, DescriptorError
from physink_tui.input.captures.capture_types import CaptureColumns, CaptureDevice
from physink_tui.input.captures.parser import Readable, parse_capture_file
from physink_tui.input.captures.plain import PlainCapture, read_plain
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.vendor_init import find_vendor_init

if TYPE_CHECKING:  # these import numpy, which a plain capture's decoding never needs (`run`)
    from physink_tui.input.captures.capture import Capture
    from physink_tui.input.hid.batch import PenColumns

CHUNK_ROWS = 16384
"""Samples formatted and written at a time."""
PLAIN_MAX_BYTES = 8 << 20
"""A capture up to this size whose every line is plain is decoded without numpy (`decode_plain`); a larger one
streams through the numpy path, whose memory stays flat (docs/BENCHMARKS.md)."""
TEXT_HEADER = "       t        x        y        p tip rng era b1 b2  tilt_x  tilt_y  report"


def read_capture(path: str) -> Capture:
    """Read a capture once (a pipe or FIFO works; a UTF-8 BOM is skipped); an unreadable file is a one-line error."""
    from physink_tui.input.captures.capture import Capture

    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as exc:
        raise CaptureFormatError(f"cannot read capture: {exc.strerror or exc}", path) from None
    return Capture.from_text(raw.removeprefix(b"\xef\xbb\xbf").decode("utf-8", errors="replace"), path=path)


def decoder_for(device: CaptureDevice) -> HidPenDecoder:
    """The device's decoder, with the vendor protocol and maxima `physink record` noted in the capture."""
    init = find_vendor_init(device.comments)
    if init is None:
        return HidPenDecoder(device.descriptor, device.vid, device.pid, name=device.name or None)
    return HidPenDecoder(device.descriptor, device.vid, device.pid, params=init.params, protocol=init.protocol,
                         name=device.name or None)


def decode_capture(capture: Capture) -> list[tuple[int, HidPenDecoder, PenColumns]]:
    """Decode every device of a capture in batch; ``(device index, decoder, columns)`` each."""
    from physink_tui.input.hid.batch import decode_batch

    results = []
    for device in capture.devices:
        decoder = _decoder_of(capture.path, device)
        events = capture.events_for(device.index)
        cols = decode_batch(decoder, [e.t for e in events], [e.data for e in events], [e.line for e in events])
        results.append((device.index, decoder, cols))
    return results


def _decoder_of(path: str | None, device: CaptureDevice) -> HidPenDecoder:
    """`decoder_for`, its error naming the capture and the device."""
    try:
        return decoder_for(device)
    except DescriptorError as exc:
        where = f"device {device.index} ({device.name or 'unnamed'})"
        raise DescriptorError(f"{path or 'capture'}: {where}: {exc}") from None


def _tilt(v: float) -> float | None:
    return None if math.isnan(v) else round(v, 2)


def write_jsonl(cols: PenColumns, out: TextIO, chunk: int = CHUNK_ROWS) -> None:
    """One DESIGN.md pen-sample object per line (values rounded to 6 decimals: byte-stable output), written
    ``chunk`` samples at a time."""
    from physink_tui.commands.decode_jsonl import format_jsonl

    for start in range(0, len(cols), chunk):
        out.write(format_jsonl(cols.rows(start, start + chunk)))


def write_text(cols: PenColumns, out: TextIO) -> None:
    """Aligned columns for reading by eye."""
    out.write(TEXT_HEADER + "\n")
    _write_text_rows(cols, out)


def _write_text_rows(cols: PenColumns, out: TextIO) -> None:
    flag = {True: "  1", False: "  ."}
    for i in range(len(cols)):
        tx, ty = _tilt(float(cols.tilt_x[i])), _tilt(float(cols.tilt_y[i]))
        out.write(
            f"{cols.t[i]:8.4f} {cols.x[i]:8.5f} {cols.y[i]:8.5f} {cols.p[i]:8.5f} {flag[bool(cols.tip[i])]} "
            f"{flag[bool(cols.range[i])]} {flag[bool(cols.eraser[i])]}{flag[bool(cols.b1[i])]}"
            f"{flag[bool(cols.b2[i])]} {'-' if tx is None else tx:>7} {'-' if ty is None else ty:>7}"
            f"    0x{int(cols.report[i]):02x}\n"
        )


def summary(capture: Capture | CaptureColumns | PlainCapture,
            results: Sequence[tuple[int, HidPenDecoder, PenColumns | None]]) -> str:
    """The stderr summary: per device, reports read, samples, ignored by reason, first bad line."""
    lines = []
    for index, decoder, _ in results:
        head = f"device {index}" if len(results) > 1 else "decode"
        layouts = "; ".join(lay.summary() for lay in decoder.layouts.values())
        lines.append(f"{head}: pen layouts: {layouts}")
        lines.append("  " + decoder.stats.summary().replace("\n", "\n  "))
    if capture.bad_lines:
        first = capture.bad_lines[0]
        lines.append(f"{len(capture.bad_lines)} capture lines skipped; first bad line {first.line}: {first.reason}")
    return "\n".join(lines)


def stream_decode(capture: CaptureColumns, write: Callable[[PenColumns, TextIO], None], out: TextIO, head: str = ""
                  ) -> list[tuple[int, HidPenDecoder, None]]:
    """Decode each device of a parsed capture a chunk at a time, writing ``head`` and then each chunk as it is
    decoded (every device's decoder is made first: a bad descriptor stops the run before anything is written)."""
    from physink_tui.input.hid.chunks import decode_in_chunks

    results = [(device.index, _decoder_of(capture.path, device), None) for device in capture.devices]
    for index, decoder, _ in results:
        times, lines, take = capture.of_device(index)
        out.write(head)
        for cols in decode_in_chunks(decoder, times, take, lines):
            write(cols, out)
    return results


class _Prefixed:
    """A binary file whose first bytes were already read: ``read`` gives those, then the rest of the file."""

    def __init__(self, head: bytes, rest: Readable) -> None:
        self.head, self.at, self.rest = head, 0, rest

    def read(self, size: int = -1) -> bytes:
        if self.at >= len(self.head):
            self.head = b""  # given out: let it go
            return self.rest.read(size)
        end = len(self.head) if size < 0 else self.at + size
        got, self.at = self.head[self.at:end], min(end, len(self.head))
        return got + self.rest.read() if size < 0 else got


def read_either(path: str, plain: bool) -> PlainCapture | CaptureColumns:
    """The capture read the plain way when ``plain`` allows it and it is plain and small, else parsed in columns
    (a pipe or FIFO works: it is read once; a UTF-8 BOM is skipped); an unreadable file is a one-line error."""
    try:
        with open(path, "rb") as f:
            head = f.read(PLAIN_MAX_BYTES + 1) if plain else b""
            got = read_plain(head, path) if plain and len(head) <= PLAIN_MAX_BYTES else None
            return got if got is not None else parse_capture_file(_Prefixed(head, f), path)
    except OSError as exc:
        raise CaptureFormatError(f"cannot read capture: {exc.strerror or exc}", path) from None


def run(args: argparse.Namespace) -> int:
    capture = read_either(args.file, args.format == "jsonl")
    if isinstance(capture, PlainCapture):  # most captures: no numpy (its import costs more than their decoding)
        decoders = [(device.index, _decoder_of(capture.path, device)) for device in capture.devices]
        write_plain(capture, decoders, sys.stdout)
        results: list[tuple[int, HidPenDecoder, None]] = [(index, decoder, None) for index, decoder in decoders]
    elif args.format == "jsonl":
        results = stream_decode(capture, write_jsonl, sys.stdout)
    else:
        results = stream_decode(capture, _write_text_rows, sys.stdout, TEXT_HEADER + "\n")
    sys.stdout.flush()
    print(summary(capture, results), file=sys.stderr)
    return 0
