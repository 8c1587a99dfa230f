"""The public sets of issue 25's second search (benchmarks/public_sets.py) are read at a pinned commit, one person
per folder, only from the folders named (never their subfolders, where repositories keep the reserved $1 logs),
their labels unified onto the $1 set's, and copies refused by name (all made here in miniature, in a local git
repository)."""

from __future__ import annotations

import math
import struct
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_generalisation import scored_rows
from mirror_repo import commit_mirror
from public_sets import ACCORD, ONE, PER_FOLDER, Entry, dollar_label, entry_rows, java_stroke

REPO = "someone/hcira-project"


def _circle_xml(name: str, r: float = 60.0, date: str = "Friday, April 14, 2023", strokes: bool = False) -> str:
    pts = [(200 + r * math.cos(2 * math.pi * k / 40), 200 + r * math.sin(2 * math.pi * k / 40)) for k in range(41)]
    body = "".join(f'<Point X="{x:.1f}" Y="{y:.1f}" T="{15 * k}"/>' for k, (x, y) in enumerate(pts))
    if strokes:
        body = f'<Stroke index="1">{body}</Stroke>'
    return f'<?xml version="1.0"?><Gesture Name="{name}" Subject="7" InputType="finger" Date="{date}">{body}</Gesture>'


def _commit(tmp_path: Path, files: dict[str, str]) -> tuple[Path, str]:
    return commit_mirror(tmp_path, REPO, files)


def test_the_courses_spellings_become_the_dollar_sets_labels() -> None:
    assert dollar_label("left square bracket3.xml") == "left_sq_bracket"
    assert dollar_label("User07-right-curly-brace-01.xml") == "right_curly_brace"
    assert dollar_label("pig tail10.xml") == "pigtail"
    assert dollar_label("zig zag02.xml") == "zigzag" == dollar_label("zig-zag02.xml")
    assert dollar_label("delete4.xml") == "delete_mark"
    with pytest.raises(ValueError, match=r"'eight' is not one of the \$1 set's"):
        dollar_label("Eight01.xml")


def test_each_subfolder_is_one_person_and_deeper_folders_are_never_read(tmp_path) -> None:
    mirrors, head = _commit(tmp_path, {
        "data/user1/circle01.xml": _circle_xml("circle01"),
        "data/user2/circle1.xml": _circle_xml("circle1", r=50),
        "data/user2/notes.txt": "not a gesture",
        "data/user2/s05/medium/circle01.xml": _circle_xml("circle01", date="Monday, March 05, 2007"),
    })
    entry = Entry("hcira", REPO, head, "data", "touchpad", PER_FOLDER)
    skipped: list[str] = []
    rows = entry_rows(entry, mirrors, set(), {}, skipped)
    assert [(r["source"], r["subject"], r["device"], r["label"]) for r in rows] == [
        ("hcira", "someone/user1", "touchpad", "circle"), ("hcira", "someone/user2", "touchpad", "circle")]
    assert rows[0]["strokes"][0][2] == [pytest.approx(200 + 60 * math.cos(4 * math.pi / 40), abs=0.05),
                                        pytest.approx(200 + 60 * math.sin(4 * math.pi / 40), abs=0.05), 30.0]
    kept, left = scored_rows(rows)
    assert len(kept) == 2 and not left and not skipped


def test_a_file_copied_from_another_person_is_skipped_and_a_copied_source_refused(tmp_path) -> None:
    files = {f"data/user1/circle{k}.xml": _circle_xml(f"circle{k}", r=40 + k) for k in range(1, 9)}
    files["data/user2/circle1.xml"] = files["data/user1/circle1.xml"]
    mirrors, head = _commit(tmp_path, files)
    skipped: list[str] = []
    rows = entry_rows(Entry("hcira", REPO, head, "data", "mouse", PER_FOLDER), mirrors, set(), {}, skipped)
    assert len(rows) == 8 and skipped == [f"{REPO}@{head[:7]}:data/user2/circle1.xml (a stroke of "
                                          "hcira:someone/user1 again)"]
    seen = {tuple((p[0], p[1]) for p in r["strokes"][0][:12]): "itt:elsewhere" for r in rows}
    with pytest.raises(ValueError, match=r"more than 5 gestures of hcira:someone/user1 are strokes of itt:elsewhere"):
        entry_rows(Entry("hcira", REPO, head, "data", "mouse", PER_FOLDER), mirrors, set(), seen, [])


