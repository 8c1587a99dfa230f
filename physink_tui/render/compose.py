"""Puts two finished RGBA frames side by side for a comparison video; draws nothing (overlays are the renderer's)."""

from __future__ import annotations

import numpy as np

from physink_tui.errors import RenderError


def side_by_side(left: np.ndarray, right: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """A new (or the given ``out``) frame with ``left`` and ``right`` next to each other, same height required.

    >>> a = np.zeros((2, 3, 4), np.uint8); b = np.full((2, 1, 4), 255, np.uint8)
    >>> side_by_side(a, b).shape
    (2, 4, 4)
    """
    for name, frame in (("left", left), ("right", right)):
        if frame.ndim != 3 or frame.shape[2] != 4 or frame.dtype != np.uint8:
            raise RenderError(f"{name} frame has shape {frame.shape!r} and dtype {frame.dtype}; "
                              "expected (height, width, 4) uint8 RGBA")
    if left.shape[0] != right.shape[0]:
        raise RenderError(f"frames of heights {left.shape[0]!r} and {right.shape[0]!r} cannot stand side by side")
    height, width = left.shape[0], left.shape[1] + right.shape[1]
    if out is None:
        out = np.empty((height, width, 4), np.uint8)
    elif out.shape != (height, width, 4):
        raise RenderError(f"output frame has shape {out.shape!r}; expected {(height, width, 4)!r}")
    out[:, : left.shape[1]] = left
    out[:, left.shape[1]:] = right
    return out
