"""A line whose end the pen curled (a rounded hook swung round where it landed or lifted), without that curl; no I/O."""

from __future__ import annotations

import numpy as np

from physink_tui.scene.recognition import stroke_geometry as sg

CURL_POINTS = 64
"""The stroke is judged on this many points equally spaced along it (then lightly smoothed)."""
CURL_MIDDLE = (0.3, 0.7)
"""The line's way is the chord between these shares of the path (a curl lies outside them)."""
CURL_OFF_DEG = 30.0
"""An end piece is the curl from the stroke's end to the last step heading more than this off the line's way."""
CURL_SHARE = 0.18
"""... at most this share of the path,"""
CURL_TURN_DEG = 125.0
"""... heading at least this far off the line's way somewhere (a curl swings round; a hook nearly in line is
`open_marks.retraced_ends`'),"""
CURL_ROUND = 0.2
"""... and round: it strays from its own chord by at least this share of it (a quarter circle's bow; a mark's short arm
is straight: `stroke_geometry.ARM_STRAIGHT`),"""
CURL_TIGHT_DEG = 60.0
"""... and tight: somewhere it turns at least this much within `CURL_SPAN` of the path."""
CURL_SPAN = 0.04
"""(the span `CURL_TIGHT_DEG` is judged over)"""
CURL_END_DEG = 90.0
"""... and swung in from its end: the step at the stroke's end heads at least this far off the line's way (a mark whose
first arm is a small hook and a tick, zig-zagging into its long arm, heads back along it there)."""
CURL_TINY = 0.05
"""An end piece off the line's way of at most this share of the path is a flick, cut with the curl whatever its shape;
exactly one end's piece is longer, and curls."""


def _end_pieces(raw: np.ndarray) -> tuple[list[tuple[int, np.ndarray, np.ndarray]], float]:
    """Each end piece of ``raw`` (judged on `CURL_POINTS` points) heading off the line's way: which end, its points
    from the line on, and how far (degrees) each of its steps heads off the line's way; and the judged path's length."""
    pts = sg.smooth(sg.resample(raw, CURL_POINTS))
    n = len(pts)
    length = sg.path_length(pts)
    if length == 0.0:
        return [], length
    way = pts[int(CURL_MIDDLE[1] * (n - 1))] - pts[int(CURL_MIDDLE[0] * (n - 1))]
    norm = float(np.hypot(*way))
    if norm == 0.0:
        return [], length
    way = way / norm
    steps = pts[1:] - pts[:-1]
    cos = (steps @ way) / np.maximum(np.hypot(steps[:, 0], steps[:, 1]), 1e-12)
    off = np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
    half = len(steps) // 2
    out = []
    head = np.flatnonzero(off[:half] > CURL_OFF_DEG)
    if len(head):
        k = int(head[-1]) + 1
        out.append((0, pts[:k + 1], off[:k]))
    tail = np.flatnonzero(off[half:] > CURL_OFF_DEG)
    if len(tail):
        piece = pts[half + int(tail[0]):]
        out.append((1, piece, off[len(steps) - (len(piece) - 1):]))
    return out, length


def curled_ends(raw: np.ndarray) -> np.ndarray | None:
    """``raw`` without the curl at one end (`CURL_SHARE`, `CURL_TURN_DEG`, `CURL_ROUND`, `CURL_TIGHT_DEG`,
    `CURL_END_DEG`) and any flick at the other (`CURL_TINY`), or None where no end curls, both do, or the other end's
    piece is more than a flick. (Its share, turn and end are judged first: most strokes stop there, before the
    dearer bow and tightness.)"""
    ends, length = _end_pieces(raw)
    shares = [sg.path_length(piece) / length for _, piece, _ in ends]
    longer = [i for i, share in enumerate(shares) if share > CURL_TINY]
    if len(longer) != 1:
        return None
    end, piece, offs = ends[longer[0]]
    if not (shares[longer[0]] <= CURL_SHARE and float(offs.max()) >= CURL_TURN_DEG
            and float(offs[0] if end == 0 else offs[-1]) >= CURL_END_DEG):
        return None
    if sg.chord_deviation(piece) < CURL_ROUND or len(piece) <= 2 \
            or sg.sharpest_turn(piece, CURL_SPAN * length) < CURL_TIGHT_DEG:
        return None
    at = sg.along(raw)
    lo, hi = 0, len(raw)
    for (end, _, _), share in zip(ends, shares, strict=True):  # the curl and any flick, cut where they join the line
        if end == 0:
            lo = int(np.searchsorted(at, share * at[-1]))
        else:
            hi = int(np.searchsorted(at, (1.0 - share) * at[-1])) + 1
    kept = raw[lo:hi]
    return kept if len(kept) >= 2 else None
