"""Chooses one 256-colour palette for a GIF from its first frame and maps frames onto it; no dithering, no I/O."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

BITS = 5
"""Bits kept per channel when colours are counted and looked up (32,768 bins)."""

CUBE_LEVELS = (0, 64, 128, 191, 255)
"""Each channel's levels in the fixed colour cube (125 entries) kept for colours the first frame lacks."""


@dataclass(frozen=True, slots=True)
class Palette:
    """Up to 256 colours and a lookup from every 15-bit colour to its nearest entry.

    Drawings are a few flat colours plus their anti-aliased edges: the 131 most frequent colours of the first
    frame are kept exactly, and a 5x5x5 colour cube gives any colour that appears only later an entry at most
    32 levels per channel away.
    """

    argb: np.ndarray
    """(256, 4) uint8 palette, each row A, R, G, B as PyAV's pal8 frames take it."""
    lookup: np.ndarray
    """(32768,) uint8: palette index for each colour with BITS bits per channel."""

    @classmethod
    def from_frame(cls, rgba: np.ndarray) -> Palette:
        """The palette of ``rgba``'s most frequent colours (by 15-bit bin, each the mean of its pixels) and the cube."""
        rgb = rgba[..., :3].reshape(-1, 3)
        bins = _bins(rgba).ravel()
        counts = np.bincount(bins, minlength=1 << (3 * BITS))
        cube = np.array([(r, g, b) for r in CUBE_LEVELS for g in CUBE_LEVELS for b in CUBE_LEVELS], np.int32)
        chosen = np.argsort(counts, kind="stable")[::-1][: 256 - len(cube)]
        chosen = chosen[counts[chosen] > 0]
        sums = np.stack([np.bincount(bins, weights=rgb[:, c], minlength=counts.size) for c in range(3)], axis=1)
        colours = np.concatenate([np.rint(sums[chosen] / counts[chosen, None]).astype(np.int32), cube])
        argb = np.zeros((256, 4), np.uint8)
        argb[:, 0] = 255
        argb[: len(colours), 1:] = colours
        every = np.arange(counts.size)
        centres = np.stack([(every >> (2 * BITS)) & 31, (every >> BITS) & 31, every & 31], axis=1) * 8 + 4
        lookup = np.empty(counts.size, np.uint8)
        for start in range(0, counts.size, 4096):
            d = ((centres[start:start + 4096, None, :] - colours[None, :, :]) ** 2).sum(axis=2)
            lookup[start:start + 4096] = d.argmin(axis=1)
        lookup[chosen] = np.arange(len(chosen))  # a chosen bin is its own colour, whatever the nearest centre
        return cls(argb, lookup)

    def indices(self, rgba: np.ndarray) -> np.ndarray:
        """(H, W) uint8 palette indices for an (H, W, 4) uint8 RGBA frame (alpha ignored)."""
        return self.lookup[_bins(rgba)]


def _bins(rgba: np.ndarray) -> np.ndarray:
    shift = 8 - BITS
    r = (rgba[..., 0] >> shift).astype(np.int32)
    g = (rgba[..., 1] >> shift).astype(np.int32)
    b = (rgba[..., 2] >> shift).astype(np.int32)
    return (r << (2 * BITS)) | (g << BITS) | b
