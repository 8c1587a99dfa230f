"""A picture of the moment the TUI shows: the latest `SessionView` drawn by the renderer at a picture's size (the
narration and the time bar below the canvas in demo mode, a SIMULATE result's paths in red) and written as a PNG;
no Textual, no decisions.
"""

from __future__ import annotations

import os
from dataclasses import replace

from physink_tui.render.frames import Demonstration, view_frame
from physink_tui.render.images import write_png
from physink_tui.render.renderer import Renderer
from physink_tui.session.view import SessionView

PICTURE_SIZE = (1280, 800)
"""Pixels of a picture exported from the TUI (what `physink export --still` draws by default)."""


def write_picture(path: str | os.PathLike[str], view: SessionView, canvas: tuple[float, float], theme: str,
                  size: tuple[int, int] = PICTURE_SIZE) -> None:
    """Draw ``view`` as the scene view shows it, at ``size`` in ``theme``, to the PNG at ``path`` (atomically).

    Raises:
        RenderError: the picture cannot be drawn or written.
    """
    content = view_frame(view, canvas)
    search = view.search
    if search is not None and search.timeline.events:
        simulated = Demonstration(view.scene, search.timeline, canvas)
        content = replace(content, trails=(*content.trails, *simulated.trails_at(simulated.duration, "simulation")))
    renderer = Renderer(size[0], size[1], canvas, theme)
    write_png(path, renderer.render(content))
