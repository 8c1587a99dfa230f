"""`physink demo` in a real terminal (tmux, 120x40): the TUI opens and replays the bundled egg cracker; the scene,
the timeline and the narration appear and change as it runs (checked through ``tmux capture-pane``)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")]

WIDTH, HEIGHT = 120, 40
SCENE_COLUMNS = 70  # the scene view's share of a line (the timeline tree is to its right)
HANG_GUARD = 300.0
"""Seconds after which a wait on the screen fails (only a stuck app gets there, never a slow one)."""


def wait_for(socket: str, condition, what: str) -> list[str]:
    """The pane's lines once ``condition(lines)`` holds; fail after the hang guard."""
    deadline = time.monotonic() + HANG_GUARD
    while not condition(lines := screen(socket)):
        assert time.monotonic() < deadline, f"{what} not seen:\n" + "\n".join(lines)
        time.sleep(0.1)
    return lines


def tmux(socket: str, *args: str) -> str:
    # COLUMNS and LINES (pytest may set them) would override the pane's size for the program inside
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES", "TMUX")}
    return subprocess.run(["tmux", "-L", socket, *args], capture_output=True, text=True, check=True, env=env).stdout


def screen(socket: str, escapes: bool = False) -> list[str]:
    return tmux(socket, "capture-pane", "-p", *(["-e"] if escapes else []), "-t", "demo").split("\n")


def test_physink_demo_opens_the_tui_and_replays_the_egg_cracker(tmp_path: Path) -> None:
    socket = f"physink-test-{os.getpid()}"
    root = Path(__file__).resolve().parent.parent
    env = {"XDG_DATA_HOME": str(tmp_path / "data"), "PYTHONPATH": str(root), "TERM": "xterm-256color"}
    command = "env -u COLUMNS -u LINES " + " ".join(f"{k}={v}" for k, v in env.items()) \
        + f" {sys.executable} -m physink_tui demo"
    # the pane exists at its size before the program starts (started with the session, it may see tmux's
    # default 80x24 first)
    tmux(socket, "new-session", "-d", "-s", "demo", "-x", str(WIDTH), "-y", str(HEIGHT), "-c", str(tmp_path), "sh")
    tmux(socket, "send-keys", "-t", "demo", f"clear; {command}; echo physink-exited-$?", "Enter")
    try:
        scenes, trees, narrations = [], set(), []
        deadline = time.monotonic() + HANG_GUARD
        while True:  # the screen sampled as the replay runs (at real speed: tens of seconds), until all is seen
            assert time.monotonic() < deadline, "the replay's scene, tree and narration were not all seen"
            time.sleep(0.2)
            plain = screen(socket)
            coloured = screen(socket, escapes=True)
            assert not any("physink-exited" in line for line in plain), "\n".join(plain)
            scenes.append("\n".join(line[:SCENE_COLUMNS * 20] for line in coloured[:30]))
            trees.add("\n".join(line[SCENE_COLUMNS + 8:] for line in plain[:30]))
            said = plain[HEIGHT - 4].strip()
            if said and (not narrations or narrations[-1] != said):
                narrations.append(said)
            if "Contact between" in "".join(trees) and any("Movement of" in n for n in narrations) \
                    and "replay done" in plain[HEIGHT - 1] + "".join(plain[HEIGHT - 2:]) and len(set(scenes)) > 5:
                break
        final = screen(socket)
        assert any("\u2580" in line for line in final[:30]), "\n".join(final)
        assert len(set(scenes)) > 5, "the scene did not change as the replay ran"
        assert any("Movement of ball" in tree for tree in trees), "\n".join(final)
        assert any("Contact between" in tree for tree in trees), trees
        assert len(narrations) >= 2 and any("Movement of" in n for n in narrations), narrations
        assert "SKETCH" in final[HEIGHT - 1] or "DEMO" in final[HEIGHT - 1], final[HEIGHT - 1]
        tmux(socket, "send-keys", "-t", "demo", "q")
        asked = wait_for(socket, lambda lines: any("Quit anyway?" in line or "physink-exited-" in line
                                                   for line in lines), "the question before quitting (or the exit)")
        if any("Quit anyway?" in line for line in asked):  # the replayed work is not saved
            tmux(socket, "send-keys", "-t", "demo", "y")
        wait_for(socket, lambda lines: any("physink-exited-" in line for line in lines), "the app's exit")
        assert any("physink-exited-0" in line for line in screen(socket)), "\n".join(screen(socket))
    finally:
        subprocess.run(["tmux", "-L", socket, "kill-server"], capture_output=True)
    journals = list((tmp_path / "data" / "physink" / "sessions").glob("*.physink.jsonl"))
    assert len(journals) == 1 and '"cmd":"end"' in journals[0].read_text().splitlines()[-1]
