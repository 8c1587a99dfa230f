"""`physink tui` in real terminals on an X server (Xvfb): Debian's xterm as a VT340 (Sixel) and Debian's kitty, each
asked by the program what it can show (not told by TERM). The screen is photographed (ImageMagick's ``import``) and
the scene's pixels are looked for in the picture: the canvas's paper found, and what it shows compared with the
renderer's own picture of the project drawn at that size — at full resolution where the terminal shows graphics, in
half-block cells where it does not (kitty before 0.28, which has no Unicode placeholders: Debian 12's 0.26).

The X tools are installed by `.ci/run` (CI), not by scripts/setup.sh; without them these tests skip, and fail under
``PHYSINK_REQUIRE_GUI=1`` (what `.ci/run` sets). ``PHYSINK_SCREENSHOTS=DIR`` keeps the photographs (the README's:
``PHYSINK_SCREENSHOTS=docs``).
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from physink_tui.formats.project.files import load_project
from physink_tui.render.frame import FrameContent
from physink_tui.render.images import decode_png, write_png
from physink_tui.render.renderer import Renderer
from physink_tui.render.theme import DARK
from physink_tui.tui.graphics import PLACEHOLDERS

ROOT = Path(__file__).resolve().parent.parent
TOOLS = ("Xvfb", "xterm", "kitty", "import")
GUARD = 120.0
"""Seconds a terminal has to show the scene (a guard against a hang: each photograph is checked as it comes)."""

pytestmark = pytest.mark.slow


def _require_tools() -> None:
    missing = [tool for tool in TOOLS if shutil.which(tool) is None]
    if not missing:
        return
    reason = f"the X tools {', '.join(missing)} are missing (.ci/run installs xvfb, xterm, kitty, imagemagick)"
    if os.environ.get("PHYSINK_REQUIRE_GUI") == "1":
        pytest.fail(f"{reason}; CI needs them (PHYSINK_REQUIRE_GUI=1)", pytrace=False)
    pytest.skip(reason)


@pytest.fixture(scope="module")
def display() -> Iterator[str]:
    """A fresh X server's display name (``:N``), for the module."""
    _require_tools()
    read, write = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", "1400x1000x24", "-nolisten", "tcp"],
                              pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    number = b""
    with os.fdopen(read, "rb") as pipe:
        while not number.endswith(b"\n"):
            chunk = pipe.read(1)
            if not chunk:
                server.kill()
                pytest.fail("Xvfb did not start")
            number += chunk
    try:
        yield f":{number.decode().strip()}"
    finally:
        server.terminate()
        server.wait(timeout=30)


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bundled egg cracker as a project (``physink demo --headless``)."""
    out = tmp_path_factory.mktemp("demo")
    subprocess.run([sys.executable, "-m", "physink_tui", "demo", "--headless", "--out", str(out)], check=True,
                   capture_output=True, env={**os.environ, "PYTHONPATH": str(ROOT)}, timeout=600)
    return out / "project.json"


@dataclass(frozen=True)
class Seen:
    """What a photograph of the screen shows of the scene."""

    box: tuple[int, int, int, int]  # the canvas's paper: x, y, width, height in the photograph
    matched: float  # share of the canvas's pixels within 48 levels of the renderer's picture
    ink: float  # share of the picture's lines and shapes found within 2 pixels in the photograph
    photo: np.ndarray


def _argb(colour: int) -> np.ndarray:
    return np.array([(colour >> 16) & 255, (colour >> 8) & 255, colour & 255])


def _longest_run(row: np.ndarray) -> tuple[int, int]:
    """(length, end) of the longest run of True in ``row``."""
    padded = np.concatenate(([0], row.astype(np.int8), [0]))
    edges = np.flatnonzero(np.diff(padded))
    starts, ends = edges[::2], edges[1::2]
    if not len(starts):
        return 0, 0
    k = int(np.argmax(ends - starts))
    return int(ends[k] - starts[k]), int(ends[k])


def look(photo: np.ndarray, scene, canvas: tuple[float, float]) -> Seen | None:
    """The scene in ``photo``: its paper (the dark theme's canvas colour), compared with the renderer's picture of
    ``scene`` at the paper's size; None while no paper shows."""
    rgb = photo[..., :3].astype(int)
    paper = np.abs(rgb - _argb(DARK.background)).max(axis=2) <= 2
    runs = [_longest_run(row) for row in paper]
    widest = max(length for length, _ in runs)
    if widest < 100:
        return None
    rows = [y for y, (length, _) in enumerate(runs) if length >= 0.9 * widest]
    y0, y1 = rows[0], rows[-1] + 1
    length, end = runs[rows[0]]
    x0, x1 = end - length, end
    if y1 - y0 < 60:
        return None
    crop = rgb[y0:y1, x0:x1]
    h, w = crop.shape[:2]
    expected = Renderer(w, h, canvas, "dark", controls=False).render(FrameContent(scene, canvas))[..., :3]
    expected = expected.astype(int)
    matched = float((np.abs(crop - expected).max(axis=2) <= 48).mean())
    padded = np.pad(crop, ((2, 2), (2, 2), (0, 0)), mode="edge")
    near = np.full((h, w), 999)
    for dy in range(5):
        for dx in range(5):
            near = np.minimum(near, np.abs(padded[dy:dy + h, dx:dx + w] - expected).max(axis=2))
    ink = np.abs(expected - _argb(DARK.background)).max(axis=2) > 60
    return Seen((x0, y0, w, h), matched, float((near[ink] <= 48).mean()) if ink.any() else 0.0, photo)


def photograph(display: str) -> np.ndarray:
    shot = subprocess.run(["import", "-display", display, "-window", "root", "png:-"], capture_output=True,
                          timeout=60, check=True)
    return decode_png(shot.stdout)


def watch(display: str, project: Path, command: list[str], done, what: str) -> Seen:
    """Start ``command`` (a terminal running ``physink tui PROJECT``) and photograph the screen until ``done(seen)``;
    the last photograph's `Seen`. Fails after `GUARD` seconds, saying what was seen."""
    home = project.parent / f"home-{command[0]}"
    env = {k: v for k, v in os.environ.items() if k not in ("TMUX", "PHYSINK_GRAPHICS", "KITTY_WINDOW_ID",
                                                           "TERM_PROGRAM", "COLORTERM", "WINDOWID")}
    env.update(DISPLAY=display, PYTHONPATH=str(ROOT), XDG_DATA_HOME=str(home / "data"),
               XDG_CONFIG_HOME=str(home / "config"), XDG_RUNTIME_DIR=str(home / "run"))
    (home / "run").mkdir(parents=True, exist_ok=True, mode=0o700)
    loaded = load_project(project)
    terminal = subprocess.Popen(command, env=env, cwd=home, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
    seen = None
    try:
        deadline = time.monotonic() + GUARD
        while time.monotonic() < deadline:
            assert terminal.poll() is None, f"{command[0]} ended with status {terminal.returncode}"
            seen = look(photograph(display), loaded.scene, loaded.canvas)
            if seen is not None and done(seen):
                _keep(seen.photo, command[0])
                return seen
            time.sleep(0.5)  # between photographs; the condition decides, not the time
        raise AssertionError(f"{command[0]} never showed {what}; last seen: "
                             f"{None if seen is None else (seen.box, round(seen.matched, 4), round(seen.ink, 3))}")
    finally:
        os.killpg(terminal.pid, signal.SIGTERM)
        try:
            terminal.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(terminal.pid, signal.SIGKILL)
            terminal.wait()


def _keep(photo: np.ndarray, name: str) -> None:
    """The photograph, cropped to what is not the X server's black, into ``PHYSINK_SCREENSHOTS`` if set."""
    folder = os.environ.get("PHYSINK_SCREENSHOTS")
    if not folder:
        return
    lit = np.flatnonzero(photo[..., :3].max(axis=(0, 2)) > 0), np.flatnonzero(photo[..., :3].max(axis=(1, 2)) > 0)
    x0, x1, y0, y1 = lit[0][0], lit[0][-1] + 1, lit[1][0], lit[1][-1] + 1
    write_png(Path(folder) / f"tui-{name}.png", np.ascontiguousarray(photo[y0:y1, x0:x1]))


def tui(project: Path) -> list[str]:
    return [sys.executable, "-m", "physink_tui", "tui", str(project)]


def test_xterm_as_a_vt340_shows_the_scene_in_sixel_at_full_resolution(display, project) -> None:
    xterm = ["xterm", "-ti", "vt340", "-tn", "xterm-256color", "-geometry", "120x40+0+0", "-fa", "DejaVu Sans Mono",
             "-fs", "10", "-xrm", "XTerm*numColorRegisters: 256", "-e", *tui(project)]
    seen = watch(display, project, xterm, lambda s: s.matched >= 0.99 and s.ink >= 0.8,
                 "the scene at full resolution")
    _, _, w, h = seen.box
    assert w > 400 and h > 250  # the canvas at the terminal's pixels, not a thumbnail


def kitty_version() -> tuple[int, ...]:
    out = subprocess.run(["kitty", "--version"], capture_output=True, text=True, check=True).stdout
    match = re.search(r"kitty (\d+)\.(\d+)(?:\.(\d+))?", out)
    assert match, out
    return tuple(int(n) for n in match.groups() if n is not None)


def test_kitty_shows_the_scene_and_an_old_kitty_gets_half_blocks(display, project) -> None:
    version = kitty_version()
    kitty = ["kitty", "--config", "NONE", "-o", "font_size=10", "-o", "initial_window_width=1200", "-o",
             "initial_window_height=800", "-o", "remember_window_size=no", "-o", "linux_display_server=x11",
             "-e", *tui(project)]
    if version >= PLACEHOLDERS:  # the Kitty graphics protocol, through placeholder cells: full resolution
        seen = watch(display, project, kitty, lambda s: s.matched >= 0.99 and s.ink >= 0.8,
                     "the scene at full resolution")
    else:  # Debian 12's 0.26: half-blocks (and a note saying why, `test_graphics_probe`)
        seen = watch(display, project, kitty, lambda s: s.matched >= 0.93 and s.ink >= 0.25,  # an empty canvas: ~0
                     "the scene in half-blocks")
        assert seen.ink < 0.7  # blocks of a cell's half, not the full-resolution picture
    assert seen.box[2] > 400 and seen.box[3] > 250
