"""End pieces `open_marks.retraced_ends` also cuts from a line as the pen's: run back narrowly along it, or curled.

`open_marks.retraced_ends` cuts an end piece that lies along the line or is a hook turned back within
`open_marks.BACK_HOOK_DEG` of it, up to `open_marks.BACK_HOOK_LANDED_SHARE` of the path where the pen landed and
`open_marks.BACK_HOOK_SHARE` where it lifted. Two more kinds of end piece are the pen's, not a mark's arm (issue 25,
session 37, the `sign` set's ST5022 writers): one run back almost along the line (`NARROW_DEG`), however long up to
`NARROW_SHARE`, and a short one where the pen lifted that curls round onto the line (`CURL_BOW`), turned back up to
`CURL_DEG`. People's marks' short arms are straight and stand off their rest by 38 degrees or more unless a fifth of
the path or longer (then 24-26 degrees; docs/BENCHMARKS.md, session 36). No I/O.
"""

from __future__ import annotations

import math

import numpy as np

NARROW_DEG = 12.0
"""An end piece whose chord (from where it turns to the stroke's end) lies within this angle of the line running back
from there doubles back along the line: the pen landing and sliding back, or running on back as it lifts (the ST
writers' lines: 0-11 degrees, 16-27 % of the path). No mark's arm is drawn so narrow: people's short arms stand 24
degrees or more off their rest at a fifth of the path or more (38 and more when shorter); the pen models' barless
radicals' ticks that the back-hook rule would cut 14-30 (`open_marks.BACK_HOOK_LANDED_SHARE`)."""
NARROW_SHARE = 0.3
"""... and it is at most this share of the path (the ST writers' narrow lead-ins: up to 27 %)."""
NARROW_TOTAL = 0.35
"""... and the pieces cut at both ends together are at most this share of the path: the line kept is most of it."""
NARROW_BOW = 0.08
"""... and it is straight: bowing off its own chord by less than this share of it beyond the pen's noise (the ST
writers' narrow lead-ins 0.01-0.05; a barless radical's tick drawn by the hurried coarse pen within 5 degrees of its
rise, its point rounded, 0.14: `tests/penmodels/math_marks.barless_radical`, extra tuning seeds 3000-4999)."""
CURL_DEG = 60.0
"""A short end piece where the pen lifted (within the back-hook rule's share) that bows off its own chord by `CURL_BOW`
of it, a curl, may stand off the line by up to this angle: the pen curling round onto the line as it lifts (the ST
writers' lines: 35-56 degrees, bowed 0.1-0.23). Not where the pen landed: a barless radical's tick, drawn first with
its point rounded, is such a curl, 37-56 degrees off its rise (`tests/penmodels/math_marks.barless_radical`, the
hurried pens on extra tuning seeds 2000-4999), where the ST writers' landed curls stand 42-43 degrees off. People's
marks' short arms are straight: of the design and fourth groups' strokes whose rest is a line once an end piece of at
most 15 % of the path is cut, the arms standing 30-75 degrees off bow 0.03 of their chord or less (ahmadosama's and the
hcira checks' 55-73 degrees)."""
CURL_BOW = 0.08
"""... bowing off its chord by at least this share of the chord, beyond the pen's noise."""


def may_cut(cuts: tuple[float, float], most: float) -> bool:
    """Whether end pieces ``cuts`` (shares of the path, from the stroke's start and from its end) may be cut: each at
    most ``most`` (the share `open_marks.retraced_ends` allows), or each at most `NARROW_SHARE` and together at most
    `NARROW_TOTAL` (`narrow_back` then judges each)."""
    return max(cuts) <= most or (max(cuts) <= NARROW_SHARE and sum(cuts) <= NARROW_TOTAL)


def narrow_back(end: np.ndarray, turn: np.ndarray, back: np.ndarray, cut: float, noise: float) -> bool:
    """Whether ``end`` (an end piece, ``cut`` of the stroke's path, from the stroke's end to where it turns, ``turn``)
    runs back along the line (which runs on from ``turn`` the way of ``back``, a unit vector) within `NARROW_DEG`, at
    most `NARROW_SHARE` of the path, straight (`NARROW_BOW`, beyond the pen's ``noise``).

    >>> lead = np.column_stack([np.linspace(25.0, 0.0, 13), np.linspace(3.0, 0.0, 13)])  # 25 px back, 7 degrees
    >>> x = np.array([1.0, 0.0])
    >>> narrow_back(lead, lead[-1], x, 0.2, 0.5), narrow_back(lead, lead[-1], x, 0.42, 0.5)  # a fifth; 42 %
    (True, False)
    """
    return (cut <= NARROW_SHARE and _off_line_deg(end, turn, back) <= NARROW_DEG
            and _bow(end, turn, noise) < NARROW_BOW)


def curled(end: np.ndarray, turn: np.ndarray, back: np.ndarray, cut: float, most: float, noise: float) -> bool:
    """Whether ``end`` (as `narrow_back`'s) is a curl onto the line: ``cut`` no more than ``most`` (the back-hook
    rule's share of the path where the pen landed or lifted), its chord within `CURL_DEG` of the line, and bowing off
    that chord by `CURL_BOW` of it or more beyond the pen's ``noise``: a mark's short arm, as far off, is straight.

    >>> t = np.linspace(0.0, math.pi / 2, 12)  # a quarter circle curling onto the line at the origin, 10 px round
    >>> curl = np.column_stack([10 * np.sin(t), 10 - 10 * np.cos(t)])[::-1]
    >>> arm = np.column_stack([np.linspace(10.0, 0.0, 12), np.linspace(10.0, 0.0, 12)])  # straight, 45 degrees
    >>> x = np.array([1.0, 0.0])
    >>> curled(curl, curl[-1], x, 0.08, 0.125, 0.5), curled(arm, arm[-1], x, 0.08, 0.125, 0.5)
    (True, False)
    """
    if cut > most:
        return False
    chord = end[0] - turn
    norm = float(np.hypot(*chord))
    if norm == 0.0 or _off_line_deg(end, turn, back) > CURL_DEG:
        return False
    return _bow(end, turn, noise) >= CURL_BOW


def _bow(end: np.ndarray, turn: np.ndarray, noise: float) -> float:
    """How far ``end`` strays from its chord (from ``turn`` to ``end[0]``) beyond the pen's ``noise``, as a share of
    the chord (0 where the chord has no length)."""
    chord = end[0] - turn
    norm = float(np.hypot(*chord))
    if norm == 0.0:
        return 0.0
    rel = end - turn
    return (float(np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]).max()) / norm - noise) / norm


def _off_line_deg(end: np.ndarray, turn: np.ndarray, back: np.ndarray) -> float:
    """The angle (degrees) between the chord from ``turn`` to the stroke's end (``end[0]``) and ``back``; 0 where the
    chord has no length."""
    chord = end[0] - turn
    norm = float(np.hypot(*chord))
    if norm == 0.0:
        return 0.0
    return math.degrees(math.acos(max(-1.0, min(1.0, float(chord @ back) / norm))))
