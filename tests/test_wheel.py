"""physink installed as its users install it: a wheel built (``pip wheel --no-deps``) from a clean copy of the
sources, installed with its dependencies in a fresh virtualenv outside the source tree, and every command run from
there — the TUI in a pseudo-terminal, showing its screen."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from dataclasses import dataclass
from pathlib import Path

import pytest
from pty_terminal import PtyProgram

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "physink_tui"
SPEECH = ROOT / "tests" / "speech"
CAPTURE = PACKAGE / "data" / "egg-cracker.hid"  # an input the tests hand the installed program, as a user would

pytestmark = pytest.mark.slow


@dataclass(frozen=True)
class Installed:
    """The wheel, the virtualenv it is installed in, and a folder outside the source tree to run commands in."""

    wheel: Path
    venv: Path
    home: Path

    @property
    def env(self) -> dict[str, str]:
        """The environment of a person who activated the virtualenv: no source tree on the path."""
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
        env.update(PATH=f"{self.venv / 'bin'}:{os.environ.get('PATH', '/usr/bin:/bin')}", VIRTUAL_ENV=str(self.venv),
                   HOME=str(self.home), XDG_DATA_HOME=str(self.home / "data"),
                   XDG_CONFIG_HOME=str(self.home / "config"), PYTHONDONTWRITEBYTECODE="1")
        return env

    def physink(self, *args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([str(self.venv / "bin" / "physink"), *args], cwd=self.home, env=self.env,
                              capture_output=True, text=True, timeout=600)


def _run(*argv: str | Path, cwd: Path) -> None:
    done = subprocess.run([str(a) for a in argv], cwd=cwd, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, f"{' '.join(map(str, argv))} failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Installed:
    work = tmp_path_factory.mktemp("wheel")
    source = work / "source"  # a copy, so no build/ or egg-info of an earlier build leaks in, and none is left behind
    source.mkdir()
    shutil.copy2(ROOT / "pyproject.toml", source)
    shutil.copytree(PACKAGE, source / "physink_tui", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    _run(sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-w", work / "dist", source, cwd=work)
    (wheel,) = (work / "dist").glob("physink_tui-*.whl")
    venv = work / "venv"
    _run(sys.executable, "-m", "venv", venv, cwd=work)  # no --system-site-packages: only what the wheel asks for
    _run(venv / "bin" / "python", "-m", "pip", "install", "--quiet", "--disable-pip-version-check", wheel, cwd=work)
    home = work / "home"
    home.mkdir()
    return Installed(wheel, venv, home)


@pytest.fixture(scope="module")
def demo(installed: Installed) -> Path:
    """``physink demo --headless``'s folder: a journal and a project for the other commands."""
    done = installed.physink("demo", "--headless", "--out", "demo")
    assert done.returncode == 0, done.stderr
    return installed.home / "demo"


def test_the_wheel_holds_every_file_the_package_reads(installed: Installed) -> None:
    """Every non-Python file of the package in the source tree (the stylesheet, bundled data) is in the wheel."""
    listed = subprocess.run(["git", "ls-files", "physink_tui"], cwd=ROOT, capture_output=True, text=True, check=True)
    resources = {p for p in listed.stdout.split() if not p.endswith(".py")}
    assert {"physink_tui/tui/physink.tcss", "physink_tui/data/egg-cracker.hid"} <= resources
    with zipfile.ZipFile(installed.wheel) as wheel:
        names = set(wheel.namelist())
    assert resources <= names, f"not in the wheel: {sorted(resources - names)}"


def test_the_installed_program_is_the_wheel_not_the_source_tree(installed: Installed) -> None:
    done = subprocess.run([str(installed.venv / "bin" / "python"), "-c",
                           "import physink_tui.tui.app as a, textual; print(a.__file__); print(textual.__file__)"],
                          cwd=installed.home, env=installed.env, capture_output=True, text=True, check=True)
    for path in done.stdout.split():
        assert Path(path).is_relative_to(installed.venv), path


def test_tui_from_the_wheel_shows_its_screen_and_quits_with_ctrl_c(installed: Installed) -> None:
    env = installed.env | {"TERM": "xterm-256color"}
    env.pop("PHYSINK_GRAPHICS", None)
    with PtyProgram(["physink", "tui"], env=env, cwd=installed.home) as tui:
        screen = tui.wait_for(lambda s: "SKETCH" in s and "nothing demonstrated yet" in s, "the control panel")
        assert "Traceback" not in screen and "Error" not in screen
        tui.send(b"\x03")  # ctrl+c, as a terminal in raw mode sends it: quits (nothing unsaved), status 0
        assert tui.wait_exit() == 0, tui.text()


def test_demo_headless(demo: Path) -> None:
    assert {"project.json", "timeline.json", "timeline.txt", "demo.mp4", "scene.png",
            "session.physink.jsonl"} <= {p.name for p in demo.iterdir()}


def test_replay(installed: Installed, demo: Path) -> None:
    done = installed.physink("replay", str(demo / "session.physink.jsonl"), "--out", "replayed")
    assert done.returncode == 0, done.stderr
    assert (installed.home / "replayed" / "timeline.json").read_bytes() == (demo / "timeline.json").read_bytes()


def test_export(installed: Installed, demo: Path) -> None:
    done = installed.physink("export", str(demo / "project.json"), "--still", "still.png", "--video", "video.mp4",
                             "--timeline", "timeline.txt", "--size", "320x200")
    assert done.returncode == 0, done.stderr
    assert (installed.home / "still.png").read_bytes().startswith(b"\x89PNG")
    assert (installed.home / "video.mp4").stat().st_size > 1000
    assert "CAUSES" in (installed.home / "timeline.txt").read_text()
    done = installed.physink("export", str(demo / "project.json"), "--timeline", "graph.svg")  # through Graphviz
    assert done.returncode == 0, done.stderr
    assert "Contact between" in (installed.home / "graph.svg").read_text()


def test_simulate(installed: Installed, demo: Path) -> None:
    done = installed.physink("simulate", str(demo / "project.json"), "--out", "simulated", "--budget", "4",
                             "--workers", "1", "--seed", "1")
    assert done.returncode == 0, done.stderr
    result = json.loads((installed.home / "simulated" / "result.json").read_text())
    assert result["rollouts"] >= 1


def test_kiosk_replay(installed: Installed) -> None:
    done = installed.physink("kiosk", "--out", "kiosk", "--replay", str(CAPTURE), "--speed", "50",
                             "--video-size", "160x100")
    assert done.returncode == 0, done.stderr
    (line,) = (installed.home / "kiosk" / "index.jsonl").read_text().splitlines()
    assert (installed.home / "kiosk" / json.loads(line)["session"] / "session.json").is_file()


def test_listen(installed: Installed) -> None:
    done = installed.physink("listen", str(SPEECH / "cmd00_0.wav"))  # the pocketsphinx model the wheel's deps bring
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["text"] == "label ball"  # heard (whether it is accepted is the grammar's)


def test_decode(installed: Installed) -> None:
    done = installed.physink("decode", str(CAPTURE))
    assert done.returncode == 0, done.stderr
    first = json.loads(done.stdout.splitlines()[0])
    assert {"t", "x", "y", "p", "tip"} <= first.keys()
