"""Issue 28, bad input and faults on export, simulate, listen, kiosk and tui, each item through the command as a user
runs it (``python -m physink_tui ...``): no traceback, no hang, no user file destroyed, no answer that depends on a
replay's speed, no silent wrong answer, and messages that name the file, the JSON path and the value."""

from __future__ import annotations

import json
import os
import signal
import socket
import stat
import struct
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from physink_tui.cli import main

ROOT = Path(__file__).resolve().parent.parent
JOURNAL = ROOT / "tests" / "journals" / "bouncing_below_b.physink.jsonl"
EGG_JOURNAL = ROOT / "tests" / "journals" / "egg_cracker.physink.jsonl"
EGG_CAPTURE = ROOT / "physink_tui" / "data" / "egg-cracker.hid"
WAV = ROOT / "tests" / "speech" / "cmd00_0.wav"
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}
GUARD = 300.0
"""Seconds after which a command is taken to hang (generous: the machine's CPU is shared)."""


def physink(*args: str, timeout: float = GUARD) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "physink_tui", *args], env=ENV, text=True, capture_output=True,
                          timeout=timeout, cwd=ROOT)


def one_line_error(done: subprocess.CompletedProcess[str], *fragments: str, status: int = 1) -> str:
    """Exit ``status`` and one ``physink`` line on stderr naming each fragment; no traceback."""
    err = done.stderr
    assert done.returncode == status, (done.returncode, err)
    lines = [line for line in err.splitlines() if line.startswith("physink")]
    assert "Traceback" not in err and len(lines) == 1, err
    for fragment in fragments:
        assert fragment in lines[0], err
    return lines[0]


@pytest.fixture(scope="module")
def replayed(tmp_path_factory) -> dict:
    """The bouncing ball's project (with its timeline) as JSON, from a replay of its journal."""
    out = tmp_path_factory.mktemp("replayed")
    assert main(["replay", str(JOURNAL), "--out", str(out)]) == 0
    return json.loads((out / "project.json").read_text())


def write(path: Path, project: dict, change: Callable[[dict], object] | None = None) -> Path:
    doc = json.loads(json.dumps(project))
    if change is not None:
        change(doc)
    path.write_text(json.dumps(doc))
    return path


def _ball(doc: dict) -> dict:
    return next(c for c in doc["components"] if c.get("shape") == "circle")


def _box(doc: dict) -> dict:
    return next(c for c in doc["components"] if c.get("shape") == "box")


BAD_PROJECTS = {
    "canvas-1e300": (lambda d: d["canvas"].update(width=1e300), "canvas.width: expected a number from 1 to 100000"),
    "radius-1e8": (lambda d: _ball(d).update(radius=1e8), "components[0].radius: expected a number from 0.01"),
    "radius-1e300": (lambda d: _ball(d).update(radius=1e300), "components[0].radius"),
    "event-ends-at-1e8": (lambda d: d["timeline"]["events"][-1].update(t1=1e8),
                          "timeline.events[3].t1: expected a time from 0 to 3600 s, got 100000000.0"),
    "zero-area": (lambda d: _box(d).update(outline=[[0, 0], [10, 0], [20, 0]]),
                  "components[1].outline: expected an outline the physics can use (the outline encloses no area)"),
    "self-intersecting": (lambda d: _box(d).update(shape="polygon", outline=[[0, 0], [10, 10], [10, 0], [0, 10]]),
                          "components[1].outline: expected an outline the physics can use"),
}


@pytest.mark.parametrize("case", sorted(BAD_PROJECTS))
def test_export_and_simulate_refuse_the_same_projects_naming_file_and_json_path(replayed, tmp_path, case) -> None:
    change, fragment = BAD_PROJECTS[case]
    project = write(tmp_path / "p.json", replayed, change)
    before = project.read_bytes()
    exported = physink("export", str(project), "--still", str(tmp_path / "x.png"), "--at", "1")
    simulated = physink("simulate", str(project), "--out", str(tmp_path / "sim"), "--budget", "3", "--workers", "1")
    assert one_line_error(exported, f"{project}: {fragment}") == one_line_error(simulated, f"{project}: {fragment}")
    assert not (tmp_path / "x.png").exists() and not (tmp_path / "sim" / "result.json").exists()
    assert project.read_bytes() == before


