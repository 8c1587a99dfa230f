"""Reads a plainly well-formed capture into each device's event texts without numpy, or says it is not plain.

`physink decode` of a small capture spends more on importing numpy than on decoding, so a capture whose every line
is plain takes this path: header lines go through `CaptureParser`'s own checks, and each ``E:`` line is split into
its stamp and its ``<length> <hex bytes>`` text, which is checked once per distinct text (a capture repeats most
of its reports). Anything the full parser would report or repair (a bad line, a stamp that jumps ahead and back, an
event before its descriptor, a line with stray spaces or a CR) makes `read_plain` return None, and the caller parses
the capture with `parser` instead: what either path accepts, it reads the same (tested on every shared capture).
"""

from __future__ import annotations

import operator
from collections import Counter
from itertools import compress, count, repeat
from operator import itemgetter
from typing import NamedTuple

from physink_tui.errors import CaptureFormatError
from physink_tui.input.captures.capture_types import GLITCH_SECONDS, MAX_SECONDS, BadLine, CaptureDevice
from physink_tui.input.captures.parser import CaptureParser

_HEADER_KINDS = frozenset(("R:", "N:", "P:", "I:", "D:"))


class PlainEvents(NamedTuple):
    """One device's reports as the capture spells them, in file order.

    Attributes:
        stamps: each report's time as written (``"000001.959698"``).
        times: the same as floats.
        reports: each report's ``<length> <hex bytes>`` text.
        lines: each report's 1-based capture line.
        data: each distinct text's bytes.
        counts: how many times each distinct text occurs.
    """

    stamps: list[str]
    times: list[float]
    reports: list[str]
    lines: list[int]
    data: dict[str, bytes]
    counts: Counter[str]


class PlainCapture(NamedTuple):
    """A capture read by `read_plain`: its devices, in the order the full parser gives, and their events (it has no
    bad lines: a capture with one is not plain)."""

    path: str | None
    devices: tuple[CaptureDevice, ...]
    events: dict[int, PlainEvents]
    bad_lines: tuple[BadLine, ...] = ()


def report_bytes(text: str) -> bytes | None:
    """The bytes of a ``<length> <hex bytes>`` text, or None unless it is exactly that: a decimal length, then that
    many two-digit hex bytes each after one space."""
    declared, _, hexes = text.partition(" ")
    if not (declared.isascii() and declared.isdigit()):
        return None
    try:
        data = bytes.fromhex(hexes)  # hex digit pairs, whitespace allowed between them
    except ValueError:
        return None
    n = len(data)
    if n != int(declared) or len(hexes) != max(3 * n - 1, 0) or hexes[2::3] != " " * (n - 1):
        return None  # with 2n hex digits in 3n - 1 characters, the others are the single spaces
    return data if n or text == declared else None


def _reports_bytes(texts: list[str]) -> dict[str, bytes] | None:
    """`report_bytes` of each text, or None if one is not a report: texts of one declared length (most are) are
    checked and read at once."""
    out: dict[str, bytes] = {}
    first = texts[0][:texts[0].find(" ") + 1] if texts else ""
    by_length: dict[str, list[str]] = {}
    if first and set(map(itemgetter(slice(0, len(first))), texts)) == {first}:  # one declared length (the usual)
        by_length[first] = texts
    else:
        for text in texts:
            by_length.setdefault(text[:text.find(" ") + 1], []).append(text)
    for head, group in by_length.items():
        n = int(head) if head[:-1].isascii() and head[:-1].isdigit() else 0
        width = len(head) + 3 * n - 1
        if n and set(map(len, group)) == {width}:
            hexes = " ".join(map(itemgetter(slice(len(head), None)), group))  # one long run of bytes
            if hexes[2::3] == " " * (len(group) * n - 1):
                try:
                    blob = bytes.fromhex(hexes)
                except ValueError:
                    return None
                if len(blob) == n * len(group):  # 2 hex digits in each of the other places
                    out.update(zip(group, [blob[k:k + n] for k in range(0, len(blob), n)], strict=True))
                    continue
        for text in group:
            got = report_bytes(text)
            if got is None:
                return None
            out[text] = got
    return out


