"""Checks the journal header's devices, mapping and vocabulary key by key (and ``device`` lines'); no JSON, no I/O.

The ``mapping`` object is the tablet-to-canvas mapping of `physink_tui.input.pen.mapping.TabletMapping`: every key
is optional (a missing one takes the identity default, see `physink_tui.input.journal_replay.pen_input_for`),
each present one is checked by type and range here, so a replay never meets a mapping it cannot build.
Unknown mapping keys are dropped with a warning, as unknown header keys are.
"""

from __future__ import annotations

from typing import Any

from physink_tui.errors import JournalError, PhysinkError
from physink_tui.formats import json_checks as checks
from physink_tui.formats.journal import value_checks
from physink_tui.formats.journal.entries import JournalDevice
from physink_tui.formats.json_checks import Place, bad, get, show

MAPPING_SIZES = ("canvas_width", "canvas_height", "tablet_width", "tablet_height")
"""Mapping keys holding a size: finite numbers > 0 (only their ratios matter)."""

MAPPING_FLAGS = ("left_handed", "keep_aspect", "display_tablet")
"""Mapping keys holding true or false."""

MAPPING_KEYS = (*MAPPING_SIZES, "area", "rotation", *MAPPING_FLAGS)
"""Every key a header ``mapping`` may have."""

ROTATIONS = (0, 90, 180, 270)
"""The values ``mapping.rotation`` takes (degrees clockwise)."""

DEVICE_KEYS = ("name", "bus", "vid", "pid", "descriptor")
"""The keys of each device object, in the order written."""

_INT = "null or an integer in 0..65535"
_HEX = 'hex bytes separated by spaces, e.g. "05 0d 09 02"'
_AREA = "a list of 4 numbers [x0, y0, x1, y1] in [0, 1] with x0 < x1 and y0 < y1"


def check_mapping(where: Place, mapping: Any, warnings: list[str] | None, *, strict: bool = False) -> dict[str, Any]:
    """The header's ``mapping`` with its known keys checked and unknown ones dropped (and warned about), or
    refused when ``strict`` (writing: what is written must read back the same).

    >>> from physink_tui.formats.journal.value_checks import at
    >>> check_mapping(at("line 1"), {"area": [None, 0, 1, 1]}, None)
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 1: key "mapping.area[0]": expected a number in [0, 1], got null
    """
    if not isinstance(mapping, dict):
        raise bad(where, "mapping", "an object", mapping)
    out: dict[str, Any] = {}
    for key, value in mapping.items():
        path = f"mapping.{key}"
        if key in MAPPING_SIZES:
            checks.positive(where, path, value)
        elif key in MAPPING_FLAGS:
            checks.flag(where, path, value)
        elif key == "rotation":
            if type(value) is not int or value not in ROTATIONS:
                raise bad(where, path, "one of 0, 90, 180, 270 (degrees clockwise)", value)
        elif key == "area":
            _check_area(where, path, value)
        elif strict:
            raise bad(where, path, f"no other keys than {', '.join(MAPPING_KEYS)}", value)
        else:
            if warnings is not None:
                warnings.append(where.unknown_key(path))
            continue
        out[key] = value
    return out


def _check_area(where: Place, path: str, area: Any) -> None:
    if not isinstance(area, list) or len(area) != 4:
        raise bad(where, path, _AREA, area)
    x0, y0, x1, y1 = (checks.unit(where, f"{path}[{i}]", v) for i, v in enumerate(area))
    if not x0 < x1:
        raise bad(where, f"{path}[2]", f"a number above x0 {x0!r} (the area's right edge)", area[2])
    if not y0 < y1:
        raise bad(where, f"{path}[3]", f"a number above y0 {y0!r} (the area's bottom edge)", area[3])


def check_vocabulary(where: Place, vocabulary: Any) -> str:
    """The header's ``vocabulary`` text, checked line by line as a vocabulary file is.

    >>> from physink_tui.formats.journal.value_checks import at
    >>> check_vocabulary(at("line 1"), "verb topples\\nverb")
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 1: key "vocabulary": expected the text of a vocabulary file; \
vocabulary:2: 'verb': expected at least one word after 'verb'
    """
    text = checks.text(where, "vocabulary", vocabulary)
    if text:
        from physink_tui.timeline.phrases import parse_vocabulary  # the core owns the vocabulary's rules

        try:
            parse_vocabulary(text, "vocabulary")
        except PhysinkError as exc:
            raise JournalError(f'{where}: key "vocabulary": expected the text of a vocabulary file; {exc}') from None
    return text


def decode_devices(where: Place, devices: Any, warnings: list[str] | None, top: str = "devices") -> list[JournalDevice]:
    """The devices of a header's ``devices`` object, or of a ``device`` line's with ``top="device"``, checked.

    >>> from physink_tui.formats.journal.value_checks import at
    >>> decode_devices(at("line 7"), {"pad1": {"name": None, "bus": 3, "vid": -1, "pid": 0, "descriptor": "a1 c0"}},
    ...                None, "device")
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 7: key "device.pad1.vid": expected null or an integer in 0..65535, got -1
    """
    if not isinstance(devices, dict) or (top == "device" and not devices):
        raise bad(where, top, "an object of device id -> device", devices)
    out = []
    for dev_id, dev in devices.items():
        checks.text(where, top, dev_id, empty=False)
        key = f"{top}.{dev_id}"
        if not isinstance(dev, dict):
            raise bad(where, key, "an object with " + ", ".join(DEVICE_KEYS), dev)
        name = get(dev, where, "name", f"{key}.name", "a string or null")
        bus, vid, pid = (
            checks.optional_int(where, f"{key}.{k}", get(dev, where, k, f"{key}.{k}", _INT), 0xFFFF)
            for k in ("bus", "vid", "pid")
        )
        out.append(
            JournalDevice(
                dev_id,
                None if name is None else checks.text(where, f"{key}.name", name),
                bus,
                vid,
                pid,
                value_checks.hex_bytes(
                    where, f"{key}.descriptor", get(dev, where, "descriptor", f"{key}.descriptor", _HEX)
                ),
            )
        )
        if warnings is not None:
            warnings.extend(where.unknown_key(f"{key}.{k}") for k in dev if k not in DEVICE_KEYS)
    return out


def encode_devices(where: Place, top: str, devices: Any) -> dict[str, Any]:
    """Devices as the JSON object of a header's ``devices`` or a ``device`` line, after checking each field."""
    out: dict[str, Any] = {}
    for dev in devices:
        if not isinstance(dev, JournalDevice):
            raise bad(where, top, "JournalDevice values", dev)
        checks.text(where, top, dev.id, empty=False)
        if dev.id in out:
            raise JournalError(f'{where}: key "{top}": device id {show(dev.id)} appears twice')
        key = f"{top}.{dev.id}"
        out[dev.id] = {
            "name": dev.name if dev.name is None else checks.text(where, f"{key}.name", dev.name),
            "bus": checks.optional_int(where, f"{key}.bus", dev.bus, 0xFFFF),
            "vid": checks.optional_int(where, f"{key}.vid", dev.vid, 0xFFFF),
            "pid": checks.optional_int(where, f"{key}.pid", dev.pid, 0xFFFF),
            "descriptor": value_checks.report_bytes(where, f"{key}.descriptor", dev.descriptor).hex(" "),
        }
    return out
