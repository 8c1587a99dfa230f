"""Decodes each distinct report of a capture once, by `decode_batch`'s whole-capture rules, in plain Python.

A pen capture repeats most of its reports (the M506 capture: 48,182 reports, 10,871 distinct), and the batch rules
depend on a report's bytes and on what the whole capture teaches (ranges widened to every in-range value, the
in-range polarity of the touching reports), never on its neighbours. So the distinct reports, with how often each
occurs, are decoded here as `decode_batch` decodes the whole capture, value for value, without numpy (whose
import alone costs more than a small capture's decoding: `physink decode`'s plain path, docs/BENCHMARKS.md).
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Iterable
from itertools import compress, repeat

from physink_tui.input.hid.decoder import DecodeStats, HidPenDecoder
from physink_tui.input.hid.pen_decoder import REASON_FRAME, REASON_TOOL, REASON_TRUNCATED, TILT_LIMIT
from physink_tui.input.hid.pen_layout import PenLayout, ValueField

Row = tuple[float, float, float, bool, bool, bool, bool, bool, float | None, float | None, int]
"""A sample without its time: x, y, p, tip, range, eraser, b1, b2, tilt_x, tilt_y (None: no tilt), report id."""


def _reader(v: ValueField) -> Callable[[int], int]:
    """The raw integer of a value, read from the report as one little-endian integer."""
    if len(v.parts) == 1 and not v.signed:
        off, mask = v.parts[0][0], (1 << v.parts[0][1]) - 1
        return lambda r: r >> off & mask
    width = v.width

    def read(r: int) -> int:
        out = shift = 0
        for off, size in v.parts:
            out |= (r >> off & (1 << size) - 1) << shift
            shift += size
        return out - (1 << width) if v.signed and out >> (width - 1) & 1 else out

    return read


def _bit(bit: int | None) -> Callable[[int], bool]:
    if bit is None:
        return lambda r: False
    return lambda r: r >> bit & 1 == 1


def _scaled(raws: Iterable[int], lo: int, hi: int) -> list[float]:
    """Each raw value scaled from ``lo..hi`` to 0..1, clipped."""
    span = hi - lo
    return [0.0 if v < 0.0 else 1.0 if v > 1.0 else v for v in [(raw - lo) / span for raw in raws]]


def _ignore(stats: DecodeStats, reason: str, count: int, out: dict[bytes, Row | str], data: bytes) -> None:
    stats.ignored[reason] += count
    out[data] = reason


def _range(declared: ValueField, raws: list[int]) -> tuple[int, int]:
    """The declared range widened to ``raws``."""
    if not raws:
        return declared.lo, declared.hi
    return min(declared.lo, min(raws)), max(declared.hi, max(raws))


def _tilt(v: ValueField | None) -> Callable[[int], float | None]:
    if v is None:
        return lambda r: None
    read, scale, offset = _reader(v), v.scale, v.offset

    def degrees(r: int) -> float:
        d = read(r) * scale + offset
        return -TILT_LIMIT if d < -TILT_LIMIT else TILT_LIMIT if d > TILT_LIMIT else d

    return degrees


def _group(lay: PenLayout, reports: list[tuple[bytes, int]], stats: DecodeStats) -> dict[bytes, Row | str]:
    """The rows of one report id's distinct reports ``(bytes, count)`` (a str: why it is ignored, counted)."""
    rid = lay.report_id
    out: dict[bytes, Row | str] = {}
    if lay.frame_byte is not None or (lay.tool is not None and lay.pen_tools):
        reports = _pen_reports(lay, reports, stats, out)
    datas = [data for data, _ in reports]
    counts = [count for _, count in reports]
    ints = list(map(int.from_bytes, datas, repeat("little")))  # bits past the layout's length are never read
    b1s, b2s = list(map(_bit(lay.b1), ints)), list(map(_bit(lay.b2), ints))
    erases = list(map(_bit(None if lay.eraser_is_button else lay.eraser), ints))
    erasers = list(map(operator.or_, map(_bit(None if lay.eraser_is_button else lay.invert), ints), erases))
    if lay.tool is not None and lay.eraser_tools:
        tools = map(_reader(ValueField((lay.tool,), False, 0, 1)), ints)
        erasers = list(map(operator.or_, erasers, map(lay.eraser_tools.__contains__, tools)))
    if lay.tip is not None:
        tips = list(map(operator.or_, map(_bit(lay.tip), ints), erases))
    elif lay.pressure is not None:
        tips = list(map(operator.or_, map(lay.pressure.lo.__lt__, map(_reader(lay.pressure), ints)), erases))
    else:
        tips = erases
    pressure = lay.pressure
    if pressure is None:
        ps = [1.0 if tip else 0.0 for tip in tips]
    else:
        raws = list(map(_reader(pressure), ints))
        lo, hi = _range(pressure, raws)
        if (lo, hi) != (pressure.lo, pressure.hi):
            stats.widened.add(f"0x{rid:02x} pressure")
        if lay.b1 is not None or lay.b2 is not None:  # a button with the tip at zero pressure is a click
            floor = pressure.lo
            tips = [tip and not (rp <= floor and (b1 or b2)) for tip, rp, b1, b2 in zip(tips, raws, b1s, b2s)]
        ps = [p if tip else 0.0 for p, tip in zip(_scaled(raws, lo, hi), tips)]
    if lay.in_range is None:
        ranges = [True] * len(ints)
    else:
        bits = list(map(_bit(lay.in_range), ints))
        in_value = not lay.in_range_inverted
        if lay.learn_in_range:
            strong = list(map(any, zip(tips, map((0.0).__lt__, ps), b1s, b2s)))
            kept, kept_set = sum(counts), sum(compress(counts, bits))
            strong_n = sum(compress(counts, strong))
            strong_set = sum(compress(counts, map(operator.and_, strong, bits)))
            in_value = strong_set * 2 >= strong_n if strong_n else kept_set * 2 >= kept if kept else in_value
        ranges = list(map(operator.or_, map(in_value.__eq__, bits), tips))
    placed = list(compress(ints, ranges))
    x_of, y_of = _reader(lay.x), _reader(lay.y)
    x_lo, x_hi = _range(lay.x, list(map(x_of, placed)))
    y_lo, y_hi = _range(lay.y, list(map(y_of, placed)))
    for name, got, declared in (("x", (x_lo, x_hi), lay.x), ("y", (y_lo, y_hi), lay.y)):
        if got != (declared.lo, declared.hi):
            stats.widened.add(f"0x{rid:02x} {name}")
    xs, ys = _scaled(map(x_of, ints), x_lo, x_hi), _scaled(map(y_of, ints), y_lo, y_hi)
    rows = zip(xs, ys, ps, tips, ranges, erasers, b1s, b2s, map(_tilt(lay.tilt_x), ints),
               map(_tilt(lay.tilt_y), ints), repeat(rid))
    out.update(zip(datas, rows))
    stats.samples += sum(counts)
    return out


