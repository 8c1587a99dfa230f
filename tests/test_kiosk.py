"""The kiosk (`physink kiosk`, issue 17) on replayed captures of visitors drawn with the virtual pen: one session per
visitor, hot zones as buttons that never draw, idle endings, the outputs of each session complete and equal to a
replay of its journal, retiring, recovery of an unfinished session, and a full disk."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import av
import pytest
from kiosk.captures import END, ball_and_platform, box_then_undo, on_canvas, visits, write_capture

from physink_tui.cli import main
from physink_tui.formats.journal.entries import HidEntry, JournalDevice
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.project.files import load_project
from physink_tui.input.captures.capture import Capture
from physink_tui.input.pen.state import TipThresholds
from physink_tui.input.virtual_pen import Stroke
from physink_tui.kiosk.controls import HOLD, PASS, PRESS, ControlFilter
from physink_tui.kiosk.folder_files import JOURNAL, SUMMARY
from physink_tui.kiosk.hot_zones import HotZoneError, default_zones, parse_zones
from physink_tui.kiosk.store import SessionStore, parse_size


def kiosk(out: Path, capture: Path, *extra: str, speed: float = 20.0) -> int:
    return main(["kiosk", "--out", str(out), "--replay", str(capture), "--speed", str(speed),
                 "--video-size", "160x100", *extra])


def index(out: Path) -> list[dict]:
    return [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]


def commands(folder: Path) -> list[tuple[str, tuple]]:
    from physink_tui.formats.journal.entries import CommandEntry

    return [(e.name, e.args) for e in read_journal(folder / JOURNAL).entries if isinstance(e, CommandEntry)]


# -- hot zones ---------------------------------------------------------------------------------------------------------


def test_a_zones_file_is_read_and_its_mistakes_are_named() -> None:
    zones = parse_zones('{"area": [0, 0.1, 1, 1], "zones": [{"action": "end", "x0": 0.5, "y0": 0, "x1": 1, '
                        '"y1": 0.1}]}', "z.json")
    assert zones.at(0.7, 0.05).action == "end" and zones.at(0.2, 0.05) is None and zones.area == (0, 0.1, 1, 1)
    with pytest.raises(HotZoneError, match=r"z.json: line 1: not JSON"):
        parse_zones("{", "z.json")
    with pytest.raises(HotZoneError, match=r"z.json: zones\[0\].action is 'jump'; expected one of mode"):
        parse_zones('{"zones": [{"action": "jump", "x0": 0, "y0": 0, "x1": 1, "y1": 1}]}', "z.json")
    with pytest.raises(HotZoneError, match=r"expected x0 < x1 and y0 < y1"):
        parse_zones('{"zones": [{"action": "end", "x0": 0.5, "y0": 0, "x1": 0.2, "y1": 1}]}', "z.json")
    with pytest.raises(HotZoneError, match=r"area\[2\] is 1.5; expected a number from 0 to 1"):
        parse_zones('{"area": [0, 0, 1.5, 1], "zones": [{"action": "end", "x0": 0, "y0": 0, "x1": 1, "y1": 1}]}',
                    "z.json")
    assert parse_size("2G") == 2_000_000_000 and parse_size("500m") == 500_000_000
    with pytest.raises(ValueError, match="not a size"):
        parse_size("lots")


def _verdicts(strokes: list[Stroke]) -> list[str]:
    capture = visits(strokes)
    d = capture.devices[0]
    controls = ControlFilter(JournalDevice("tablet0", d.name, d.bus, d.vid, d.pid, d.descriptor), default_zones(),
                             TipThresholds())
    return [controls.report(e.data, e.t).what for e in capture.events]


def test_a_tap_in_a_zone_presses_its_button_and_no_report_of_it_reaches_the_session() -> None:
    verdicts = _verdicts([Stroke(END)])
    assert verdicts.count(PRESS) == 1
    touched = verdicts.index(HOLD)
    assert set(verdicts[touched:verdicts.index(PRESS) + 1]) == {HOLD, PRESS}  # from the touch to the lift
    assert set(verdicts[:touched]) == {PASS}  # hovering in is passed on


def test_a_stroke_begun_on_the_canvas_stays_a_stroke_when_it_crosses_into_a_zone() -> None:
    verdicts = _verdicts([Stroke((on_canvas(0.8, 0.3), (0.875, 0.02)))])
    assert set(verdicts) == {PASS}


# -- sessions ----------------------------------------------------------------------------------------------------------


def test_each_visitor_becomes_a_session_with_every_output_and_its_journal_replays_to_the_same_project(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    capture = write_capture(visits(ball_and_platform(), box_then_undo()), tmp_path / "visits.hid")
    out = tmp_path / "out"
    assert kiosk(out, capture) == 0
    log = capsys.readouterr().out
    first, second = index(out)
    assert first["ended"] == "end zone" and second["ended"] == "capture ended"
    assert first["bodies"] == 2 and first["events"] > 0 and second["bodies"] == 1  # the circle was undone
    a, b = (out / first["session"]), (out / second["session"])
    assert ("mode", ("demo",)) in commands(a) and ("undo", ()) in commands(b)
    assert "end" not in [name for name, _ in commands(a)][:-1]  # the end zone ends; the journal's end is the last
    for folder, record in ((a, first), (b, second)):
        assert set(record["files"]) == {p.name for p in folder.iterdir()}
        assert json.loads((folder / SUMMARY).read_text()) == record
        assert main(["replay", str(folder / JOURNAL), "--out", str(tmp_path / "again")]) == 0
        assert (tmp_path / "again" / "project.json").read_bytes() == (folder / "project.json").read_bytes()
        with av.open(str(folder / "video.mp4")) as video:
            assert sum(1 for _ in video.decode(video=0)) > 0
    assert "Contact between" in (a / "narration.txt").read_text()
    assert f"session {first['session']} started" in log and "kiosk: mode demo" in log
    # the taps on the strip drew nothing: the bodies are the ball (high up) and the platform, none at the top edge
    scene = load_project(a / "project.json").scene
    assert sorted(round(b.position[1] / 1000, 1) for b in scene.bodies()) == [0.2, 0.6]


def test_a_visitor_who_walks_away_is_ended_by_the_idle_time_and_the_next_one_gets_a_new_session(
        tmp_path: Path) -> None:
    capture = write_capture(visits(box_then_undo(), ball_and_platform(), pause_s=10.0), tmp_path / "visits.hid")
    out = tmp_path / "out"
    assert kiosk(out, capture, "--idle", "2", speed=5.0) == 0  # 1.6 s of wall time between the idle end and B
    assert [r["ended"] for r in index(out)] == ["idle", "end zone"]


def test_keep_retires_the_oldest_finished_sessions(tmp_path: Path) -> None:
    capture = write_capture(visits(ball_and_platform(), ball_and_platform()), tmp_path / "visits.hid")
    out = tmp_path / "out"
    assert kiosk(out, capture, "--keep", "1") == 0
    records = index(out)
    kept = [p.name for p in SessionStore(out).sessions()]
    assert len(kept) == 1 and kept[0] == records[1]["session"]
    assert {"session": records[0]["session"], "retired": True} in records


def test_an_unfinished_session_is_recovered_and_finalised_before_new_sessions(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    capture = write_capture(visits(ball_and_platform()), tmp_path / "visits.hid")
    done = tmp_path / "done"
    assert kiosk(done, capture) == 0
    capsys.readouterr()
    (record,) = index(done)
    out = tmp_path / "out"
    crashed = out / "20260101T000000Z"
    crashed.mkdir(parents=True)
    journal = (done / record["session"] / JOURNAL).read_bytes()
    line_start = journal.rindex(b"\n", 0, len(journal) * 2 // 3) + 1
    (crashed / JOURNAL).write_bytes(journal[: line_start + 5])  # killed mid-session, five bytes into a line
    assert kiosk(out, write_capture(visits([Stroke.box(*on_canvas(0.1, 0.1), *on_canvas(0.3, 0.2))]),
                                    tmp_path / "one.hid")) == 0
    log = capsys.readouterr().out
    assert "recovering unfinished session 20260101T000000Z" in log and "torn" in log
    recovered, new = index(out)
    assert recovered["session"] == crashed.name and recovered["recovered"] and recovered["ended"] == "recovered"
    assert (crashed / "video.mp4").exists() and (crashed / "project.json").exists()
    assert new["recovered"] is False
    assert log.index("recovering") < log.index(f"session {new['session']} started")


def test_a_full_disk_stops_recording_with_a_clear_line(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(SessionStore, "free_bytes", lambda self: 1_000_000)
    capture = write_capture(visits(ball_and_platform()), tmp_path / "visits.hid")
    out = tmp_path / "out"
    assert kiosk(out, capture) == 0
    assert "not recording: only 1 MB free" in capsys.readouterr().out
    assert SessionStore(out).sessions() == []


def test_kiosk_refuses_a_bad_zones_file_naming_it(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    zones = tmp_path / "zones.json"
    zones.write_text('{"zones": []}')
    assert main(["kiosk", "--out", str(tmp_path / "o"), "--replay", "x.hid", "--hot-zones", str(zones)]) == 1
    assert f"{zones}: expected an object with a non-empty list" in capsys.readouterr().err
    shutil.rmtree(tmp_path / "o", ignore_errors=True)


def test_the_committed_sample_capture_is_what_the_script_makes() -> None:
    from kiosk.captures import SAMPLE, sample_text

    assert SAMPLE.read_text(encoding="utf-8") == sample_text()


def test_the_systemd_unit_runs_a_kiosk_command_line_that_parses() -> None:
    from physink_tui.cli import build_parser

    unit = (Path(__file__).resolve().parents[1] / "packaging" / "systemd" / "physink-kiosk.service").read_text()
    (exec_start,) = [line for line in unit.splitlines() if line.startswith("ExecStart=")]
    argv = exec_start.removeprefix("ExecStart=").split()
    assert argv[0].endswith("/physink")
    args = build_parser().parse_args(argv[1:])
    assert args.command == "kiosk" and args.out == "/var/lib/physink-kiosk/sessions" and args.replay is None
    assert "Restart=on-failure" in unit and "SupplementaryGroups=plugdev" in unit and "KillSignal=SIGTERM" in unit


def test_pad_buttons_switch_to_demo_and_end_the_session(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A Huion in its vendor mode: button 1 (sketch/demo) and button 4 (end session), as the default pad says."""
    ball, platform, _, drag, _ = ball_and_platform()
    capture = write_capture(visits([ball, platform, (1,), drag, (4,)], [ball], device="huion-v2"),
                            tmp_path / "pad.hid")
    out = tmp_path / "out"
    assert kiosk(out, capture) == 0
    first, second = index(out)
    assert first["ended"] == "end button" and first["events"] > 0 and second["ended"] == "capture ended"
    assert commands(out / first["session"])[0] == ("mode", ("demo",))
    journal = read_journal(out / first["session"] / JOURNAL)
    assert not any(isinstance(e, HidEntry) and e.data[1] == 0xE0 for e in journal.entries)  # pad reports held back
    assert "kiosk: mode demo" in capsys.readouterr().out


