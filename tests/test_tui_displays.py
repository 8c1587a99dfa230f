"""Which display a pen display covers: X monitors and the terminal window read from xrandr's and xwininfo's
output, the canvas's rectangle on the monitor as the tablet area, and the settings screen fitting it."""

from __future__ import annotations

import asyncio

import pytest

from physink_tui.errors import PhysinkError
from physink_tui.tui import displays
from physink_tui.tui.config import Config, load_config, save_config
from physink_tui.tui.displays import Monitor, Rect
from physink_tui.tui.widgets.scene_view import SceneView
from tests.tui_helpers import SIZE, click, open_settings, tui_app, until_app

XRANDR = """Monitors: 2
 0: +*eDP-1 1920/344x1080/193+0+0  eDP-1
 1: +DP-2 2560/597x1440/336+1920+0  DP-2
"""
XWININFO = """
xwininfo: Window id: 0x3a00003 "physink"

  Absolute upper-left X:  2020
  Absolute upper-left Y:  140
  Relative upper-left X:  0
  Relative upper-left Y:  0
  Width: 1200
  Height: 800
"""


def test_monitors_and_the_window_are_read_from_the_x_tools_output() -> None:
    assert displays.parse_monitors(XRANDR) == [Monitor("eDP-1", Rect(0, 0, 1920, 1080)),
                                               Monitor("DP-2", Rect(1920, 0, 2560, 1440))]
    assert displays.parse_window(XWININFO) == Rect(2020, 140, 1200, 800)
    with pytest.raises(PhysinkError, match="no height"):
        displays.parse_window("Absolute upper-left X: 1\nAbsolute upper-left Y: 2\nWidth: 3\n")


def test_the_area_is_the_canvas_rectangle_as_fractions_of_its_monitor() -> None:
    monitor = Monitor("DP-2", Rect(1920, 0, 2560, 1440))
    canvas = displays.canvas_rect(Rect(2020, 140, 1200, 800), (120, 40), (10, 2, 60, 30))  # 10x20 px cells
    assert canvas == Rect(2120, 180, 600, 600)
    assert displays.area_on(monitor, canvas) == (0.0781, 0.125, 0.3125, 0.5417)
    with pytest.raises(PhysinkError, match="not wholly on monitor eDP-1"):
        displays.area_on(Monitor("eDP-1", Rect(0, 0, 1920, 1080)), canvas)


def test_no_x_display_means_no_monitors_and_a_window_named_unknown(monkeypatch) -> None:
    monkeypatch.delenv("DISPLAY", raising=False)
    assert displays.list_monitors() == []
    with pytest.raises(PhysinkError, match="set the area by hand"):
        displays.terminal_window()


def test_the_display_setting_round_trips_and_a_bad_one_is_named(tmp_path) -> None:
    path = tmp_path / "config.json"
    save_config(Config(display="DP-2", display_tablet=True), path)
    assert load_config(path).display == "DP-2"
    path.write_text('{"display": " DP-2"}')
    with pytest.raises(PhysinkError, match="display: expected a monitor's name"):
        load_config(path)


def test_the_settings_screen_fits_the_area_to_the_canvas_on_the_chosen_monitor(tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(displays, "list_monitors", lambda: displays.parse_monitors(XRANDR))
    monkeypatch.setattr(displays, "terminal_window", lambda: Rect(1920, 0, 1200, 800))  # 10x20 px cells

    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            screen = await open_settings(pilot)
            error = screen.query_one("#settings-error")
            await click(pilot, "#fit-area")
            await until_app(pilot, lambda: "choose the monitor" in str(error.render()), "the monitor asked for")
            screen.query_one("#display").value = "DP-2"
            await click(pilot, "#fit-area")
            await until_app(pilot, lambda: "Area fitted" in str(error.render()), "the area fitted")
            (columns, rows), (left, top, width, height) = app.main.query_one(SceneView).canvas_cells()
            assert (columns, rows) == SIZE and width > 0 and height > 0
            expected = (left * 10 / 2560, top * 20 / 1440, (left + width) * 10 / 2560, (top + height) * 20 / 1440)
            area = tuple(float(screen.query_one(f"#area-{n}").value) for n in ("x0", "y0", "x1", "y1"))
            assert area == pytest.approx(expected, abs=1e-4)
            assert screen.query_one("#display-tablet").value
            await click(pilot, "#save")
            await until_app(pilot, lambda: app.screen is app.main and app.config.display == "DP-2",
                            "the settings saved and closed")
            assert app.config.display == "DP-2" and app.config.display_tablet
            assert app.config.area == pytest.approx(expected, abs=1e-4)

    asyncio.run(go())
