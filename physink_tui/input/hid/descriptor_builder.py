"""Builds HID report descriptor bytes from readable item calls; parsing them is `descriptor`'s job.

Each function returns the bytes of one short item (HID 1.11 section 6.2.2.2) in its shortest correct encoding:
one, two or four data bytes. Values the specification reads as signed (logical and physical extents) are
written in two's complement in the smallest size that holds them, so a logical maximum of 255 takes two bytes
(``26 ff 00``): a lone ``ff`` is -1 to parsers that sign-extend, as Windows does. Unsigned values (pages,
usages, sizes, counts, ids, units, flags) take the smallest size that holds them unsigned. A zero is written
with one data byte, as real descriptors do, rather than as a zero-size item.

>>> build(usage_page(0x0D), usage(0x02), collection("application"), end_collection()).hex(" ")
'05 0d 09 02 a1 01 c0'
>>> logical(0, 255).hex(" ")
'15 00 26 ff 00'
"""

from __future__ import annotations

from collections.abc import Iterable

# Item types (bits 2-3 of the prefix).
_MAIN, _GLOBAL, _LOCAL = 0, 1, 2

COLLECTION_KINDS = {"physical": 0x00, "application": 0x01, "logical": 0x02, "report": 0x03}
"""Collection item values by name (HID 1.11 6.2.2.6)."""

# Input item flags (HID 1.11 6.2.2.5): bit 0 constant, bit 1 variable, bit 2 relative.
DATA_ARRAY = 0x00
CONSTANT = 0x01
DATA_VARIABLE = 0x02
CONSTANT_VARIABLE = 0x03
DATA_VARIABLE_RELATIVE = 0x06

# Unit codes: nibble 0 is the system (1 SI linear, 2 SI rotation, 3 English linear, 4 English rotation),
# nibble 1 the exponent of length (or of angle, for the rotation systems).
UNIT_NONE = 0x00
UNIT_CM = 0x11
UNIT_RADIANS = 0x12
UNIT_INCH = 0x13
UNIT_DEGREES = 0x14


def _item(tag: int, kind: int, data: bytes) -> bytes:
    size_code = {0: 0, 1: 1, 2: 2, 4: 3}[len(data)]
    return bytes([(tag << 4) | (kind << 2) | size_code]) + data


def _unsigned(value: int, what: str) -> bytes:
    if not 0 <= value <= 0xFFFFFFFF:
        raise ValueError(f"{what} {value!r} does not fit an unsigned 32-bit item (expected 0..0xffffffff)")
    n = 1 if value < 0x100 else 2 if value < 0x10000 else 4
    return value.to_bytes(n, "little")


def _signed(value: int, what: str) -> bytes:
    if not -(1 << 31) <= value < 1 << 31:
        raise ValueError(f"{what} {value!r} does not fit a signed 32-bit item (expected -2**31..2**31-1)")
    n = 1 if -0x80 <= value < 0x80 else 2 if -0x8000 <= value < 0x8000 else 4
    return value.to_bytes(n, "little", signed=True)


def build(*parts: bytes | Iterable[bytes]) -> bytes:
    """Concatenate items (or iterables of items) into one descriptor.

    >>> build(report_size(1), [report_count(2), input(CONSTANT)]).hex(" ")
    '75 01 95 02 81 01'
    """
    out = bytearray()
    for part in parts:
        if isinstance(part, bytes | bytearray):
            out += part
        else:
            for item in part:
                out += item
    return bytes(out)


# -- main items -----------------------------------------------------------------------------------


def input(flags: int = DATA_VARIABLE) -> bytes:
    """Input item (the name shadows the builtin on purpose: it is the HID item's name); ``flags`` as
    `DATA_VARIABLE`, `CONSTANT`, ..."""
    return _item(0x8, _MAIN, _unsigned(flags, "input flags"))


