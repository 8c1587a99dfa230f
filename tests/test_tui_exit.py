"""How the TUI ends: a crash of the Textual app exits non-zero (its traceback shown), a bug that stops the session or
a background job is said in a dialog and quitting then exits 1; quitting normally exits 0."""

from __future__ import annotations

import asyncio
import os
import sys
from pathlib import Path

import pytest
from pty_terminal import PtyProgram

from physink_tui.commands.demo import demo_journal
from physink_tui.tui.app import RunnerFailed
from physink_tui.tui.screens.modals import ErrorModal
from tests.tui_helpers import SIZE, screen_is, tui_app, until

ROOT = Path(__file__).resolve().parent.parent

CRASHING = """
import sys
from physink_tui.tui.screens.main import MainScreen

def show(self, view):
    raise RuntimeError("a bug drawing the view")

MainScreen.show = show
from physink_tui.cli import main
sys.exit(main(["tui"]))
"""


@pytest.mark.slow
def test_a_crash_of_the_app_shows_its_traceback_and_exits_1(tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k not in ("TMUX", "PHYSINK_GRAPHICS")}
    env.update(TERM="xterm-256color", PYTHONPATH=str(ROOT), XDG_DATA_HOME=str(tmp_path / "data"),
               XDG_CONFIG_HOME=str(tmp_path / "config"))
    with PtyProgram([sys.executable, "-c", CRASHING], env=env, cwd=tmp_path) as tui:
        assert tui.wait_exit() == 1
        tui.wait_for(lambda s: "RuntimeError" in s and "a bug drawing the view" in s, "the traceback")


def test_quitting_normally_exits_0(tmp_path: Path) -> None:
    async def go() -> int | None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            await pilot.press("q")
        return app.return_code
    assert asyncio.run(go()) == 0


def test_a_session_that_stopped_on_a_bug_is_said_and_quitting_exits_1(tmp_path: Path) -> None:
    async def go() -> int | None:
        app = tui_app(tmp_path)
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: True)
            app.post_message(RunnerFailed(ValueError("a bug in the session")))
            await screen_is(pilot, ErrorModal)
            assert "a bug in the session" in str(app.screen.query_one("#error-text").render())
            await pilot.press("escape")
            await pilot.press("q")
        return app.return_code
    assert asyncio.run(go()) == 1


def test_a_background_job_that_dies_on_a_bug_is_said_and_quitting_exits_1(tmp_path: Path, monkeypatch) -> None:
    from physink_tui.render import export

    def broken(*args, **kwargs):
        raise ZeroDivisionError("a bug in the video export")

    monkeypatch.setattr(export.Export, "video", broken)
    header, entries = demo_journal()

    async def go() -> int | None:
        app = tui_app(tmp_path, header=header, prior=tuple(entries))
        async with app.run_test(size=SIZE) as pilot:
            await until(pilot, lambda v: v.timeline is not None and bool(v.timeline.events), timeout=60)
            await pilot.press("e")
            await screen_is(pilot, ErrorModal)
            assert "a bug in the video export" in str(app.screen.query_one("#error-text").render())
            await pilot.press("escape")
            await pilot.press("q")
        return app.return_code
    assert asyncio.run(go()) == 1
