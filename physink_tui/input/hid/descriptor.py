"""Parses a HID report descriptor into reports and fields; knows nothing about pens or devices.

The parser follows the HID 1.11 specification and the Linux kernel's ``hid-core.c`` where the
specification leaves room (usage pages are applied at the main item, logical maxima are signed
only when the minimum is negative). Limits that guard against broken or hostile descriptors are
the kernel's: report size up to 256 bits, report count up to 12,288, reports up to 16 KiB.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from physink_tui.errors import DescriptorError
from physink_tui.input.hid.usages import usage_name

MAX_REPORT_SIZE_BITS = 256
MAX_REPORT_COUNT = 12288
MAX_REPORT_BYTES = 16384
MAX_USAGE_RANGE = 65536

MAIN, GLOBAL, LOCAL = 0, 1, 2
INPUT, OUTPUT, FEATURE = "input", "output", "feature"
_MAIN_KINDS = {0x8: INPUT, 0x9: OUTPUT, 0xB: FEATURE}

# Input/Output/Feature item flag bits.
FLAG_CONSTANT = 0x01
FLAG_VARIABLE = 0x02
FLAG_RELATIVE = 0x04
FLAG_NULL_STATE = 0x40


@dataclass(frozen=True, slots=True)
class Collection:
    """One Collection item.

    Attributes:
        kind: 0 physical, 1 application, 2 logical, 3 report, ... (HID 1.11 6.2.2.6).
        usage: the extended usage (page << 16 | id) that named it, 0 if none.
        offset: byte offset of the Collection item in the descriptor.
    """

    kind: int
    usage: int
    offset: int


@dataclass(frozen=True, slots=True)
class Field:
    """One report field: ``count`` values of ``size`` bits starting at ``bit_offset``.

    Attributes:
        report_id: the report id (0 when the descriptor uses none).
        kind: ``"input"``, ``"output"`` or ``"feature"``.
        bit_offset: offset of the first value in bits from the start of the report, including
            the report-id byte when the descriptor uses report ids.
        size: bits per value (0..256).
        count: number of values.
        flags: the main item's data (constant, variable, relative, ... bits).
        usages: extended usages: for a variable field the usage of each value (shorter lists
            repeat their last usage, as the kernel does); for an array the usages its values index.
        logical_min, logical_max: the logical range; signed when the minimum is negative.
        physical_min, physical_max: the physical range (equal to the logical one when unset).
        unit: the raw HID unit code (0 when none).
        unit_exponent: the power of ten applied to physical values.
        collections: the collections enclosing the field, outermost first.
        offset: byte offset of the main item that declared it.
    """

    report_id: int
    kind: str
    bit_offset: int
    size: int
    count: int
    flags: int
    usages: tuple[int, ...]
    logical_min: int
    logical_max: int
    physical_min: int
    physical_max: int
    unit: int
    unit_exponent: int
    collections: tuple[Collection, ...]
    offset: int

    @property
    def is_constant(self) -> bool:
        return bool(self.flags & FLAG_CONSTANT)

    @property
    def is_variable(self) -> bool:
        return bool(self.flags & FLAG_VARIABLE)

    @property
    def is_relative(self) -> bool:
        return bool(self.flags & FLAG_RELATIVE)

    @property
    def is_signed(self) -> bool:
        return self.logical_min < 0

    @property
    def application(self) -> int:
        """Usage of the outermost application collection, 0 if none."""
        for c in self.collections:
            if c.kind == 1:
                return c.usage
        return 0

    def usage_at(self, index: int) -> int:
        """Usage of value ``index`` of a variable field (0 when it has none)."""
        if not self.usages:
            return 0
        return self.usages[min(index, len(self.usages) - 1)]

    def describe(self) -> str:
        names = ",".join(usage_name(u) for u in self.usages[:4]) or "padding"
        return f"{names}@{self.bit_offset}:{self.size}x{self.count}[{self.logical_min}..{self.logical_max}]"


@dataclass(frozen=True, slots=True)
class Report:
    """All fields of one (kind, report id) pair, and its length in bytes including the id byte."""

    report_id: int
    kind: str
    fields: tuple[Field, ...]
    size_bytes: int


@dataclass(frozen=True, slots=True)
class ReportDescriptor:
    """A parsed report descriptor.

    Attributes:
        raw: the descriptor bytes.
        uses_report_ids: whether reports start with a report-id byte.
        reports: every report, keyed by ``(kind, report_id)``.
        collections: every collection in order of appearance.
        warnings: items skipped as the kernel skips them (unknown main item, reserved item type),
            one message each naming the byte offset; empty for a clean descriptor.
    """

    raw: bytes
    uses_report_ids: bool
    reports: dict[tuple[str, int], Report]
    collections: tuple[Collection, ...]
    warnings: tuple[str, ...] = ()

    @classmethod
    def from_bytes(cls, data: bytes) -> ReportDescriptor:
        """Parse descriptor bytes; raise `DescriptorError` naming the byte offset of a fatal problem."""
        return _Parser(bytes(data)).parse()

    def input_reports(self) -> list[Report]:
        return [r for (kind, _), r in sorted(self.reports.items()) if kind == INPUT]

    def input_report(self, report_id: int) -> Report | None:
        return self.reports.get((INPUT, report_id))


@dataclass
class _Globals:
    usage_page: int = 0
    logical_min: int = 0
    logical_max: int = 0
    physical_min: int | None = None
    physical_max: int | None = None
    unit_exponent: int = 0
    unit: int = 0
    report_size: int = 0
    report_id: int = 0
    report_count: int = 0
    logical_min_raw: tuple[int, int] = (0, 0)
    logical_max_raw: tuple[int, int] = (0, 0)
    physical_min_raw: tuple[int, int] | None = None
    physical_max_raw: tuple[int, int] | None = None

    def copy(self) -> _Globals:
        return _Globals(**{k: getattr(self, k) for k in self.__dataclass_fields__})


@dataclass
class _Locals:
    usages: list[tuple[int, int]] = field(default_factory=list)  # (value, item size in bytes)
    usage_min: tuple[int, int] | None = None
    delimiter_depth: int = 0


def _signed(value: int, nbytes: int) -> int:
    bits = nbytes * 8
    if bits and value & (1 << (bits - 1)):
        return value - (1 << bits)
    return value


class _Parser:
    def __init__(self, data: bytes) -> None:
        self.data = data
        self.globals = _Globals()
        self.stack: list[_Globals] = []
        self.locals = _Locals()
        self.collections: list[Collection] = []
        self.open: list[Collection] = []
        self.fields: dict[tuple[str, int], list[Field]] = {}
        self.bit_pos: dict[tuple[str, int], int] = {}
        self.uses_ids = False
        self.warnings: list[str] = []

    def parse(self) -> ReportDescriptor:
        data, pos, n = self.data, 0, len(self.data)
        if n == 0:
            raise DescriptorError("empty report descriptor", 0)
        while pos < n:
            prefix = data[pos]
            if prefix == 0xFE:  # long item: skip its data
                if pos + 2 >= n:
                    raise DescriptorError("truncated long item", pos)
                size = data[pos + 1]
                if pos + 3 + size > n:
                    raise DescriptorError(f"long item of {size} bytes runs past the end", pos)
                pos += 3 + size
                continue
            size = (0, 1, 2, 4)[prefix & 3]
            if pos + 1 + size > n:
                raise DescriptorError(
                    f"item 0x{prefix:02x} needs {size} data bytes, only {n - pos - 1} left", pos
                )
            value = int.from_bytes(data[pos + 1 : pos + 1 + size], "little")
            kind, tag = (prefix >> 2) & 3, prefix >> 4
            if kind == MAIN:
                self._main(tag, value, pos)
            elif kind == GLOBAL:
                self._global(tag, value, size, pos)
            elif kind == LOCAL:
                self._local(tag, value, size, pos)
            else:  # the kernel logs a reserved item type and carries on
                self.warnings.append(f"byte {pos}: reserved item type in prefix 0x{prefix:02x} skipped")
            pos += 1 + size
        if self.open:
            raise DescriptorError(
                f"unbalanced collections: {len(self.open)} still open at the end", self.open[-1].offset
            )
        reports = {}
        for key, flds in self.fields.items():
            bits = self.bit_pos[key]
            reports[key] = Report(key[1], key[0], tuple(flds), (bits + 7) // 8)
        return ReportDescriptor(self.data, self.uses_ids, reports, tuple(self.collections), tuple(self.warnings))

    # -- items ---------------------------------------------------------------------------------

    def _global(self, tag: int, value: int, size: int, pos: int) -> None:
        g = self.globals
        if tag == 0x0:
            g.usage_page = value
        elif tag == 0x1:
            g.logical_min_raw = (value, size)
        elif tag == 0x2:
            g.logical_max_raw = (value, size)
        elif tag == 0x3:
            g.physical_min_raw = (value, size)
        elif tag == 0x4:
            g.physical_max_raw = (value, size)
        elif tag == 0x5:
            # a 4-bit two's complement nibble is the common reading (kernel hid-core does the same)
            g.unit_exponent = (value - 16 if value >= 8 else value) if value < 16 else _signed(value, size)
        elif tag == 0x6:
            g.unit = value
        elif tag == 0x7:
            if value > MAX_REPORT_SIZE_BITS:
                raise DescriptorError(f"report size {value} bits is oversized (at most {MAX_REPORT_SIZE_BITS})", pos)
            g.report_size = value
        elif tag == 0x8:
            if value == 0 or value > 255:
                raise DescriptorError(f"report id {value} is invalid (expected 1..255)", pos)
            g.report_id = value
            self.uses_ids = True
        elif tag == 0x9:
            if value > MAX_REPORT_COUNT:
                raise DescriptorError(f"report count {value} is too large (at most {MAX_REPORT_COUNT})", pos)
            g.report_count = value
        elif tag == 0xA:
            self.stack.append(g.copy())
        elif tag == 0xB:
            if not self.stack:
                raise DescriptorError("Pop without a matching Push", pos)
            self.globals = self.stack.pop()
        else:
            raise DescriptorError(f"unknown global item tag 0x{tag:x}", pos)

    def _local(self, tag: int, value: int, size: int, pos: int) -> None:
        loc = self.locals
        if tag == 0x0:
            loc.usages.append((value, size))
        elif tag == 0x1:
            loc.usage_min = (value, size)
        elif tag == 0x2:
            if loc.usage_min is None:
                return  # Usage Maximum without Minimum: ignored, as the kernel does
            lo, lo_size = loc.usage_min
            hi = value
            if size < 4 and lo_size == 4:
                hi = (lo & 0xFFFF0000) | hi
            if hi < lo or hi - lo >= MAX_USAGE_RANGE:
                raise DescriptorError(f"usage range 0x{lo:x}..0x{hi:x} is invalid", pos)
            width = 4 if (size == 4 or lo_size == 4) else 2
            loc.usages.extend((u, width) for u in range(lo, hi + 1))
            loc.usage_min = None
        elif tag == 0xA:
            loc.delimiter_depth += 1 if value else -1
        # designators and strings are not needed for decoding

    def _resolve_usages(self) -> list[int]:
        page = self.globals.usage_page
        return [u if size == 4 else (page << 16) | (u & 0xFFFF) for u, size in self.locals.usages]

    def _main(self, tag: int, value: int, pos: int) -> None:
        if tag == 0xA:
            usages = self._resolve_usages()
            coll = Collection(value & 0xFF, usages[0] if usages else 0, pos)
            self.collections.append(coll)
            self.open.append(coll)
        elif tag == 0xC:
            if not self.open:
                raise DescriptorError("End Collection without a matching Collection", pos)
            self.open.pop()
        elif tag in _MAIN_KINDS:
            self._add_field(_MAIN_KINDS[tag], value, pos)
        else:  # the kernel logs an unknown main item, drops its locals and carries on
            self.warnings.append(f"byte {pos}: unknown main item tag 0x{tag:x} skipped")
        self.locals = _Locals()

    def _add_field(self, kind: str, flags: int, pos: int) -> None:
        g = self.globals
        lmin_v, lmin_s = g.logical_min_raw
        lmax_v, lmax_s = g.logical_max_raw
        lmin = _signed(lmin_v, lmin_s)
        lmax = _signed(lmax_v, lmax_s) if lmin < 0 else lmax_v
        if g.physical_min_raw is None and g.physical_max_raw is None:
            pmin, pmax = lmin, lmax
        else:
            pv, ps = g.physical_min_raw or (0, 0)
            qv, qs = g.physical_max_raw or (0, 0)
            pmin = _signed(pv, ps)
            pmax = _signed(qv, qs) if pmin < 0 else qv
            if pmin == 0 and pmax == 0:
                pmin, pmax = lmin, lmax
        key = (kind, g.report_id)
        start = self.bit_pos.get(key, 8 if g.report_id else 0)
        width = g.report_size * g.report_count
        end = start + width
        if end > MAX_REPORT_BYTES * 8:
            raise DescriptorError(
                f"report 0x{g.report_id:02x} grows past {MAX_REPORT_BYTES} bytes", pos
            )
        self.bit_pos[key] = end
        if width == 0:
            return
        usages = tuple(self._resolve_usages())
        self.fields.setdefault(key, []).append(
            Field(
                report_id=g.report_id,
                kind=kind,
                bit_offset=start,
                size=g.report_size,
                count=g.report_count,
                flags=flags,
                usages=usages,
                logical_min=lmin,
                logical_max=lmax,
                physical_min=pmin,
                physical_max=pmax,
                unit=g.unit,
                unit_exponent=g.unit_exponent,
                collections=tuple(self.open),
                offset=pos,
            )
        )
