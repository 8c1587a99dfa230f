"""Encodes RGBA frames as Sixel (DEC's terminal graphics, as xterm, foot, mlterm, WezTerm and others read it):
up to 256 colours (`gif_palette.Palette`), bands of six pixel rows, runs compressed; writes nothing to a terminal.

Format: ``ESC P 0;1;0 q`` (pixels left 0 keep the background), raster attributes ``"1;1;W;H``, colour
registers ``#n;2;r;g;b`` (percent), then per band and colour ``#n`` and one character per column (63 + the six
bits of the rows that colour covers, ``!k`` + character for a run of k), ``$`` back to the band's start, ``-`` to
the next band, and ``ESC \\``.
"""

from __future__ import annotations

import numpy as np

from physink_tui.errors import RenderError
from physink_tui.render.gif_palette import Palette

DCS_START = "\x1bP0;1;0q"
ST = "\x1b\\"


def encode(rgba: np.ndarray, palette: Palette | None = None) -> str:
    """``rgba`` (height, width, 4 uint8; alpha ignored) as one Sixel image, in ``palette`` (default: the frame's
    own, `Palette.from_frame`).

    Raises:
        RenderError: ``rgba`` is not an RGBA frame.
    """
    if not (isinstance(rgba, np.ndarray) and rgba.dtype == np.uint8 and rgba.ndim == 3 and rgba.shape[2] == 4
            and rgba.shape[0] > 0 and rgba.shape[1] > 0):
        raise RenderError(f"sixel: expected a (height, width, 4) uint8 RGBA array, got shape "
                          f"{getattr(rgba, 'shape', None)!r}")
    palette = palette or Palette.from_frame(rgba)
    index = palette.indices(rgba).astype(np.int16)
    height, width = index.shape
    used = np.unique(index)
    out = [DCS_START, f'"1;1;{width};{height}']
    for n in used.tolist():
        r, g, b = (round(int(v) * 100 / 255) for v in palette.argb[n, 1:])
        out.append(f"#{n};2;{r};{g};{b}")
    pad = (-height) % 6
    if pad:
        index = np.vstack([index, np.full((pad, width), -1, np.int16)])
    weights = (1 << np.arange(6, dtype=np.int16))[:, None]
    for top in range(0, index.shape[0], 6):
        band = index[top:top + 6]
        colours = np.unique(band[band >= 0]).tolist()
        for k, n in enumerate(colours):
            bits = ((band == n) * weights).sum(axis=0)
            out.append(f"#{n}{_runs(bits)}")
            if k < len(colours) - 1:
                out.append("$")
        out.append("-")
    out.append(ST)
    return "".join(out)


def _runs(bits: np.ndarray) -> str:
    """One band's columns for one colour, runs of four or more as ``!k`` + character (trailing zeros dropped)."""
    nonzero = np.flatnonzero(bits)
    if not nonzero.size:
        return ""
    bits = bits[: nonzero[-1] + 1]
    cuts = np.flatnonzero(bits[1:] != bits[:-1]) + 1
    starts = [0, *cuts.tolist()]
    ends = [*cuts.tolist(), len(bits)]
    parts = []
    for start, end, value in zip(starts, ends, bits[starts].tolist(), strict=True):
        char = chr(63 + value)
        run = end - start
        parts.append(f"!{run}{char}" if run > 3 else char * run)
    return "".join(parts)
