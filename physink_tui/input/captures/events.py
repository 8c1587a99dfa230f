"""Converts a run of strictly formed capture ``E:`` lines to columns with numpy, checking every character; no other
line kinds, and no error reports (a run that is not strictly formed is left to the line-by-line parser).

Strict form: ``E: <digits>[.<digits>] <digits>`` then `` hh`` per byte (two hex digits), no trailing space. Lines are
grouped by their width and field positions; each group is one byte matrix, checked and read column by column.
"""

from __future__ import annotations

import numpy as np

_NIBBLE = np.full(256, -1, dtype=np.int16)
_NIBBLE[np.frombuffer(b"0123456789", np.uint8)] = np.arange(10)
_NIBBLE[np.frombuffer(b"abcdef", np.uint8)] = np.arange(10, 16)
_NIBBLE[np.frombuffer(b"ABCDEF", np.uint8)] = np.arange(10, 16)
MAX_DIGITS = 15
"""A stamp with more digits is left to the line parser (below this, digits / 10**decimals is exactly float(stamp))."""


def _digits(m: np.ndarray) -> bool:
    return bool(((m >= 48) & (m <= 57)).all())


def _number(m: np.ndarray) -> np.ndarray:
    """The decimal number each row's digit columns spell."""
    value = np.zeros(len(m), dtype=np.int64)
    for k in range(m.shape[1]):
        value = value * 10 + (m[:, k].astype(np.int64) - 48)
    return value


def _group(m: np.ndarray, p1: int, p2: int, dot: int, max_seconds: float
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Times, declared lengths and byte matrix of rows alike in width and field positions, or None if any row is not
    strictly formed, declares another length than it holds, or is later than ``max_seconds``."""
    w = m.shape[1]
    if bytes(m[0, :3]) != b"E: " or not (m[:, :3] == m[0, :3]).all() or p2 <= p1 + 1 or (w - p2) % 3:
        return None
    if dot >= 0 and not (3 < dot < p1 - 1 and (m[:, dot] == 46).all()):
        return None
    whole, frac = m[:, 3:dot if dot >= 0 else p1], m[:, dot + 1:p1] if dot >= 0 else m[:, p1:p1]
    if whole.shape[1] + frac.shape[1] > MAX_DIGITS or not (_digits(whole) and _digits(frac)):
        return None
    if not (m[:, p1] == 32).all() or not _digits(m[:, p1 + 1:p2]):
        return None
    hexes = m[:, p2:]
    if not (hexes[:, 0::3] == 32).all():
        return None
    hi, lo = _NIBBLE[hexes[:, 1::3]], _NIBBLE[hexes[:, 2::3]]
    if (hi < 0).any() or (lo < 0).any():
        return None
    digits = np.concatenate([whole, frac], axis=1)
    t = _number(digits) / float(10 ** frac.shape[1])
    declared = _number(m[:, p1 + 1:p2])
    if not (declared == hi.shape[1]).all() or not (t <= max_seconds).all():
        return None
    return t, declared, (hi * 16 + lo).astype(np.uint8)


def strict_events(lines: list[str], max_seconds: float) -> tuple[np.ndarray, np.ndarray, bytes] | None:
    """Times, lengths and concatenated bytes of ``lines`` (each starting ``"E: "``), or None unless every line is
    strictly formed, holds the bytes it declares and is no later than ``max_seconds``."""
    try:
        buf = np.frombuffer(("\n".join(lines) + "\n").encode("ascii"), dtype=np.uint8)
    except UnicodeEncodeError:
        return None
    ends = np.flatnonzero(buf == 10)
    starts = np.concatenate([[0], ends[:-1] + 1])
    widths = ends - starts
    spaces = np.flatnonzero(buf == 32)
    first = np.searchsorted(spaces, starts + 3)
    if (first + 1 >= len(spaces)).any():
        return None
    p1, p2 = spaces[first] - starts, spaces[np.minimum(first + 1, len(spaces) - 1)] - starts
    p2 = np.where(p2 >= widths, widths, p2)  # no bytes: the length is the line's last field
    dots = np.flatnonzero(buf == 46)
    at = np.searchsorted(dots, starts + 3)
    dot = np.full(len(starts), -1, dtype=np.int64)
    has = at < len(dots)
    dot[has] = dots[at[has]] - starts[has]
    dot = np.where((dot >= 0) & (dot < p1), dot, -1)
    base = int(widths.max()) + 2
    if base > 50000:
        return None
    keys, inverse = np.unique(((widths * base + p1) * base + p2) * base + dot + 1, return_inverse=True)
    inverse = inverse.ravel()
    t = np.empty(len(starts), dtype=np.float64)
    lengths = np.empty(len(starts), dtype=np.int64)
    parts = []
    for g, key in enumerate(keys.tolist()):
        rest, d = divmod(key, base)
        rest, b = divmod(rest, base)
        w, a = divmod(rest, base)
        d -= 1
        rows = np.flatnonzero(inverse == g)
        m = buf[starts[rows, None] + np.arange(w)]
        got = _group(m, a, b, d, max_seconds)
        if got is None:
            return None
        t[rows], lengths[rows] = got[0], got[1]
        parts.append((rows, got[2]))
    offsets = np.concatenate([[0], np.cumsum(lengths)])
    blob = np.empty(int(offsets[-1]), dtype=np.uint8)
    for rows, data in parts:
        if data.shape[1]:
            blob[offsets[rows, None] + np.arange(data.shape[1])] = data
    return t, lengths, blob.tobytes()
