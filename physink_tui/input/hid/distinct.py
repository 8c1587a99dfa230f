"""Decodes each distinct report of a capture once, by `decode_batch`'s whole-capture rules, in plain Python.

A pen capture repeats most of its reports (the M506 capture: 48,182 reports, 10,871 distinct), and the batch rules
depend on a report's bytes and on what the whole capture teaches (ranges widened to every in-range value, the
in-range polarity of the touching reports), never on its neighbours. So the distinct reports, with how often each
occurs, are decoded here as `decode_batch` decodes the whole capture, value for value, without numpy (whose
import alone costs more than a small capture's decoding: `physink decode`'s plain path, docs/BENCHMARKS.md).
"""

from __future__ import annotations

from collections.abc import Callable

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


def _ignore(stats: DecodeStats, reason: str, count: int, line: int) -> None:
    stats.ignored[reason] += count
    if stats.first_ignored is None or line < stats.first_ignored[0]:
        stats.first_ignored = (line, reason)


def _range(declared: ValueField, raws: list[int]) -> tuple[int, int]:
    """The declared range widened to ``raws``."""
    if not raws:
        return declared.lo, declared.hi
    return min(declared.lo, min(raws)), max(declared.hi, max(raws))


def _scale(raw: int, lo: int, hi: int) -> float:
    v = (raw - lo) / (hi - lo)
    return 0.0 if v < 0.0 else 1.0 if v > 1.0 else v


def _tilt(v: ValueField | None) -> Callable[[int], float | None]:
    if v is None:
        return lambda r: None
    read, scale, offset = _reader(v), v.scale, v.offset

    def degrees(r: int) -> float:
        d = read(r) * scale + offset
        return -TILT_LIMIT if d < -TILT_LIMIT else TILT_LIMIT if d > TILT_LIMIT else d

    return degrees


def _group(lay: PenLayout, reports: list[tuple[bytes, int, int]], stats: DecodeStats) -> dict[bytes, Row | None]:
    """The rows of one report id's distinct reports ``(bytes, count, first line)`` (None: ignored, counted)."""
    rid, length = lay.report_id, lay.length
    b1_of, b2_of = _bit(lay.b1), _bit(lay.b2)
    erase_of = _bit(None if lay.eraser_is_button else lay.eraser)
    invert_of = _bit(None if lay.eraser_is_button else lay.invert)
    tip_of = _bit(lay.tip)
    pressure = lay.pressure
    pressure_of = _reader(pressure) if pressure is not None else None
    x_of, y_of, tx_of, ty_of = _reader(lay.x), _reader(lay.y), _tilt(lay.tilt_x), _tilt(lay.tilt_y)
    tool_of = _reader(ValueField((lay.tool,), False, 0, 1)) if lay.tool is not None else None
    out: dict[bytes, Row | None] = {}
    kept = []  # (bytes, count, report integer, b1, b2, eraser, erase, raw pressure)
    for data, count, line in reports:
        r = int.from_bytes(data[:length], "little")
        if lay.frame_byte is not None:
            index, mask, values = lay.frame_byte
            if data[index] & mask in values:
                _ignore(stats, f"{REASON_FRAME} 0x{rid:02x}", count, line)
                out[data] = None
                continue
        eraser = False
        if tool_of is not None:
            tool = tool_of(r)
            if lay.pen_tools and tool not in lay.pen_tools:
                _ignore(stats, f"{REASON_TOOL} 0x{rid:02x}", count, line)
                out[data] = None
                continue
            eraser = bool(lay.eraser_tools) and tool in lay.eraser_tools
        erase = erase_of(r)
        eraser = eraser or invert_of(r) or erase
        kept.append((data, count, r, b1_of(r), b2_of(r), eraser, erase,
                     pressure_of(r) if pressure_of is not None else 0))
    if pressure is not None:
        p_lo, p_hi = _range(pressure, [k[7] for k in kept])
        if (p_lo, p_hi) != (pressure.lo, pressure.hi):
            stats.widened.add(f"0x{rid:02x} pressure")
    buttons = lay.b1 is not None or lay.b2 is not None
    touched = []  # (bytes, count, report integer, b1, b2, eraser, p, tip)
    for data, count, r, b1, b2, eraser, erase, rp in kept:
        if lay.tip is not None:
            tip = tip_of(r) or erase
        elif pressure is not None:
            tip = rp > pressure.lo or erase
        else:
            tip = erase
        if pressure is not None:
            p = _scale(rp, p_lo, p_hi)
            if buttons and tip and rp <= pressure.lo and (b1 or b2):
                tip = False
            if not tip:
                p = 0.0
        else:
            p = 1.0 if tip else 0.0
        touched.append((data, count, r, b1, b2, eraser, p, tip))
    in_value = not lay.in_range_inverted
    if lay.in_range is not None:
        ib = lay.in_range
        if lay.learn_in_range:
            strong = strong_set = all_kept = all_set = 0
            for _, count, r, b1, b2, _, p, tip in touched:
                bit = r >> ib & 1
                all_kept += count
                all_set += count * bit
                if tip or p > 0.0 or b1 or b2:
                    strong += count
                    strong_set += count * bit
            in_value = (strong_set * 2 >= strong if strong else all_set * 2 >= all_kept if all_kept else in_value)
        ranges = [(r >> ib & 1 == in_value) or tip for _, _, r, _, _, _, _, tip in touched]
    else:
        ranges = [True] * len(touched)
    placed = [k[2] for k, rng in zip(touched, ranges, strict=True) if rng]
    x_lo, x_hi = _range(lay.x, [x_of(r) for r in placed])
    y_lo, y_hi = _range(lay.y, [y_of(r) for r in placed])
    for name, got, declared in (("x", (x_lo, x_hi), lay.x), ("y", (y_lo, y_hi), lay.y)):
        if got != (declared.lo, declared.hi):
            stats.widened.add(f"0x{rid:02x} {name}")
    for (data, count, r, b1, b2, eraser, p, tip), rng in zip(touched, ranges, strict=True):
        out[data] = (_scale(x_of(r), x_lo, x_hi), _scale(y_of(r), y_lo, y_hi), p, tip, rng, eraser, b1, b2,
                     tx_of(r), ty_of(r), rid)
        stats.samples += count
    return out


def decode_distinct(decoder: HidPenDecoder, reports: dict[bytes, tuple[int, int]]) -> dict[bytes, Row | None]:
    """Each distinct report's row (None when it is no pen sample), as `decode_batch` of all the reports gives.

    Args:
        decoder: the device's decoder; its layouts are used, its stats get the counts of every report (not the
            reports read nor the times going backwards: the caller knows those).
        reports: each distinct report, with how many times it occurs and the capture line it first occurs on.
    """
    stats = decoder.stats
    out: dict[bytes, Row | None] = {}
    groups: dict[int, list[tuple[bytes, int, int]]] = {}
    for data, (count, line) in reports.items():
        if not data:
            _ignore(stats, "empty report", count, line)
            out[data] = None
            continue
        rid = data[0] if decoder.uses_ids else 0
        lay = decoder.layouts.get(rid)
        if lay is None:
            reason = (f"report 0x{rid:02x} is not a pen report" if rid in decoder.known_ids
                      else f"unknown report id 0x{rid:02x}")
            _ignore(stats, reason, count, line)
            out[data] = None
        elif len(data) < lay.length:
            _ignore(stats, f"{REASON_TRUNCATED} 0x{rid:02x}", count, line)
            out[data] = None
        else:
            groups.setdefault(rid, []).append((data, count, line))
    for rid, group in groups.items():
        out.update(_group(decoder.layouts[rid], group, stats))
    return out
