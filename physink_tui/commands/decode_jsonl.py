"""Formats decoded pen columns as DESIGN.md JSON lines in bulk, byte for byte what ``json.dumps`` gives; no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.input.hid.batch import PenColumns

_FLAGS = ("tip", "range", "eraser", "b1", "b2")
_HEAD = '{"t": '
_BOOL_TEXT = [
    "".join(f'"{name}": {"true" if code >> k & 1 else "false"}, ' for k, name in enumerate(_FLAGS))
    for code in range(1 << len(_FLAGS))
]
"""The five flags of a line, keyed by their bits (tip 1, range 2, eraser 4, b1 8, b2 16)."""


def _number(v: float) -> str:
    """A float as ``json.dumps`` writes it (``float.__repr__``; NaN and the infinities as JSON's Python dialect)."""
    if math.isfinite(v):
        return repr(v)
    return "NaN" if v != v else ("Infinity" if v > 0 else "-Infinity")


def _as_rounded(values: np.ndarray, digits: int) -> list[str]:
    """``round(v, digits)`` of each value as JSON text.

    A value that numpy's rounding leaves unchanged is already what ``round`` gives (it is the double nearest a
    number of ``digits`` decimals, and for magnitudes below 1e9 Python's exact rounding keeps it), so only the
    others go through ``round``."""
    same = (np.round(values, digits) == values) & (np.abs(values) < 1e9)
    if same.all():
        return list(map(repr, values.tolist()))
    return [repr(v) if s else _number(round(v, digits)) for v, s in zip(values.tolist(), same.tolist(), strict=True)]


def _time_matrix(t: np.ndarray) -> np.ndarray | None:
    """``repr(round(v, 6))`` of each time as a NUL-padded byte matrix, made from integer seconds and microseconds,
    or None unless every time allows it.

    A time that is the double nearest a number of 6 decimals (every capture stamp) prints as that number, trailing
    zeros dropped (a double holds 15 significant digits, so no shorter decimal names it), positionally from 1e-4 up."""
    with np.errstate(invalid="ignore", over="ignore"):
        whole = np.rint(t * 1e6)
        ok = (whole / 1e6 == t) & (((t >= 1e-4) & (t < 1e9)) | ((t == 0) & ~np.signbit(t)))
    if not ok.all():
        return None
    seconds, fraction = np.divmod(whole.astype(np.int64), 1_000_000)
    width = len(str(int(seconds.max())))
    m = np.empty((len(t), width + 7), dtype=np.uint8)
    for k in range(width):
        m[:, width - 1 - k] = 48 + seconds // 10**k % 10
    m[:, width] = ord(".")
    for k in range(6):
        m[:, width + 6 - k] = 48 + fraction // 10**k % 10
    lead = np.logical_and.accumulate(m[:, :width - 1] == 48, axis=1)
    m[:, :width - 1][lead] = 0  # leading zeros go, one digit stays
    trail = np.flip(np.logical_and.accumulate(np.flip(m[:, width + 2:] == 48, axis=1), axis=1), axis=1)
    m[:, width + 2:][trail] = 0  # trailing zeros go, one digit stays
    return m


def _slot(table: list[str], inverse: np.ndarray) -> np.ndarray:
    """Row ``i`` is ``table[inverse[i]]`` as NUL-padded ASCII bytes."""
    data = np.array([x.encode("ascii") for x in table] or [b""], dtype=bytes)
    width = max(data.dtype.itemsize, 1)
    return data.astype(f"S{width}").view(np.uint8).reshape(len(data), width)[inverse]


def _texts(col: np.ndarray, digits: int, before: str = "", after: str = "", nan: str = "NaN") -> np.ndarray:
    """``before + round(v, digits) + after`` of each value (NaN as ``nan``) as a NUL-padded byte matrix, each
    distinct value formatted once."""
    values, inverse = np.unique(col, return_inverse=True)
    table = [before + (nan if v != v else x) + after
             for v, x in zip(values.tolist(), _as_rounded(values, digits), strict=True)]
    return _slot(table, inverse.ravel())


def format_jsonl(cols: PenColumns) -> str:
    """The lines ``json.dumps`` of each sample's dict would give (values rounded to 6 decimals, tilt to 2, absent
    tilt null).

    Each field is a column of NUL-padded bytes, made once per distinct value (times from their digits); the columns
    side by side are the lines, and dropping the NULs gives the text."""
    n = len(cols)
    if not n:
        return ""
    code = (cols.tip.astype(np.int64) | cols.range.astype(np.int64) << 1 | cols.eraser.astype(np.int64) << 2
            | cols.b1.astype(np.int64) << 3 | cols.b2.astype(np.int64) << 4)
    times = _time_matrix(cols.t)
    if times is None:
        times = _slot(_as_rounded(cols.t, 6), np.arange(n))
    slots = [
        _slot([_HEAD], np.zeros(n, dtype=np.int64)), times,
        _texts(cols.x, 6, ', "x": '), _texts(cols.y, 6, ', "y": '), _texts(cols.p, 6, ', "p": ', ", "),
    ]
    if np.isnan(cols.tilt_x).all() and np.isnan(cols.tilt_y).all():
        keys, inverse = np.unique(code | cols.report.astype(np.int64) << 5, return_inverse=True)
        slots.append(_slot([f'{_BOOL_TEXT[k & 31]}"tilt_x": null, "tilt_y": null, "report": {k >> 5}}}\n'
                            for k in keys.tolist()], inverse.ravel()))
    else:
        slots += [
            _slot(_BOOL_TEXT, code),
            _texts(cols.tilt_x, 2, '"tilt_x": ', nan="null"),
            _texts(cols.tilt_y, 2, ', "tilt_y": ', ', "report": ', nan="null"),
            _slot([f"{r}}}\n" for r in range(256)], cols.report.astype(np.int64)),
        ]
    lines = np.concatenate(slots, axis=1)
    return lines[lines != 0].tobytes().decode("ascii")
