"""Decodes a long run of reports a chunk at a time with `decode_batch`, sample for sample what one batch gives; no I/O.

The batch decoder learns ranges and the in-range polarity from all the reports it is given. To keep memory flat,
a run longer than one chunk is first read through once (three times when a layout learns its in-range polarity,
which depends on the pressure range, and the pen's x/y ranges on the polarity) with counts going nowhere; the
chunks are then decoded with what the whole run taught.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterator

import numpy as np

from physink_tui.input.hid.batch import PenColumns, decode_batch, polarity
from physink_tui.input.hid.decoder import DecodeStats, HidPenDecoder

CHUNK_REPORTS = 65536
"""Reports decoded at a time."""


def _merge(total: dict[int, dict], seen: dict[int, dict]) -> None:
    """Fold one chunk's ranges (min of lows, max of highs) and polarity counts (sums) into ``total``."""
    for rid, values in seen.items():
        into = total.setdefault(rid, {})
        for name, value in values.items():
            old = into.get(name)
            if old is None:
                into[name] = value
            elif name == "in_counts":
                into[name] = tuple(a + b for a, b in zip(old, value, strict=True))
            else:
                into[name] = (min(old[0], value[0]), max(old[1], value[1]))


def learn(decoder: HidPenDecoder, times: np.ndarray, reports: Callable[[int, int], list[bytes]],
          spans: list[tuple[int, int]]) -> dict[int, dict]:
    """What a single batch over all the spans would learn, per report id (see `decode_batch`'s ``learned``)."""
    learns_polarity = any(lay.learn_in_range and lay.in_range is not None for lay in decoder.layouts.values())
    stages = (("pressure",), ("in_value",), ("x", "y")) if learns_polarity else (("pressure", "x", "y"),)
    learned: dict[int, dict] = {}
    for names in stages:
        total: dict[int, dict] = {}
        for a, b in spans:
            seen: dict[int, dict] = {}
            decode_batch(decoder, times[a:b], reports(a, b), learned=learned, seen=seen, stats=DecodeStats())
            _merge(total, seen)
        for rid, values in total.items():
            lay = decoder.layouts[rid]
            into = learned.setdefault(rid, {})
            for name in names:
                if name == "in_value" and "in_counts" in values:
                    into[name] = polarity(values["in_counts"], not lay.in_range_inverted)
                elif name in values:
                    into[name] = values[name]
    return learned


def decode_in_chunks(
    decoder: HidPenDecoder,
    times: np.ndarray,
    reports: Callable[[int, int], list[bytes]],
    lines: np.ndarray,
    chunk: int = CHUNK_REPORTS,
) -> Iterator[PenColumns]:
    """The samples of ``len(times)`` reports, a chunk at a time; counts go to ``decoder.stats``.

    Args:
        decoder: the device's decoder.
        times: each report's time.
        reports: ``reports(a, b)`` gives the reports ``a:b``.
        lines: each report's capture line.
        chunk: reports per chunk.
    """
    n = len(times)
    spans = [(a, min(a + chunk, n)) for a in range(0, n, chunk)] or [(0, 0)]
    learned = learn(decoder, times, reports, spans) if len(spans) > 1 else None
    t_before = None
    for a, b in spans:
        cols = decode_batch(decoder, times[a:b], reports(a, b), lines[a:b], learned=learned, t_before=t_before)
        if b > a:
            t_before = float(times[b - 1])
        yield dataclasses.replace(cols, index=cols.index + a) if a else cols
