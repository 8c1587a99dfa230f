"""Strokes that wind or scrub rather than outline: a spring drawn as one coil (a helix) or a scribble back and
forth (no shape); what they are not is left to `recognize`."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import helix_geometry
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.small_loops import remove_small_loops

COILED = 3.5 * math.pi
"""A stroke turning this far one way in all (radians) may be a spring: more than once round and most of a second."""
COIL_SHARPNESS = 0.7
"""A spring's loops may be pointed (a hurried hand), but not turn as sharply as a star's corners (about 0.9 of
their turning in the sharpest fifth)."""


def helix_or_scribble(work: np.ndarray, n: int, diag: float, length: float,
                      th: np.ndarray | None = None, unlooped: np.ndarray | None = None) -> Recognition | None:
    """A spring (loops advancing along an axis, turning smoothly, `COILED` far without its small loops:
    `small_loops.remove_small_loops`) or a scribble back and forth, else None (``th``: the path's turning,
    `stroke_geometry.turning`, and ``unlooped``: ``remove_small_loops(work)``, where already measured)."""
    th = sg.turning(work) if th is None else th
    total_turn, abs_turn = float(np.add.reduce(th)), float(np.add.reduce(np.abs(th)))
    if abs(total_turn) > COILED and abs(float(_turning_without_small_loops(work, th, unlooped).sum())) > COILED:
        # a finger's or pen's small loop where it landed or lifted (or at a corner) is no loop of the spring
        coil = sg.resample(sg.remove_hooks(work), n)
        coil_turn = sg.turning(coil)
        if sf.turn_concentration(sg.turning(sg.resample(coil, 40))) < COIL_SHARPNESS:  # a star winds twice too
            total, spread = float(coil_turn.sum()), float(np.abs(coil_turn).sum())
            helix = helix_geometry(coil, total, spread)
            # its loops counted from either end (`beautify.helix_geometry` counts whole turns from the start, so the
            # part-loop falls at the end one way and at the start the other): a spring drawn from its other end
            if helix is not None and helix_geometry(coil[::-1], -total, spread) is not None:
                return Recognition("helix", 0.9, helix, (("curve", 0.1),))
    reversals = int(np.count_nonzero(np.abs(th) > math.radians(150)))
    if length > 5 * diag and (reversals >= 4 or (abs_turn > 6 * math.pi and abs(total_turn) < 0.3 * abs_turn)):
        return Recognition(None, 0.0, None, (), "a scribble back and forth, not a shape")
    return None


def _turning_without_small_loops(work: np.ndarray, th: np.ndarray, unlooped: np.ndarray | None) -> np.ndarray:
    """The turning of ``work`` (``th``) without its small loops (``unlooped``, where already cut): ``th`` itself where
    it has none (`small_loops.remove_small_loops` gives back ``work``)."""
    unlooped = remove_small_loops(work) if unlooped is None else unlooped
    return th if unlooped is work else sg.turning(unlooped)