def collection(kind: str | int) -> bytes:
    """Collection item: ``"physical"``, ``"application"``, ``"logical"``, ``"report"`` or a raw value.

    >>> collection("physical").hex(" ")
    'a1 00'
    """
    if isinstance(kind, str):
        if kind not in COLLECTION_KINDS:
            expected = ", ".join(COLLECTION_KINDS)
            raise ValueError(f"collection kind {kind!r} is unknown (expected one of {expected})")
        kind = COLLECTION_KINDS[kind]
    return _item(0xA, _MAIN, _unsigned(kind, "collection kind"))


def end_collection() -> bytes:
    """End Collection item (no data)."""
    return _item(0xC, _MAIN, b"")


# -- global items ---------------------------------------------------------------------------------


def usage_page(page: int) -> bytes:
    """Usage Page item.

    >>> usage_page(0xFF0D).hex(" ")
    '06 0d ff'
    """
    return _item(0x0, _GLOBAL, _unsigned(page, "usage page"))


def logical_minimum(value: int) -> bytes:
    return _item(0x1, _GLOBAL, _signed(value, "logical minimum"))


def logical_maximum(value: int) -> bytes:
    """Logical Maximum item, signed: ``logical_maximum(255)`` is ``26 ff 00``."""
    return _item(0x2, _GLOBAL, _signed(value, "logical maximum"))


def physical_minimum(value: int) -> bytes:
    return _item(0x3, _GLOBAL, _signed(value, "physical minimum"))


def physical_maximum(value: int) -> bytes:
    return _item(0x4, _GLOBAL, _signed(value, "physical maximum"))


def logical(lo: int, hi: int) -> bytes:
    """Logical Minimum and Maximum.

    >>> logical(-127, 127).hex(" ")
    '15 81 25 7f'
    """
    return logical_minimum(lo) + logical_maximum(hi)


def physical(lo: int, hi: int) -> bytes:
    """Physical Minimum and Maximum, in units of `unit` times ten to the `unit_exponent`."""
    return physical_minimum(lo) + physical_maximum(hi)


def unit_exponent(exponent: int) -> bytes:
    """Unit Exponent as the 4-bit two's complement nibble HID 1.11 specifies (-2 is ``55 0e``).

    >>> unit_exponent(-3).hex(" ")
    '55 0d'
    """
    if not -8 <= exponent <= 7:
        raise ValueError(f"unit exponent {exponent!r} does not fit the 4-bit nibble (expected -8..7)")
    return _item(0x5, _GLOBAL, bytes([exponent & 0x0F]))


def unit(code: int) -> bytes:
    """Unit item, e.g. `UNIT_CM`, `UNIT_INCH`, `UNIT_DEGREES`."""
    return _item(0x6, _GLOBAL, _unsigned(code, "unit"))


def report_size(bits: int) -> bytes:
    return _item(0x7, _GLOBAL, _unsigned(bits, "report size"))


def report_id(report: int) -> bytes:
    if not 1 <= report <= 255:
        raise ValueError(f"report id {report!r} is invalid (expected 1..255)")
    return _item(0x8, _GLOBAL, _unsigned(report, "report id"))


def report_count(count: int) -> bytes:
    return _item(0x9, _GLOBAL, _unsigned(count, "report count"))


def push() -> bytes:
    """Push the global item state."""
    return _item(0xA, _GLOBAL, b"")


def pop() -> bytes:
    """Pop the global item state saved by the last `push`."""
    return _item(0xB, _GLOBAL, b"")


# -- local items ----------------------------------------------------------------------------------


def usage(uid: int) -> bytes:
    """Usage item; a value above 0xffff is an extended usage (page << 16 | id) and takes four bytes.

    >>> usage(0x130).hex(" "), usage(0xFF0D0130).hex(" ")
    ('0a 30 01', '0b 30 01 0d ff')
    """
    return _item(0x0, _LOCAL, _unsigned(uid, "usage"))


def usage_minimum(uid: int) -> bytes:
    return _item(0x1, _LOCAL, _unsigned(uid, "usage minimum"))


def usage_maximum(uid: int) -> bytes:
    return _item(0x2, _LOCAL, _unsigned(uid, "usage maximum"))


def usage_range(lo: int, hi: int) -> bytes:
    """Usage Minimum and Maximum."""
    return usage_minimum(lo) + usage_maximum(hi)
