"""Formats decoded pen columns as DESIGN.md JSON lines in bulk, byte for byte what ``json.dumps`` gives; no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.input.hid_batch import PenColumns

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


def _times(t: np.ndarray) -> tuple[list[str], list[str]]:
    """``repr(round(v, 6))`` of each time as two pieces, whole seconds and ``.fraction``, made from integers.

    A time that is the double nearest a number of 6 decimals (every capture stamp) prints as that number, trailing
    zeros dropped (a double holds 15 significant digits, so no shorter decimal names it); it is positional from
    1e-4 up. Other values (and rows of 15 digits or more) go through ``round`` and ``repr``."""
    n = len(t)
    with np.errstate(invalid="ignore", over="ignore"):
        whole = np.rint(t * 1e6)
        ok = (whole / 1e6 == t) & (((t >= 1e-4) & (t < 1e9)) | ((t == 0) & ~np.signbit(t)))
    micro = np.where(ok, whole, 0).astype(np.int64)
    seconds, fraction = np.divmod(micro, 1_000_000)
    digits = np.empty((n, 7), dtype=np.uint8)
    digits[:, 0] = ord(".")
    for k in range(6):
        digits[:, 6 - k] = 48 + fraction // 10**k % 10
    zeros = np.flip(np.logical_and.accumulate(np.flip(digits[:, 2:] == 48, axis=1), axis=1), axis=1)
    digits[:, 2:][zeros] = 0  # trailing zeros end the string (numpy drops trailing NULs); one digit stays
    fractions = digits.view("S7").ravel().astype("U7").tolist()
    wholes = list(map(str, seconds.tolist()))
    for i in np.flatnonzero(~ok).tolist():
        wholes[i], fractions[i] = _number(round(float(t[i]), 6)), ""
    return wholes, fractions


def _texts(col: np.ndarray, digits: int, before: str = "", after: str = "", distinct: bool = True,
           nan: str = "NaN") -> list[str]:
    """``before + round(v, digits) + after`` of each value as JSON text (NaN as ``nan``); with ``distinct``, each
    distinct value is formatted once."""
    if not distinct:
        texts = _as_rounded(col, digits)
        return texts if not (before or after) else [before + x + after for x in texts]
    values, inverse = np.unique(col, return_inverse=True)
    table = np.array([before + (nan if v != v else x) + after
                      for v, x in zip(values.tolist(), _as_rounded(values, digits), strict=True)] or [""], dtype=object)
    return table[inverse.ravel()].tolist()


def format_jsonl(cols: PenColumns) -> str:
    """The lines ``json.dumps`` of each sample's dict would give (values rounded to 6 decimals, tilt to 2, absent
    tilt null): each column's text is made in bulk and the pieces of all lines are joined once. What follows
    ``"p"`` is one piece per line, looked up by flags and report id, when the tablet has no tilt."""
    n = len(cols)
    if not n:
        return ""
    code = (cols.tip.astype(np.int64) | cols.range.astype(np.int64) << 1 | cols.eraser.astype(np.int64) << 2
            | cols.b1.astype(np.int64) << 3 | cols.b2.astype(np.int64) << 4)
    columns = [
        *_times(cols.t),
        _texts(cols.x, 6, ', "x": '),
        _texts(cols.y, 6, ', "y": '),
        _texts(cols.p, 6, ', "p": ', ", "),
    ]
    if np.isnan(cols.tilt_x).all() and np.isnan(cols.tilt_y).all():
        keys, inverse = np.unique(code | cols.report.astype(np.int64) << 5, return_inverse=True)
        table = [f'{_BOOL_TEXT[k & 31]}"tilt_x": null, "tilt_y": null, "report": {k >> 5}}}\n{_HEAD}'
                 for k in keys.tolist()]
        columns.append(np.array(table, dtype=object)[inverse.ravel()].tolist())
    else:
        columns += [
            np.array(_BOOL_TEXT, dtype=object)[code].tolist(),
            _texts(cols.tilt_x, 2, '"tilt_x": ', nan="null"),
            _texts(cols.tilt_y, 2, ', "tilt_y": ', ', "report": ', nan="null"),
            np.array([f"{r}}}\n{_HEAD}" for r in range(256)], dtype=object)[cols.report].tolist(),
        ]
    pieces: list[str] = [""] * (n * len(columns))
    for k, column in enumerate(columns):
        pieces[k::len(columns)] = column
    return (_HEAD + "".join(pieces))[:-len(_HEAD)]  # each line's last piece starts the next line
