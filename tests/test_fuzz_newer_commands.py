"""Fuzz (hypothesis, derandomized) of export, simulate, listen, kiosk and tui over projects, WAVs, captures, journals
and settings files made by mutating good ones: every case gives a result or one ``physink`` line, never a traceback,
never hangs (each case bounded by a generous guard), and destroys no input and no earlier output."""

from __future__ import annotations

import asyncio
import json
import os
import shutil
import subprocess
import sys
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from physink_tui.cli import main

ROOT = Path(__file__).resolve().parent.parent
JOURNAL = ROOT / "tests" / "journals" / "bouncing_below_b.physink.jsonl"
CAPTURE = ROOT / "physink_tui" / "data" / "egg-cracker.hid"
WAV = ROOT / "tests" / "speech" / "cmd00_0.wav"
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}
GUARD = 300.0
"""Seconds after which a case is taken to hang (generous: the machine's CPU is shared)."""


def fuzz(examples: int) -> settings:
    return settings(derandomize=True, deadline=None, suppress_health_check=list(HealthCheck), database=None,
                    max_examples=examples)


def bounded(call: Callable[[], Any]) -> Any:
    """``call()`` on a thread of its own; the case fails if it has not returned within `GUARD` seconds."""
    result: list[Any] = []
    failure: list[BaseException] = []

    def run() -> None:
        try:
            result.append(call())
        except BaseException as exc:  # handed to the test's thread
            failure.append(exc)

    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    worker.join(GUARD)
    assert not worker.is_alive(), f"hung for {GUARD:g} s"
    if failure:
        raise failure[0]
    return result[0]


def one_result(capsys, argv: list[str]) -> tuple[int, str, str]:
    """Runs ``physink ARGV`` in this process: exit 0, or 1 with one ``physink:`` line; an exception escaping
    main (a traceback) fails the case."""
    status = bounded(lambda: main(argv))
    out, err = capsys.readouterr()
    assert status in (0, 1), (argv, status, err)
    event(f"exit {status}" + (f": {err.split(': ', 2)[2][:30]}" if status == 1 and err.count(": ") > 1 else ""))
    if status == 1:
        assert err.startswith("physink: ") and err.count("\n") == 1, err
    return status, out, err


EXTREMES = st.sampled_from([0, -1, 1e-9, 1e8, 1e300, -1e300, 3600.5, 1e9, "", None, [], {}, True, "b99", "e1",
                            [[0, 0], [1, 0], [2, 0]], [[0, 0], [10, 10], [10, 0], [0, 10]]])
VALUES = EXTREMES | st.floats() | st.integers(min_value=-(10**20), max_value=10**20) | st.text(max_size=4)


def _paths(doc: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix] if prefix else []
    if isinstance(doc, dict):
        for k, v in doc.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(doc, list):
        for i, v in enumerate(doc[:3]):
            out += _paths(v, (*prefix, i))
    return out


def _mutated(doc: Any, draws: list[tuple[int, Any, float, str]]) -> Any:
    """``doc`` with each draw applied: a value replaced, a key deleted, or a number scaled (most keep the file
    well-formed, so that the commands get past reading it)."""
    doc = json.loads(json.dumps(doc))
    for pick, value, factor, how in draws:
        paths = _paths(doc)
        numbers = [p for p in paths if _at(doc, p) is not None and type(_at(doc, p)) in (int, float)]
        if how == "scale" and numbers:
            path = numbers[pick % len(numbers)]
            old = _at(doc, path)
            value = old * factor if type(old) is float else int(old * factor)
        elif not paths:
            break
        else:
            path = paths[pick % len(paths)]
        parent = doc
        for key in path[:-1]:
            parent = parent[key]
        if how == "delete" and isinstance(parent, dict):
            del parent[path[-1]]
        else:
            parent[path[-1]] = value
    return doc


def _at(doc: Any, path: tuple) -> Any:
    for key in path:
        doc = doc[key]
    return doc


MUTATIONS = st.lists(st.tuples(st.integers(min_value=0, max_value=10**6), VALUES,
                               st.sampled_from([0.5, 2.0, 1.001, 10.0, 1e3, -1.0, 0.0]),
                               st.sampled_from(["scale", "scale", "scale", "set", "delete"])), min_size=1, max_size=3)


