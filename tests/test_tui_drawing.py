"""Drawing with the mouse in the TUI (through Pilot) reaches the session as a pen: a box, a circle and an X."""

from __future__ import annotations

import asyncio

from physink_tui.scene.components import BACKGROUND, Body, Joint
from tests.tui_helpers import SIZE, box_points, cells_of, circle_points, draw, tui_app, until, x_cells


def test_a_box_a_circle_and_an_x_drawn_with_the_mouse_become_a_welded_box_and_a_circle(tmp_path) -> None:
    asyncio.run(draw_a_welded_box_and_a_circle(tmp_path))


async def draw_a_welded_box_and_a_circle(tmp_path) -> None:
    app = tui_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await until(pilot, lambda v: True)
        await draw(pilot, [cells_of(app, box_points(0.15, 0.45, 0.45, 0.7))], lambda v: len(v.scene.components) == 1)
        await draw(pilot, [cells_of(app, circle_points(0.7, 0.35, 110))], lambda v: len(v.scene.components) == 2)
        view = await draw(pilot, x_cells(app, 0.3, 0.57),
                          lambda v: any(isinstance(c, Joint) for c in v.scene.components.values()))
        bodies = [c for c in view.scene.components.values() if isinstance(c, Body)]
        joints = [c for c in view.scene.components.values() if isinstance(c, Joint)]
        assert sorted(b.shape for b in bodies) == ["box", "circle"], [m.text for m in view.messages]
        box = next(b for b in bodies if b.shape == "box")
        assert [(j.kind, j.a, j.b) for j in joints] == [("weld", box.id, BACKGROUND)]
        assert view.scene.is_fixed(box.id) and not view.scene.is_fixed(next(b.id for b in bodies if b is not box))
