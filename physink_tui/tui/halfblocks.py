"""Turns RGBA pixels into terminal lines of Unicode upper half blocks (two pixels a cell); draws nothing itself.

Each cell shows two pixels, one above the other: the upper as the foreground colour of ``▀``, the lower as the
background. Runs of cells with the same pair of colours become one segment, and styles are cached by colour
pair, so a mostly blank canvas costs a few segments a line. This works in every terminal with true colour;
graphics protocols (Sixel, Kitty) are a later refinement.
"""

from __future__ import annotations

import numpy as np
from rich.color import Color
from rich.segment import Segment
from rich.style import Style
from textual.strip import Strip

UPPER_HALF = "\u2580"
_MAX_STYLES = 50_000


class HalfBlocks:
    """Converts frames to `Strip`s, keeping the styles it made (one instance per view)."""

    def __init__(self) -> None:
        self._styles: dict[int, Style] = {}

    def _style(self, key: int) -> Style:
        style = self._styles.get(key)
        if style is None:
            if len(self._styles) > _MAX_STYLES:
                self._styles.clear()
            top, bottom = key >> 24, key & 0xFFFFFF
            style = Style(color=Color.from_rgb(top >> 16, (top >> 8) & 255, top & 255),
                          bgcolor=Color.from_rgb(bottom >> 16, (bottom >> 8) & 255, bottom & 255))
            self._styles[key] = style
        return style

    def strips(self, rgba: np.ndarray) -> list[Strip]:
        """One strip per pair of pixel rows of ``rgba`` (height, width, 4); an odd last row pairs with black."""
        height, width = rgba.shape[:2]
        rgb = rgba[..., :3].astype(np.int64)
        packed = (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]
        if height % 2:
            packed = np.vstack([packed, np.zeros((1, width), dtype=np.int64)])
        keys = (packed[0::2] << 24) | packed[1::2]
        lines = []
        for row in keys:
            cuts = np.flatnonzero(row[1:] != row[:-1]) + 1
            starts = [0, *cuts.tolist()]
            ends = [*cuts.tolist(), width]
            values = row[starts].tolist()
            segments = [Segment(UPPER_HALF * (end - start), self._style(value))
                        for start, end, value in zip(starts, ends, values, strict=True)]
            lines.append(Strip(segments, width))
        return lines