def test_a_copy_of_the_reserved_logs_stops_the_gathering_by_name(tmp_path) -> None:
    mirrors, head = _commit(tmp_path, {"mine/circle01.xml": _circle_xml("circle01", date="Monday, March 05, 2007")})
    with pytest.raises(ValueError, match=r"mine/circle01\.xml: dated 'Monday, March 05, 2007'.*reserved"):
        entry_rows(Entry("itt", REPO, head, "mine", "mouse", ONE, "someone"), mirrors, set(), {}, [])
    mirrors2, head2 = _commit(tmp_path / "b", {"mine/circle01.xml": _circle_xml("circle01")})
    row = entry_rows(Entry("itt", REPO, head2, "mine", "mouse", ONE, "someone"), mirrors2, set(), {}, [])[0]
    known = {tuple((p[0], p[1]) for p in row["strokes"][0][:12])}
    with pytest.raises(ValueError, match=r"mine/circle01\.xml: its points are a stroke of the \$1 logs"):
        entry_rows(Entry("itt", REPO, head2, "mine", "mouse", ONE, "someone"), mirrors2, known, {}, [])


def test_the_mmg_set_keeps_its_people_devices_and_strokes(tmp_path) -> None:
    mirrors, head = _commit(tmp_path, {
        "mmg/7-finger-FAST/7-finger-fast-line-01.xml": _circle_xml("line~01", strokes=True)})
    (row,) = entry_rows(Entry("mmg", REPO, head, "mmg", None, PER_FOLDER), mirrors, set(), {}, [])
    assert (row["source"], row["subject"], row["device"], row["label"], len(row["strokes"])) == (
        "mmg", "7", "finger", "line", 1)


def _java_raw_feature(points: list[tuple[int, int]], t0: float = 1308480555195.0) -> bytes:
    """A ``RawFeature`` serialised as Java writes one: a class description, a double[] of times, a Point[]."""
    uid = bytes(range(8))
    out = b"\xac\xed\x00\x05sr\x00\x22com.gt.gesture.features.RawFeature" + uid + b"\x02\x00\x02[\x00\x07curTimet" \
          b"\x00\x02[D[\x00\x09drawPointt\x00\x11[Ljava/awt/Point;xp"
    out += b"ur\x00\x02[D" + uid + b"\x02\x00\x00xp" + len(points).to_bytes(4, "big")
    out += b"".join(struct.pack(">d", t0 + 16.0 * k) for k in range(len(points)))
    out += b"ur\x00\x11[Ljava.awt.Point;" + uid + b"\x02\x00\x00xp" + len(points).to_bytes(4, "big")
    for k, (x, y) in enumerate(points):
        out += (b"sr\x00\x0ejava.awt.Point" + uid + b"\x02\x00\x02I\x00\x01xI\x00\x01yxp") if k == 0 else \
            b"sq\x00~\x00\x08"
        out += struct.pack(">ii", x, y)
    return out


def test_java_serialised_strokes_keep_their_points_and_clock() -> None:
    stroke = java_stroke("a.TRAINDATA", _java_raw_feature([(10, 20), (30, 20), (50, 21)]))
    assert stroke == [[10.0, 20.0, 0.0], [30.0, 20.0, 16.0], [50.0, 21.0, 32.0]]
    with pytest.raises(ValueError, match=r"b\.TRAINDATA: not a serialised RawFeature"):
        java_stroke("b.TRAINDATA", b"\xac\xed\x00\x05 something else")


def test_a_file_of_samples_per_label_is_one_gesture_a_sample(tmp_path) -> None:
    seq = "".join("<Sequence><Classes><string>Circle</string></Classes><Points>" + "".join(
        f"<Point><X>{200 + r * math.cos(2 * math.pi * k / 30):.0f}</X><Y>{200 + r * math.sin(2 * math.pi * k / 30):.0f}"
        "</Y></Point>" for k in range(31)) + "</Points></Sequence>" for r in (40, 60))
    mirrors, head = _commit(tmp_path, {"TrainingData/Circle.xml": f"<ArrayOfSequence>{seq}</ArrayOfSequence>"})
    rows = entry_rows(Entry("ahmadosama", REPO, head, "TrainingData", "mouse", ONE, "someone", form=ACCORD), mirrors,
                      set(), {}, [])
    assert [(r["subject"], r["label"], len(r["strokes"][0])) for r in rows] == [("someone", "Circle", 31)] * 2
    kept, _ = scored_rows(rows)
    assert all(sorted(r["accepts"]) == ["circle", "ellipse"] for r in kept)
