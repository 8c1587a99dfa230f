"""Optional light smoothing of pen positions while touching; at most half a sample of lag, no state machine.

Each touching position is averaged with the previous touching position (a two-tap moving average:
its group delay is half a report interval, well inside the one-sample budget), which takes out the
one-count jitter cheap tablets show without rounding corners away. Hover positions, pressure and
switches pass untouched, and the filter restarts at every pen-down.
"""

from __future__ import annotations

from physink_tui.input.pen.sample import PenSample


class PositionSmoother:
    """Two-tap average of consecutive touching positions.

    >>> sm = PositionSmoother()
    >>> a = PenSample(0.0, 0.2, 0.2, 0.5, True, True, False, False, False, None, None, 2)
    >>> sm.apply(a).x, sm.apply(a._replace(t=0.005, x=0.4)).x
    (0.2, 0.30000000000000004)
    """

    __slots__ = ("_prev",)

    def __init__(self) -> None:
        self._prev: PenSample | None = None

    def apply(self, sample: PenSample) -> PenSample:
        if not sample.tip:
            self._prev = None
            return sample
        prev, self._prev = self._prev, sample
        if prev is None:
            return sample
        return sample._replace(x=(sample.x + prev.x) * 0.5, y=(sample.y + prev.y) * 0.5)
