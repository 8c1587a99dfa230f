"""The column-at-a-time ``E:`` reader gives what the line-by-line checks give, or leaves the run to them."""

from __future__ import annotations

import random

import pytest

from physink_tui.input.captures.capture import Capture
from physink_tui.input.captures.events import strict_events

VARIANTS = [
    "E: 000001.959698 3 01 a0 FF", "E: 1.959698 3 01 a0 ff", "E: 9 3 01 02 03", "E: 0.000001 1 7f",
    "E: 000003.000100 4 02 00 10 00", "E: 1.5 3 01 02 03  ", "E: 1.5 3 01 02 03\r", "E: 1.5 3 0102 03",
    "E: 1.5 2 01 02 03", "E: 1.5 0", "E: 1. 1 01", "E: .5 1 01", "E: 1.5 1 0g", "E: 99999999999 1 01",
    "E: 123456789012.1234567 1 01", "E:  1.5 1 01", "E: 1.5 1 01 ", "E: 1.5 x 01", "E: 2.25 2 aB Cd",
]


def _reference(line: str) -> tuple[float, bytes] | None:
    """What the hid-recorder format means by a line (None: not an event)."""
    parts = line.strip()[2:].split(None, 2)
    try:
        t, data = float(parts[0]), bytes.fromhex(parts[2] if len(parts) == 3 else "")
        ok = parts[0].replace(".", "", 1).isdigit() and not parts[0].startswith(".") and not parts[0].endswith(".")
    except (ValueError, IndexError):
        return None
    return (t, data) if ok and parts[1].isdigit() and int(parts[1]) == len(data) and t <= 1e7 else None


@pytest.mark.parametrize("seed", range(40))
def test_runs_of_mixed_lines_read_as_one_by_one(seed) -> None:
    """Times stay within `GLITCH_SECONDS` of each other: no report is dropped as a glitch."""
    rng = random.Random(seed)
    lines = [rng.choice(VARIANTS) for _ in range(rng.randint(1, 30))]
    capture = Capture.from_text("R: 2 a1 c0\n" + "\n".join(lines) + "\n")
    expected = [(k + 2, *ref) for k, line in enumerate(lines) if (ref := _reference(line)) is not None]
    assert [(e.line, e.t, e.data) for e in capture.events] == expected
    assert len(capture.bad_lines) == len(lines) - len(expected)


def test_strict_runs_are_read_in_columns_and_others_left_alone() -> None:
    t, lengths, blob = strict_events(["E: 000001.959698 3 01 a0 FF", "E: 2.5 1 7f", "E: 12 2 00 01"], 1e7)
    assert t.tolist() == [1.959698, 2.5, 12.0] and lengths.tolist() == [3, 1, 2]
    assert blob == bytes.fromhex("01a0ff7f0001")
    for line in ("E: 1.5 2 01 02 03", "E: 1.5 3 01 02 03 ", "E: 1. 1 01", "E: 20000000 1 01", "E: 1.5 1 0g"):
        assert strict_events(["E: 1 1 00", line], 1e7) is None
