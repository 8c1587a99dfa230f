"""`physink replay` of captures: the gestures a user drew, printed and written, the same every time."""

from __future__ import annotations

import json
from pathlib import Path

from physink_tui.cli import main

RECORDED = Path(__file__).resolve().parent / "recorded_hid"


def test_replay_of_a_capture_lists_its_strokes(tmp_path, capsys) -> None:
    assert main(["replay", str(RECORDED / "uclogic-v1-strokes.hid"), "--out", str(tmp_path)]) == 0
    out, err = capsys.readouterr()
    assert out.count(" stroke ") == 4 and "4 strokes" in err
    rows = [json.loads(line) for line in (tmp_path / "gestures.jsonl").read_text().splitlines()]
    strokes = [r for r in rows if r["gesture"] == "stroke"]
    assert len(strokes) == 4
    assert all(len(s["points"]) > 20 and not s["eraser"] and s["ended_by"] == "lift" for s in strokes)
    for s in strokes:
        times = [p[2] for p in s["points"]]
        assert times == sorted(times)
        assert all(0 <= p[0] <= 1 and 0 <= p[1] <= 1 and 0 < p[3] <= 1 for p in s["points"])


def test_replay_is_deterministic(tmp_path, capsys) -> None:
    for name in ("a", "b"):
        assert main(["replay", str(RECORDED / "wacom-ff0d-strokes.hid"), "--out", str(tmp_path / name)]) == 0
    capsys.readouterr()
    assert (tmp_path / "a" / "gestures.jsonl").read_bytes() == (tmp_path / "b" / "gestures.jsonl").read_bytes()


def test_replay_of_a_missing_file_is_one_line(tmp_path, capsys) -> None:
    assert main(["replay", str(tmp_path / "nope.hid"), "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "nope.hid" in err[0]


def test_capture_cut_mid_stroke_still_ends_the_stroke(tmp_path, capsys) -> None:
    lines = (RECORDED / "windows-ink-strokes.hid").read_text().splitlines()
    events = [i for i, line in enumerate(lines) if line.startswith("E:")]
    cut = tmp_path / "cut.hid"
    cut.write_text("\n".join(lines[: events[150]]) + "\n")  # stops while the first line is being drawn
    assert main(["replay", str(cut), "--out", str(tmp_path / "o")]) == 0
    rows = [json.loads(line) for line in (tmp_path / "o" / "gestures.jsonl").read_text().splitlines()]
    strokes = [r for r in rows if r["gesture"] == "stroke"]
    assert len(strokes) == 1 and strokes[0]["ended_by"] == "device-lost"
