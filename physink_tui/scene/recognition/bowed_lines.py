"""Lines a quick wrist bowed one way, lying slanted or level: no parenthesis stands so, and no circle fits their bow.

`open_marks.flicked` lets a one-way bow through `open_marks.swung_line`'s turning test only where it is shallow
(`open_marks.FLICK_SAG`), deepest about its middle (`open_marks.FLICK_MIDDLE`) and straight at one end
(`open_marks.FLICK_END_DEG`): each guards a parenthesis' shape (a lopsided one curling near one end, a flat one curled
at both). A parenthesis is written upright, leaning as handwriting does; a stroke whose chord lies far off the upright
is none, and an arc drawn so is told by its circle (`open_marks.SWUNG_ARC`, still asked). `slanted_flick` asks less of
such a stroke; `end_bent` lets it stray a little farther (`open_marks.SWUNG_FAR`) where its bend lies near its end, to
one side: a curl the cuts left where the pen lifted, not an arc's bow (about its middle), a wave's (both sides) nor a
tick's short arm (drawn first). No I/O.
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
    found = _slanted_offsets(coarse)
    if found is None:
        return False
    norm, off, along = found
    k = int(np.argmax(np.abs(off)))
    return abs(float(off[k])) < SLANT_SAG * norm and SLANT_END <= float(along[k]) <= 1.0 - SLANT_END


END_SIDE = 0.6
"""A stroke bends to one side where its points on the other side of its chord (start to end) reach at most this share
of the farthest point's distance: a wave or an S swings both ways about equally (the pen models' flat zig-zags and
s-curves that stray as far: 0.67-0.99 of it, `benchmarks/bench_hurried_marks.py`, tuning seeds), the `sign` set's
lines curled at an end 0-0.48 (issue 25, session 38)."""
END_NEAR = 0.375
"""... and bends where the pen lifted: its farthest point lies no farther than this share of the chord from its end.
An arc bows about its middle (the pen models' slanted arcs and marks straying 0.09-0.105 of their length: 0.43-0.57
of the chord along, `bench_lines.py`, `bench_hurried_marks.py`, tuning seeds); a tick's or a radical's short arm is
drawn first, where the pen landed (ahmadosama's Tick #77, a mouse's rounded tick: 0.20 along; the rule taking bends
there read it as a line); the `sign` set's lines curled where the pen lifted: 0.68-0.94 (issue 25, session 38)."""


def end_bent(coarse: np.ndarray) -> bool:
    """Whether ``coarse`` lies more than `SLANT_DEG` off the vertical and bends to one side of its chord (`END_SIDE`),
    farthest from it near its end (`END_NEAR`): a line curled where the pen lifted, which
    `open_marks.swung_line` lets stray a little farther than a bow (`open_marks.SWUNG_FAR`).

    >>> x = np.linspace(0.0, 1.0, 101)
    >>> curled = np.column_stack([x, 0.1 * x ** 6])
    >>> end_bent(curled), end_bent(curled[:, ::-1]), end_bent(curled[::-1])  # level; upright; curled where it landed
    (True, False, False)
    >>> end_bent(np.column_stack([x, 0.1 * np.sin(np.pi * x)]))  # an arc: about its middle
    False
    >>> end_bent(np.column_stack([x, 0.06 * np.sin(2 * np.pi * x ** 1.5)]))  # a wave: both sides
    False
    """
    found = _slanted_offsets(coarse)
    if found is None:
        return False
    _, off, along = found
    k = int(np.argmax(np.abs(off)))
    other = float(-off.min()) if off[k] > 0 else float(off.max())
    return other <= END_SIDE * abs(float(off[k])) and float(along[k]) >= 1.0 - END_NEAR


def slanted(points: np.ndarray) -> bool:
    """Whether the chord of ``points`` (start to end) lies more than `SLANT_DEG` off the page's vertical."""
    chord = points[-1] - points[0]
    return math.degrees(math.atan2(abs(float(chord[0])), abs(float(chord[1])))) > SLANT_DEG


def _slanted_offsets(coarse: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """For a `slanted` stroke with ends apart: its chord's length, each point's signed distance off the chord and how
    far along it each lies (a share of the chord); else None."""
    chord = coarse[-1] - coarse[0]
    norm = float(np.hypot(*chord))
    if norm == 0.0 or not slanted(coarse):
        return None
    rel = coarse - coarse[0]
    return norm, (rel[:, 0] * chord[1] - rel[:, 1] * chord[0]) / norm, rel @ chord / (norm * norm)
