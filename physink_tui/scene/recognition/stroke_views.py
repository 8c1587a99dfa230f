"""One stroke at unit size as the checks after the rules judge it (resampled, smoothed, hooks cut), each made once.

The checks `recognize` asks after the rules' reading (`waves`, `stairs`, `hooked_ticks`, `round_brackets`,
`angular_braces`, `lopsided_braces`, `square_braces`) each judged the same stroke on the same resampled copies, made
again by each: the same arrays, the same arithmetic. A `StrokeViews` holds them for one recognition only (made per
call, never shared between strokes), read-only, so each is made once and every check reads exactly what it made before.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

import numpy as np

from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg

T = TypeVar("T")


class StrokeViews:
    """``unit`` (the stroke's points at unit size) seen as the checks see it, each view made once, when first asked."""

    __slots__ = ("_made", "unit")

    def __init__(self, unit: np.ndarray) -> None:
        self.unit = unit
        self._made: dict[tuple[object, ...], object] = {}

    def _once(self, key: tuple[object, ...], make: Callable[[], T]) -> T:
        if key not in self._made:
            found = make()
            if isinstance(found, np.ndarray):
                found.flags.writeable = False  # shared by the checks: none may change it
            self._made[key] = found
        return self._made[key]  # type: ignore[return-value]

    def smoothed(self, n: int) -> np.ndarray:
        """The stroke on ``n`` points equally spaced along it, lightly smoothed (`stroke_geometry.smooth`)."""
        return self._once(("smoothed", n), lambda: sg.smooth(sg.resample(self.unit, n)))

    def hooks_cut(self, n: int) -> np.ndarray:
        """`stroke_geometry.hooks_cut` of the stroke on ``n`` points (its `smoothed` copy, a hook at either end cut,
        on ``n`` points again)."""
        return self._once(("hooks_cut", n), lambda: sg.resample(sg.remove_hooks(self.smoothed(n)), n))

    def cut_lobes(self, n: int, noise: float) -> list[float]:
        """`stroke_features.lobes` of `hooks_cut` at the pen's ``noise`` (in unit size): read, not changed."""
        return self._once(("cut_lobes", n, noise), lambda: sf.lobes(self.hooks_cut(n), noise=noise))

    def once(self, key: tuple[object, ...], make: Callable[[], T]) -> T:
        """What ``make`` finds of this stroke, found once under ``key`` (a check's name and its arguments)."""
        return self._once(("check", *key), make)
