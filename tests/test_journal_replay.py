"""`physink replay` of journals: HID lines through their device, pen lines, commands and speech, truncation."""

from __future__ import annotations

import json
from pathlib import Path

from physink_tui.cli import main
from physink_tui.formats.journal.entries import CommandEntry, PenEntry, SayEntry
from physink_tui.input.captures.capture import Capture
from physink_tui.input.journal_compose import capture_entries, header_for_capture, write_journal

RECORDED = Path(__file__).resolve().parent / "recorded_hid"


def make_journal(path: Path) -> None:
    capture = Capture.from_file(RECORDED / "huion-v2-strokes.hid")
    mouse = [PenEntry(20.0 + 0.01 * i, 0.1 + 0.01 * i, 0.9, 0.5 if 0 < i < 30 else 0.0, 0 < i < 30, True,
                      False, False, False) for i in range(31)]
    commands = [CommandEntry(12.0, "mode", ("demo",)), SayEntry(13.5, "label ball"),
                CommandEntry(14.0, "seek", (1.5,))]
    write_journal(path, header_for_capture(capture), capture_entries(capture), mouse, commands)


def test_journal_replay_gives_tablet_and_mouse_strokes_and_lists_commands(tmp_path, capsys) -> None:
    journal = tmp_path / "s.physink.jsonl"
    make_journal(journal)
    assert main(["replay", str(journal), "--out", str(tmp_path / "out")]) == 0
    out, err = capsys.readouterr()
    rows = [json.loads(line) for line in (tmp_path / "out" / "gestures.jsonl").read_text().splitlines()]
    strokes = [r for r in rows if r["gesture"] == "stroke"]
    assert len(strokes) == 5  # the capture's four and the mouse's one
    assert strokes[-1]["points"][0][1] == 0.9
    assert "command       mode demo" in out and "said          'label ball'" in out
    lines = out.splitlines()
    assert lines.index(next(x for x in lines if "mode demo" in x)) < lines.index(next(x for x in lines if "said" in x))
    assert "5 strokes" in err


def test_truncated_journal_replays_what_came_before(tmp_path, capsys) -> None:
    journal = tmp_path / "cut.physink.jsonl"
    make_journal(journal)
    data = journal.read_bytes()
    journal.write_bytes(data[: data.rindex(b"\n", 0, len(data) - 1) + 20])  # cut inside the last line
    assert main(["replay", str(journal), "--out", str(tmp_path / "out")]) == 0
    err = capsys.readouterr().err
    assert "incomplete" in err


def test_malformed_journal_line_is_one_line_error(tmp_path, capsys) -> None:
    journal = tmp_path / "bad.physink.jsonl"
    make_journal(journal)
    lines = journal.read_text().splitlines()
    lines[5] = lines[5].replace('"t":', '"t":"soon","x":', 1)
    journal.write_text("\n".join(lines) + "\n")
    assert main(["replay", str(journal), "--out", str(tmp_path / "out")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "line 6" in err[0] and "bad.physink.jsonl" in err[0]


def test_journal_is_read_and_decoded_once(tmp_path, capsys, monkeypatch) -> None:
    """The replay lists the gestures the session decoded: each HID line is decoded once, the file read once."""
    from physink_tui.formats.journal import reader
    from physink_tui.input.hid.decoder import HidPenDecoder

    journal = tmp_path / "s.physink.jsonl"
    make_journal(journal)
    hid_lines = sum('"hid"' in line for line in journal.read_text().splitlines())
    decoded, opened = [], []
    real_decode, real_iter = HidPenDecoder.decode, reader.iter_journal
    monkeypatch.setattr(HidPenDecoder, "decode", lambda self, *a, **k: decoded.append(1) or real_decode(self, *a, **k))
    monkeypatch.setattr(reader, "iter_journal", lambda path: opened.append(path) or real_iter(path))
    assert main(["replay", str(journal), "--out", str(tmp_path / "out")]) == 0
    assert len(decoded) == hid_lines and len(opened) == 1
    assert "5 strokes" in capsys.readouterr().err
