"""Draws pen samples as Unicode braille dots for a terminal; no decoding, no colours, no terminal I/O."""

from __future__ import annotations

from collections.abc import Iterable

# Bit of each dot in a braille cell, indexed [row][column] (Unicode 2800 block).
_DOTS = ((0x01, 0x08), (0x02, 0x10), (0x04, 0x20), (0x40, 0x80))


def braille_plot(points: Iterable[tuple[float, float]], width: int = 60, height: int = 20) -> str:
    """Plot ``(x, y)`` points in 0..1 (y down) into ``height`` lines of ``width`` braille cells.

    >>> print(braille_plot([(0.0, 0.0), (1.0, 1.0)], width=2, height=1))
    ⠁⢀
    """
    cells = [[0] * width for _ in range(height)]
    for x, y in points:
        if not (0.0 <= x <= 1.0 and 0.0 <= y <= 1.0):
            continue
        dx = min(int(x * width * 2), width * 2 - 1)
        dy = min(int(y * height * 4), height * 4 - 1)
        cells[dy // 4][dx // 2] |= _DOTS[dy % 4][dx % 2]
    return "\n".join("".join(chr(0x2800 + c) for c in row) for row in cells)
