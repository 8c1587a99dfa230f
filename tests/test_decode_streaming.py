"""Decoding a capture a chunk at a time gives what one batch over the whole capture gives, samples and counts."""

from __future__ import annotations

import io

import numpy as np
import pytest
from shared_data import shared_path

from physink_tui.commands.decode import decode_capture, decoder_for, summary
from physink_tui.errors import PhysinkError
from physink_tui.input.capture import Capture
from physink_tui.input.capture_parser import parse_capture_file
from physink_tui.input.hid_chunks import decode_in_chunks

HID_DIR = shared_path("hid", module_level=True)
FILES = sorted(HID_DIR.glob("*.hid"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_chunks_decode_as_one_batch(path) -> None:
    capture = Capture.from_file(path)
    try:
        whole = decode_capture(capture)
    except PhysinkError:
        pytest.skip("this capture does not decode")
    with open(path, "rb") as f:
        cols = parse_capture_file(f, str(path), chunk_bytes=4096)  # lines cut at many chunk boundaries
    assert cols.bad_lines == capture.bad_lines and cols.devices == capture.devices
    chunked = []
    for device in cols.devices:
        rows = cols.rows_of(device.index)
        decoder = decoder_for(device)
        parts = list(decode_in_chunks(decoder, cols.t[rows], lambda a, b, r=rows: cols.reports(r[a:b]),
                                      cols.line[rows], chunk=997))
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
