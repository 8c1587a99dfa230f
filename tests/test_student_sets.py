"""The students' gesture sets (benchmarks/student_sets.py) are read at a pinned commit of each repository, their
spellings of the labels unified onto benchmarks/label_kinds.tsv, their clocks kept only where usable, and copies of
the reserved $1 logs refused by name (all made here in miniature, in a local git repository)."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import student_sets
from bench_generalisation import scored_rows
from mirror_repo import commit_mirror
from student_sets import label_of, times_ms

from physink_tui.scene.recognition.recognize import recognize_stroke

REPO = "ITT-99/assignment-06-gesture-recognition-someone"


def _circle_xml(name: str, date: str = "Tuesday, June 16, 2026", seconds: bool = False) -> str:
    pts = [(200 + 60 * math.cos(2 * math.pi * k / 40), 200 + 60 * math.sin(2 * math.pi * k / 40)) for k in range(41)]
    clock = [1781609527.0 + 0.02 * k if seconds else 15 * k for k in range(41)]
    body = "".join(f'<Point X="{x:.0f}" Y="{y:.0f}" T="{t}"/>' for (x, y), t in zip(pts, clock, strict=True))
    return f'<?xml version="1.0"?><Gesture Name="{name}" Subject="1" Date="{date}">{body}</Gesture>'


def _commit(tmp_path: Path, files: dict[str, str]) -> tuple[Path, str]:
    return commit_mirror(tmp_path, REPO, files)


def test_students_spellings_become_the_tables_labels() -> None:
    assert label_of("left-curly-bracket-3.csv") == "left_curly_brace"
    assert label_of("right_sq_brace10.xml") == "right_sq_bracket"
    assert label_of("delete07.xml") == "delete_mark"
    assert label_of("arrow_01.xml") == "arrow"
    assert label_of("zig-zag04.xml") == "zigzag"


def test_a_clock_is_kept_in_ms_only_where_it_can_time_the_stroke() -> None:
    assert times_ms([1000.0, 1015.0, 1031.0]) == [0.0, 15.0, 31.0]
    assert times_ms([1718647446.85, 1718647447.03, 1718647447.05]) == pytest.approx([0.0, 180.0, 200.0], abs=0.5)
    assert times_ms([1718814081.48, 63.0, 130.0]) == [None] * 3  # an epoch, then ms: no clock to trust
    assert times_ms([1718721549.0] * 5 + [1718721550.0] * 5) == [None] * 10  # whole seconds
    assert times_ms([None, None]) == [None, None]


def test_a_students_set_is_read_at_its_commit_by_person_and_scored_by_the_table(tmp_path, monkeypatch) -> None:
    mirrors, head = _commit(tmp_path, {
        "datasets/mine/circle01.xml": _circle_xml("circle01"),
        "datasets/mine/circle02.xml": _circle_xml("circle02", seconds=True),
        "datasets/mine/left-square-bracket-1.csv": ",x,y\n0,10,10\n1,0,10\n2,0,90\n3,10,90\n",
        "datasets/mine/click03.xml": '<Gesture Name="click03"><Point X="1" Y="1" T="0"/></Gesture>',
        "notes/other.xml": _circle_xml("circle09"),  # outside the student's folder: not read
    })
    monkeypatch.setattr(student_sets, "REPOS", ((REPO, head, "datasets/mine"),))
    skipped: list[str] = []
    rows = student_sets.rows(mirrors, skipped)
    assert [(r["subject"], r["label"], r["device"]) for r in rows] == [
        ("someone", "circle", "mouse"), ("someone", "circle", "mouse"), ("someone", "left_sq_bracket", "mouse")]
    assert rows[0]["strokes"][0][2][2] == 30.0 and rows[1]["strokes"][0][2][2] == pytest.approx(40.0)
    assert rows[2]["strokes"][0][0] == [10.0, 10.0, None]
    assert skipped == [f"{REPO}@{head[:7]}:datasets/mine/click03.xml"]
    kept, left = scored_rows(rows)
    assert len(kept) == 3 and not left
    assert recognize_stroke([p[:2] for p in kept[0]["strokes"][0]]).kind in kept[0]["accepts"]


def test_a_copy_of_the_reserved_dollar1_logs_stops_the_gathering_by_name(tmp_path, monkeypatch) -> None:
    mirrors, head = _commit(tmp_path, {"logs/circle01.xml": _circle_xml("circle01", date="Monday, March 05, 2007")})
    monkeypatch.setattr(student_sets, "REPOS", ((REPO, head, "logs"),))
    with pytest.raises(ValueError, match=r"logs/circle01\.xml: dated 'Monday, March 05, 2007'.*reserved"):
        student_sets.rows(mirrors, [])
