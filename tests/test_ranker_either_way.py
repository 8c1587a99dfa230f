"""The learned ranker's corner roundness and bends measured alike from either end (issue 25, session 31): a stroke and
its reverse give the ranker the same ``max_roundness``, ``mean_roundness`` and ``max_bend``
(`stroke_features.roundness_either_way`, `bends_either_way`); the rules keep `corner_roundness` and `bends`."""

from __future__ import annotations

import numpy as np
import pytest
from test_mirrored_marks import _wavy_path
from test_open_marks import _stroke, cached_rows
from test_people_strokes import people_rows

from physink_tui.scene.recognition import ranker
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg

EITHER_WAY = ("max_roundness", "mean_roundness", "max_bend")
"""The ranker's features measured alike from either end here."""


@pytest.mark.parametrize("seed", range(8))
def test_roundness_and_bends_are_the_same_from_either_end(seed: int) -> None:
    pts = _wavy_path(seed)
    corners = sg.find_corners(pts, every_dip=True)
    last = len(pts) - 1
    rev, rev_corners = pts[::-1].copy(), [last - c for c in reversed(corners)]
    np.testing.assert_allclose(sf.roundness_either_way(rev, rev_corners)[::-1], sf.roundness_either_way(pts, corners),
                               rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(sf.bends_either_way(sg.turning(rev), rev_corners)[::-1],
                               sf.bends_either_way(sg.turning(pts), corners), rtol=1e-9, atol=1e-9)


def test_a_bends_last_segment_counts_its_last_turn() -> None:
    """`bends_either_way` differs from `bends` only in the last segment, which runs to the last point that turns."""
    pts = _wavy_path(3)
    th = sg.turning(pts)
    corners = sg.find_corners(pts, every_dip=True)
    assert sf.bends_either_way(th, corners)[:-1] == sf.bends(th, corners)[:-1]


PEOPLE = {
    "hcira": ["klarubbio/hcira_p1@e8eb332:xml/s06/left_curly_brace09.xml",
              "klarubbio/hcira_p1@e8eb332:xml/s07/pigtail05.xml",
              "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/right square bracket3.xml"],
}
"""People's strokes whose ranker roundness or bends leaned with direction at 54414db (`bench_reversed.py`: a brace
and a pigtail read differently reversed through them; the bracket sat at the ranker's margin when they were first
measured alike without a refit, session 30)."""


def _either_way_features(points: list[list[float]]) -> tuple[np.ndarray, np.ndarray]:
    idx = [ranker.FEATURES.index(f) for f in EITHER_WAY]
    return ranker.features(points, None)[idx], ranker.features(points[::-1], None)[idx]


@pytest.mark.parametrize("file", PEOPLE["hcira"], ids=lambda f: f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1])
def test_a_persons_stroke_gives_the_ranker_the_same_roundness_reversed(file: str) -> None:
    row = cached_rows("public-sets/hcira.jsonl").get(file)
    assert row is not None, file
    forward, backward = _either_way_features(_stroke(row)[0])
    np.testing.assert_allclose(backward, forward, rtol=1e-9, atol=1e-12)


def test_the_dollar1_question_mark_gives_the_ranker_the_same_roundness_reversed() -> None:
    """dollar1 s02 medium question_mark05: a curve as drawn and a polyline reversed at 54414db through the ranker."""
    row = next(r for r in people_rows() if r["file"] == "s02/medium/question_mark05.xml")
    forward, backward = _either_way_features([p[:2] for p in row["strokes"][0]])
    np.testing.assert_allclose(backward, forward, rtol=1e-9, atol=1e-12)