def test_the_same_check_refuses_a_project_loaded_in_a_session(replayed, tmp_path) -> None:
    # A journal's load line (what the TUI's Load and the kiosk journal) runs the same check: a message, no load.
    project = json.loads(json.dumps(replayed))
    BAD_PROJECTS["radius-1e8"][0](project)
    journal = tmp_path / "load.physink.jsonl"
    header = JOURNAL.read_text().splitlines()[0]
    journal.write_text(header + "\n" + json.dumps({"t": 0.5, "cmd": "load", "args": ["p.json"], "project": project})
                       + "\n")
    done = physink("replay", str(journal), "--out", str(tmp_path / "out"))
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr
    assert "load p.json: components[0].radius: expected a number from 0.01" in done.stdout + done.stderr
    assert json.loads((tmp_path / "out" / "project.json").read_text())["components"] == []


def test_a_timeline_naming_a_body_the_scene_lacks_is_drawn_with_a_word_and_not_simulated(replayed, tmp_path) -> None:
    # What a user gets by erasing a body after demonstrating and saving: still their work, so it loads.
    project = write(tmp_path / "p.json", replayed,
                    lambda d: d["timeline"]["events"][1]["components"][0].update(id="b99"))
    exported = physink("export", str(project), "--still", str(tmp_path / "x.png"))
    assert exported.returncode == 0 and "Traceback" not in exported.stderr
    assert "export: the timeline names 'b99', which the scene of" in exported.stderr
    simulated = physink("simulate", str(project), "--out", str(tmp_path / "sim"), "--workers", "1")
    one_line_error(simulated, str(project), "the demonstration moves 'b99', which the scene does not have")


def test_simulate_of_a_timeline_with_only_its_start_says_so(replayed, tmp_path) -> None:
    project = write(tmp_path / "p.json", replayed, lambda d: d["timeline"].update(events=d["timeline"]["events"][:1]))
    done = physink("simulate", str(project), "--out", str(tmp_path / "sim"), "--workers", "1")
    one_line_error(done, str(project), "no demonstration to reproduce (a timeline with nothing after its start event)")


def test_export_reads_a_project_with_a_bom_and_names_a_journal(replayed, tmp_path) -> None:
    bom = tmp_path / "bom.json"
    bom.write_bytes(b"\xef\xbb\xbf" + json.dumps(replayed).encode())
    done = physink("export", str(bom), "--still", str(tmp_path / "x.png"))
    assert done.returncode == 0 and (tmp_path / "x.png").read_bytes()[:4] == b"\x89PNG", done.stderr
    done = physink("export", str(JOURNAL), "--still", str(tmp_path / "y.png"))
    one_line_error(done, str(JOURNAL), "this is a journal (.physink.jsonl); expected a project")


@pytest.mark.parametrize("option", ["--timeline", "--still"])
def test_export_never_replaces_its_project(replayed, tmp_path, option) -> None:
    project = write(tmp_path / "P.json", replayed)
    before = project.read_bytes()
    done = physink("export", str(project), option, str(project))
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert project.read_bytes() == before


def test_export_never_replaces_a_device_a_fifo_or_a_symlink(replayed, tmp_path) -> None:
    project = write(tmp_path / "p.json", replayed)
    fifo = tmp_path / "pipe.png"
    os.mkfifo(fifo)
    target = tmp_path / "kept.png"
    target.write_bytes(b"mine")
    link = tmp_path / "link.png"
    link.symlink_to(target)
    for path, kind in ((fifo, "a FIFO"), (link, "a symbolic link")):
        one_line_error(physink("export", str(project), "--still", str(path)), str(path), f"would replace {kind}")
    one_line_error(physink("export", str(project), "--still", "/dev/full"), "/dev/full")
    assert fifo.is_fifo() and link.is_symlink() and target.read_bytes() == b"mine"
    assert Path("/dev/full").is_char_device()
    device = tmp_path / "device.png"
    try:
        os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 3))  # /dev/null's numbers, under a .png name
    except PermissionError:
        return  # not root: the FIFO and the symlink made the point
    one_line_error(physink("export", str(project), "--still", str(device)), str(device), "a character device")
    assert device.is_char_device()


