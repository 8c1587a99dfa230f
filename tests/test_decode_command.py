"""`physink decode` as a user runs it: output formats, the summary, bad input, determinism."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physink_tui.cli import main

RECORDED = Path(__file__).resolve().parent / "recorded_hid"
KEYS = ["t", "x", "y", "p", "tip", "range", "eraser", "b1", "b2", "tilt_x", "tilt_y", "report"]


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(["decode", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_jsonl_has_the_design_keys_in_order(capsys) -> None:
    code, out, err = run(capsys, str(RECORDED / "windows-ink-strokes.hid"))
    assert code == 0
    rows = [json.loads(line) for line in out.splitlines()]
    assert rows and all(list(r) == KEYS for r in rows)
    assert any(r["tip"] for r in rows) and all(r["report"] == 2 for r in rows)
    assert f"{len(rows)} pen samples" in err


def test_text_format_has_a_header_and_one_line_per_sample(capsys) -> None:
    _, jsonl, _ = run(capsys, str(RECORDED / "huion-v2-strokes.hid"))
    code, text, _ = run(capsys, str(RECORDED / "huion-v2-strokes.hid"), "--format", "text")
    assert code == 0
    lines = text.splitlines()
    assert lines[0].split()[:4] == ["t", "x", "y", "p"]
    assert len(lines) - 1 == len(jsonl.splitlines())


def test_same_capture_gives_identical_bytes(capsys) -> None:
    outs = [run(capsys, str(RECORDED / "wacom-ff0d-strokes.hid"))[1] for _ in range(2)]
    assert outs[0] == outs[1]


def test_damaged_lines_are_counted_and_the_first_is_named(tmp_path, capsys) -> None:
    lines = (RECORDED / "windows-ink-strokes.hid").read_text().splitlines()
    first_event = next(i for i, line in enumerate(lines) if line.startswith("E:"))
    lines[first_event + 5] = "E: 000000.100000 11 02 21 zz"  # garbage hex
    lines[first_event + 9] = "E: 000000.200000 3 02 21 00"  # a truncated report (declared length matches)
    lines.insert(first_event + 12, "X: what is this")
    path = tmp_path / "damaged.hid"
    path.write_text("\n".join(lines) + "\n")
    code, out, err = run(capsys, str(path))
    assert code == 0 and out
    assert "truncated report 0x02" in err
    assert f"first bad line {first_event + 6}:" in err
    assert "2 capture lines skipped" in err


def test_descriptor_without_a_pen_is_one_line_and_exit_1(tmp_path, capsys) -> None:
    path = tmp_path / "mouse.hid"
    path.write_text("R: 7 05 01 09 02 a1 01 c0\nN: Mouse\nI: 3 1234 0001\nE: 000000.000000 1 00\n")
    code, out, err = run(capsys, str(path))
    assert code == 1 and not out
    assert len(err.strip().splitlines()) == 1
    assert "mouse.hid" in err and "no pen report" in err


@pytest.mark.parametrize(
    ("text", "needle"),
    [("", "no"), ("E: 000000.000000 1 00\n", "bad.hid:1:"), ("R: 3 05 01\n", "bad.hid:1:")],
    ids=["empty", "events-before-descriptor", "short-descriptor"],
)
def test_unusable_captures_are_one_line_errors(tmp_path, capsys, text: str, needle: str) -> None:
    path = tmp_path / "bad.hid"
    path.write_text(text)
    code, _, err = run(capsys, str(path))
    assert code == 1
    assert len(err.strip().splitlines()) == 1 and "bad.hid" in err and needle in err


def test_broken_descriptor_names_the_byte_offset(tmp_path, capsys) -> None:
    path = tmp_path / "broken.hid"
    path.write_text("R: 4 05 0d c0 c0\nN: Broken\n")
    code, _, err = run(capsys, str(path))
    assert code == 1 and "End Collection without a matching Collection" in err and "byte 2" in err
