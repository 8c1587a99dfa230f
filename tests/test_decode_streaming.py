"""Decoding a capture a chunk at a time gives what one batch over the whole capture gives, samples and counts."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest
from shared_data import shared_path

from physink_tui.commands.decode import decode_capture, decoder_for, summary
from physink_tui.errors import PhysinkError
from physink_tui.input.captures.capture import Capture
from physink_tui.input.captures.parser import parse_capture_file
from physink_tui.input.hid.chunks import decode_in_chunks

HID_DIR = shared_path("hid", module_level=True)
RECORDED = Path(__file__).resolve().parent / "recorded_hid"
FILES = sorted(HID_DIR.glob("*.hid"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_chunks_decode_as_one_batch(path) -> None:
    capture = Capture.from_file(path)
    try:
        whole = decode_capture(capture)
    except PhysinkError:
        return  # a capture with no pen report is a one-line PhysinkError: nothing to format, which is right
    with open(path, "rb") as f:
        cols = parse_capture_file(f, str(path), chunk_bytes=4096)  # lines cut at many chunk boundaries
    assert cols.bad_lines == capture.bad_lines and cols.devices == capture.devices
    chunked = []
    for device in cols.devices:
        times, lines, take = cols.of_device(device.index)
        decoder = decoder_for(device)
        parts = list(decode_in_chunks(decoder, times, take, lines, chunk=997))
        chunked.append((device.index, decoder, parts))
    assert summary(cols, [(i, d, None) for i, d, _ in chunked]) == summary(capture, whole)
    for (_, _, ref), (_, _, parts) in zip(whole, chunked, strict=True):
        for name in ("t", "x", "y", "p", "tip", "range", "eraser", "b1", "b2", "tilt_x", "tilt_y", "report", "index"):
            got = np.concatenate([getattr(c, name) for c in parts])
            np.testing.assert_array_equal(got, getattr(ref, name), err_msg=name)


def test_a_file_without_a_final_newline_and_with_a_bom_reads_as_text() -> None:
    text = "\ufeff# note\nR: 2 a1 c0\nE: 0.5 2 01 ff\nE: 1.5 2 01 fe\nE: bad\nE: 2.0 1 01"
    cols = parse_capture_file(io.BytesIO(text.encode()), None, chunk_bytes=7)
    ref = Capture.from_text(text)
    assert cols.devices == ref.devices and cols.bad_lines == ref.bad_lines
    assert cols.reports(np.arange(len(cols))) == [e.data for e in ref.events]
    assert cols.line.tolist() == [e.line for e in ref.events] == [3, 4, 6]


@pytest.mark.parametrize("fmt", ["jsonl", "text"])
def test_two_devices_stream_as_the_whole_capture_decodes(tmp_path, capsys, fmt) -> None:
    """Two devices with interleaved reports: `physink decode` writes device 0's samples, then device 1's, in the
    format the whole-capture path gives, with the same summary."""
    from physink_tui.cli import main
    from physink_tui.commands.decode import TEXT_HEADER, write_jsonl, write_text

    lines = (RECORDED / "uclogic-v1-strokes.hid").read_text().splitlines()
    header = [x for x in lines if not x.startswith("E:")]
    events = [x for x in lines if x.startswith("E:")]
    text = "D: 0\n" + "\n".join(header) + "\nD: 1\n" + "\n".join(header) + "\n"
    for k in range(0, len(events), 50):
        text += f"D: {k // 50 % 2}\n" + "\n".join(events[k:k + 50]) + "\n"
    path = tmp_path / "two.hid"
    path.write_text(text)
    capture = Capture.from_file(path)
    whole = decode_capture(capture)
    expected = io.StringIO()
    for _, _, cols in whole:
        (write_jsonl if fmt == "jsonl" else write_text)(cols, expected)
    assert main(["decode", str(path), "--format", fmt]) == 0
    out, err = capsys.readouterr()
    assert out == expected.getvalue() and (fmt == "jsonl" or out.count(TEXT_HEADER) == 2)
    assert err.strip() == summary(capture, whole)
    assert "device 1" in err


def test_a_bad_second_descriptor_stops_decode_before_any_output(tmp_path, capsys) -> None:
    from physink_tui.cli import main

    lines = (RECORDED / "uclogic-v1-strokes.hid").read_text().splitlines()
    path = tmp_path / "bad.hid"
    path.write_text("D: 0\n" + "\n".join(lines) + "\nD: 1\nR: 4 05 0d c0 c0\nN: Broken\n")
    assert main(["decode", str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and "device 1 (Broken)" in err
