"""Helpers for the TUI's Pilot tests: an app without a tablet journaling into a temporary folder, waiting for the
session, and drawing with the mouse in canvas fractions."""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from physink_tui.session.view import SessionView
from physink_tui.tui.app import PhysinkApp, TuiOptions, make_app
from physink_tui.tui.screens.settings import SettingsScreen
from physink_tui.tui.widgets.scene_view import SceneView

SIZE = (120, 40)


def tui_app(folder: Path, **options) -> PhysinkApp:
    """An app journaling into ``folder``/sessions, looking for no tablet, offering no recovery unless asked."""
    values = {"tablet": False, "journal_dir": folder / "sessions", "recover": False,
              "config_path": folder / "config" / "config.json", **options}
    return make_app(TuiOptions(**values))


def latest(app: PhysinkApp) -> SessionView | None:
    return app.live.runner.latest_view() if app.live is not None else None


async def until(pilot, predicate: Callable[[SessionView], bool], timeout: float = 10.0) -> SessionView:
    """Wait (letting the app run) until the latest view satisfies ``predicate``; fail after ``timeout`` s."""
    app = pilot.app
    deadline = time.monotonic() + timeout
    while True:
        view = latest(app)
        if view is not None and predicate(view):
            return view
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out; last view: mode={getattr(view, 'mode', None)} "
                                 f"components={list(view.scene.components) if view else None} "
                                 f"messages={[m.text for m in view.messages] if view else None}")
        await pilot.pause(0.05)


async def wait_for(pilot, condition: Callable[[], bool], what: str, guard: float = 60.0) -> None:
    """Let the app run until ``condition()`` holds; fail saying ``what`` after ``guard`` s (a hang, not a timing)."""
    deadline = time.monotonic() + guard
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"never saw {what}")
        await pilot.pause(0.05)


async def screen_is(pilot, kind: type, guard: float = 60.0):
    """Wait until the app's screen is a ``kind`` (a dialog opening); fail after ``guard`` s (a hang)."""
    deadline = time.monotonic() + guard
    while not isinstance(pilot.app.screen, kind):
        if time.monotonic() > deadline:
            raise AssertionError(f"the screen is {pilot.app.screen!r}, not a {kind.__name__}")
        await pilot.pause(0.05)
    return pilot.app.screen


async def open_settings(pilot) -> SettingsScreen:
    """Press F2 once the session is up and return the settings screen it opens."""
    await until(pilot, lambda v: True)
    await pilot.press("f2")
    await pilot.pause(0.2)
    screen = pilot.app.screen
    assert isinstance(screen, SettingsScreen), screen
    return screen


def cell(app: PhysinkApp, x: float, y: float) -> tuple[int, int]:
    """The scene view's cell over canvas fraction (x, y)."""
    scene = app.main.query_one(SceneView)
    left, top, width, height = scene._renderer.box
    across, down, _ = scene._scale  # renderer pixels a cell
    return (int((left + x * width) / across), int((top + y * height) / down))


async def drag(pilot, points: Sequence[tuple[float, float]], button: int = 1) -> None:
    """Press at the first canvas point, move through the others (each cell once), release at the last."""
    await drag_cells(pilot, cells_of(pilot.app, points), button)


async def drag_cells(pilot, cells: Sequence[tuple[int, int]], button: int = 1) -> None:
    """Press on the first cell of the scene view, move through the others, release on the last."""
    await pilot.mouse_down(SceneView, offset=cells[0], button=button)
    for c in cells[1:]:
        await pilot.hover(SceneView, offset=c)
    await pilot.mouse_up(SceneView, offset=cells[-1])


async def draw(pilot, strokes: Sequence[Sequence[tuple[int, int]]],
               done: Callable[[SessionView], bool], attempts: int = 3) -> SessionView:
    """Drag the mouse through each stroke's cells until ``done(view)``; up to ``attempts`` times.

    Pilot's events arrive in real time, and a loaded machine can stall the app's loop between a button press and
    the first move for longer than the 400 ms that make a press a dwell: the session then (rightly) takes the
    stroke as a drag, which draws nothing. A failed attempt is undone until the scene is what it was, then drawn
    again; a drawing that never works still fails.
    """
    before = latest(pilot.app).scene
    for attempt in range(attempts):
        for cells in strokes:
            await drag_cells(pilot, cells)
        try:
            return await until(pilot, done, timeout=5.0)
        except AssertionError:
            if attempt == attempts - 1:
                raise
        for _ in range(4):
            if latest(pilot.app).scene == before:
                break
            await pilot.press("u")
            await pilot.pause(0.3)
    raise AssertionError("unreachable")


def cells_of(app: PhysinkApp, points: Sequence[tuple[float, float]]) -> list[tuple[int, int]]:
    """Canvas points as the scene view's cells, each cell once in a row."""
    cells: list[tuple[int, int]] = []
    for x, y in points:
        c = cell(app, x, y)
        if not cells or cells[-1] != c:
            cells.append(c)
    return cells


def x_cells(app: PhysinkApp, x: float, y: float, steps: int = 3) -> tuple[list[tuple[int, int]], ...]:
    """The two arms of an X round canvas fraction (x, y) as cells, each step one column and one row: a mouse
    moves a whole cell at a time, so an arm is a clean diagonal only when each move changes both."""
    c, r = cell(app, x, y)
    c, r = c - steps // 2, r - steps // 2
    return ([(c + k, r + k) for k in range(steps + 1)], [(c + steps - k, r + k) for k in range(steps + 1)])


def box_points(x0: float, y0: float, x1: float, y1: float, n: int = 12) -> list[tuple[float, float]]:
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    out = []
    for (ax, ay), (bx, by) in itertools.pairwise(corners):
        out += [(ax + (bx - ax) * k / n, ay + (by - ay) * k / n) for k in range(n)]
    return [*out, corners[-1]]


def circle_points(cx: float, cy: float, r: float, canvas: tuple[float, float] = (1600, 1000),
                  n: int = 40) -> list[tuple[float, float]]:
    """A circle of radius ``r`` canvas units round canvas fraction (cx, cy), closed."""
    return [(cx + r / canvas[0] * math.cos(2 * math.pi * k / n), cy + r / canvas[1] * math.sin(2 * math.pi * k / n))
            for k in range(n + 1)]
