"""The settings screen: the tablet-to-canvas mapping, tip thresholds and theme as a form; returns the new
`Config` (checked) for the app to save and apply, or None when cancelled.
"""

from __future__ import annotations

from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Button, Checkbox, Input, Label, Select, Static

from physink_tui.errors import PhysinkError
from physink_tui.tui.config import THEMES, Config


class SettingsScreen(ModalScreen[Config | None]):
    """Edits a `Config`."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "cancel")]

    def __init__(self, config: Config) -> None:
        super().__init__()
        self.config = config

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

        area = tuple(number(f"area-{n}") for n in ("x0", "y0", "x1", "y1"))
        return Config(
            theme=str(self.query_one("#theme", Select).value),
            area=area,  # type: ignore[arg-type]
            rotation=int(self.query_one("#rotation", Select).value),  # type: ignore[arg-type]
            left_handed=self.query_one("#left-handed", Checkbox).value,
            keep_aspect=self.query_one("#keep-aspect", Checkbox).value,
            display_tablet=self.query_one("#display-tablet", Checkbox).value,
            tip_down=number("tip-down"),
            tip_up=number("tip-up"),
        ).check()

    def on_button_pressed(self, event: Button.Pressed) -> None:
        if event.button.id == "cancel":
            self.dismiss(None)
            return
        try:
            config = self.read()
        except PhysinkError as exc:
            self.query_one("#settings-error", Static).update(f"[b]Not saved:[/b] {exc}")
            return
        self.dismiss(config)

    def action_cancel(self) -> None:
        self.dismiss(None)
