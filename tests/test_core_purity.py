"""The core (scene, timeline, sim) loads no UI/device/audio/video library and reads no clock and does no I/O.

Two checks beside the import-linter contract in pyproject.toml: what importing each core package really
pulls into ``sys.modules`` (catches imports through third-party code, which import-linter cannot see), and
an ``ast`` scan of the core's source for clocks and I/O (which no import contract can express).
"""

from __future__ import annotations

import ast
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
PACKAGE = REPO / "physink_tui"
CORE = ("scene", "timeline", "sim")

FORBIDDEN_MODULES = (
    "textual",
    "rich",
    "skia",
    "av",
    "hid",
    "usb",
    "serial",
    "sounddevice",
    "pocketsphinx",
    "vosk",
    "dask",
    "distributed",
    "physink_tui.input",
    "physink_tui.render",
    "physink_tui.commands",
    "physink_tui.cli",
    "physink_tui.formats",
    "physink_tui.session",
)

# Modules whose import alone means clock or I/O access.
IO_MODULES = {"time", "os", "pathlib", "socket", "subprocess", "shutil", "tempfile", "select", "selectors"}
# Builtins that do I/O when called.
IO_BUILTINS = {"open", "input"}
# Attribute calls that read the wall clock (datetime.now(), date.today(), ...).
CLOCK_ATTRIBUTES = {"now", "utcnow", "today", "fromtimestamp", "utcfromtimestamp"}


def _loaded_modules(module: str) -> list[str]:
    code = f"import json, sys; import {module}; print(json.dumps(sorted(sys.modules)))"
    path = [str(REPO), *filter(None, [os.environ.get("PYTHONPATH")])]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(path)}
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, env=env, check=False
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.parametrize("package", CORE)
def test_core_package_imports_no_edge_library(package: str) -> None:
    loaded = _loaded_modules(f"physink_tui.{package}")
    offending = sorted(
        name for name in loaded for bad in FORBIDDEN_MODULES if name == bad or name.startswith(bad + ".")
    )
    assert offending == [], f"importing physink_tui.{package} loads {offending}"


def io_uses(source: str, filename: str = "<source>") -> list[str]:
    """Names each clock or I/O use in ``source`` as ``file:line: what``."""
    found = []
    for node in ast.walk(ast.parse(source, filename)):
        where = f"{filename}:{getattr(node, 'lineno', '?')}"
        if isinstance(node, ast.Import):
            found += [f"{where}: import {a.name}" for a in node.names if a.name.split(".")[0] in IO_MODULES]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            if node.module.split(".")[0] in IO_MODULES:
                found.append(f"{where}: from {node.module} import ...")
        elif isinstance(node, ast.Call):
            func = node.func
            if isinstance(func, ast.Name) and func.id in IO_BUILTINS:
                found.append(f"{where}: {func.id}(...)")
            elif isinstance(func, ast.Attribute) and func.attr in CLOCK_ATTRIBUTES:
                found.append(f"{where}: .{func.attr}(...)")
    return found


def test_io_uses_finds_clocks_and_io() -> None:
    bad = (
        "import time\nimport os.path\nfrom pathlib import Path\nfrom datetime import datetime\n"
        "import socket, subprocess\nx = datetime.now()\nf = open('x')\n"
    )
    assert len(io_uses(bad)) == 7
    assert io_uses("from datetime import timedelta\nimport math\nx = math.sqrt(2)\n") == []


def test_core_source_reads_no_clock_and_does_no_io() -> None:
    files = sorted(path for package in CORE for path in (PACKAGE / package).rglob("*.py"))
    assert files, "no core source found"
    found = [use for path in files for use in io_uses(path.read_text(), str(path.relative_to(REPO)))]
    assert found == [], "the core must get time and data from its inputs:\n" + "\n".join(found)


def pymunk_reaches(source: str, where: str = "<source>") -> list[str]:
    """Where ``source`` reaches the pymunk objects behind a `World` (``.pymunk_parts``, kept for tests)."""
    return [f"{where}:{node.lineno}: .pymunk_parts" for node in ast.walk(ast.parse(source))
            if isinstance(node, ast.Attribute) and node.attr == "pymunk_parts"]


def test_only_the_physics_layer_reaches_the_pymunk_objects_behind_a_world() -> None:
    assert pymunk_reaches("x = world.pymunk_parts.space\n") == ["<source>:1: .pymunk_parts"]
    physics = PACKAGE / "scene" / "physics"
    files = sorted(path for path in PACKAGE.rglob("*.py") if physics not in path.parents)
    found = [use for path in files for use in pymunk_reaches(path.read_text(), str(path.relative_to(REPO)))]
    assert found == [], "ask World its questions (pymunk is scene.physics' alone):\n" + "\n".join(found)
