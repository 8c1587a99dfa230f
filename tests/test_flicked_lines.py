"""Lines flicked with a Tablet PC pen, bowed one way by the swing of the wrist (issue 25, session 36: the `sign` set's
ST5022 writers): a fast stroke bows 5-9 % of its chord, deepest about its middle, bent at one end and straight at the
other, not evenly as an arc does (no circle explains the bow), and it is a line (`open_marks.flicked`, asked by
`open_marks.swung_line`), by the rules and with the learned ranker. An arc drawn as shallow, which a circle fits, stays
an arc.

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/sign.jsonl`, as `test_open_marks.py`
reads the public sets) and skip without it, saying so; the arcs are the stroke generator's, so they never skip.
"""

from __future__ import annotations

import random

import pytest
from sign_rows import assert_read_as, sign_id, sign_row
from strokegen import strokes as gen
from test_swung_lines import SWUNG

from physink_tui.scene.recognition.recognize import recognize_stroke

FLICKED = [
    "writer001/sessionB/diagonal_upRight-1-9.json",
    "writer002/sessionA/diagonal_downLeft-1-2.json",
    "writer002/sessionD/diagonal_upRight-1-4.json",
    "writer004/sessionC/diagonal_downLeft-1-24.json",
    "writer005/sessionD/diagonal_upRight-1-18.json",
    "writer008/sessionD/diagonal_upRight-1-13.json",
    "writer001/sessionC/left-1-0.json",
    "writer004/sessionC/left-1-19.json",
]
"""ST5022 writers' lines (tuning writers) read as arcs at main 02d2055."""


@pytest.mark.parametrize("file", FLICKED, ids=[sign_id(f) for f in FLICKED])
def test_a_writers_flicked_line_is_a_line(file: str) -> None:
    assert_read_as(sign_row(file), "line")


def test_a_shallow_arc_is_not_taken_for_a_flicked_line() -> None:
    """Arcs of 20-40 degrees (`strokegen.strokes.arc`: a radius wobbling 1 %, the pen's noise) bow 4-9 % of their chord,
    as deep as a flicked line, and turn one way, but a circle fits their bow: none is read as a swung line (0 of 200
    when written)."""
    taken = []
    for sweep in (20, 25, 30, 35, 40):
        for seed in range(40):
            found = recognize_stroke([p[:2] for p in gen.arc(random.Random(f"flicked-arc:{sweep}:{seed}"),
                                                             sweep_deg=sweep)])
            if (found.kind, found.alternatives) == SWUNG:
                taken.append((sweep, seed))
    assert not taken, taken
