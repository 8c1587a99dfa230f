"""The TUI's settings file (``$XDG_CONFIG_HOME/physink/config.json``): the tablet-to-canvas mapping (and which
monitor a pen display is), the tip thresholds and the theme, read, checked and written atomically; no Textual,
and nothing applied here.

A new session's journal header carries the mapping and tip thresholds (`Config.header`), so a replay decodes the
pen exactly as the session did; changed settings therefore apply from the next session, the theme at once.
"""

from __future__ import annotations

import json
import os
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from physink_tui.errors import PhysinkError
from physink_tui.formats import json_checks as checks
from physink_tui.formats.atomic_write import write_text_atomic
from physink_tui.formats.journal.entries import JournalHeader
from physink_tui.formats.json_checks import Place
from physink_tui.input.pen.mapping import TabletMapping, mapping_to_header
from physink_tui.input.pen.state import TipThresholds
from physink_tui.tui import storage

THEMES = ("dark", "light")
DEFAULT_CANVAS = (1600.0, 1000.0)


@dataclass(frozen=True, slots=True)
class Config:
    """The settings.

    Attributes:
        theme: the scene's ``dark`` or ``light`` theme.
        area: ``(x0, y0, x1, y1)``, the part of the tablet's active area used, fractions 0..1 (x0 < x1, y0 < y1).
        rotation: degrees clockwise the tablet is turned: 0, 90, 180 or 270.
        left_handed: the tablet turned round for the left hand.
        keep_aspect: crop the used area to the canvas's proportions (so circles stay round).
        display_tablet: a pen display: its area covers the canvas one to one.
        display: which monitor the pen display is (its X output name, e.g. ``DP-1``), "" when not said; the
            settings screen fits ``area`` to where the canvas is drawn on it (`physink_tui.tui.displays`).
        tip_down, tip_up: tip contact begins above ``tip_down`` and ends below ``tip_up`` (normalised pressure,
            0 <= up < down <= 1).
    """

    theme: str = "dark"
    area: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)
    rotation: int = 0
    left_handed: bool = False
    keep_aspect: bool = True
    display_tablet: bool = False
    display: str = ""
    tip_down: float = 0.05
    tip_up: float = 0.01

    def check(self) -> Config:
        """This config, or `PhysinkError` naming the first bad setting."""
        if self.theme not in THEMES:
            raise PhysinkError(f"theme: expected one of {', '.join(THEMES)}, got {self.theme!r}")
        if not isinstance(self.display, str) or self.display != self.display.strip():
            raise PhysinkError(f"display: expected a monitor's name (e.g. \"DP-1\") or \"\", got {self.display!r}")
        try:
            self.mapping()
        except (ValueError, TypeError) as exc:
            raise PhysinkError(f"mapping: {exc}") from None
        try:
            TipThresholds(self.tip_down, self.tip_up)
        except (ValueError, TypeError) as exc:
            raise PhysinkError(str(exc)) from None
        return self

    def mapping(self, canvas: tuple[float, float] = DEFAULT_CANVAS) -> TabletMapping:
        return TabletMapping(canvas_width=canvas[0], canvas_height=canvas[1], area=self.area,
                             rotation=self.rotation, left_handed=self.left_handed, keep_aspect=self.keep_aspect,
                             display_tablet=self.display_tablet)

    def header(self, canvas: tuple[float, float] = DEFAULT_CANVAS) -> JournalHeader:
        """The journal header of a new session with these settings (the tablet's size is learnt from it)."""
        mapping = mapping_to_header(self.mapping(canvas))
        for key in ("tablet_width", "tablet_height"):  # unknown until a tablet is read: the canvas's proportions
            mapping.pop(key, None)
        return JournalHeader(canvas[0], canvas[1], (), mapping, self.tip_down, self.tip_up)


def config_path() -> Path:
    return storage.config_home() / "physink" / "config.json"


def load_config(path: str | os.PathLike[str] | None = None) -> Config:
    """The settings in ``path`` (default `config_path`); the defaults when the file does not exist.

    Raises:
        PhysinkError: the file cannot be read, is not JSON, or has a bad setting (named).
    """
    target = Path(path) if path is not None else config_path()
    try:
        text = target.read_text(encoding="utf-8")
    except FileNotFoundError:
        return Config()
    except (OSError, UnicodeDecodeError) as exc:
        raise PhysinkError(f"{target}: cannot read the settings: {exc}") from None
    try:
        data = json.loads(text)
    except ValueError as exc:
        raise PhysinkError(f"{target}: not JSON ({exc})") from None
    if not isinstance(data, dict):
        raise PhysinkError(f"{target}: expected a JSON object of settings, got {type(data).__name__}")
    known = Config.__dataclass_fields__
    unknown = sorted(set(data) - set(known))
    if unknown:
        raise PhysinkError(f"{target}: unknown setting {unknown[0]!r} (known: {', '.join(known)})")
    values = _checked(dict(data), Place(str(target), PhysinkError))
    try:
        return Config(**values).check()
    except PhysinkError as exc:
        raise PhysinkError(f"{target}: {exc}") from None


def _checked(values: dict[str, Any], where: Place) -> dict[str, Any]:
    """Each setting's type and range, named by its key (``area[2]: expected a number in [0, 1], got "x"``);
    how settings go together (x0 < x1...) is `Config.check`'s."""
    for key in ("left_handed", "keep_aspect", "display_tablet"):
        if key in values:
            checks.flag(where, key, values[key])
    if "theme" in values:
        checks.one_of(where, "theme", values["theme"], THEMES)
    if "display" in values:
        checks.text(where, "display", values["display"], 'a monitor\'s name (e.g. "DP-1") or ""')
    rotation = values.get("rotation", 0)
    if isinstance(rotation, bool | float) or rotation not in (0, 90, 180, 270):
        raise where.bad("rotation", "0, 90, 180 or 270", rotation)
    for key in ("tip_down", "tip_up"):
        if key in values:
            values[key] = checks.unit(where, key, values[key])
    if "area" in values:
        area = values["area"]
        if not (isinstance(area, list) and len(area) == 4):
            raise where.bad("area", "[x0, y0, x1, y1], four numbers in [0, 1]", area)
        values["area"] = tuple(checks.unit(where, f"area[{i}]", v) for i, v in enumerate(area))
    return values


def save_config(config: Config, path: str | os.PathLike[str] | None = None) -> Path:
    """Writes the settings atomically; returns the path."""
    target = Path(path) if path is not None else config_path()
    config.check()
    target.parent.mkdir(parents=True, exist_ok=True)
    data = asdict(config)
    data["area"] = list(config.area)
    try:
        write_text_atomic(target, json.dumps(data, indent=2) + "\n")
    except OSError as exc:
        raise PhysinkError(f"{target}: cannot write the settings: {exc}") from None
    return target