def test_a_zones_file_gives_the_pad_buttons_other_actions(tmp_path: Path) -> None:
    zones = parse_zones('{"zones": [{"action": "end", "x0": 0, "y0": 0, "x1": 1, "y1": 0.05}], '
                        '"pad": {"2": "clear"}}', "z.json")
    assert zones.pad_action(2) == "clear" and zones.pad_action(1) is None
    with pytest.raises(HotZoneError, match=r"pad\['1'\] is 'fly'"):
        parse_zones('{"zones": [{"action": "end", "x0": 0, "y0": 0, "x1": 1, "y1": 1}], "pad": {"1": "fly"}}', "z")


def test_a_disk_that_fills_mid_session_stops_the_journal_with_a_clear_line_and_keeps_what_was_written(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    import errno

    from physink_tui.formats.journal import writer

    real_write, calls = writer._write, [0]

    def filling(fd: int, data: bytes, start: int) -> int:
        calls[0] += 1
        if calls[0] > 400:  # the header and a few hundred reports fit, then the disk is full
            raise OSError(errno.ENOSPC, "No space left on device")
        return real_write(fd, data, start)

    monkeypatch.setattr(writer, "_write", filling)
    capture = write_capture(visits(ball_and_platform()), tmp_path / "visits.hid")
    out = tmp_path / "out"
    assert kiosk(out, capture) == 0
    log = capsys.readouterr().out
    assert "recording stopped for session" in log and "No space left on device" in log
    (folder,) = SessionStore(out).sessions()
    journal = read_journal(folder / JOURNAL)
    assert journal.truncated is None and not journal.warnings and 300 < len(journal.entries) < 400
    assert (folder / SUMMARY).exists()  # what was journaled is still finished into outputs


class _Unplugging:
    """A tablet that sends one visitor's first strokes, is unplugged (its reader ends with an error), then is
    plugged back and sends the rest — as `ReconnectingSource` passes such a device on."""

    def __init__(self, capture, cut: int) -> None:
        from physink_tui.input.scripted_sources import CaptureReplaySource

        self.device_id = "tablet0"
        self._parts = (Capture(capture.devices, capture.events[:cut]), Capture(capture.devices, capture.events[cut:]))
        self._sources = [CaptureReplaySource(part, realtime=True, speed=20.0) for part in self._parts]

    def start(self, out) -> None:
        import queue as queue_module
        import threading

        from physink_tui.errors import DeviceError
        from physink_tui.input.sources import SourceEnded

        def run() -> None:
            for k, source in enumerate(self._sources):
                items: queue_module.Queue = queue_module.Queue()
                source.start(items)
                while not isinstance(item := items.get(), SourceEnded):
                    out.put(item)
                source.stop()
                if k == 0:
                    out.put(SourceEnded(item.t, self.device_id, DeviceError("tablet0: the device went away")))
            out.put(SourceEnded(0.0, self.device_id, None))

        threading.Thread(target=run, daemon=True).start()

    def stop(self) -> None:
        for source in self._sources:
            source.stop()


def test_an_unplugged_tablet_pauses_the_session_and_plugging_it_back_resumes_it(tmp_path: Path) -> None:
    import time

    from physink_tui.input.journal_compose import header_for_capture
    from physink_tui.kiosk.service import Kiosk, KioskSettings
    from physink_tui.render.export import Look

    capture = visits(ball_and_platform())
    cut = len(capture.events) // 3
    lines: list[str] = []
    out = tmp_path / "out"
    k = Kiosk(SessionStore(out), default_zones(), KioskSettings(look=Look(160, 100, 10)), lines.append)
    d = capture.devices[0]
    device = JournalDevice("tablet0", d.name, d.bus, d.vid, d.pid, d.descriptor)
    start = time.monotonic()
    assert k.run(_Unplugging(capture, cut), device, header_for_capture(Capture((d,), ())), replay=True,
                 clock=lambda: (time.monotonic() - start) * 20.0) == 0
    assert any("went away" in line for line in lines)
    (record,) = index(out)  # one session across the unplugging
    assert record["ended"] == "end zone" and record["bodies"] == 2
