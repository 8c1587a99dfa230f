"""The settings: a file in the XDG config folder (checked, written atomically) and a screen that edits it; the
mapping and tip thresholds go into the next session's journal header, the theme applies at once."""

from __future__ import annotations

import asyncio
import json

import pytest

from physink_tui.errors import PhysinkError
from physink_tui.tui.config import Config, config_path, load_config, save_config
from physink_tui.tui.widgets.scene_view import SceneView
from tests.tui_helpers import SIZE, click, open_settings, tui_app, until, until_app


def test_the_settings_file_round_trips_and_names_a_bad_setting(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    assert config_path() == tmp_path / "physink" / "config.json"
    assert load_config() == Config()
    config = Config(theme="light", area=(0.1, 0.0, 0.9, 1.0), rotation=90, left_handed=True, tip_down=0.1)
    save_config(config)
    assert load_config() == config
    path = config_path()
    for text, named in [('{"rotation": 45}', "rotation"), ('{"colour": 1}', "colour"), ("[1]", "object"),
                        ('{"tip_down": 0.01, "tip_up": 0.02}', "tip"), ('{"area": [0, 0, 1]}', "area"), ("{", "JSON")]:
        path.write_text(text)
        with pytest.raises(PhysinkError, match=named):
            load_config()


def test_the_header_of_a_new_session_carries_the_mapping_and_thresholds() -> None:
    header = Config(area=(0.0, 0.0, 0.5, 0.5), rotation=180, tip_down=0.2, tip_up=0.1).header()
    assert header.mapping["area"] == [0.0, 0.0, 0.5, 0.5] and header.mapping["rotation"] == 180
    assert (header.tip_down, header.tip_up) == (0.2, 0.1)


def test_the_settings_screen_saves_applies_the_theme_and_refuses_bad_values(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            screen = await open_settings(pilot)
            screen.query_one("#tip-down").value = "0.01"
            screen.query_one("#tip-up").value = "0.02"
            await click(pilot, "#save")
            await until_app(pilot, lambda: "tip" in str(screen.query_one("#settings-error").render()), "the refusal")
            assert app.screen is screen
            screen.query_one("#tip-down").value = "0.08"
            screen.query_one("#tip-up").value = "0.02"
            screen.query_one("#theme").value = "light"
            screen.query_one("#rotation").value = 270
            screen.query_one("#left-handed").value = True
            await click(pilot, "#save")
            await until_app(pilot, lambda: app.screen is app.main and app.config.rotation == 270,
                            "the settings saved and closed")
            assert app.main.query_one(SceneView).theme_name == "light"
            assert app.config.rotation == 270 and app.config.tip_down == 0.08
    asyncio.run(go())
    saved = json.loads((tmp_path / "config" / "config.json").read_text())
    assert saved["theme"] == "light" and saved["rotation"] == 270 and saved["left_handed"] is True

    async def again() -> None:  # the next session starts with them
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            header = app.live.header
            assert header.mapping["rotation"] == 270 and header.mapping["left_handed"] is True
            assert header.tip_down == 0.08 and app.main.query_one(SceneView).theme_name == "light"
    asyncio.run(again())
