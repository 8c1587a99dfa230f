"""The `sign` set's strokes (the cached public set, read as `test_open_marks.cached_rows` reads it) by their file
under a writer, and the two checks the sign tests make of one: read alone, and drawn through a whole session."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from drawn_strokes import drawn_person_stroke
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

SIGN = "public-sets/sign.jsonl"
GESTER = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"


def sign_id(file: str) -> str:
    """A test id for a `sign` file (``writer004/sessionA/left-1-12.json`` -> ``writer004/A/left-1-12``)."""
    return file.replace("/session", "/").replace(".json", "")


def sign_row(file: str) -> dict:
    """The row of ``file`` (under `GESTER`) in the cached `sign` set; skips without the cache."""
    row = cached_rows(SIGN).get(GESTER + file)
    assert row is not None, f"{file} is not in {SIGN}"
    return row


def assert_read_as(row: dict, kind: str) -> None:
    """The row's stroke, as drawn and timed, is read as ``kind`` by the rules alone and with the learned ranker."""
    points, times = _stroke(row)
    assert recognize_stroke(points, times, learned=False).kind == kind
    assert recognize_stroke(points, times).kind == kind


def assert_body_through_a_session(row: dict, kind: str, folder: Path) -> None:
    """The row's stroke drawn 300 px across by the careful virtual pen through the thesis device, journal -> replay
    -> project (`drawn_strokes.drawn_person_stroke`), is one body of ``kind``."""
    shapes, told = drawn_person_stroke(np.asarray(_stroke(row)[0], dtype=float), folder)
    assert shapes == [kind], told
