"""Decodes each distinct report of a capture once, by `decode_batch`'s whole-capture rules, in plain Python.

A pen capture repeats most of its reports (the M506 capture: 48,182 reports, 10,871 distinct), and the batch rules
depend on a report's bytes and on what the whole capture teaches (ranges widened to every in-range value, the
in-range polarity of the touching reports), never on its neighbours. So the distinct reports, with how often each
occurs, are decoded here as `decode_batch` decodes the whole capture, value for value, without numpy (whose
import alone costs more than a small capture's decoding: `physink decode`'s plain path, docs/BENCHMARKS.md).
"""

from __future__ import annotations

import operator
from collections.abc import Callable
from functools import partial
from itertools import compress, repeat
from operator import itemgetter
from typing import Any

from physink_tui.input.hid.decoder import DecodeStats, HidPenDecoder
from physink_tui.input.hid.pen_decoder import REASON_FRAME, REASON_TOOL, REASON_TRUNCATED, TILT_LIMIT, value_expr
from physink_tui.input.hid.pen_layout import PenLayout, ValueField


class Samples:
    """Decoded distinct reports as columns: the sample of ``reports[k]`` (its time aside) is ``x[k]``, ``y[k]``,
    ``p[k]``, ``tip[k]``, ``range[k]``, ``eraser[k]``, ``b1[k]``, ``b2[k]``, ``tilt_x[k]``, ``tilt_y[k]`` (None: no
    tilt) and ``report[k]`` (its id)."""

    __slots__ = ("b1", "b2", "eraser", "p", "range", "report", "reports", "tilt_x", "tilt_y", "tip", "x", "y")

    def __init__(self) -> None:
        self.reports: list[bytes] = []
        self.x: list[float] = []
        self.y: list[float] = []
        self.p: list[float] = []
        self.tip: list[bool] = []
        self.range: list[bool] = []
        self.eraser: list[bool] = []
        self.b1: list[bool] = []
        self.b2: list[bool] = []
        self.tilt_x: list[float | None] = []
        self.tilt_y: list[float | None] = []
        self.report: list[int] = []


def _ignore(stats: DecodeStats, reason: str, count: int, out: dict[bytes, str], data: bytes) -> None:
    stats.ignored[reason] += count
    out[data] = reason


def _range(declared: ValueField, raws: list[int]) -> tuple[int, int]:
    """The declared range widened to ``raws``."""
    if not raws:
        return declared.lo, declared.hi
    return min(declared.lo, min(raws)), max(declared.hi, max(raws))


def _tilt(v: ValueField | None) -> Callable[[int], float | None]:
    """A raw tilt value to degrees (None without tilt)."""
    if v is None:
        return lambda raw: None
    scale, offset = v.scale, v.offset

    def degrees(raw: int) -> float:
        d = raw * scale + offset
        return -TILT_LIMIT if d < -TILT_LIMIT else TILT_LIMIT if d > TILT_LIMIT else d

    return degrees


def _signed(raw: int, width: int) -> int:
    return raw - (1 << width) if raw >> (width - 1) & 1 else raw


def raw_reader(lay: PenLayout) -> Callable[[int], tuple[int, ...]]:
    """A function generated once for a layout (as `pen_decoder` does): a report, read as one little-endian integer,
    to its raw values ``(x, y, pressure, tilt_x, tilt_y, tip, in_range, eraser, invert, b1, b2, tool)``, 0 where
    the layout has none (and for the eraser and invert bits where the pen has no eraser)."""
    def value(v: ValueField | None) -> str:
        if v is None:
            return "0"
        return f"_signed({value_expr(v)}, {v.width})" if v.signed else f"({value_expr(v)})"

    def bit(b: int | None) -> str:
        return "0" if b is None else f"(v >> {b} & 1)"

    no_eraser = lay.eraser_is_button
    tool = f"(v >> {lay.tool[0]} & {(1 << lay.tool[1]) - 1:#x})" if lay.tool is not None else "0"
    values = [value(lay.x), value(lay.y), value(lay.pressure), value(lay.tilt_x), value(lay.tilt_y), bit(lay.tip),
              bit(lay.in_range), bit(None if no_eraser else lay.eraser), bit(None if no_eraser else lay.invert),
              bit(lay.b1), bit(lay.b2), tool]
    namespace: dict[str, Any] = {"_signed": _signed}
    code = f"def raw(v):\n    return ({', '.join(values)})\n"
    exec(compile(code, f"<raw values of pen layout 0x{lay.report_id:02x} {lay.source}>", "exec"), namespace)
    return namespace["raw"]


