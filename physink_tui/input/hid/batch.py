"""Decodes whole captures at once with numpy: the same layouts as `HidPenDecoder`, column by column.

Reports are grouped by report id into byte matrices and every value is sliced out of all rows
with one vectorised shift-and-mask. The state the streaming decoder learns as it goes is taken
from the whole capture instead: a range widens to everything the pen reported while in range,
and an in-range polarity is the one the touching reports show. On a capture whose values stay in
their declared ranges the two decoders agree sample for sample (tested).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from operator import itemgetter

import numpy as np

from physink_tui.input.hid.decoder import DecodeStats, HidPenDecoder
from physink_tui.input.hid.pen_decoder import REASON_FRAME, REASON_TOOL, REASON_TRUNCATED, TILT_LIMIT
from physink_tui.input.hid.pen_layout import PenLayout, ValueField
from physink_tui.input.pen.sample import PenSample


@dataclass(frozen=True, slots=True)
class PenColumns:
    """Decoded samples as columns, in report order (tilt is NaN where the tablet has none).

    Attributes:
        t, x, y, p, tilt_x, tilt_y: float64 arrays (seconds, 0..1, degrees).
        tip, range, eraser, b1, b2: bool arrays.
        report: uint8 array of report ids.
        index: position of each sample's report in the input sequence.
    """

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    p: np.ndarray
    tip: np.ndarray
    range: np.ndarray
    eraser: np.ndarray
    b1: np.ndarray
    b2: np.ndarray
    tilt_x: np.ndarray
    tilt_y: np.ndarray
    report: np.ndarray
    index: np.ndarray

    def __len__(self) -> int:
        return len(self.t)

    def rows(self, start: int, stop: int) -> PenColumns:
        """The samples ``start:stop`` (views, not copies)."""
        return PenColumns(*(getattr(self, f)[start:stop] for f in self.__dataclass_fields__))

    def samples(self) -> list[PenSample]:
        """The columns as `PenSample`s (None for absent tilt)."""
        tx = [None if v != v else v for v in self.tilt_x.tolist()]
        ty = [None if v != v else v for v in self.tilt_y.tolist()]
        return [
            PenSample(*row)
            for row in zip(
                self.t.tolist(), self.x.tolist(), self.y.tolist(), self.p.tolist(), self.tip.tolist(),
                self.range.tolist(), self.eraser.tolist(), self.b1.tolist(), self.b2.tolist(), tx, ty,
                self.report.tolist(), strict=True,
            )
        ]


def _raw(m: np.ndarray, v: ValueField) -> np.ndarray:
    """Slice a value out of every row of a uint8 matrix."""
    out = np.zeros(len(m), dtype=np.int64)
    shift = 0
    for off, size in v.parts:
        first, nbytes = off // 8, (off % 8 + size + 7) // 8
        acc = np.zeros(len(m), dtype=np.uint64)
        for k in range(nbytes):
            acc |= m[:, first + k].astype(np.uint64) << np.uint64(8 * k)
        part = (acc >> np.uint64(off % 8)) & np.uint64((1 << size) - 1)
        out |= part.astype(np.int64) << shift
        shift += size
    if v.signed:
        out = np.where(out >> (shift - 1) & 1, out - (1 << shift), out)
    return out


def _bit(m: np.ndarray, bit: int | None) -> np.ndarray:
    if bit is None:
        return np.zeros(len(m), dtype=bool)
    return (m[:, bit // 8] >> (bit % 8)) & 1 == 1


def _normalise(raw: np.ndarray, v: ValueField, use: np.ndarray, name: str, learned: dict, seen: dict
               ) -> tuple[np.ndarray, bool]:
    """Scale ``raw`` to 0..1 by the range ``learned[name]`` or else the declared one widened to the ``use`` rows;
    the range used goes to ``seen[name]``."""
    lo, hi = learned.get(name, (v.lo, v.hi))
    if name not in learned and use.any():
        lo, hi = min(lo, int(raw[use].min())), max(hi, int(raw[use].max()))
    seen[name] = (lo, hi)
    widened = (lo, hi) != (v.lo, v.hi)
    return np.clip((raw - lo) / (hi - lo), 0.0, 1.0), widened


def _decode_group(lay: PenLayout, m: np.ndarray, stats: DecodeStats, lines: np.ndarray, learned: dict, seen: dict
                  ) -> tuple[dict, np.ndarray]:
    """Decode the rows of one report id; return columns and the mask of rows that are samples.

    What the rows teach (ranges, the in-range polarity's counts) is taken from ``learned`` when there, else from
    the rows, and goes to ``seen``: see `decode_batch`."""
    keep = np.ones(len(m), dtype=bool)
    if lay.frame_byte is not None:
        index, mask, values = lay.frame_byte
        frame = np.isin(m[:, index] & mask, values)
        _ignore_rows(stats, lines[frame], f"{REASON_FRAME} 0x{lay.report_id:02x}")
        keep &= ~frame
    eraser = np.zeros(len(m), dtype=bool)
    if lay.tool is not None:
        tool = _raw(m, ValueField((lay.tool,), False, 0, 1))
        if lay.pen_tools:
            bad = keep & ~np.isin(tool, lay.pen_tools)
            _ignore_rows(stats, lines[bad], f"{REASON_TOOL} 0x{lay.report_id:02x}")
            keep &= ~bad
        if lay.eraser_tools:
            eraser |= np.isin(tool, lay.eraser_tools)
    b1, b2 = _bit(m, lay.b1), _bit(m, lay.b2)
    erase = np.zeros(len(m), dtype=bool) if lay.eraser_is_button else _bit(m, lay.eraser)
    if lay.invert is not None and not lay.eraser_is_button:
        eraser |= _bit(m, lay.invert)
    eraser |= erase
    pressure = lay.pressure
    rp = _raw(m, pressure) if pressure is not None else None
    if lay.tip is not None:
        tip = _bit(m, lay.tip) | erase
    elif pressure is not None and rp is not None:
        tip = (rp > pressure.lo) | erase
    else:
        tip = erase.copy()
    if pressure is not None and rp is not None:
        p, p_wide = _normalise(rp, pressure, keep, "pressure", learned, seen)
        if lay.b1 is not None or lay.b2 is not None:
            tip &= ~((rp <= pressure.lo) & (b1 | b2))
        p = np.where(tip, p, 0.0)
    else:
        p, p_wide = np.where(tip, 1.0, 0.0), False
    if lay.in_range is not None:
        ib = _bit(m, lay.in_range)
        in_value = not lay.in_range_inverted
        if lay.learn_in_range:
            strong = keep & (tip | (p > 0) | b1 | b2)
            counts = (int(np.count_nonzero(strong)), int(np.count_nonzero(ib[strong])), int(np.count_nonzero(keep)),
                      int(np.count_nonzero(ib[keep])))
            seen["in_counts"] = counts
            in_value = learned.get("in_value", polarity(counts, in_value))
        rng = (ib == in_value) | tip
    else:
        rng = np.ones(len(m), dtype=bool)
    rx, ry = _raw(m, lay.x), _raw(m, lay.y)
    x, x_wide = _normalise(rx, lay.x, keep & rng, "x", learned, seen)
    y, y_wide = _normalise(ry, lay.y, keep & rng, "y", learned, seen)
    for name, wide in (("x", x_wide), ("y", y_wide), ("pressure", p_wide)):
        if wide:
            stats.widened.add(f"0x{lay.report_id:02x} {name}")
    cols = {"x": x, "y": y, "p": p, "tip": tip, "range": rng, "eraser": eraser, "b1": b1, "b2": b2}
    for name in ("tilt_x", "tilt_y"):
        tv = getattr(lay, name)
        if tv is None:
            cols[name] = np.full(len(m), np.nan)
        else:
            cols[name] = np.clip(_raw(m, tv) * tv.scale + tv.offset, -TILT_LIMIT, TILT_LIMIT)
    return cols, keep


def polarity(counts: tuple[int, int, int, int], default: bool) -> bool:
    """The in-range bit's value while in range: the majority of the strong rows', else of all kept rows'."""
    strong, strong_set, kept, kept_set = counts
    if strong:
        return strong_set * 2 >= strong
    return kept_set * 2 >= kept if kept else default


def _ignore_rows(stats: DecodeStats, lines: np.ndarray, reason: str) -> None:
    if len(lines):
        stats.ignored[reason] += len(lines)
        first = int(lines.min())
        if stats.first_ignored is None or first < stats.first_ignored[0]:
            stats.first_ignored = (first, reason)


def decode_batch(
    decoder: HidPenDecoder,
    times: Sequence[float] | np.ndarray,
    reports: Sequence[bytes],
    lines: Sequence[int] | np.ndarray | None = None,
    *,
    learned: dict[int, dict] | None = None,
    seen: dict[int, dict] | None = None,
    stats: DecodeStats | None = None,
    t_before: float | None = None,
) -> PenColumns:
    """Decode a whole sequence of reports; counts go to ``decoder.stats`` as in streaming mode.

    Args:
        decoder: the device's decoder (its layouts and its stats are used; its streaming state is not).
        times: the time of each report.
        reports: the raw reports.
        lines: where each report came from (capture line numbers), for the summary.
        learned: per report id, what the whole capture taught (``"pressure"``, ``"x"``, ``"y"``: ranges;
            ``"in_value"``: the in-range polarity), used instead of learning from these reports alone: a capture
            decoded a chunk at a time then gives the samples the whole capture at once would (`chunks`).
        seen: filled per report id with the ranges used and ``"in_counts"`` (polarity counts) of these reports.
        stats: where the counts go instead of ``decoder.stats``.
        t_before: the time of the report before these, to count time going backwards across chunks.
    """
    n = len(reports)
    stats = decoder.stats if stats is None else stats
    learned = {} if learned is None else learned
    seen = {} if seen is None else seen
    t_all = np.asarray(times, dtype=np.float64)
    line_arr = np.asarray(lines if lines is not None else range(n), dtype=np.int64)
    stats.reports += n
    if n > 1:
        stats.backwards += int(np.count_nonzero(np.diff(t_all) < 0))
    if n and t_before is not None and t_all[0] < t_before:
        stats.backwards += 1
    lengths = np.fromiter(map(len, reports), dtype=np.int64, count=n)
    empty = lengths == 0
    _ignore_rows(stats, line_arr[empty], "empty report")
    if decoder.uses_ids and not empty.any():
        rids = np.fromiter(map(itemgetter(0), reports), dtype=np.int64, count=n)
    elif decoder.uses_ids:
        rids = np.fromiter((r[0] if r else 0 for r in reports), dtype=np.int64, count=n)
    else:
        rids = np.zeros(n, dtype=np.int64)
    parts: list[tuple[np.ndarray, dict]] = []
    for rid in np.flatnonzero(np.bincount(rids[~empty], minlength=1)).tolist():  # ids present, ascending
        members = np.flatnonzero((rids == rid) & ~empty)
        lay = decoder.layouts.get(rid)
        if lay is None:
            reason = (f"report 0x{rid:02x} is not a pen report" if rid in decoder.known_ids
                      else f"unknown report id 0x{rid:02x}")
            _ignore_rows(stats, line_arr[members], reason)
            continue
        short = lengths[members] < lay.length
        _ignore_rows(stats, line_arr[members[short]], f"{REASON_TRUNCATED} 0x{rid:02x}")
        members = members[~short]
        if not len(members):
            continue
        length = lay.length
        if (lengths[members] == length).all():
            blob = b"".join(map(reports.__getitem__, members.tolist()))
        else:
            blob = b"".join([reports[i][:length] for i in members.tolist()])
        m = np.frombuffer(blob, dtype=np.uint8).reshape(len(members), length)
        cols, keep = _decode_group(lay, m, stats, line_arr[members], learned.get(rid, {}), seen.setdefault(rid, {}))
        cols = {k: v[keep] for k, v in cols.items()}
        cols["report"] = np.full(int(keep.sum()), rid, dtype=np.uint8)
        parts.append((members[keep], cols))
    if not parts:
        empty_f = np.zeros(0)
        return PenColumns(empty_f, empty_f, empty_f, empty_f, *(np.zeros(0, bool),) * 5, empty_f, empty_f,
                          np.zeros(0, np.uint8), np.zeros(0, np.int64))
    index = np.concatenate([idx for idx, _ in parts])
    order = np.argsort(index, kind="stable")
    merged = {k: np.concatenate([c[k] for _, c in parts])[order] for k in parts[0][1]}
    index = index[order]
    stats.samples += len(index)
    return PenColumns(t=t_all[index], index=index, **merged)
