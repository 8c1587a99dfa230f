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


def _rounded(col: np.ndarray, digits: int, none_if_nan: bool = False, distinct: bool = True) -> list[str]:
    """``round(v, digits)`` of each value as JSON text; with ``distinct``, each distinct value formatted once."""
    if not distinct and not none_if_nan:
        return _as_rounded(col, digits)
    values, inverse = np.unique(col, return_inverse=True)
    text = _as_rounded(values, digits)
    if none_if_nan:
        text = ["null" if v != v else x for v, x in zip(values.tolist(), text, strict=True)]
    if none_if_nan and len(values) and values[-1] != values[-1]:  # np.unique keeps every NaN apart
        nan_at = np.flatnonzero(np.isnan(values))
        text = text[: nan_at[0]] + ["null"] * len(nan_at)
    return [text[i] for i in inverse.ravel().tolist()]


def format_jsonl(cols: PenColumns) -> str:
    """The lines ``json.dumps`` of each sample's dict would give (values rounded to 6 decimals, tilt to 2)."""
    if not len(cols):
        return ""
    code = (cols.tip.astype(np.int64) | cols.range.astype(np.int64) << 1 | cols.eraser.astype(np.int64) << 2
            | cols.b1.astype(np.int64) << 3 | cols.b2.astype(np.int64) << 4)
    flags = [_BOOL_TEXT[c] for c in code.tolist()]
    tail = [f'"tilt_x": {a}, "tilt_y": {b}, "report": {r}}}\n' for a, b, r in zip(
        _rounded(cols.tilt_x, 2, True), _rounded(cols.tilt_y, 2, True), cols.report.tolist(), strict=True)]
    return "".join([
        f'{{"t": {t}, "x": {x}, "y": {y}, "p": {p}, {f}{rest}' for t, x, y, p, f, rest in zip(
            _rounded(cols.t, 6, distinct=False), _rounded(cols.x, 6), _rounded(cols.y, 6), _rounded(cols.p, 6),
            flags, tail, strict=True)
    ])