def _times(stamps: list[str]) -> list[float] | None:
    """The stamps as floats, or None unless each is digits with an optional fraction, none is later than
    `MAX_SECONDS` and none jumps more than `GLITCH_SECONDS` ahead of the one before (the full parser decides
    whether such a jump is a glitch)."""
    text = "\n" + "\n".join(stamps) + "\n"
    try:
        other = text.encode("ascii").translate(None, b"0123456789.\n")
    except UnicodeEncodeError:
        return None
    if other or "\n." in text or ".\n" in text:  # a point first or last
        return None
    try:  # digits and points only, none first or last: `float` refuses only an empty stamp or a second point
        times = list(map(float, stamps))
    except ValueError:
        return None
    if times and (max(times) > MAX_SECONDS
                  or (len(times) > 1 and max(map(operator.sub, times[1:], times)) > GLITCH_SECONDS)):
        return None
    return times


def _split(run: list[str]) -> tuple[list[str], list[str]] | None:
    """The stamps and the ``<length> <hex bytes>`` texts of lines starting ``"E: "``, as ``line.split(" ", 2)``
    gives them, or None when a line has fewer fields. Stamps of one width (hid-recorder's) are sliced out."""
    width = run[0].find(" ", 3)
    try:
        if width > 3 and set(map(itemgetter(width), run)) == {" "}:  # a stamp with a space in it fails `_times`
            return list(map(itemgetter(slice(3, width)), run)), list(map(itemgetter(slice(width + 1, None)), run))
    except IndexError:  # a shorter line
        pass
    parts = [line.split(" ", 2) for line in run]
    if min(map(len, parts)) != 3:
        return None
    return [p[1] for p in parts], [p[2] for p in parts]


def _others(lines: list[str]) -> list[int]:
    """The indexes of the lines that do not start ``"E: "``, and then ``len(lines)``."""
    events = map(str.startswith, lines, repeat("E: "))
    return [*compress(count(), map(operator.not_, events)), len(lines)]


def read_plain(raw: bytes, path: str | None) -> PlainCapture | None:
    """Read a capture file's bytes (UTF-8, a BOM skipped) the plain way, or None when the full parser is needed.

    Raises nothing of its own: a capture the full parser would refuse is left to it, so the error is its."""
    parser = CaptureParser(path)
    found: dict[int, tuple[list[str], list[str], list[int]]] = {}
    text = raw.decode("utf-8", errors="replace").removeprefix("\ufeff")
    lines = text.split("\n")
    into = None
    start = 0  # the first line not yet read
    try:
        for k in _others(lines):
            if k > start:  # a run of event lines, at once
                got = _split(lines[start:k])
                if into is None or got is None:
                    return None
                parser.pending.clear()  # comments before an event belong to no header
                into[0].extend(got[0])
                into[1].extend(got[1])
                into[2].extend(range(start + 1, k + 1))
            if k == len(lines):
                break
            start = k + 1
            line = lines[k].strip()
            if not line:
                continue
            if line[0] == "#":
                parser.pending.append(line[2:] if line.startswith("# ") else line[1:])
                continue
            if line[:2] not in _HEADER_KINDS:
                return None
            parser.slow_line(k + 1, line)
            if parser.bad:
                return None
            dev = parser.current
            into = found.setdefault(dev.index, ([], [], [])) if dev is not None and dev.descriptor else None
    except CaptureFormatError:
        return None
    if not parser.devices or any(not d.descriptor for d in parser.devices.values()):
        return None
    events = {}
    for index in parser.devices:
        stamps, reports, linenos = found.get(index, ([], [], []))
        times = _times(stamps)
        if times is None:
            return None
        counts = Counter(reports)
        data = _reports_bytes(list(counts))
        if data is None:
            return None
        events[index] = PlainEvents(stamps, times, reports, linenos, data, counts)
    return PlainCapture(path, tuple(d.build() for d in parser.devices.values()), events)
