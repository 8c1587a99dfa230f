"""Lines a quick wrist bowed one way, lying slanted or level: no parenthesis stands so, and no circle fits their bow.

`open_marks.flicked` lets a one-way bow through `open_marks.swung_line`'s turning test only where it is shallow
(`open_marks.FLICK_SAG`), deepest about its middle (`open_marks.FLICK_MIDDLE`) and straight at one end
(`open_marks.FLICK_END_DEG`): each guards a parenthesis' shape (a lopsided one curling near one end, a flat one curled
at both). A parenthesis is written upright, leaning as handwriting does; a stroke whose chord lies far off the upright
is none, and an arc drawn so is told by its circle (`open_marks.SWUNG_ARC`, still asked). `slanted_flick` asks less of
such a stroke. No I/O.
"""

from __future__ import annotations

import math

import numpy as np

SLANT_DEG = 25.0
"""A stroke whose chord (start to end) lies more than this many degrees off the page's vertical is no parenthesis:
the pen models' parentheses lean 10-12 degrees at most (`tests/penmodels/paren_habits.py`, `math_marks.py`), twice
that is the margin; the `sign` set's slanted and level lines read as arcs (ST5022 writers, issue 25, session 37) lie
34-89 degrees off it."""
SLANT_SAG = 0.12
"""... which bows off its chord by less than this share of it (the `sign` lines read as arcs bow 0.054-0.132, the
deepest few with a hook; a circular arc of 54 degrees bows 0.12, and `open_marks.SWUNG_STRAY` and `SWUNG_INK` already
refuse arcs of 60 degrees)."""
SLANT_END = 0.15
"""... deepest no nearer an end of its chord than this share of it: a bend nearer is a hook where the pen landed or
lifted (`open_marks.retraced_ends`, `lines.without_hooked_ends`), not a bow."""


def slanted_flick(coarse: np.ndarray) -> bool:
    """Whether ``coarse`` (a stroke turning one way) lies more than `SLANT_DEG` off the vertical and bows off its
    chord, start to end, by less than `SLANT_SAG` of it, deepest no nearer an end than `SLANT_END` of it: a line a
    quick wrist bowed, which `open_marks.swung_line` takes where no circle explains the bow.

    >>> x = np.linspace(0.0, 1.0, 101)
    >>> bow = np.column_stack([x, 0.08 * np.sin(np.pi * x) ** 3])
    >>> slanted_flick(bow), slanted_flick(bow[:, ::-1])  # level; the same bow standing upright
    (True, False)
    >>> slanted_flick(np.column_stack([x, 0.15 * np.sin(np.pi * x)]))  # too deep
    False
    """
    chord = coarse[-1] - coarse[0]
    norm = float(np.hypot(*chord))
    if norm == 0.0 or not slanted(coarse):
        return False
    rel = coarse - coarse[0]
    off = np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]) / norm
    k = int(np.argmax(off))
    along = float(rel[k] @ chord) / (norm * norm)
    return float(off[k]) < SLANT_SAG * norm and SLANT_END <= along <= 1.0 - SLANT_END


def slanted(points: np.ndarray) -> bool:
    """Whether the chord of ``points`` (start to end) lies more than `SLANT_DEG` off the page's vertical."""
    chord = points[-1] - points[0]
    return math.degrees(math.atan2(abs(float(chord[0])), abs(float(chord[1])))) > SLANT_DEG