def _clip(v: float) -> float:
    return 0.0 if v < 0.0 else 1.0 if v > 1.0 else v


def _group(lay: PenLayout, datas: list[bytes], counts: list[int], stats: DecodeStats, samples: Samples,
           ignored: dict[bytes, str]) -> None:
    """One report id's distinct reports (``datas``, each occurring ``counts`` times) decoded into ``samples``, or
    their reasons into ``ignored``; the counts go to ``stats``."""
    rid = lay.report_id
    if lay.frame_byte is not None or (lay.tool is not None and lay.pen_tools):
        datas, counts = _pen_reports(lay, datas, counts, stats, ignored)
        if not datas:
            return
    # bits past the layout's length are never read, so the whole report is one integer
    values = list(map(raw_reader(lay), map(partial(int.from_bytes, byteorder="little"), datas)))
    pressure = lay.pressure
    floor = p_lo = p_hi = 0
    if pressure is not None:
        floor = pressure.lo
        p_lo, p_hi = _range(pressure, [v[2] for v in values])
        if (p_lo, p_hi) != (pressure.lo, pressure.hi):
            stats.widened.add(f"0x{rid:02x} pressure")
    has_tip, buttons = lay.tip is not None, lay.b1 is not None or lay.b2 is not None
    eraser_tools = lay.eraser_tools if lay.tool is not None else ()
    pen = []  # tip, p, eraser, b1, b2 of each report
    for _, _, rp, _, _, tip_bit, _, erase, invert, b1, b2, tool in values:
        eraser = erase == 1 or invert == 1 or tool in eraser_tools
        if has_tip:
            tip = tip_bit == 1 or erase == 1
        else:
            tip = (pressure is not None and rp > floor) or erase == 1
        if pressure is None:
            p = 1.0 if tip else 0.0
        else:
            if buttons and tip and rp <= floor and (b1 or b2):  # a button with the tip at zero pressure: a click
                tip = False
            p = _clip((rp - p_lo) / (p_hi - p_lo)) if tip else 0.0
        pen.append((tip, p, eraser, b1 == 1, b2 == 1))
    if lay.in_range is None:
        ranges = [True] * len(values)
    else:
        in_value = not lay.in_range_inverted
        if lay.learn_in_range:  # the polarity the touching reports show, else most reports
            strong = strong_set = kept = kept_set = 0
            for (tip, p, _, b1, b2), v, count in zip(pen, values, counts, strict=True):
                kept += count
                kept_set += count * v[6]
                if tip or p > 0.0 or b1 or b2:
                    strong += count
                    strong_set += count * v[6]
            in_value = strong_set * 2 >= strong if strong else kept_set * 2 >= kept if kept else in_value
        ranges = [v[6] == in_value or pv[0] for v, pv in zip(values, pen, strict=True)]
    placed = list(compress(values, ranges))
    x_lo, x_hi = _range(lay.x, [v[0] for v in placed])
    y_lo, y_hi = _range(lay.y, [v[1] for v in placed])
    for name, got, declared in (("x", (x_lo, x_hi), lay.x), ("y", (y_lo, y_hi), lay.y)):
        if got != (declared.lo, declared.hi):
            stats.widened.add(f"0x{rid:02x} {name}")
    x_span, y_span = x_hi - x_lo, y_hi - y_lo
    samples.reports += datas
    samples.x += [_clip((v[0] - x_lo) / x_span) for v in values]
    samples.y += [_clip((v[1] - y_lo) / y_span) for v in values]
    tips, ps, erasers, b1s, b2s = zip(*pen, strict=True)
    samples.tip += tips
    samples.p += ps
    samples.range += ranges
    samples.eraser += erasers
    samples.b1 += b1s
    samples.b2 += b2s
    samples.tilt_x += map(_tilt(lay.tilt_x), [v[3] for v in values])
    samples.tilt_y += map(_tilt(lay.tilt_y), [v[4] for v in values])
    samples.report += repeat(rid, len(values))
    stats.samples += sum(counts)