def test_export_refuses_two_outputs_in_one_file_and_png_bytes_under_another_name(replayed, tmp_path) -> None:
    project = write(tmp_path / "p.json", replayed)
    one_line_error(physink("export", str(project), "--video", str(tmp_path / "X.gif"), "--still",
                           str(tmp_path / "X.gif")), "--still writes a PNG picture; name it .png")
    one_line_error(physink("export", str(project), "--still", str(tmp_path / "x.jpg")), "x.jpg", "name it .png")
    frames = tmp_path / "frames"
    one_line_error(physink("export", str(project), "--frames", str(frames), "--still", str(frames / "00003.png")),
                   "--still is one of them")
    assert not (tmp_path / "X.gif").exists() and not (tmp_path / "x.jpg").exists()


def _children(pid: int) -> list[int]:
    """The process ``pid``'s children, by its threads' /proc lists; a thread that ends between the listing and the
    read (the process starts and ends threads as it goes) has none."""
    found = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        try:
            found += [int(c) for c in (task / "children").read_text().split()]
        except FileNotFoundError:
            continue
    return found


@pytest.mark.parametrize("sig", [signal.SIGKILL, signal.SIGTERM])
def test_a_killed_simulate_leaves_the_previous_complete_result(tmp_path, sig) -> None:
    out = tmp_path / "sim"
    bouncing, egg = tmp_path / "bouncing", tmp_path / "egg"
    assert main(["replay", str(JOURNAL), "--out", str(bouncing)]) == 0
    assert main(["replay", str(EGG_JOURNAL), "--out", str(egg)]) == 0
    assert physink("simulate", str(bouncing / "project.json"), "--out", str(out), "--workers", "1").returncode == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    assert set(before) == {"result.json", "timeline.json", "timeline.txt", "project.json"}
    child = subprocess.Popen([sys.executable, "-m", "physink_tui", "simulate", str(egg / "project.json"), "--out",
                              str(out), "--workers", "2"], env=ENV, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, cwd=ROOT)
    deadline = time.monotonic() + GUARD
    while not _children(child.pid):  # its worker processes: the search has begun
        assert child.poll() is None and time.monotonic() < deadline, "the search never started"
        time.sleep(0.01)
    workers = _children(child.pid)
    child.send_signal(sig)
    child.wait(timeout=GUARD)
    assert {p.name: p.read_bytes() for p in out.iterdir() if not p.name.startswith(".")} == before
    while running := [pid for pid in workers if _alive(pid)]:  # no worker is left behind, waiting forever
        assert time.monotonic() < deadline + GUARD, f"workers {running} outlived the killed simulate"
        time.sleep(0.05)


