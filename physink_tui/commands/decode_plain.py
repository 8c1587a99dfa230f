"""`physink decode` of a plain capture as JSON lines without numpy: each distinct report decoded and formatted once.

The lines are byte for byte what the numpy path (`decode_jsonl`) writes, ``json.dumps`` of each sample's dict
(tested on every shared capture); only what follows a report's time is shared between its repeats.
"""

from __future__ import annotations

import operator
from itertools import chain, compress, repeat
from typing import TextIO

from physink_tui.input.captures.plain import PlainCapture, PlainEvents
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.distinct import decode_distinct

FLAGS = ("tip", "range", "eraser", "b1", "b2")
FLAG_TEXT = [
    "".join(f'"{name}": {"true" if code >> k & 1 else "false"}, ' for k, name in enumerate(FLAGS))
    for code in range(1 << len(FLAGS))
]
"""The five flags of a line, keyed by their bits (tip 1, range 2, eraser 4, b1 8, b2 16)."""
LINES_AT_ONCE = 16384
"""Lines joined and written at a time."""


def _rounded(values: list[float], digits: int) -> list[str]:
    """``repr(round(v, digits))`` of each finite value, each distinct value formatted once.

    ``format(v, f".{digits}f")`` has the digits ``round`` keeps (both round the exact binary value), and for
    1e-4 <= |v| < 1e9 (at most 15 significant digits) ``repr`` of that double is those digits without trailing
    zeros (one kept after the point): no shorter decimal names the same double. Values outside that range go
    through ``round`` and ``repr``. (No value is -0.0, which a set would merge with 0.0: the scaled values are
    0.0 or above.)"""
    distinct = list(set(values))
    if not distinct:
        return []
    fixed = map(str.rstrip, map(format, distinct, repeat(f".{digits}f")), repeat("0"))
    texts = ("\n".join(fixed) + "\n").replace(".\n", ".0\n").split("\n")
    for k, v in enumerate(distinct):
        if v != 0.0 and not 1.5e-4 <= abs(v) < 1e9:  # what may round below 1e-4 or has more than 15 digits
            texts[k] = repr(round(v, digits))
    text_of = dict(zip(distinct, texts, strict=False))  # texts has one more, empty
    return list(map(text_of.__getitem__, values))


def _tilts(values: list[float | None]) -> list[str]:
    return ["null" if v is None else repr(round(v, 2)) for v in values]


def _tails(decoder: HidPenDecoder, events: PlainEvents) -> tuple[dict[str, str | None], dict[bytes, str]]:
    """Each distinct report text's line tail, what follows its time (None: no sample), and why each report that
    gives no sample is ignored; the counts go to ``decoder.stats``."""
    counts = list(map(events.counts.__getitem__, events.data))
    distinct = dict(zip(events.data.values(), counts, strict=True))
    if len(distinct) < len(events.data):  # texts differing only in hex case are one report
        distinct = dict.fromkeys(distinct, 0)
        for data, count in zip(events.data.values(), counts, strict=True):
            distinct[data] += count
    s, ignored = decode_distinct(decoder, distinct)
    flags = [FLAG_TEXT[a | b << 1 | c << 2 | d << 3 | e << 4]
             for a, b, c, d, e in zip(s.tip, s.range, s.eraser, s.b1, s.b2, strict=True)]
    tails: dict[bytes, str | None] = dict(zip(s.reports, [
        f', "x": {a}, "y": {b}, "p": {c}, {d}"tilt_x": {e}, "tilt_y": {f}, "report": {g}}}\n'
        for a, b, c, d, e, f, g in zip(_rounded(s.x, 6), _rounded(s.y, 6), _rounded(s.p, 6), flags,
                                       _tilts(s.tilt_x), _tilts(s.tilt_y), s.report, strict=True)
    ], strict=True))
    tails.update(dict.fromkeys(ignored))
    return dict(zip(events.data, map(tails.__getitem__, events.data.values()), strict=True)), ignored


def time_texts(events: PlainEvents) -> list[str]:
    """``repr(round(t, 6))`` of each report's time (``json.dumps``' text for DESIGN.md's rounded time).

    When every stamp is 1 to 9 digits, a point and 1 to 6 digits, all of one width (hid-recorder's), a stamp from
    1e-4 s up or zero names the double nearest it, which ``round`` keeps and ``repr`` prints as the shortest
    decimal naming it: the stamp without leading and trailing zeros, one digit kept each side of the point. Other
    stamps go through ``round`` and ``repr``."""
    stamps, times = events.stamps, events.times  # digits with at most one point, neither first nor last
    if not stamps:
        return []
    n, width, point = len(stamps), len(stamps[0]), stamps[0].find(".")
    text = "\n".join(stamps)
    if not (0 < point <= 9 and width - point <= 7 and len(text) == n * (width + 1) - 1
            and text[width::width + 1] == "\n" * (n - 1) and text[point::width + 1] == "." * n) \
            or min(filter(None, times), default=1.0) < 1e-4:  # not all one width with the point in one place
        return list(map(repr, map(round, times, repeat(6))))
    text = "\n" + "\n".join(map(str.strip, stamps, repeat("0"))) + "\n"
    return text.replace("\n.", "\n0.").replace(".\n", ".0\n")[1:-1].split("\n")


def write_plain(capture: PlainCapture, decoders: list[tuple[int, HidPenDecoder]], out: TextIO) -> None:
    """Each device's samples as JSON lines, device after device; the counts go to each decoder's stats."""
    for index, decoder in decoders:
        events = capture.events[index]
        stats, times = decoder.stats, events.times
        stats.reports += len(times)
        if times != sorted(times):  # (sorting sorted times is one pass)
            stats.backwards += sum(map(operator.lt, times[1:], times))
        tail_of, ignored = _tails(decoder, events)
        maybe = list(map(tail_of.__getitem__, events.reports))
        heads = time_texts(events)
        if None in maybe:  # the reports that give no sample: their times go too
            first = maybe.index(None)
            stats.first_ignored = (events.lines[first], ignored[events.data[events.reports[first]]])
            heads = list(compress(heads, maybe))
        tails = list(filter(None, maybe))
        for start in range(0, len(heads), LINES_AT_ONCE):
            stop = start + LINES_AT_ONCE
            out.write("".join(chain.from_iterable(zip(repeat('{"t": '), heads[start:stop], tails[start:stop]))))
