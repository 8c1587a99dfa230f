"""The kiosk listening (``physink kiosk --speech``): a recording played as the microphone, in real time, while a
replayed visitor draws; what is said during the session is journaled as a ``say`` entry and labels what was just
drawn; speech outside a session and a missing microphone change nothing else."""

from __future__ import annotations

import itertools
import queue
import threading
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from kiosk.captures import END, on_canvas, visits, write_capture

from physink_tui.cli import main
from physink_tui.commands import kiosk as kiosk_command
from physink_tui.errors import MicrophoneError
from physink_tui.formats.journal.entries import SayEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.project.files import load_project
from physink_tui.input.captures.capture import Capture
from physink_tui.input.sources import RawReport
from physink_tui.input.speech.audio import RATE, read_wav
from physink_tui.input.speech.microphone import BLOCK
from physink_tui.input.virtual_pen import Stroke
from physink_tui.kiosk import speech as kiosk_speech
from physink_tui.kiosk.folder_files import JOURNAL
from physink_tui.kiosk.store import SessionStore

SPEECH = Path(__file__).parent / "speech"
HANG_GUARD = 60.0


class LiveRecording:
    """A microphone in real time: quiet room noise in 50 ms blocks, and ``samples`` once ``cue`` is set."""

    def __init__(self, samples: np.ndarray, cue: threading.Event, deliver: Callable[[bytes], None]) -> None:
        self.samples, self.cue, self.deliver = samples, cue, deliver
        self.stopped = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)

    def start(self) -> None:
        self.thread.start()

    def _run(self) -> None:
        rng = np.random.default_rng(5)
        pending: np.ndarray | None = None
        next_at = time.monotonic()
        while not self.stopped.is_set():
            if pending is None and self.cue.is_set():
                pending, self.cue = self.samples, threading.Event()  # said once
            if pending is not None and len(pending):
                block, pending = pending[:BLOCK], pending[BLOCK:]
                block = np.pad(block, (0, BLOCK - len(block)))
            else:
                block = rng.normal(0, 8, BLOCK).astype(np.int16)
            self.deliver(block.astype("<i2").tobytes())
            next_at += BLOCK / RATE
            time.sleep(max(0.0, next_at - time.monotonic()))

    def stop(self) -> None:
        self.stopped.set()
        self.thread.join()

    def close(self) -> None:
        pass


def visitor_drawing_a_ball(tmp_path: Path) -> Path:
    """A visitor draws a ball, stays a few seconds (talking), and presses the end zone."""
    return write_capture(visits([Stroke.circle(on_canvas(0.3, 0.4), 0.05, aspect=1.6)], [Stroke(END)],
                                pause_s=5.0), tmp_path / "ball.hid")


def waiting_for(heard: threading.Event, capture: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The kiosk's replay of ``capture`` waits, before the last report of the visitor's drawing, until ``heard``:
    the replay's clock stands at that report's time meanwhile, so the words are taken as said just after the
    drawing however long a loaded machine takes to recognise them (their "just after" is 5 s of input time)."""
    events = Capture.from_file(capture).events
    gaps = [b.t - a.t for a, b in itertools.pairwise(events)]
    last_drawn = gaps.index(max(gaps))  # the pause between the drawing and the end zone
    make_source = kiosk_command._replay_source

    def gated_source(*args, **kwargs):
        source, device, header = make_source(*args, **kwargs)
        start = source.start

        class Gate(queue.Queue):
            reports = 0

            def put(self, item, block=True, timeout=None) -> None:
                if isinstance(item, RawReport):
                    if self.reports == last_drawn:  # (never heard: on after the hang guard, and the test fails)
                        heard.wait(HANG_GUARD)
                    self.reports += 1
                self.out.put(item)

        def gated_start(out) -> None:
            gate = Gate()
            gate.out = out
            start(gate)

        source.start = gated_start
        return source, device, header

    monkeypatch.setattr(kiosk_command, "_replay_source", gated_source)


def test_a_spoken_label_during_a_session_is_journaled_and_labels_what_was_drawn(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    cue, heard = threading.Event(), threading.Event()
    said = read_wav(SPEECH / "cmd00_0.wav")  # "label ball"
    monkeypatch.setattr(kiosk_speech, "sounddevice_stream",
                        lambda: (lambda deliver: LiveRecording(said, cue, deliver)))
    logged: list[str] = []
    real_print = print

    def watching_print(*args: object, **kwargs: object) -> None:
        line = " ".join(str(a) for a in args)
        logged.append(line)
        if "started" in line:  # the visitor's first touch began a session: they speak now
            cue.set()
        if "heard" in line:
            heard.set()
        real_print(*args, **kwargs)

    monkeypatch.setattr("builtins.print", watching_print)
    out = tmp_path / "out"
    capture = visitor_drawing_a_ball(tmp_path)
    waiting_for(heard, capture, monkeypatch)
    assert main(["kiosk", "--out", str(out), "--replay", str(capture), "--speech", "--video-size", "160x100"]) == 0
    assert any("listening for spoken labels" in line for line in logged)
    assert any('heard "label ball"' in line for line in logged)
    (folder,) = SessionStore(out).sessions()
    says = [e for e in read_journal(folder / JOURNAL).entries if isinstance(e, SayEntry)]
    assert [s.text for s in says] == ["label ball"]
    project = load_project(folder / "project.json")
    assert [b.label for b in project.scene.bodies()] == ["ball"]


def test_speech_with_a_fast_replay_is_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["kiosk", "--out", str(tmp_path / "out"), "--replay", str(visitor_drawing_a_ball(tmp_path)),
                 "--speech", "--speed", "10"]) == 2
    assert "--speech listens in real time" in capsys.readouterr().err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_without_a_microphone_the_kiosk_says_so_and_records(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                             monkeypatch: pytest.MonkeyPatch) -> None:
    def no_microphone() -> Callable[[Callable[[bytes], None]], object]:
        def open_stream(deliver: Callable[[bytes], None]) -> object:
            raise MicrophoneError("no microphone: cannot record from the default input device at 16 kHz mono")
        return open_stream

    monkeypatch.setattr(kiosk_speech, "sounddevice_stream", no_microphone)
    out = tmp_path / "out"
    capture = write_capture(visits([Stroke.box(*on_canvas(0.2, 0.2), *on_canvas(0.4, 0.3))]), tmp_path / "box.hid")
    assert main(["kiosk", "--out", str(out), "--replay", str(capture), "--speech", "--video-size", "160x100"]) == 0
    log = capsys.readouterr().out
    assert "kiosk: not listening: no microphone" in log
    (folder,) = SessionStore(out).sessions()
    assert (folder / "project.json").exists()