def _alive(pid: int) -> bool:
    """Whether ``pid`` is a process that has not exited (a zombie has; an orphan's parent reaps it, or not)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


def _server(answer: bytes | None) -> Iterator[int]:
    """A local port that accepts and then says nothing (None) or ``answer``."""
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen()
    held: list[socket.socket] = []

    def serve() -> None:
        while True:
            try:
                conn, _ = listener.accept()
            except OSError:
                return
            held.append(conn)
            if answer is not None:
                conn.sendall(answer)

    threading.Thread(target=serve, daemon=True).start()
    yield listener.getsockname()[1]
    listener.close()
    for conn in held:
        conn.close()


@pytest.mark.parametrize(("answer", "fragment"), [
    (None, "no Dask scheduler answered at"),
    (b"HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\nhello" * 8, "something answered there, but not as a Dask scheduler"),
])
def test_simulate_at_a_scheduler_that_is_not_one_is_one_line(replayed, tmp_path, answer, fragment) -> None:
    pytest.importorskip("distributed")
    project = write(tmp_path / "p.json", replayed)
    for port in _server(answer):
        done = physink("simulate", str(project), "--out", str(tmp_path / "sim"), "--scheduler",
                       f"tcp://127.0.0.1:{port}")
        one_line_error(done, f"tcp://127.0.0.1:{port}", fragment)
    assert not (tmp_path / "sim" / "result.json").exists()


# --- listen -------------------------------------------------------------------------------------------------------


def _wav_parts(path: Path) -> tuple[int, int, bytes]:
    """(rate, channels, 16-bit samples) of a plain PCM WAV."""
    import wave

    with wave.open(str(path)) as w:
        return w.getframerate(), w.getnchannels(), w.readframes(w.getnframes())


def extensible(samples16: bytes, rate: int, bits: int, channels: int) -> bytes:
    """The mono 16-bit ``samples16`` as a WAVE_FORMAT_EXTENSIBLE file of ``bits`` per sample and ``channels``."""
    import numpy as np

    mono = np.frombuffer(samples16, dtype="<i2").astype(np.int64) << (bits - 16)
    width = bits // 8
    frames = np.repeat(mono, channels)
    data = b"".join(int(v).to_bytes(width, "little", signed=True) for v in frames) if width == 3 else \
        frames.astype(f"<i{width}").tobytes()
    guid = struct.pack("<H", 1) + bytes.fromhex("000000001000800000aa00389b71")
    fmt = struct.pack("<HHIIHHHHI", 0xFFFE, channels, rate, rate * channels * width, channels * width, bits, 22,
                      bits, (1 << channels) - 1) + guid
    body = b"WAVE" + b"fmt " + struct.pack("<I", len(fmt)) + fmt + b"data" + struct.pack("<I", len(data)) + data
    return b"RIFF" + struct.pack("<I", len(body)) + body


def test_listen_reads_extensible_pcm_as_it_reads_plain_pcm(tmp_path) -> None:
    plain = physink("listen", str(WAV))
    assert plain.returncode == 0, plain.stderr
    rate, channels, samples = _wav_parts(WAV)
    assert channels == 1
    for bits, count in ((16, 1), (24, 2), (32, 3)):
        path = tmp_path / f"x{bits}-{count}.wav"
        path.write_bytes(extensible(samples, rate, bits, count))
        heard = physink("listen", str(path))
        assert heard.returncode == 0, heard.stderr
        assert json.loads(heard.stdout) == json.loads(plain.stdout), (bits, count)


@pytest.mark.parametrize(("cut", "fragment"), [
    (lambda raw: raw[: len(raw) // 2 * 2 - 1], "the recording is cut off"),
    (lambda raw: raw[:44], "a WAV header with no samples"),
    (lambda raw: raw[:30], "it ends inside its header: the file is cut off"),
])
def test_listen_names_a_truncated_or_header_only_wav(tmp_path, cut, fragment) -> None:
    path = tmp_path / "cut.wav"
    path.write_bytes(cut(WAV.read_bytes()))
    one_line_error(physink("listen", str(path)), str(path), fragment)


# --- kiosk --------------------------------------------------------------------------------------------------------


def kiosk(out: Path, capture: Path | str, *extra: str, speed: str = "100") -> subprocess.CompletedProcess[str]:
    return physink("kiosk", "--out", str(out), "--replay", str(capture), "--speed", speed, "--video-size", "160x100",
                   *extra)


@pytest.mark.parametrize("what", ["missing", "folder"])
def test_kiosk_replay_of_a_missing_file_or_a_folder_is_one_line(tmp_path, what) -> None:
    capture = tmp_path / "none.hid" if what == "missing" else tmp_path
    one_line_error(kiosk(tmp_path / "out", capture), str(capture), "cannot read the capture")


def test_kiosk_names_a_device_value_that_can_never_be_a_tablet(tmp_path) -> None:
    done = physink("kiosk", "--out", str(tmp_path / "out"), "--device", "zzzz:yyyy")
    one_line_error(done, "--device 'zzzz:yyyy'", "VID:PID in hex", status=2)
    (tmp_path / "plain").write_text("not a device")
    done = physink("kiosk", "--out", str(tmp_path / "out"), "--device", str(tmp_path / "plain"))
    one_line_error(done, f"--device '{tmp_path / 'plain'}': not a device node", status=2)
    done = physink("kiosk", "--out", str(tmp_path / "out"), "--device", "/dev/null")  # a device, but no tablet
    one_line_error(done, "/dev/null: its report descriptor is unknown")


def test_kiosk_says_when_a_capture_records_no_session(tmp_path) -> None:
    capture = tmp_path / "hover.hid"
    lines = EGG_CAPTURE.read_text().splitlines()
    capture.write_text("\n".join([*(line for line in lines if not line.startswith("E:")),
                                  "E: 000001.000000 3 01 02 03"]) + "\n")
    done = kiosk(tmp_path / "out", capture)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert "the capture ended without a session" in done.stdout


def _journals(out: Path) -> list[bytes]:
    return [(folder / "journal.physink.jsonl").read_bytes() for folder in sorted(p for p in out.iterdir()
                                                                                  if p.is_dir())]


def test_the_bundled_capture_records_the_same_session_at_any_speed(tmp_path) -> None:
    recorded = {}
    for speed in ("5", "20", "100", "10000"):
        done = kiosk(tmp_path / speed, EGG_CAPTURE, speed=speed)
        assert done.returncode == 0, done.stdout + done.stderr
        recorded[speed] = _journals(tmp_path / speed)
    assert len(recorded["5"]) == 1 and recorded["5"] == recorded["20"] == recorded["100"] == recorded["10000"]
    summaries = [json.loads(line) for speed in recorded for line in (tmp_path / speed / "index.jsonl").read_text()
                 .splitlines()]
    assert len({(s["seconds"], s["bodies"], s["components"]) for s in summaries}) == 1, summaries


def test_quick_mode_presses_record_the_same_session_at_any_speed(tmp_path) -> None:
    # Each press toggles the mode the session shows: a fast replay must not read it before the last press is handled.
    from kiosk.captures import END, MODE, on_canvas, visits, write_capture

    from physink_tui.formats.journal.entries import CommandEntry
    from physink_tui.formats.journal.reader import read_journal
    from physink_tui.input.virtual_pen import Stroke

    capture = write_capture(visits([Stroke.circle(on_canvas(0.2, 0.2), 0.04, aspect=1.6),
                                    Stroke.box(*on_canvas(0.1, 0.6), *on_canvas(0.5, 0.66)),
                                    Stroke(MODE), Stroke(MODE), Stroke(MODE),
                                    Stroke((on_canvas(0.2, 0.2), on_canvas(0.3, 0.4), on_canvas(0.32, 0.55))),
                                    Stroke(END)]), tmp_path / "modes.hid")
    journals = []
    for speed in ("20", "10000"):
        assert kiosk(tmp_path / speed, capture, speed=speed).returncode == 0
        (folder,) = [p for p in (tmp_path / speed).iterdir() if p.is_dir()]
        journals.append((folder / "journal.physink.jsonl").read_bytes())
        modes = [e.args for e in read_journal(folder / "journal.physink.jsonl").entries
                 if isinstance(e, CommandEntry) and e.name == "mode"]
        assert modes == [("demo",), ("sketch",), ("demo",)], (speed, modes)
    assert journals[0] == journals[1]


def test_kiosk_retention_never_retires_the_session_just_recorded(tmp_path) -> None:
    done = kiosk(tmp_path / "out", EGG_CAPTURE, "--max-disk", "1k")
    assert done.returncode == 0, done.stdout + done.stderr
    folders = [p for p in (tmp_path / "out").iterdir() if p.is_dir()]
    assert len(folders) == 1 and (folders[0] / "session.json").exists() and "retired" not in done.stdout


def test_kiosk_recovery_keeps_the_lines_before_a_bad_one_and_says_what_it_dropped(tmp_path) -> None:
    first = tmp_path / "first"
    assert kiosk(first, EGG_CAPTURE).returncode == 0
    lines = _journals(first)[0].splitlines(keepends=True)
    out = tmp_path / "out"
    (out / "20260101T000000Z").mkdir(parents=True)
    (out / "20260101T000000Z" / "journal.physink.jsonl").write_bytes(b"".join(lines[:-10]) + b"garbage{\n"
                                                                      + b"".join(lines[-10:]))
    (out / "20250101T000000Z").mkdir()
    (out / "20250101T000000Z" / "journal.physink.jsonl").write_bytes(b'{"format": "nope"}\n' + lines[1])
    silent = tmp_path / "silent.hid"
    silent.write_text("\n".join(line for line in EGG_CAPTURE.read_text().splitlines() if not line.startswith("E:")))
    done = kiosk(out, silent)
    assert "Traceback" not in done.stderr
    said = [line for line in done.stdout.splitlines() if "recovering unfinished session" in line]
    assert said == [f"kiosk: recovering unfinished session 20260101T000000Z: {len(lines) - 11} inputs; dropped "
                    f"line {len(lines) - 9} and the 10 after it (line {len(lines) - 9}: not valid JSON (Expecting "
                    "value at column 1))"], done.stdout
    summary = json.loads((out / "20260101T000000Z" / "session.json").read_text())
    assert summary["bodies"] >= 1 and summary["dropped"].startswith(f"dropped line {len(lines) - 9}")
    assert "cannot recover 20250101T000000Z" in done.stdout
    assert "kept as journal.physink.jsonl.unreadable" in done.stdout
    assert (out / "20250101T000000Z" / "journal.physink.jsonl.unreadable").exists()  # set aside, never removed
    again = kiosk(out, silent)
    assert "kiosk: recovering" not in again.stdout and "cannot recover" not in again.stdout  # never retried


# --- tui ----------------------------------------------------------------------------------------------------------


def test_tui_starts_beside_a_dangling_journal_symlink_and_offers_a_damaged_journal(tmp_path) -> None:
    import asyncio

    from tui_helpers import screen_is, tui_app

    from physink_tui.tui.screens.modals import ConfirmModal

    sessions = tmp_path / "sessions"
    sessions.mkdir()
    (sessions / "gone.physink.jsonl").symlink_to(tmp_path / "nowhere.physink.jsonl")
    lines = JOURNAL.read_bytes().splitlines(keepends=True)
    (sessions / "damaged.physink.jsonl").write_bytes(b"".join(lines[:30]) + b"{not json\n" + b"".join(lines[30:40]))

    async def start() -> str:
        app = tui_app(tmp_path, recover=True)
        async with app.run_test(size=(120, 40)) as pilot:
            question = await screen_is(pilot, ConfirmModal)  # the recovery question (a 120 s hang guard)
            return str(question._question)

    question = asyncio.run(start())
    assert "damaged.physink.jsonl (29 inputs)" in question and "dropped line 31 and the 10 after it" in question


def test_a_bad_setting_is_named_by_its_key(tmp_path) -> None:
    from physink_tui.errors import PhysinkError
    from physink_tui.tui.config import load_config

    path = tmp_path / "config.json"
    path.write_text('{"area": [0, 0, "x", 1]}')
    with pytest.raises(PhysinkError) as caught:
        load_config(path)
    assert str(caught.value) == f'{path}: area[2]: expected a number in [0, 1], got "x"'


def test_physink_tui_starts_beside_a_dangling_symlink_and_offers_the_damaged_journal(tmp_path) -> None:
    # `physink tui` in a terminal, as a person starts it (a pty read through a terminal emulator).
    from pty_terminal import PtyProgram

    sessions = tmp_path / "data" / "physink" / "sessions"
    sessions.mkdir(parents=True)
    (sessions / "gone.physink.jsonl").symlink_to(tmp_path / "nowhere.physink.jsonl")
    lines = JOURNAL.read_bytes().splitlines(keepends=True)
    (sessions / "damaged.physink.jsonl").write_bytes(b"".join(lines[:30]) + b"{not json\n" + b"".join(lines[30:40]))
    env = {k: v for k, v in os.environ.items() if k not in ("TMUX", "PHYSINK_GRAPHICS")}
    env.update(TERM="xterm-256color", PYTHONPATH=str(ROOT), XDG_DATA_HOME=str(tmp_path / "data"),
               XDG_CONFIG_HOME=str(tmp_path / "config"))
    with PtyProgram([sys.executable, "-m", "physink_tui", "tui"], env=env, cwd=tmp_path) as tui:
        tui.wait_for(lambda s: "damaged.physink.jsonl" in s and "damaged:" in s and "Recover" in s,
                     "the recovery question naming the damaged journal", guard=GUARD)
        tui.send(b"n")  # start afresh: the journal is kept, renamed, and not offered again
        tui.wait_for(lambda s: "Recover" not in s, "the control panel", guard=GUARD)
        tui.send(b"q")
        assert tui.wait_exit(guard=GUARD) == 0
    assert (sessions / "damaged.physink.jsonl.recovered").exists() and (sessions / "gone.physink.jsonl").is_symlink()
