"""Maps a tablet's active area onto the canvas: area, rotation, left-handed use, aspect; no I/O.

Positions arrive in 0..1 of the tablet's active area (x right, y down, as the tablet is built) and
leave in 0..1 of the canvas (x right, y down). By default the used part of the tablet is cropped,
centred, to the canvas's aspect ratio, so a circle drawn on the tablet stays a circle and the whole
canvas is reachable (what Wacom calls "force proportions"). A display tablet maps its area onto the
canvas one to one instead: the pen must land where the screen shows it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(frozen=True, slots=True)
class TabletMapping:
    """How tablet positions become canvas positions.

    Attributes:
        canvas_width, canvas_height: the canvas size in any unit (only the ratio matters), > 0.
        tablet_width, tablet_height: the tablet's active area in physical units (e.g. mm or logical
            counts at equal resolution), > 0; only the ratio matters.
        area: ``(x0, y0, x1, y1)`` in 0..1 of the active area, the part used (before rotation);
            ``x0 < x1``, ``y0 < y1``.
        rotation: degrees clockwise the tablet is turned on the desk: 0, 90, 180 or 270.
        left_handed: the tablet is turned round for the left hand (adds 180 degrees).
        keep_aspect: crop the used area to the canvas's aspect ratio (ignored for display tablets).
        display_tablet: a pen display: the area maps onto the whole canvas, no cropping.
    """

    canvas_width: float = 16.0
    canvas_height: float = 10.0
    tablet_width: float = 16.0
    tablet_height: float = 10.0
    area: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)
    rotation: int = 0
    left_handed: bool = False
    keep_aspect: bool = True
    display_tablet: bool = False
    _box: tuple[float, float, float, float] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for name in ("canvas_width", "canvas_height", "tablet_width", "tablet_height"):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and value > 0):
                raise ValueError(f"mapping {name} must be a positive number, got {value!r}")
        x0, y0, x1, y1 = self.area
        if not (0.0 <= x0 < x1 <= 1.0 and 0.0 <= y0 < y1 <= 1.0):
            raise ValueError(f"mapping area must be (x0, y0, x1, y1) with 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1, "
                             f"got {self.area!r}")
        if self.rotation not in (0, 90, 180, 270):
            raise ValueError(f"mapping rotation must be 0, 90, 180 or 270, got {self.rotation!r}")
        object.__setattr__(self, "_box", self._used_box())

    @property
    def turn(self) -> int:
        """Total clockwise turn of the tablet in degrees."""
        return (self.rotation + (180 if self.left_handed else 0)) % 360

    def _used_box(self) -> tuple[float, float, float, float]:
        """The used area in rotated tablet coordinates, cropped to the canvas aspect when asked."""
        x0, y0, x1, y1 = _rotate_box(self.area, self.turn)
        if self.display_tablet or not self.keep_aspect:
            return x0, y0, x1, y1
        w_units, h_units = (self.tablet_width, self.tablet_height)
        if self.turn in (90, 270):
            w_units, h_units = h_units, w_units
        used_w, used_h = (x1 - x0) * w_units, (y1 - y0) * h_units
        canvas_ratio = self.canvas_width / self.canvas_height
        if used_w / used_h > canvas_ratio:  # too wide: crop the sides
            keep = used_h * canvas_ratio / w_units
            cx = (x0 + x1) / 2
            return cx - keep / 2, y0, cx + keep / 2, y1
        keep = used_w / canvas_ratio / h_units
        cy = (y0 + y1) / 2
        return x0, cy - keep / 2, x1, cy + keep / 2

    def to_canvas(self, x: float, y: float) -> tuple[float, float]:
        """Canvas position of a tablet position, clamped to the canvas.

        >>> TabletMapping(canvas_width=1, canvas_height=1, tablet_width=2, tablet_height=1).to_canvas(0.25, 0.5)
        (0.0, 0.5)
        >>> TabletMapping(rotation=180).to_canvas(0.0, 0.0)
        (1.0, 1.0)
        """
        rx, ry = _rotate_point(x, y, self.turn)
        x0, y0, x1, y1 = self._box
        cx = (rx - x0) / (x1 - x0)
        cy = (ry - y0) / (y1 - y0)
        return (0.0 if cx < 0.0 else 1.0 if cx > 1.0 else cx, 0.0 if cy < 0.0 else 1.0 if cy > 1.0 else cy)


def _rotate_point(x: float, y: float, turn: int) -> tuple[float, float]:
    """A tablet turned ``turn`` degrees clockwise: where its point (x, y) appears to the user."""
    if turn == 90:
        return 1.0 - y, x
    if turn == 180:
        return 1.0 - x, 1.0 - y
    if turn == 270:
        return y, 1.0 - x
    return x, y


def _rotate_box(box: tuple[float, float, float, float], turn: int) -> tuple[float, float, float, float]:
    (ax, ay), (bx, by) = _rotate_point(box[0], box[1], turn), _rotate_point(box[2], box[3], turn)
    return min(ax, bx), min(ay, by), max(ax, bx), max(ay, by)


_KEYS = ("canvas_width", "canvas_height", "tablet_width", "tablet_height", "area", "rotation", "left_handed",
         "keep_aspect", "display_tablet")


def mapping_to_header(mapping: TabletMapping) -> dict[str, Any]:
    """The mapping as the journal header's ``mapping`` object."""
    out = {key: getattr(mapping, key) for key in _KEYS}
    out["area"] = list(mapping.area)
    return out


def mapping_from_header(data: Any) -> TabletMapping:
    """Rebuild a mapping from a journal header; ValueError naming the bad key."""
    if not isinstance(data, dict):
        raise ValueError(f"mapping: expected an object, got {data!r}")
    unknown = set(data) - set(_KEYS)
    if unknown:
        raise ValueError(f"mapping: unknown key {sorted(unknown)[0]!r}")
    kwargs = dict(data)
    if "area" in kwargs:
        area = kwargs["area"]
        if not (isinstance(area, list | tuple) and len(area) == 4):
            raise ValueError(f"mapping: key 'area' must be 4 numbers, got {area!r}")
        kwargs["area"] = tuple(float(v) for v in area)
    for key in ("left_handed", "keep_aspect", "display_tablet"):
        if key in kwargs and not isinstance(kwargs[key], bool):
            raise ValueError(f"mapping: key {key!r} must be true or false, got {kwargs[key]!r}")
    return TabletMapping(**kwargs)
