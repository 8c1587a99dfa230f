"""The decoded pen sample, the unit every pen source produces; no decoding or device logic."""

from __future__ import annotations

from typing import NamedTuple


class PenSample(NamedTuple):
    """One pen report, normalised.

    A NamedTuple rather than a frozen dataclass: it is immutable and slotted like one, and it
    is built once per HID report on the hot decoding path, where a tuple is about four times
    cheaper to construct (0.5 µs against 2.0 µs measured). Change it with ``sample._replace(...)``.

    Attributes:
        t: seconds, on the clock of whoever read the report (capture time, monotonic clock).
        x: 0..1 across the tablet's active area, left to right.
        y: 0..1 down the tablet's active area, top to bottom.
        p: tip pressure 0..1 (1.0 while touching and 0.0 otherwise on tablets without pressure).
        tip: the tip (or the eraser end) touches the surface.
        range: the pen is in proximity of the tablet.
        eraser: the eraser end (or an eraser tool) is the one in proximity.
        b1: first barrel button.
        b2: second barrel button.
        tilt_x: degrees, positive towards the right, or None when the tablet reports no tilt.
        tilt_y: degrees, positive towards the user, or None when the tablet reports no tilt.
        report: the report id the sample came from (0 for descriptors without ids).
    """

    t: float
    x: float
    y: float
    p: float
    tip: bool
    range: bool
    eraser: bool
    b1: bool
    b2: bool
    tilt_x: float | None
    tilt_y: float | None
    report: int
