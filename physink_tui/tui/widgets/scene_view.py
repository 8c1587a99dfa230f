"""The scene view: the renderer's frame of the latest `SessionView` in the terminal, and the mouse as a pen;
decides nothing (pen samples go out as messages for the screen to hand to the session).

The picture is one of `physink_tui.tui.graphics.KINDS`: ``halfblocks`` (every terminal: each cell two pixels,
`physink_tui.tui.halfblocks`), or the frame at the terminal's own pixel size sent with the Kitty graphics
protocol (shown through placeholder cells) or as Sixel (drawn over blank cells after each refresh), both written
through the app's driver so they stay in order with Textual's output (`physink_tui.render.kitty`, `.sixel`). The
renderer draws with the canvas's aspect kept. The left button draws, the right one erases; holding the button
still is a dwell (the session's gesture engine sees the time pass); positions go out in canvas fractions.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np
from rich.color import Color
from rich.segment import Segment
from rich.style import Style
from textual import events
from textual.message import Message
from textual.strip import Strip
from textual.widget import Widget

from physink_tui.errors import RenderError
from physink_tui.render import kitty, sixel
from physink_tui.render.frames import Demonstration, view_frame
from physink_tui.render.gif_palette import Palette
from physink_tui.render.limits import MIN_SIDE
from physink_tui.render.renderer import Renderer
from physink_tui.session.view import SessionView
from physink_tui.tui.graphics import DEFAULT_CELL, KINDS
from physink_tui.tui.halfblocks import HalfBlocks

PRESSURE = 0.6
"""The pressure a mouse button stands for."""
KITTY_IMAGE = {"truecolor": 0x50494E, "256": 201}
"""The Kitty image id the scene view replaces frame after frame, by the colours Textual writes: placeholder cells
name it by their foreground colour, 24-bit on a true-colour terminal, the 8-bit palette index otherwise (Textual
turns a colour of the other kind into its own, which would name another image)."""
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

    def __init__(self, canvas: tuple[float, float], theme: str = "dark", graphics: str = "halfblocks",
                 cell: tuple[int, int] = DEFAULT_CELL, **kwargs) -> None:
        super().__init__(**kwargs)
        if graphics not in KINDS:
            raise ValueError(f"graphics {graphics!r}: expected one of {', '.join(KINDS)}")
        self.canvas = (float(canvas[0]), float(canvas[1]))
        self.theme_name = theme
        self.graphics = graphics
        # pixels the renderer draws across and down each cell, and the factor averaged down to what is shown
        self._scale = (SUPERSAMPLE, 2 * SUPERSAMPLE, SUPERSAMPLE) if graphics == "halfblocks" else (*cell, 1)
        self._image_id = 0  # the Kitty image, chosen by the app's colours at the first frame (`KITTY_IMAGE`)
        self._palette: Palette | None = None  # Sixel's, made from the first frame of a theme
        self.sent: list[str] = []
        """The escapes of the last frame written to the terminal (Kitty, Sixel; tests read it)."""
        self.view: SessionView | None = None
        self._renderer: Renderer | None = None
        self._blocks = HalfBlocks()
        self._strips: list[Strip] = []
        self._pressed: int | None = None  # the mouse button held over the scene, or None
        self._last: tuple[float, float] | None = None  # where the last pen sample went out (canvas fractions)
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
        width, height = columns * self._scale[0], rows * self._scale[1]
        self._palette = None
        if width >= MIN_SIDE and height >= MIN_SIDE:
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
        factor = self._scale[2]
        if factor > 1:
            h, w = pixels.shape[0] // factor, pixels.shape[1] // factor
            pixels = pixels.reshape(h, factor, w, factor, 4).mean(axis=(1, 3)).astype(np.uint8)
        if self.graphics == "halfblocks":
            self._strips = self._blocks.strips(pixels)
            changed = True
        else:
            changed = self._picture(pixels)
        self.frames_drawn += 1
        self.draw_seconds.append(time.perf_counter() - start)
        del self.draw_seconds[:-1000]
        if changed:  # the graphics protocols' cells stay as they are: Textual has nothing to repaint
            self.refresh()

    def _picture(self, pixels: np.ndarray) -> bool:
        """Kitty: the frame replaces the image the placeholder cells show. Sixel: the frame drawn over blank
        cells (after Textual's refresh when they are new). Whether the cells changed (a new size)."""
        columns, rows = self.size.width, self.size.height
        changed = len(self._strips) != rows or not self._strips or self._strips[0].cell_length != columns
        if self.graphics == "kitty":
            truecolor = self.app.console.color_system == "truecolor"
            self._image_id = KITTY_IMAGE["truecolor" if truecolor else "256"]
            self.sent = [kitty.transmit(pixels, self._image_id, columns, rows)]
            self._write(self.sent[0])
            if changed:
                style = Style(color=Color.from_rgb(*kitty.id_colour(self._image_id)) if truecolor
                              else Color.from_ansi(self._image_id))
                self._strips = [Strip([Segment(text, style)], columns)
                                for text in kitty.placeholder_rows(columns, rows)]
            return changed
        self._palette = self._palette or Palette.from_frame(pixels)
        self.sent = [sixel.encode(pixels, self._palette)]
        if changed:
            self._strips = [Strip.blank(columns)] * rows
        self.repaint_picture()
        return changed

    def repaint_picture(self) -> None:
        """Sixel: draw the last frame again once Textual has refreshed (it paints blank cells over it when it
        repaints the screen, e.g. when a modal closes)."""
        if self.graphics == "sixel" and self.sent:
            self.call_after_refresh(self._draw_sixel, self.sent[0])

    def painted(self, region: tuple[int, int, int, int] | None,
                spans: Sequence[tuple[int, int, int]] = ()) -> None:
        """Textual has just written cells to the terminal (``region`` x, y, width, height of a whole layout, or the
        ``spans`` (y, x1, x2) of a partial update): a Sixel picture those cells covered is drawn again at once, in
        order after them (a full repaint, e.g. when the tree first fills, writes blank cells over it)."""
        if self.graphics != "sixel" or not self.sent or not self.screen.is_active:
            return
        box = self.content_region
        if region is not None:
            x, y, width, height = region
            hit = x < box.right and box.x < x + width and y < box.bottom and box.y < y + height
        else:
            hit = any(box.y <= row < box.bottom and x1 < box.right and box.x < x2 for row, x1, x2 in spans)
        if hit:
            self._draw_sixel(self.sent[0])

    def _draw_sixel(self, data: str) -> None:
        if not self.screen.is_active or data is not self.sent[0]:
            return  # a modal covers the scene, or a newer frame follows
        x, y = self.content_region.x, self.content_region.y
        self._write(f"\x1b7\x1b[{y + 1};{x + 1}H{data}\x1b8")  # save the cursor, draw at the view, restore

    def _write(self, data: str) -> None:
        """Straight to the terminal through Textual's driver (its writer thread keeps it in order with the
        screen's updates); nothing in headless tests."""
        driver = self.app._driver  # Textual has no public way to send escapes of one's own
        if driver is not None and not self.app.is_headless:
            driver.write(data)

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
        return (x * self._scale[0] - left) / width, (y * self._scale[1] - top) / height

    def canvas_cells(self) -> tuple[tuple[int, int], tuple[float, float, float, float]]:
        """The terminal's (columns, rows) and where the canvas is drawn in it: (left, top, width, height) in cells
        (a pen display's area is fitted to it, `physink_tui.tui.displays`)."""
        region = self.content_region
        box = self._renderer.box if self._renderer is not None else (0.0, 0.0, 0.0, 0.0)
        across, down, _ = self._scale
        screen = self.app.size
        return ((screen.width, screen.height),
                (region.x + box[0] / across, region.y + box[1] / down, box[2] / across, box[3] / down))

    @staticmethod
    def _point(event: events.MouseEvent) -> tuple[float, float]:
        x, y = event.pointer_x, event.pointer_y
        if x == int(x) and y == int(y):  # a cell, not a pixel: its centre
            x, y = x + 0.5, y + 0.5
        return x, y

    def _post(self, event: events.MouseEvent, tip: bool, in_range: bool = True) -> None:
        where = self.to_canvas(*self._point(event))
        if where is not None:
            self._last = where
            self.post_message(self.Pen(where[0], where[1], tip, self._pressed == 3, in_range))

    def lift(self) -> None:
        """End a drag under way where the mouse last was (the app quitting, or asking to): the pen goes up and out of
        range as a mouse-up would take it; nothing when no button is held."""
        if self._pressed is None:
            return
        if self._last is not None:
            x, y = self._last
            self.post_message(self.Pen(x, y, False, self._pressed == 3))
            self.post_message(self.Pen(x, y, False, self._pressed == 3, False))
        self._pressed = None
        self.release_mouse()

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
