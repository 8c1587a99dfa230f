"""The scene view: the renderer's frame of the latest `SessionView` in half-block cells, and the mouse as a pen;
decides nothing (pen samples go out as messages for the screen to hand to the session).

Each cell is two pixels (`physink_tui.tui.halfblocks`); the renderer draws at that size with the canvas's aspect
kept (square pixels in a cell twice as tall as wide). The left button draws, the right one erases; holding the
button still is a dwell (the session's gesture engine sees the time pass); positions go out in canvas fractions.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np
from textual import events
from textual.message import Message
from textual.strip import Strip
from textual.widget import Widget

from physink_tui.errors import RenderError
from physink_tui.render.frames import Demonstration, view_frame
from physink_tui.render.renderer import MIN_SIZE, Renderer
from physink_tui.session.view import SessionView
from physink_tui.tui.halfblocks import HalfBlocks

PRESSURE = 0.6
"""The pressure a mouse button stands for."""
SUPERSAMPLE = 2
"""The renderer draws this many pixels across each half-block pixel (each way), averaged: thin lines and labels
(the renderer's smallest text is 9 pixels) stay in proportion at a terminal's few pixels."""


class SceneView(Widget, can_focus=True):
    """Shows the scene of the views it is given (`show`); posts `SceneView.Pen` for mouse input."""

    @dataclass
    class Pen(Message):
        """A mouse sample over the scene: canvas fractions (0..1, y down), button state."""

        x: float
        y: float
        tip: bool
        eraser: bool
        in_range: bool = True

    def __init__(self, canvas: tuple[float, float], theme: str = "dark", **kwargs) -> None:
        super().__init__(**kwargs)
        self.canvas = (float(canvas[0]), float(canvas[1]))
        self.theme_name = theme
        self.view: SessionView | None = None
        self._renderer: Renderer | None = None
        self._blocks = HalfBlocks()
        self._strips: list[Strip] = []
        self._pressed: int | None = None  # the mouse button held over the scene, or None
        self._overlay: tuple[object, Demonstration] | None = None
        self.highlight: frozenset[str] = frozenset()
        """Bodies outlined (the timeline event chosen last); forgotten when the scene changes."""
        self._highlight_of: object = None
        self.frames_drawn = 0
        """Frames drawn since the start (benchmarks, tests)."""
        self.draw_seconds: list[float] = []
        """Wall seconds each of the last frames took to draw and convert (benchmarks)."""

    # -- showing -------------------------------------------------------------------------------------------

    def show(self, view: SessionView) -> None:
        """Draw ``view`` (the latest snapshot); a view of the same revision as the one drawn changes nothing."""
        if self.view is not None and view.revision == self.view.revision and self._strips:
            self.view = view
            return
        self.view = view
        self._draw()

    def set_theme(self, theme: str) -> None:
        """Draw in ``theme`` (``dark`` or ``light``) from now on."""
        self.theme_name = theme
        self._renderer = None
        self._make_renderer(self.size.width, self.size.height)
        self._draw()

    def on_resize(self, event: events.Resize) -> None:
        self._make_renderer(event.size.width, event.size.height)
        self._draw()

    def _make_renderer(self, columns: int, rows: int) -> None:
        width, height = columns * SUPERSAMPLE, rows * 2 * SUPERSAMPLE
        if width >= MIN_SIZE and height >= MIN_SIZE:
            self._renderer = Renderer(width, height, self.canvas, self.theme_name, controls=False)
        else:
            self._renderer = None

    def _draw(self) -> None:
        renderer, view = self._renderer, self.view
        if renderer is None or view is None:
            self._strips = []
            self.refresh()
            return
        start = time.perf_counter()
        content = view_frame(view, self.canvas)
        trails = self._simulation_trails(view)
        if self.highlight and view.scene is not self._highlight_of:
            self.highlight = frozenset()
        contacts = tuple(replace(c, sides="") for c in content.contacts)  # words are the tree's and the narration's:
        content = replace(content, subtitle=None, trails=content.trails + trails, highlight=self.highlight,
                          contacts=contacts)  # at a terminal's few pixels they would hide the machine
        try:
            pixels = renderer.render(content)
        except RenderError:  # a project of another canvas: shown as text by the status bar
            return
        if SUPERSAMPLE > 1:
            h, w = pixels.shape[0] // SUPERSAMPLE, pixels.shape[1] // SUPERSAMPLE
            pixels = pixels.reshape(h, SUPERSAMPLE, w, SUPERSAMPLE, 4).mean(axis=(1, 3)).astype(np.uint8)
        self._strips = self._blocks.strips(pixels)
        self.frames_drawn += 1
        self.draw_seconds.append(time.perf_counter() - start)
        del self.draw_seconds[:-1000]
        self.refresh()

    def emphasise(self, components: tuple[str, ...]) -> None:
        """Outline these components while the timeline shown stays the same."""
        self.highlight = frozenset(components)
        self._highlight_of = self.view.scene if self.view is not None else None
        self._draw()

    def _simulation_trails(self, view: SessionView) -> tuple:
        """The red paths of the SIMULATE result shown (at its end)."""
        search = view.search
        if search is None or not search.timeline.events:
            return ()
        if self._overlay is None or self._overlay[0] is not search:
            self._overlay = (search, Demonstration(view.scene, search.timeline, self.canvas))
        demo = self._overlay[1]
        return demo.trails_at(demo.duration, "simulation")

    def render_line(self, y: int) -> Strip:
        if y < len(self._strips):
            return self._strips[y]
        return Strip.blank(self.size.width)

    # -- the mouse as a pen -------------------------------------------------------------------------------

    def to_canvas(self, x: float, y: float) -> tuple[float, float] | None:
        """Cell position (fractions allowed: a pixel-precise mouse) to canvas fractions, or None before a size."""
        renderer = self._renderer
        if renderer is None:
            return None
        left, top, width, height = renderer.box
        return (x * SUPERSAMPLE - left) / width, (y * 2 * SUPERSAMPLE - top) / height

    @staticmethod
    def _point(event: events.MouseEvent) -> tuple[float, float]:
        x, y = event.pointer_x, event.pointer_y
        if x == int(x) and y == int(y):  # a cell, not a pixel: its centre
            x, y = x + 0.5, y + 0.5
        return x, y

    def _post(self, event: events.MouseEvent, tip: bool, in_range: bool = True) -> None:
        where = self.to_canvas(*self._point(event))
        if where is not None:
            self.post_message(self.Pen(where[0], where[1], tip, self._pressed == 3, in_range))

    def on_mouse_down(self, event: events.MouseDown) -> None:
        if event.button not in (1, 3) or self._pressed is not None:
            return
        self._pressed = event.button
        self.capture_mouse()
        self._post(event, tip=False)
        self._post(event, tip=True)
        event.stop()

    def on_mouse_move(self, event: events.MouseMove) -> None:
        if self._pressed is not None:
            self._post(event, tip=True)
            event.stop()

    def on_mouse_up(self, event: events.MouseUp) -> None:
        if self._pressed is None:
            return
        self._post(event, tip=False)
        self._post(event, tip=False, in_range=False)
        self._pressed = None
        self.release_mouse()
        event.stop()
