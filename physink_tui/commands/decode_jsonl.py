"""Formats decoded pen columns as DESIGN.md JSON lines in bulk, byte for byte what ``json.dumps`` gives; no I/O."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.input.hid_batch import PenColumns

_FLAGS = ("tip", "range", "eraser", "b1", "b2")
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
    tilt null): each column's text is made in bulk and the pieces of all lines are joined once."""
    n = len(cols)
    if not n:
        return ""
    code = (cols.tip.astype(np.int64) | cols.range.astype(np.int64) << 1 | cols.eraser.astype(np.int64) << 2
            | cols.b1.astype(np.int64) << 3 | cols.b2.astype(np.int64) << 4)
    columns = [
        ['{"t": '] * n,
        _texts(cols.t, 6, distinct=False),
        _texts(cols.x, 6, ', "x": '),
        _texts(cols.y, 6, ', "y": '),
        _texts(cols.p, 6, ', "p": ', ", "),
        np.array(_BOOL_TEXT, dtype=object)[code].tolist(),
        _texts(cols.tilt_x, 2, '"tilt_x": ', nan="null"),
        _texts(cols.tilt_y, 2, ', "tilt_y": ', ', "report": ', nan="null"),
        np.array([f"{r}}}\n" for r in range(256)], dtype=object)[cols.report].tolist(),
    ]
    pieces: list[str] = [""] * (n * len(columns))
    for k, column in enumerate(columns):
        pieces[k::len(columns)] = column
    return "".join(pieces)
