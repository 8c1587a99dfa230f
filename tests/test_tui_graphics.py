"""The scene view with a terminal graphics protocol: each frame goes out as Kitty or Sixel escapes that decode to
the renderer's frame at the terminal's pixel size, the cells show the Kitty placeholders (or stay blank under
Sixel), and the mouse still draws where it points."""

from __future__ import annotations

import asyncio

import numpy as np
from terminal_graphics import kitty_image, sixel_image

from physink_tui.render import kitty
from physink_tui.tui.widgets.scene_view import SceneView
from tests.tui_helpers import SIZE, box_points, cells_of, draw, tui_app, until, until_app, until_shown

CELL = (6, 12)


def test_kitty_frames_are_sent_whole_and_shown_through_placeholders(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path, graphics="kitty", cell=CELL)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.mode == "sketch")
            scene = app.main.query_one(SceneView)
            await until_app(pilot, lambda: bool(scene.sent), "a frame sent")
            columns, rows = scene.size.width, scene.size.height
            keys, pixels = kitty_image(scene.sent[0])
            assert (keys["c"], keys["r"]) == (str(columns), str(rows))
            assert pixels.shape == (rows * CELL[1], columns * CELL[0], 4)
            line = scene.render_line(3)
            assert line.text == kitty.PLACEHOLDER + kitty.DIACRITICS[3] + kitty.DIACRITICS[0] + (
                kitty.PLACEHOLDER * (columns - 1))
            assert line.cell_length == columns
            drawn = await draw(pilot, [cells_of(app, box_points(0.3, 0.3, 0.6, 0.6))],
                               lambda v: len(v.scene.components) == 1)
            body = next(iter(drawn.scene.components.values()))
            assert 0.4 * 1600 < body.position[0] < 0.5 * 1600 and 0.4 * 1000 < body.position[1] < 0.5 * 1000
            await until_shown(pilot, lambda v: v.scene == drawn.scene)
            _, after = kitty_image(scene.sent[0])
            assert not np.array_equal(after, pixels)  # the box is in the picture sent
    asyncio.run(go())


def test_sixel_frames_decode_to_the_scene_and_the_cells_stay_blank(tmp_path) -> None:
    async def go() -> None:
        app = tui_app(tmp_path, graphics="sixel", cell=CELL)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.mode == "sketch")
            scene = app.main.query_one(SceneView)
            await until_app(pilot, lambda: bool(scene.sent), "a frame sent")
            pixels = sixel_image(scene.sent[0])
            assert pixels.shape == (scene.size.height * CELL[1], scene.size.width * CELL[0], 3)
            assert scene.render_line(5).text == " " * scene.size.width
    asyncio.run(go())