@pytest.fixture(scope="module")
def good(tmp_path_factory) -> dict[str, Any]:
    """The bouncing ball's project (trajectories shortened: more cases a second) and a simulation of it."""
    out = tmp_path_factory.mktemp("good")
    assert main(["replay", str(JOURNAL), "--out", str(out / "replay")]) == 0
    project = json.loads((out / "replay" / "project.json").read_text())
    for ev in project["timeline"]["events"]:
        ev["trajectory"] = ev["trajectory"][::8]
    (out / "project.json").write_text(json.dumps(project))
    assert main(["simulate", str(out / "project.json"), "--out", str(out / "sim"), "--budget", "3", "--workers",
                 "1"]) == 0
    return {"project": project, "simulation": out / "sim"}


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.iterdir() if p.is_file() and not p.name.startswith(".")}


# --- export -------------------------------------------------------------------------------------------------------


@fuzz(60)
@given(MUTATIONS, st.integers(min_value=0, max_value=9).map(
    lambda k: ("input", "earlier", "fifo", "symlink")[k - 6] if k >= 6 else "fresh"))
def test_export_of_mutated_projects(good, tmp_path_factory, capsys, draws, target: str) -> None:
    folder = tmp_path_factory.mktemp("export")
    project = folder / "p.json"
    project.write_text(json.dumps(_mutated(good["project"], draws)))
    before = project.read_bytes()
    earlier = folder / "earlier.png"
    earlier.write_bytes(b"an earlier picture")
    (folder / "kept.json").write_bytes(b"kept")
    still = {"fresh": folder / "new.png", "input": project, "earlier": earlier, "fifo": folder / "fifo.png",
             "symlink": folder / "link.png"}[target]
    if target == "fifo":
        os.mkfifo(still)
    if target == "symlink":
        still.symlink_to(folder / "kept.json")
    status, _, _ = one_result(capsys, ["export", str(project), "--still", str(still), "--at", "1", "--timeline",
                                       str(folder / "t.json"), "--size", "160x100"])
    assert project.read_bytes() == before and (folder / "kept.json").read_bytes() == b"kept"
    if target == "fifo":
        assert still.is_fifo()
    if target == "symlink":
        assert still.is_symlink()
    if status == 1 or target != "earlier":  # only a picture asked for replaces the one there
        assert earlier.read_bytes() == b"an earlier picture"
    if status == 0:
        assert still.read_bytes()[:4] == b"\x89PNG"


# --- simulate -----------------------------------------------------------------------------------------------------


@fuzz(40)
@given(MUTATIONS)
def test_simulate_of_mutated_projects(good, tmp_path_factory, capsys, draws) -> None:
    folder = tmp_path_factory.mktemp("simulate")
    project = folder / "p.json"
    project.write_text(json.dumps(_mutated(good["project"], draws)))
    before = project.read_bytes()
    out = folder / "out"
    shutil.copytree(good["simulation"], out)
    earlier = _snapshot(out)
    status, _, _ = one_result(capsys, ["simulate", str(project), "--out", str(out), "--budget", "3", "--workers",
                                       "1"])
    assert project.read_bytes() == before
    now = _snapshot(out)
    if status == 1:
        assert now == earlier
    else:
        assert set(now) == set(earlier) and json.loads(now["result.json"])["rollouts"] >= 1
    assert not [p for p in out.iterdir() if p.name.endswith(".tmp")]


# --- listen -------------------------------------------------------------------------------------------------------


def _half_second() -> bytes:
    """The fixture's header and its first half second (the sizes in the header made to say so): quick to hear."""
    raw = bytearray(WAV.read_bytes()[:44 + 16000])
    assert raw[36:40] == b"data"
    raw[40:44] = (16000).to_bytes(4, "little")
    raw[4:8] = (len(raw) - 8).to_bytes(4, "little")
    return bytes(raw)


