"""Helpers for the TUI's Pilot tests: an app without a tablet journaling into a temporary folder, on a session clock
the test can hold still; waiting for the session or the app (conditions, with only a hang guard); drawing with the
mouse in canvas fractions."""

from __future__ import annotations

import contextlib
import itertools
import math
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

from physink_tui.session.view import SessionView
from physink_tui.tui.app import PhysinkApp, TuiOptions, make_app
from physink_tui.tui.screens.settings import SettingsScreen
from physink_tui.tui.widgets.scene_view import SceneView

SIZE = (120, 40)
HANG_GUARD = 120.0
"""Seconds after which a wait gives up: only a stuck test gets there; it never decides pass or fail on speed."""
MOVE_SECONDS = 0.01
"""Session seconds between two mouse events of a drawing (a 100 Hz mouse), whatever the machine's pace."""
STROKE_GAP = 0.3
"""Session seconds between one stroke's release and the next one's press in a drawing."""


class HeldClock:
    """The live session's clock in a test: the monotonic clock, except while `held`, when it stands still and
    moves only by the test's `step`s; once let go it runs on from where it stood (it never jumps or goes back).
    Holds nest: the clock runs again when the outermost ends.

    While it is held the session publishes a view only for a command or once a step has moved it a frame on.

    >>> clock = HeldClock()
    >>> with clock.held() as hand:
    ...     a = clock(); hand.step(0.01); b = clock()
    >>> round(b - a, 9), clock() >= b
    (0.01, True)
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._offset = 0.0  # monotonic seconds not counted (spent held)
        self._at: float | None = None  # the reading while held
        self._depth = 0

    def __call__(self) -> float:
        with self._lock:
            return self._at if self._at is not None else time.monotonic() - self._offset

    def step(self, seconds: float) -> None:
        with self._lock:
            if self._at is None:
                raise RuntimeError("the clock steps only while held")
            self._at += seconds

    @contextlib.contextmanager
    def held(self) -> Iterator[HeldClock]:
        with self._lock:
            if self._at is None:
                self._at = time.monotonic() - self._offset
            self._depth += 1
        try:
            yield self
        finally:
            with self._lock:
                self._depth -= 1
                if self._depth == 0 and self._at is not None:
                    self._offset = time.monotonic() - self._at
                    self._at = None


def tui_app(folder: Path, **options) -> PhysinkApp:
    """An app journaling into ``folder``/sessions, looking for no tablet, offering no recovery unless asked, its
    session on a `HeldClock` (``app.options.clock``)."""
    values = {"tablet": False, "journal_dir": folder / "sessions", "recover": False,
              "config_path": folder / "config" / "config.json", "clock": HeldClock(), **options}
    return make_app(TuiOptions(**values))


def latest(app: PhysinkApp) -> SessionView | None:
    return app.live.runner.latest_view() if app.live is not None else None


async def until(pilot, predicate: Callable[[SessionView], bool], timeout: float = HANG_GUARD) -> SessionView:
    """Wait (letting the app run) until the latest view satisfies ``predicate``; fail after the hang guard."""
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


async def until_app(pilot, condition: Callable[[], bool], what: str = "", timeout: float = HANG_GUARD) -> None:
    """Wait (letting the app run) until ``condition()`` holds of the app (a screen, a widget, a worker); fail
    after the hang guard, naming ``what`` was awaited."""
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what or condition}")
        await pilot.pause(0.05)
    await pilot.pause()  # what the change set going (a layout: where the next click lands) done too


async def until_shown(pilot, predicate: Callable[[SessionView], bool]) -> SessionView:
    """Wait until the main screen has been handed a view satisfying ``predicate`` (views reach it paced, after the
    runner published them), then until the app is idle (that view drawn); the view."""
    main = pilot.app.main
    await until_app(pilot, lambda: main is not None and main.view is not None and predicate(main.view),
                    "the screen to show the view awaited")
    await pilot.pause()
    return main.view


async def click(pilot, selector: str) -> None:
    """Click the button ``selector`` once it takes clicks: a Textual button ignores a click while its press effect
    shows (0.2 s after the last one), so a second click on it at once would be lost."""
    button = pilot.app.screen.query_one(selector)
    await until_app(pilot, lambda: not button.has_class("-active"), f"{selector} to take clicks again")
    await pilot.click(selector)


async def screen_is(pilot, kind: type, guard: float = HANG_GUARD):
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
    await until_app(pilot, lambda: isinstance(pilot.app.screen, SettingsScreen), "the settings screen")
    return pilot.app.screen


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
    """Press on the first cell of the scene view, move through the others, release on the last: with the session's
    clock held, `MOVE_SECONDS` apart whatever the machine's pace (each event is stamped before Pilot returns, as
    the mouse pen submits on the UI thread)."""
    with pilot.app.options.clock.held() as clock:
        await pilot.mouse_down(SceneView, offset=cells[0], button=button)
        for c in cells[1:]:
            clock.step(MOVE_SECONDS)
            await pilot.hover(SceneView, offset=c)
        clock.step(MOVE_SECONDS)
        await pilot.mouse_up(SceneView, offset=cells[-1])


async def tap(pilot, where: tuple[int, int]) -> None:
    """Press and release on the scene view's cell ``where`` with the session's clock held: a tap on any machine (a
    stall of the app's loop between the press and the release would otherwise read as the pen held still, a dwell
    that grabs the body under it)."""
    with pilot.app.options.clock.held():
        await pilot.click(SceneView, offset=where)


async def draw(pilot, strokes: Sequence[Sequence[tuple[int, int]]],
               done: Callable[[SessionView], bool]) -> SessionView:
    """Drag the mouse through each stroke's cells (`drag_cells`), the session's clock held from the first press to
    the last release, then wait until ``done(view)``.

    A drawing made this way is the same input on any machine: a stall of the app's loop between a press and the
    first move (a loaded machine) does not pass for the pen held still, which the session would rightly take for a
    dwell (the stroke a drag, drawing nothing), nor does one between an X's two strokes let its first arm be taken
    on its own (`physink_tui.session.modes.sketch.X_WAIT`).
    """
    with pilot.app.options.clock.held() as clock:
        for k, cells in enumerate(strokes):
            if k:
                clock.step(STROKE_GAP)
            await drag_cells(pilot, cells)
    return await until(pilot, done)


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
