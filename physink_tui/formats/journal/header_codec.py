"""The journal header's JSON line, both ways, checked key by key; entries are `codec`'s, files are not here.

Only ``format``, ``version``, ``canvas`` and ``devices`` are required on reading; ``program`` defaults to
``"unknown"``, ``mapping`` to ``{}`` (the tablet's area onto the whole canvas), ``tip_thresholds`` to libinput's
5 % down / 1 % up, ``vocabulary`` to none. Unknown keys are ignored and reported as warnings.
The header is written in a fixed key order (``format``, ``version``, ``program``, ``canvas``, ``devices``,
``mapping``, ``tip_thresholds``), devices in the order given and ``mapping`` with sorted keys, so
the same header always gives the same bytes and a header read back re-encodes to the bytes it was read from.
"""

from __future__ import annotations

from typing import Any

from physink_tui.formats import json_checks as checks
from physink_tui.formats.journal.codec import compact_json, json_string, parse_object
from physink_tui.formats.journal.entries import (
    DEFAULT_TIP_DOWN,
    DEFAULT_TIP_UP,
    FORMAT,
    FORMAT_VERSION,
    UNKNOWN_PROGRAM,
    JournalHeader,
)
from physink_tui.formats.journal.header_checks import check_mapping, check_vocabulary, decode_devices, encode_devices
from physink_tui.formats.journal.value_checks import at
from physink_tui.formats.json_checks import Place, bad, get

HEADER_KEYS = ("format", "version", "program", "canvas", "devices", "mapping", "tip_thresholds", "vocabulary")
"""The header's keys, in the order written."""



def encode_header(header: JournalHeader) -> str:
    """The header as one line (without the newline), after checking every field.

    >>> from physink_tui.formats.journal.entries import JournalDevice
    >>> h = JournalHeader(800, 600, (JournalDevice("pen0", "Pen", 3, 0x56A, 0x350, b"\\xa1\\xc0"),), {}, 0.05, 0.01,
    ...                   program="physink-tui 0.1.0")
    >>> encode_header(h)
    '{"format":"physink-journal","version":1,"program":"physink-tui 0.1.0","canvas":{"width":800,...'
    >>> print(encode_header(h).partition('"devices":')[2])
    {"pen0":{"name":"Pen","bus":3,"vid":1386,"pid":848,"descriptor":"a1 c0"}},"mapping":{},"tip_thresholds":{...}}
    """
    where = at("header")
    canvas = {
        "width": checks.positive(where, "canvas.width", header.canvas_width),
        "height": checks.positive(where, "canvas.height", header.canvas_height),
    }
    devices = encode_devices(where, "devices", header.devices)
    check_mapping(where, header.mapping, None, strict=True)
    if header.vocabulary:
        check_vocabulary(where, header.vocabulary)
    down, up = _tip_thresholds(where, header.tip_down, header.tip_up)
    parts = [
        f'"format":{json_string(FORMAT)}',
        f'"version":{FORMAT_VERSION}',
        f'"program":{json_string(checks.text(where, "program", header.program, empty=False))}',
        f'"canvas":{compact_json(canvas)}',
        f'"devices":{compact_json(devices)}',
        f'"mapping":{compact_json(header.mapping, sort_keys=True)}',
        f'"tip_thresholds":{{"down":{down!r},"up":{up!r}}}',
    ]
    if header.vocabulary:
        parts.append(f'"vocabulary":{json_string(checks.text(where, "vocabulary", header.vocabulary))}')
    return "{" + ",".join(parts) + "}"


def _tip_thresholds(where: Place, down: Any, up: Any) -> tuple[float, float]:
    down = checks.unit(where, "tip_thresholds.down", down)
    if down <= 0.0:
        raise bad(where, "tip_thresholds.down", "a number in (0, 1]", down)
    up_value = checks.unit(where, "tip_thresholds.up", up)
    if not up_value < down:
        raise bad(where, "tip_thresholds.up", f"a number >= 0 and below down {down!r}", up)
    return down, up_value


def decode_header(text: str, lineno: int = 1, warnings: list[str] | None = None) -> JournalHeader:
    """The header read from its line; unknown keys are ignored and reported in ``warnings`` when given.

    Raises:
        JournalError: ``line <lineno>: key "<key>": expected ..., got ...`` for the first bad field.

    >>> decode_header('{"format":"physink-journal","version":2}')
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 1: key "version": expected 1 (the newest version this program reads), got 2
    """
    where = at(f"line {lineno}")
    obj = parse_object(text, where)
    found = get(obj, where, "format", "format", f'"{FORMAT}" (the first line must be the journal header)')
    if found != FORMAT:
        raise bad(where, "format", f'"{FORMAT}" (the first line must be the journal header)', found)
    version = get(obj, where, "version", "version", f"{FORMAT_VERSION}")
    if type(version) is not int or version != FORMAT_VERSION:
        raise bad(where, "version", f"{FORMAT_VERSION} (the newest version this program reads)", version)
    program = checks.text(where, "program", obj.get("program", UNKNOWN_PROGRAM), empty=False)
    canvas = _sub_object(obj, where, "canvas", ("width", "height"), warnings)
    width = checks.positive(where, "canvas.width", get(canvas, where, "width", "canvas.width", "a number > 0"))
    height = checks.positive(where, "canvas.height", get(canvas, where, "height", "canvas.height", "a number > 0"))
    devices = tuple(decode_devices(where, get(obj, where, "devices", "devices", "an object"), warnings))
    mapping = check_mapping(where, obj.get("mapping", {}), warnings)
    down, up = DEFAULT_TIP_DOWN, DEFAULT_TIP_UP
    if "tip_thresholds" in obj:
        tips = _sub_object(obj, where, "tip_thresholds", ("down", "up"), warnings)
        down, up = _tip_thresholds(
            where,
            get(tips, where, "down", "tip_thresholds.down", "a number in (0, 1]"),
            get(tips, where, "up", "tip_thresholds.up", "a number in [0, 1)"),
        )
    vocabulary = check_vocabulary(where, obj.get("vocabulary", ""))
    if warnings is not None:
        warnings.extend(where.unknown_key(key) for key in obj if key not in HEADER_KEYS)
    return JournalHeader(width, height, devices, mapping, down, up, program, vocabulary)


def _sub_object(
    obj: dict[str, Any], where: Place, key: str, keys: tuple[str, ...], warnings: list[str] | None
) -> dict[str, Any]:
    expected = "an object with " + " and ".join(keys)
    value = get(obj, where, key, key, expected)
    if not isinstance(value, dict):
        raise bad(where, key, expected, value)
    if warnings is not None:
        warnings.extend(where.unknown_key(f"{key}.{k}") for k in value if k not in keys)
    return value