@st.composite
def wav_bytes(draw: st.DrawFn) -> bytes:
    from test_newer_commands_faults import extensible

    raw = bytearray(_half_second())
    if draw(st.booleans()):
        raw = bytearray(extensible(bytes(raw[44:]), 16000, draw(st.sampled_from([16, 24, 32])),
                                   draw(st.integers(min_value=1, max_value=3))))
    for _ in range(draw(st.integers(min_value=0, max_value=2))):
        kind = draw(st.sampled_from(["cut", "byte", "word", "word", "extensible"]))
        if kind == "cut":
            del raw[draw(st.integers(min_value=0, max_value=len(raw))):]
        elif kind == "byte" and raw:
            raw[draw(st.integers(min_value=0, max_value=min(60, len(raw) - 1)))] = draw(st.integers(0, 255))
        elif kind == "word" and len(raw) >= 44:
            at = draw(st.sampled_from([4, 16, 20, 22, 24, 28, 32, 34, 40]))  # sizes, tag, channels, rate, bits
            width = 2 if at in (20, 22, 32, 34) else 4
            values = [0, 1, 3, 0xFFFE, 0xFFFF, 7, 24] if width == 2 else [0, 1, 44, 0xFFFFFFFF, 2**31, 16000, 3]
            raw[at:at + width] = draw(st.sampled_from(values)).to_bytes(width, "little")
        elif kind == "extensible" and len(raw) >= 44:  # the tag alone: a fmt chunk too short for it
            raw[20:22] = (0xFFFE).to_bytes(2, "little")
    return bytes(raw)


@fuzz(40)
@given(wav_bytes())
def test_listen_to_mutated_wavs(tmp_path_factory, capsys, data: bytes) -> None:
    path = tmp_path_factory.mktemp("listen") / "x.wav"
    path.write_bytes(data)
    status, out, _ = one_result(capsys, ["listen", str(path)])
    assert path.read_bytes() == data
    if status == 0:
        assert set(json.loads(out)) == {"text", "command", "rejected"}


# --- kiosk (a process each: it takes signals) ---------------------------------------------------------------------


@st.composite
def capture_text(draw: st.DrawFn) -> str:
    lines = CAPTURE.read_text().splitlines()
    events = [i for i, line in enumerate(lines) if line.startswith("E:")]
    for _ in range(draw(st.integers(min_value=1, max_value=3))):
        kind = draw(st.sampled_from(["drop", "garbage", "time", "bytes", "header"]))
        at = events[draw(st.integers(min_value=0, max_value=len(events) - 1))] if events else 0
        if kind == "drop":
            del lines[at:at + draw(st.integers(min_value=1, max_value=400))]
        elif kind == "garbage":
            lines.insert(at, draw(st.sampled_from(["E: x", "R: 1 zz", "E: 1e309 2 01 02", "\x00\xff", "D: 9",
                                                   "E: -5 1 07"])))
        elif kind == "time" and at < len(lines):
            parts = lines[at].split(" ")
            parts[1] = draw(st.sampled_from(["0.0", "9999999.0", "3.5", "1e7", "nan"]))
            lines[at] = " ".join(parts)
        elif kind == "bytes" and at < len(lines):
            lines[at] = " ".join(lines[at].split(" ")[:draw(st.integers(min_value=2, max_value=5))])
        elif kind == "header":
            heads = [i for i, line in enumerate(lines) if line[:2] in ("R:", "N:", "I:")]
            if heads:
                del lines[heads[draw(st.integers(min_value=0, max_value=len(heads) - 1))]]
        events = [i for i, line in enumerate(lines) if line.startswith("E:")]
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def recorded(tmp_path_factory) -> Path:
    """A kiosk folder holding one finished session of the bundled capture."""
    out = tmp_path_factory.mktemp("kiosk") / "out"
    done = subprocess.run([sys.executable, "-m", "physink_tui", "kiosk", "--out", str(out), "--replay", str(CAPTURE),
                           "--speed", "1000", "--video-size", "160x100"], env=ENV, capture_output=True, text=True,
                          timeout=GUARD)
    assert done.returncode == 0, done.stdout + done.stderr
    return out


ZONES = {"area": [0.0, 0.1, 1.0, 1.0], "zones": [{"action": "mode", "x0": 0.0, "y0": 0.0, "x1": 0.25, "y1": 0.1},
                                               {"action": "end", "x0": 0.75, "y0": 0.0, "x1": 1.0, "y1": 0.1}],
         "pad": {"1": "mode", "4": "end"}}


