"""The kiosk survives being killed (issue 17): a `physink kiosk --replay` process is SIGKILLed at random moments,
restarted each time, and the journals are checked against the capture; SIGTERM finalises the session and exits 0.

How far behind the journal was at a kill is measured in input time, the capture's own: the replay runs at a
quarter speed, so 100 ms of input time is 400 ms of wall time and the few milliseconds between a wall-clock reading
in this test and the kiosk's own reading of the capture do not matter (the wall-clock side is a benchmark).
"""

from __future__ import annotations

import bisect
import json
import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from kiosk.captures import ball_and_platform, box_then_undo, visits, write_capture
from kiosk.process import PHYSINK, start_kiosk

from physink_tui.formats.journal.entries import HidEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.kiosk.folder_files import JOURNAL, OUTPUTS, SUMMARY

SPEED = 0.25
KILLS = 20
MAX_BEHIND_S = 0.1


def hid_lines(journal: Path) -> list[bytes]:
    return [e.data for e in read_journal(journal).entries if isinstance(e, HidEntry)]


def capture_positions(reports: list[bytes], sent: list[bytes], start: int = 0) -> list[int]:
    """Where each journaled report is in the capture (the journal holds a subsequence of it, in order)."""
    positions, i = [], start
    for data in reports:
        while sent[i] != data:
            i += 1
        positions.append(i)
        i += 1
    return positions


@pytest.mark.slow
def test_sigkill_at_random_moments_loses_at_most_100_ms_of_input_and_every_session_is_recovered(
        tmp_path: Path) -> None:
    capture = visits(ball_and_platform(), box_then_undo(), pause_s=3.0)
    path = write_capture(capture, tmp_path / "visits.hid")
    times = [e.t - capture.events[0].t for e in capture.events]
    sent = [e.data for e in capture.events]
    # which reports a session journals (not hovering before a touch, not the taps on the zones): a run to the end
    reference = tmp_path / "reference"
    proc, _ = start_kiosk(reference, path, 20.0)
    assert proc.wait(timeout=120) == 0
    worthy: list[int] = []
    for folder in sorted(p for p in reference.iterdir() if p.is_dir()):
        worthy += capture_positions(hid_lines(folder / JOURNAL), sent, worthy[-1] + 1 if worthy else 0)
    worthy_times = [times[i] for i in worthy]

    rng = random.Random(17)
    out = tmp_path / "out"
    behind: list[float] = []
    while len(behind) < KILLS:
        before = {p.name for p in out.iterdir() if p.is_dir()} if out.exists() else set()
        proc, reading = start_kiosk(out, path, SPEED)
        time.sleep(rng.uniform(0.2, 4.0))
        killed_at = (time.monotonic() - reading) * SPEED  # input time read by the moment of the kill
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        new = sorted(p for p in out.iterdir() if p.is_dir() and p.name not in before)
        journaled = [i for folder in new for i in capture_positions(hid_lines(folder / JOURNAL), sent)]
        read = bisect.bisect_right(worthy_times, killed_at) - 1  # the last report a session would journal, read
        if read < 0 or not journaled:
            continue  # killed before the first touch: nothing to journal yet
        assert max(journaled) <= worthy[read] + 1 or times[max(journaled)] <= killed_at + 0.05
        behind.append(worthy_times[read] - times[max(journaled)])
    print("behind (s of input time):", sorted(round(b, 3) for b in behind))
    assert max(behind) <= MAX_BEHIND_S, sorted(behind)[-5:]

    # a last run recovers what the last kill left and finishes: every session is complete, and valid
    proc, _ = start_kiosk(out, path, 20.0)
    assert proc.wait(timeout=300) == 0
    records = [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]
    folders = sorted(p for p in out.iterdir() if p.is_dir())
    assert sorted(r["session"] for r in records) == [p.name for p in folders]  # each indexed once
    assert sum(r["recovered"] for r in records) >= KILLS - 1
    for folder in folders:
        files = {p.name for p in folder.iterdir()}
        assert {JOURNAL, SUMMARY, "project.json", "narration.txt", "video.mp4"} <= files <= {JOURNAL, *OUTPUTS}
        again = tmp_path / "again"
        subprocess.run([*PHYSINK, "replay", str(folder / JOURNAL), "--out", str(again)], check=True,
                       capture_output=True)
        assert (again / "project.json").read_bytes() == (folder / "project.json").read_bytes(), folder.name


def test_sigterm_finalises_the_session_and_exits_0(tmp_path: Path) -> None:
    path = write_capture(visits(ball_and_platform()), tmp_path / "visits.hid")
    out = tmp_path / "out"
    proc = subprocess.Popen([*PHYSINK, "kiosk", "--out", str(out), "--replay", str(path), "--speed", "0.5",
                             "--video-size", "160x100"], stdout=subprocess.PIPE, text=True, bufsize=1)
    assert proc.stdout is not None
    for line in proc.stdout:
        if " started" in line:
            break
    time.sleep(0.5)
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=60) == 0
    (record,) = [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]
    assert record["ended"] == "stopped" and not record["recovered"]
    assert (out / record["session"] / "video.mp4").exists()
    assert read_journal(out / record["session"] / JOURNAL).entries[-1].name == "end"


def test_the_kiosk_never_imports_textual(tmp_path: Path) -> None:
    code = ("import sys, physink_tui.commands.kiosk, physink_tui.kiosk.service; "
            "sys.exit('textual' in sys.modules)")
    assert subprocess.run([sys.executable, "-c", code], env={**os.environ}).returncode == 0
