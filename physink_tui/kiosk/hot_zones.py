"""Hot zones: rectangles of the tablet's surface that are buttons, the drawing area left beside them, and what the
tablet's pad buttons (ExpressKeys) do; reads a zones file, never a device.

A kiosk has no keyboard. Tapping the pen in a hot zone triggers its action instead of drawing: ``mode`` (sketch to
demo and back), ``sketch``, ``demo``, ``undo``, ``redo``, ``clear``, ``play``, ``stop``, or ``end`` (the session
is over: it is saved and exported). The default is a strip along the top edge of the tablet, 8 % of its height,
cut in four: sketch/demo, undo, redo, end session; the canvas is mapped onto the rest of the tablet (`area`), so
the strip never draws. A tablet with pad buttons has them too: by default button 1 is sketch/demo, 2 undo, 3 redo,
4 end session (`DEFAULT_PAD`).

A zones file (``--hot-zones FILE``) is JSON::

    {"area": [0.0, 0.1, 1.0, 1.0],
     "zones": [{"action": "mode", "x0": 0.0, "y0": 0.0, "x1": 0.5, "y1": 0.1},
               {"action": "end", "x0": 0.5, "y0": 0.0, "x1": 1.0, "y1": 0.1}],
     "pad": {"1": "mode", "2": "end"}}

with positions in 0..1 of the tablet's active area (x to the right, y down, as the tablet reports them, before any
rotation), ``area`` the part of the tablet the canvas is mapped onto (default: the whole tablet), ``pad`` the action
of each pad button by number (default `DEFAULT_PAD`; ``{}`` for none).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

from physink_tui.errors import PhysinkError

ACTIONS = ("mode", "sketch", "demo", "undo", "redo", "clear", "play", "stop", "end")
"""What a hot zone can do (see the module docstring)."""
DEFAULT_PAD = ((1, "mode"), (2, "undo"), (3, "redo"), (4, "end"))
"""What the first pad buttons do, when the tablet has any."""
STRIP = 0.08
"""Height of the default strip of zones along the top edge, as a fraction of the tablet's height."""


class HotZoneError(PhysinkError):
    """A zones file that cannot be used (names the file and what is wrong)."""


@dataclass(frozen=True, slots=True)
class HotZone:
    """One button on the tablet's surface: ``action`` when the pen taps inside ``(x0, y0)-(x1, y1)``."""

    action: str
    x0: float
    y0: float
    x1: float
    y1: float

    def contains(self, x: float, y: float) -> bool:
        return self.x0 <= x < self.x1 and self.y0 <= y < self.y1


@dataclass(frozen=True, slots=True)
class HotZones:
    """The zones, the drawing area beside them (``(x0, y0, x1, y1)`` in 0..1 of the tablet) and the pad buttons'
    actions (``(button number, action)`` pairs)."""

    zones: tuple[HotZone, ...]
    area: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)
    pad: tuple[tuple[int, str], ...] = DEFAULT_PAD

    def pad_action(self, button: int) -> str | None:
        """What pad button ``button`` does, or None."""
        return dict(self.pad).get(button)

    def at(self, x: float, y: float) -> HotZone | None:
        """The zone under the tablet position ``(x, y)``, or None (the first listed wins where zones overlap)."""
        return next((zone for zone in self.zones if zone.contains(x, y)), None)


def default_zones() -> HotZones:
    """A strip of `STRIP` along the top edge: sketch/demo, undo, redo, end session; the canvas below it."""
    actions = ("mode", "undo", "redo", "end")
    width = 1.0 / len(actions)
    zones = tuple(HotZone(a, i * width, 0.0, (i + 1) * width, STRIP) for i, a in enumerate(actions))
    return HotZones(zones, (0.0, STRIP, 1.0, 1.0))


def _fraction(value: object, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) \
            or not 0.0 <= value <= 1.0:
        raise ValueError(f"{where} is {value!r}; expected a number from 0 to 1")
    return float(value)


def _rect(values: list[object], where: str) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = (_fraction(v, f"{where}[{i}]") for i, v in enumerate(values))
    if not (x0 < x1 and y0 < y1):
        raise ValueError(f"{where} is {[x0, y0, x1, y1]!r}; expected x0 < x1 and y0 < y1")
    return x0, y0, x1, y1


def parse_zones(text: str, source: str) -> HotZones:
    """The hot zones of a zones file's ``text`` (``source`` names it in errors).

    Raises:
        HotZoneError: not JSON, or a zone or the area out of shape (the file and the value named).
    """
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise HotZoneError(f"{source}: line {exc.lineno}: not JSON ({exc.msg})") from None
    try:
        if not isinstance(data, dict) or not isinstance(data.get("zones"), list) or not data["zones"]:
            raise ValueError('expected an object with a non-empty list "zones"')
        zones = []
        for i, item in enumerate(data["zones"]):
            where = f"zones[{i}]"
            if not isinstance(item, dict):
                raise ValueError(f"{where} is {item!r}; expected an object")
            action = item.get("action")
            if action not in ACTIONS:
                raise ValueError(f"{where}.action is {action!r}; expected one of {', '.join(ACTIONS)}")
            rect = _rect([item.get(k) for k in ("x0", "y0", "x1", "y1")], f"{where} (x0, y0, x1, y1)")
            zones.append(HotZone(action, *rect))
        area = data.get("area", [0.0, 0.0, 1.0, 1.0])
        if not isinstance(area, list) or len(area) != 4:
            raise ValueError(f"area is {area!r}; expected [x0, y0, x1, y1]")
        pad = data.get("pad", {str(n): a for n, a in DEFAULT_PAD})
        if not isinstance(pad, dict):
            raise ValueError(f'pad is {pad!r}; expected an object such as {{"1": "mode"}}')
        buttons = []
        for key, action in pad.items():
            if not (isinstance(key, str) and key.isdigit() and 1 <= int(key) <= 64):
                raise ValueError(f"pad key {key!r} is not a button number from 1 to 64")
            if action not in ACTIONS:
                raise ValueError(f"pad[{key!r}] is {action!r}; expected one of {', '.join(ACTIONS)}")
            buttons.append((int(key), action))
        return HotZones(tuple(zones), _rect(area, "area"), tuple(sorted(buttons)))
    except ValueError as exc:
        raise HotZoneError(f"{source}: {exc}") from None


def read_zones(path: str | None) -> HotZones:
    """The zones file at ``path``, or `default_zones` for None.

    Raises:
        HotZoneError: the file cannot be read or is not a zones file.
    """
    if path is None:
        return default_zones()
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise HotZoneError(f"{path}: cannot read the hot zones file: {exc}") from None
    return parse_zones(text, path)