@fuzz(10)
@given(capture_text(), st.integers(min_value=0, max_value=10**6), st.none() | MUTATIONS)
def test_kiosk_on_mutated_captures_and_journals(recorded, tmp_path_factory, capture: str, cut: int,
                                                zones_draws) -> None:
    folder = tmp_path_factory.mktemp("kiosk")
    out = folder / "out"
    shutil.copytree(recorded, out)
    session = next(p for p in out.iterdir() if p.is_dir())
    earlier = {p.name: p.read_bytes() for p in session.iterdir()}
    index = (out / "index.jsonl").read_bytes()
    journal = (session / "journal.physink.jsonl").read_bytes().splitlines(keepends=True)
    unfinished = out / "20200101T000000Z"  # a crashed session, its journal cut and damaged somewhere
    unfinished.mkdir()
    at = 1 + cut % (len(journal) - 1)
    (unfinished / "journal.physink.jsonl").write_bytes(b"".join(journal[:at]) + b"{\"t\": oops\n"
                                                       + b"".join(journal[at:at + 5])[: cut % 50])
    path = folder / "c.hid"
    path.write_text(capture)
    zones = []
    if zones_draws is not None:  # a hot zones file too, mutated
        (folder / "zones.json").write_text(json.dumps(_mutated(ZONES, zones_draws)))
        zones = ["--hot-zones", str(folder / "zones.json")]
    done = subprocess.run([sys.executable, "-m", "physink_tui", "kiosk", "--out", str(out), "--replay", str(path),
                           "--speed", "1000", "--video-size", "160x100", *zones], env=ENV, capture_output=True,
                          text=True, timeout=GUARD)
    assert done.returncode in (0, 1) and "Traceback" not in done.stderr + done.stdout, done.stderr
    if done.returncode == 1:
        assert len([line for line in done.stderr.splitlines() if line.startswith("physink")]) <= 1, done.stderr
    assert path.read_text() == capture
    assert {p.name: p.read_bytes() for p in session.iterdir()} == earlier
    assert (out / "index.jsonl").read_bytes().startswith(index)
    if "physink: " not in done.stderr:  # (a bad zones file is refused before anything else)
        assert (unfinished / "session.json").exists()  # recovered from the lines before the damage


# --- tui ----------------------------------------------------------------------------------------------------------


SETTINGS = {"theme": "dark", "area": [0.0, 0.0, 1.0, 1.0], "rotation": 0, "left_handed": False, "keep_aspect": True,
            "display_tablet": False, "display": "", "tip_down": 0.05, "tip_up": 0.01}


@fuzz(6)
@given(MUTATIONS, MUTATIONS, st.integers(min_value=1, max_value=200))
def test_tui_starts_on_mutated_settings_projects_and_journals(good, tmp_path_factory, settings_draws, project_draws,
                                                             cut: int) -> None:
    from tui_helpers import tui_app

    from physink_tui.tui.screens.modals import ConfirmModal

    folder = tmp_path_factory.mktemp("tui")
    config = folder / "config" / "config.json"
    config.parent.mkdir()
    config.write_text(json.dumps(_mutated(SETTINGS, settings_draws)))
    project = folder / "p.json"
    project.write_text(json.dumps(_mutated(good["project"], project_draws)))
    sessions = folder / "sessions"
    sessions.mkdir()
    lines = JOURNAL.read_bytes().splitlines(keepends=True)
    damaged = b"".join(lines[:cut]) + b"\xff{oops\n" + b"".join(lines[cut:cut + 3])
    (sessions / "old.physink.jsonl").write_bytes(damaged)
    files = {project: project.read_bytes(), config: config.read_bytes()}

    async def start() -> None:
        app = tui_app(folder, recover=True, project=str(project))
        async with app.run_test(size=(120, 40)) as pilot:
            while app.live is None or app.live.runner.latest_view() is None:
                if isinstance(app.screen, ConfirmModal):
                    await pilot.press("y")
                await pilot.pause(0.05)

    async def guarded() -> None:
        await asyncio.wait_for(start(), GUARD)  # the guard against a hang (Textual wants the main thread)

    asyncio.run(guarded())
    assert all(path.read_bytes() == data for path, data in files.items())
    kept = [p for p in sessions.iterdir() if p.name.startswith("old.")]
    assert len(kept) == 1 and kept[0].read_bytes() == damaged  # offered, then renamed .recovered: never lost