def _pen_reports(lay: PenLayout, datas: list[bytes], counts: list[int], stats: DecodeStats,
                 out: dict[bytes, str]) -> tuple[list[bytes], list[int]]:
    """The reports that are the pen's, and their counts: pad, strip or dial reports and other tools (mice,
    lenses) are counted and their reasons put in ``out``."""
    rid, pens, pen_counts = lay.report_id, [], []
    tool_at, tool_mask = lay.tool if lay.tool is not None else (0, 0)
    tool_mask = (1 << tool_mask) - 1
    for data, count in zip(datas, counts, strict=True):
        if lay.frame_byte is not None:
            index, mask, values = lay.frame_byte
            if data[index] & mask in values:
                _ignore(stats, f"{REASON_FRAME} 0x{rid:02x}", count, out, data)
                continue
        tool = int.from_bytes(data, "little") >> tool_at & tool_mask
        if lay.tool is not None and lay.pen_tools and tool not in lay.pen_tools:
            _ignore(stats, f"{REASON_TOOL} 0x{rid:02x}", count, out, data)
            continue
        pens.append(data)
        pen_counts.append(count)
    return pens, pen_counts


def decode_distinct(decoder: HidPenDecoder, reports: dict[bytes, int]) -> tuple[Samples, dict[bytes, str]]:
    """Each distinct report's sample, or why it is no pen sample, as `decode_batch` of all the reports gives.

    Args:
        decoder: the device's decoder; its layouts are used, and its stats get the samples and the ignored reports
            by reason (not the reports read, the first ignored one, the times going backwards: the caller knows
            those).
        reports: each distinct report, with how many times it occurs.
    """
    stats = decoder.stats
    samples, ignored = Samples(), dict[bytes, str]()
    datas = list(reports)
    if b"" in reports:
        datas.remove(b"")
        _ignore(stats, "empty report", reports[b""], ignored, b"")
    rids = list(map(itemgetter(0), datas)) if decoder.uses_ids else [0] * len(datas)
    for rid in dict.fromkeys(rids):  # each report id, in the order they first come
        members = list(compress(datas, map(rid.__eq__, rids))) if len(rids) > 1 else datas
        counts = list(map(reports.__getitem__, members))
        lay = decoder.layouts.get(rid)
        if lay is None:
            reason = (f"report 0x{rid:02x} is not a pen report" if rid in decoder.known_ids
                      else f"unknown report id 0x{rid:02x}")
            stats.ignored[reason] += sum(counts)
            ignored.update(dict.fromkeys(members, reason))
            continue
        if min(map(len, members)) < lay.length:
            whole = list(map(lay.length.__le__, map(len, members)))
            for data, count in zip(compress(members, map(operator.not_, whole)),
                                   compress(counts, map(operator.not_, whole)), strict=True):
                _ignore(stats, f"{REASON_TRUNCATED} 0x{rid:02x}", count, ignored, data)
            members, counts = list(compress(members, whole)), list(compress(counts, whole))
            if not members:
                continue
        _group(lay, members, counts, stats, samples, ignored)
    return samples, ignored
