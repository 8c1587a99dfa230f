"""`physink decode`: a capture file to pen samples on stdout and a summary on stderr; no device I/O."""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable, Sequence
from typing import TextIO

from physink_tui.commands.decode_jsonl import format_jsonl
from physink_tui.errors import CaptureFormatError, DescriptorError
from physink_tui.input.captures.capture import Capture, CaptureColumns, CaptureDevice
from physink_tui.input.captures.parser import parse_capture_file
from physink_tui.input.hid.batch import PenColumns, decode_batch
from physink_tui.input.hid.chunks import decode_in_chunks
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.vendor_init import find_vendor_init

CHUNK_ROWS = 16384
"""Samples formatted and written at a time."""
TEXT_HEADER = "       t        x        y        p tip rng era b1 b2  tilt_x  tilt_y  report"


def read_capture(path: str) -> Capture:
    """Read a capture once (a pipe or FIFO works; a UTF-8 BOM is skipped); an unreadable file is a one-line error."""
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


def summary(capture: Capture | CaptureColumns,
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


def read_capture_columns(path: str) -> CaptureColumns:
    """Parse a capture a chunk of lines at a time (a pipe or FIFO works; a UTF-8 BOM is skipped); an unreadable
    file is a one-line error."""
    try:
        with open(path, "rb") as f:
            return parse_capture_file(f, path)
    except OSError as exc:
        raise CaptureFormatError(f"cannot read capture: {exc.strerror or exc}", path) from None


def stream_decode(capture: CaptureColumns, write: Callable[[PenColumns, TextIO], None], out: TextIO, head: str = ""
                  ) -> list[tuple[int, HidPenDecoder, None]]:
    """Decode each device of a parsed capture a chunk at a time, writing ``head`` and then each chunk as it is
    decoded (every device's decoder is made first: a bad descriptor stops the run before anything is written)."""
    results = [(device.index, _decoder_of(capture.path, device), None) for device in capture.devices]
    for index, decoder, _ in results:
        times, lines, take = capture.of_device(index)
        out.write(head)
        for cols in decode_in_chunks(decoder, times, take, lines):
            write(cols, out)
    return results


def run(args: argparse.Namespace) -> int:
    capture = read_capture_columns(args.file)
    if args.format == "jsonl":
        results = stream_decode(capture, write_jsonl, sys.stdout)
    else:
        results = stream_decode(capture, _write_text_rows, sys.stdout, TEXT_HEADER + "\n")
    sys.stdout.flush()
    print(summary(capture, results), file=sys.stderr)
    return 0
