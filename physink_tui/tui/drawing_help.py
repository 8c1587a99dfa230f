"""The drawing vocabulary the help screen shows: each gesture as a small braille drawing, what it makes, and the
sizes that count — taken from the constants the interpretation, the X pairing and the gesture engine use, so the help
cannot drift from what the program does; text only, no Textual.
"""

from __future__ import annotations

import itertools
import math
import textwrap
from collections.abc import Iterable
from dataclasses import dataclass

from physink_tui.input.pen.gestures import GestureConfig
from physink_tui.render.braille import braille_plot
from physink_tui.scene.interpretation.interpret import INSIDE_SHARE, JOINT_MAX_SIZE
from physink_tui.scene.interpretation.x_pairing import MIN_ANGLE
from physink_tui.session.modes.sketch import X_CANDIDATE, X_WAIT

DRAWING = (10, 4)
"""Braille cells (columns, rows) of each small drawing: 20 x 16 dots."""

Points = list[tuple[float, float]]


@dataclass(frozen=True, slots=True)
class Gesture:
    """One entry of the vocabulary: what to draw, its picture (braille lines), what it makes and the sizes."""

    name: str
    drawing: tuple[str, ...]
    meaning: str


def _segment(a: tuple[float, float], b: tuple[float, float], n: int = 40) -> Points:
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n + 1)]


def _polyline(*corners: tuple[float, float]) -> Points:
    points: Points = []
    for a, b in itertools.pairwise(corners):
        points += _segment(a, b)
    return points


def _box(x0: float, y0: float, x1: float, y1: float) -> Points:
    return _polyline((x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0))


def _ellipse(cx: float, cy: float, rx: float, ry: float, n: int = 80) -> Points:
    return [(cx + rx * math.cos(2 * math.pi * k / n), cy + ry * math.sin(2 * math.pi * k / n)) for k in range(n)]


def _zigzag(x0: float, x1: float, y: float, amplitude: float, teeth: int = 5) -> Points:
    corners = [(x0 + (x1 - x0) * k / (2 * teeth), y + (amplitude if k % 2 else -amplitude) * (k > 0))
               for k in range(2 * teeth + 1)]
    return _polyline(*corners)


def _draw(points: Iterable[tuple[float, float]]) -> tuple[str, ...]:
    return tuple(braille_plot(points, *DRAWING).split("\n"))


def vocabulary(canvas: tuple[float, float]) -> list[Gesture]:
    """The gestures, in the order the interpretation tries them, with sizes for a ``canvas`` (units) sketch."""
    diagonal = math.hypot(*canvas)
    arm = X_CANDIDATE * diagonal
    pen = GestureConfig()
    body = _box(0.05, 0.2, 0.95, 0.8)
    return [
        Gesture("line through a body", _draw(body + _segment((0.0, 0.95), (0.9, 0.05))),
                "erases the body (its middle inside, both ends outside); so does the right mouse button or the "
                "pen's eraser end. u undoes it"),
        Gesture("small circle in a body", _draw(body + _ellipse(0.5, 0.5, 0.12, 0.16)),
                f"a pin: the body turns on what lies under it. The circle is smaller than {JOINT_MAX_SIZE:.0%} of "
                f"the body and at least {INSIDE_SHARE:.0%} of it inside"),
        Gesture("X in a body", _draw(body + _segment((0.3, 0.3), (0.7, 0.7)) + _segment((0.7, 0.3), (0.3, 0.7))),
                f"a weld to what lies under it, or fixes the body in place. Two strokes crossing near their middles "
                f"at {MIN_ANGLE:g}° or more, each shorter than {X_CANDIDATE:.0%} of the canvas diagonal "
                f"({arm:.0f} units), the second begun within {X_WAIT:g} s of the first"),
        Gesture("zigzag", _draw(_box(0.0, 0.25, 0.15, 0.75) + _zigzag(0.15, 1.0, 0.5, 0.3, teeth=3)),
                "a spring along its horizontal or vertical axis: loops or teeth along a line, one end in a fixed "
                "body (an X fixes a body)"),
        Gesture("circle or ellipse", _draw(_ellipse(0.5, 0.5, 0.3, 0.4)), "a round body (a ball)"),
        Gesture("box, polygon, line", _draw(_box(0.1, 0.25, 0.9, 0.75) + _segment((0.1, 0.95), (0.9, 0.95))),
                "a rigid body; a long thin box is a platform"),
        Gesture("curve between bodies", _draw(_box(0.0, 0.1, 0.25, 0.4) + _box(0.75, 0.1, 1.0, 0.4)
                                              + [(0.12 + 0.76 * k / 40, 0.25 + 0.7 * math.sin(math.pi * k / 40))
                                                 for k in range(41)]),
                "a rope: its ends hold on to the bodies they lie in"),
        Gesture("hold still, then drag", _draw(body + _ellipse(0.5, 0.5, 0.04, 0.05)
                                               + _segment((0.5, 0.5), (0.95, 0.1))),
                f"moves the body: keep the pen within {pen.dwell_radius:.0%} of the canvas for "
                f"{pen.dwell_seconds:g} s first. In demo mode dragging a body demonstrates its movement"),
        Gesture("tap", _draw(body + _ellipse(0.5, 0.5, 0.03, 0.04)),
                f"selects the body (a touch shorter than {pen.tap_seconds:g} s); l labels it"),
    ]


def vocabulary_lines(canvas: tuple[float, float], width: int = 88) -> list[str]:
    """The vocabulary as help lines: each drawing beside its name and meaning, wrapped to ``width`` columns."""
    lines: list[str] = []
    text_width = width - DRAWING[0] - 4
    for gesture in vocabulary(canvas):
        words = textwrap.wrap(f"{gesture.name}: {gesture.meaning}", text_width)
        rows = max(len(words), len(gesture.drawing))
        for row in range(rows):
            picture = gesture.drawing[row] if row < len(gesture.drawing) else " " * DRAWING[0]
            lines.append(f"  {picture}  {words[row] if row < len(words) else ''}".rstrip())
        lines.append("")
    return lines