def _pen_reports(lay: PenLayout, reports: list[tuple[bytes, int]], stats: DecodeStats,
                 out: dict[bytes, Row | str]) -> list[tuple[bytes, int]]:
    """The reports that are the pen's: pad, strip or dial reports and other tools (mice, lenses) are counted and
    their reasons put in ``out``."""
    rid, pens = lay.report_id, []
    tool_of = _reader(ValueField((lay.tool,), False, 0, 1)) if lay.tool is not None else None
    for data, count in reports:
        if lay.frame_byte is not None:
            index, mask, values = lay.frame_byte
            if data[index] & mask in values:
                _ignore(stats, f"{REASON_FRAME} 0x{rid:02x}", count, out, data)
                continue
        if tool_of is not None and lay.pen_tools and tool_of(int.from_bytes(data, "little")) not in lay.pen_tools:
            _ignore(stats, f"{REASON_TOOL} 0x{rid:02x}", count, out, data)
            continue
        pens.append((data, count))
    return pens


def decode_distinct(decoder: HidPenDecoder, reports: dict[bytes, int]) -> dict[bytes, Row | str]:
    """Each distinct report's row, or why it is no pen sample, as `decode_batch` of all the reports gives.

    Args:
        decoder: the device's decoder; its layouts are used, and its stats get the samples and the ignored reports
            by reason (not the reports read, the first ignored one, the times going backwards: the caller knows
            those).
        reports: each distinct report, with how many times it occurs.
    """
    stats = decoder.stats
    out: dict[bytes, Row | str] = {}
    groups: dict[int, list[tuple[bytes, int]]] = {}
    for data, count in reports.items():
        if not data:
            _ignore(stats, "empty report", count, out, data)
            continue
        rid = data[0] if decoder.uses_ids else 0
        lay = decoder.layouts.get(rid)
        if lay is None:
            reason = (f"report 0x{rid:02x} is not a pen report" if rid in decoder.known_ids
                      else f"unknown report id 0x{rid:02x}")
            _ignore(stats, reason, count, out, data)
        elif len(data) < lay.length:
            _ignore(stats, f"{REASON_TRUNCATED} 0x{rid:02x}", count, out, data)
        else:
            groups.setdefault(rid, []).append((data, count))
    for rid, group in groups.items():
        out.update(_group(decoder.layouts[rid], group, stats))
    return out
