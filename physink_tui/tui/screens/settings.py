"""The settings screen: the tablet-to-canvas mapping (with which monitor a pen display is, and its area fitted to
where the canvas is drawn on it), tip thresholds and theme as a form; returns the new `Config` (checked) for the
app to save and apply, or None when cancelled.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Button, Checkbox, Input, Label, Select, Static

from physink_tui.errors import PhysinkError
from physink_tui.tui import displays
from physink_tui.tui.config import THEMES, Config

NOT_SET = "(not set)"


class SettingsScreen(ModalScreen[Config | None]):
    """Edits a `Config`."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "cancel")]

    def __init__(self, config: Config,
                 canvas_cells: Callable[[], tuple[tuple[int, int], tuple[float, float, float, float]]] | None = None,
                 ) -> None:
        """``canvas_cells``: the terminal's (columns, rows) and the canvas's (left, top, width, height) in its cells,
        for fitting a pen display's area (None: not offered)."""
        super().__init__()
        self.config = config
        self.canvas_cells = canvas_cells
        self.monitors = displays.list_monitors()

    def compose(self) -> ComposeResult:
        c = self.config
        with Vertical(id="dialog", classes="settings"):
            yield Label("Settings", classes="title")
            with VerticalScroll():
                yield Static("Tablet area used (fractions of its active area: left, top, right, bottom)")
                with Horizontal(classes="row"):
                    for name, value in zip(("x0", "y0", "x1", "y1"), c.area, strict=True):
                        yield Input(f"{value:g}", id=f"area-{name}", classes="number")
                with Horizontal(classes="row"):
                    yield Label("Rotation (degrees clockwise) ")
                    yield Select([(str(r), r) for r in (0, 90, 180, 270)], value=c.rotation, allow_blank=False,
                                 id="rotation")
                yield Checkbox("Keep the canvas's proportions (circles stay round)", c.keep_aspect, id="keep-aspect")
                yield Checkbox("Left-handed (the tablet turned round)", c.left_handed, id="left-handed")
                yield Checkbox("Pen display (the tablet covers the canvas one to one)", c.display_tablet,
                               id="display-tablet")
                names = [m.name for m in self.monitors]
                if c.display and c.display not in names:
                    names.append(c.display)
                with Horizontal(classes="row"):
                    yield Label("The pen display is monitor ")
                    yield Select([(NOT_SET, ""), *((n, n) for n in names)], value=c.display, allow_blank=False,
                                 id="display")
                    yield Button("Fit the area to the canvas on it", id="fit-area", compact=True,
                                 disabled=self.canvas_cells is None)
                with Horizontal(classes="row"):
                    yield Label("Tip down above ")
                    yield Input(f"{c.tip_down:g}", id="tip-down", classes="number")
                    yield Label(" up below ")
                    yield Input(f"{c.tip_up:g}", id="tip-up", classes="number")
                with Horizontal(classes="row"):
                    yield Label("Theme ")
                    yield Select([(t, t) for t in THEMES], value=c.theme, allow_blank=False, id="theme")
                yield Static("The theme applies now; the mapping and tip thresholds from the next session (a "
                             "session's journal keeps the ones it started with).", classes="hint")
                yield Static("", id="settings-error")
            with Horizontal(classes="buttons"):
                yield Button("Save", id="save", variant="primary")
                yield Button("Cancel", id="cancel")

    def read(self) -> Config:
        """The form as a `Config`; `PhysinkError` naming a bad field."""
        def number(widget_id: str) -> float:
            text = self.query_one(f"#{widget_id}", Input).value.strip()
            try:
                return float(text)
            except ValueError:
                raise PhysinkError(f"{widget_id}: expected a number, got {text!r}") from None

        x0, y0, x1, y1 = (number(f"area-{n}") for n in ("x0", "y0", "x1", "y1"))
        rotation = self.query_one("#rotation", Select).value  # one of 0, 90, 180, 270 (never blank)
        return Config(
            theme=str(self.query_one("#theme", Select).value),
            area=(x0, y0, x1, y1),
            rotation=rotation if isinstance(rotation, int) else 0,
            left_handed=self.query_one("#left-handed", Checkbox).value,
            keep_aspect=self.query_one("#keep-aspect", Checkbox).value,
            display_tablet=self.query_one("#display-tablet", Checkbox).value,
            display=str(self.query_one("#display", Select).value),
            tip_down=number("tip-down"),
            tip_up=number("tip-up"),
        ).check()

    def on_button_pressed(self, event: Button.Pressed) -> None:
        if event.button.id == "cancel":
            self.dismiss(None)
            return
        if event.button.id == "fit-area":
            self.fit_area()
            return
        try:
            config = self.read()
        except PhysinkError as exc:
            self.query_one("#settings-error", Static).update(f"[b]Not saved:[/b] {exc}")
            return
        self.dismiss(config)

    def fit_area(self) -> None:
        """The area: the canvas's rectangle on the chosen monitor (the terminal window's place from X); the pen
        display box ticked. What stands in the way is said in the form."""
        error = self.query_one("#settings-error", Static)
        name = str(self.query_one("#display", Select).value)
        monitor = next((m for m in self.monitors if m.name == name), None)
        try:
            if monitor is None:
                raise PhysinkError("choose the monitor the pen display is (xrandr lists "
                                   f"{', '.join(m.name for m in self.monitors) or 'none'})")
            if self.query_one("#rotation", Select).value != 0:
                raise PhysinkError("a turned pen display's area is set by hand (rotation is not 0)")
            assert self.canvas_cells is not None  # the button is disabled without it
            cells, canvas = self.canvas_cells()
            area = displays.area_on(monitor, displays.canvas_rect(displays.terminal_window(), cells, canvas))
        except PhysinkError as exc:
            error.update(f"[b]Area not fitted:[/b] {exc}")
            return
        for name_, value in zip(("x0", "y0", "x1", "y1"), area, strict=True):
            self.query_one(f"#area-{name_}", Input).value = f"{value:g}"
        self.query_one("#display-tablet", Checkbox).value = True
        error.update(f"Area fitted to the canvas on {monitor.name}: {', '.join(f'{v:g}' for v in area)}")

    def action_cancel(self) -> None:
        self.dismiss(None)
