"""`physink decode` of a plain capture as JSON lines without numpy: each distinct report decoded and formatted once.

The lines are byte for byte what the numpy path (`decode_jsonl`) writes, ``json.dumps`` of each sample's dict
(tested on every shared capture); only what follows a report's time is shared between its repeats.
"""

from __future__ import annotations

import operator
import re
from itertools import chain, compress, repeat
from typing import TextIO

from physink_tui.input.captures.plain import PlainCapture, PlainEvents
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.distinct import Row, decode_distinct

FLAGS = ("tip", "range", "eraser", "b1", "b2")
FLAG_TEXT = [
    "".join(f'"{name}": {"true" if code >> k & 1 else "false"}, ' for k, name in enumerate(FLAGS))
    for code in range(1 << len(FLAGS))
]
"""The five flags of a line, keyed by their bits (tip 1, range 2, eraser 4, b1 8, b2 16)."""
_SHORT_STAMPS = re.compile(r"(?:\d{1,9}\.\d{1,6}\n)*", re.ASCII)
LINES_AT_ONCE = 16384
"""Lines joined and written at a time."""


def _tail(row: Row) -> str:
    """A sample's line from just after its time (values rounded as ``json.dumps`` of DESIGN.md's dict has them)."""
    x, y, p, tip, rng, eraser, b1, b2, tx, ty, rid = row
    code = tip | rng << 1 | eraser << 2 | b1 << 3 | b2 << 4
    tilt_x = "null" if tx is None else repr(round(tx, 2))
    tilt_y = "null" if ty is None else repr(round(ty, 2))
    return (f', "x": {round(x, 6)!r}, "y": {round(y, 6)!r}, "p": {round(p, 6)!r}, {FLAG_TEXT[code]}'
            f'"tilt_x": {tilt_x}, "tilt_y": {tilt_y}, "report": {rid}}}\n')


def _tails(decoder: HidPenDecoder, events: PlainEvents) -> dict[str, str | None]:
    """Each distinct report text's line tail (None: no sample), its counts going to ``decoder.stats``."""
    distinct: dict[bytes, tuple[int, int]] = {}
    for text, data in events.data.items():  # texts differing only in hex case are one report
        count, line = events.counts[text], events.first_line[text]
        if data in distinct:
            count, line = count + distinct[data][0], min(line, distinct[data][1])
        distinct[data] = (count, line)
    rows = decode_distinct(decoder, distinct)
    tails = {data: None if row is None else _tail(row) for data, row in rows.items()}
    return {text: tails[data] for text, data in events.data.items()}


def time_texts(events: PlainEvents) -> list[str]:
    """``repr(round(t, 6))`` of each report's time (``json.dumps``' text for DESIGN.md's rounded time).

    A stamp of at most 9 + 6 digits with a point, from 1e-4 s up or zero, names the double nearest it, which
    ``round`` keeps and ``repr`` prints as the shortest decimal naming it: the stamp itself without leading and
    trailing zeros (one digit kept each side of the point). Other stamps go through ``round`` and ``repr``."""
    stamps, times = events.stamps, events.times
    if not stamps or _SHORT_STAMPS.fullmatch("\n".join(stamps) + "\n") is None \
            or min(filter(None, times), default=1.0) < 1e-4:
        return list(map(repr, map(round, times, repeat(6))))
    text = "\n" + "\n".join(map(str.strip, stamps, repeat("0"))) + "\n"
    return text.replace("\n.", "\n0.").replace(".\n", ".0\n")[1:-1].split("\n")


def write_plain(capture: PlainCapture, decoders: list[tuple[int, HidPenDecoder]], out: TextIO) -> None:
    """Each device's samples as JSON lines, device after device; the counts go to each decoder's stats."""
    for index, decoder in decoders:
        events = capture.events[index]
        stats, times = decoder.stats, events.times
        stats.reports += len(times)
        stats.backwards += sum(map(operator.lt, times[1:], times))
        tails = list(map(_tails(decoder, events).__getitem__, events.reports))
        heads = time_texts(events)
        if None in tails:
            keep = list(map(operator.is_not, tails, repeat(None)))
            heads, tails = list(compress(heads, keep)), list(compress(tails, keep))
        for start in range(0, len(heads), LINES_AT_ONCE):
            stop = start + LINES_AT_ONCE
            out.write("".join(chain.from_iterable(zip(repeat('{"t": '), heads[start:stop], tails[start:stop]))))
