"""The fifth search's sets are read in the form the Gester tool republishes them (made here in miniature, no stroke of
any set): a gesture a JSON file, its pen-downs by ``stroke_id``, its person named by its folders; and the fifth
held-back group they make is left out of every run but ``--fifth``, which scores it alone."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_generalisation import FIFTH_SETS, FOURTH_SETS, SIGN_SETS, THIRD_SETS, group_of, scored_rows, second_group
from fifth_sets import gester_gesture
from label_kinds import read_table
from mirror_repo import commit_mirror
from public_sets import FIFTH_ENTRIES, GESTER, ONE, Entry, entry_rows
from stroke_sets import source_of

from physink_tui.scene.recognition.primitives import KINDS

REPO = "someone/gestures"


def _ring(n: int = 24, r: float = 80.0, cx: float = 200.0) -> list[tuple[float, float]]:
    return [(cx + r * math.cos(2 * math.pi * k / n), 150 + r * math.sin(2 * math.pi * k / n)) for k in range(n + 1)]


def _gesture(name: str, strokes: list[list[tuple[float, float]]], os: str = "Tablet PC", start: int = 5000,
             path: str = "Pen") -> str:
    points = [{"x": x, "y": y, "w": None, "z": None, "t": start + 1000 * j + 15 * i, "stroke_id": j}
              for j, stroke in enumerate(strokes) for i, (x, y) in enumerate(stroke)]
    return json.dumps({"name": name, "subject": 1, "date": None, "paths": {path: {"strokes": points}},
                       "device": {"osBrowserInfo": os, "pen": True, "finger": False, "mouse": False}})


def test_a_gesture_file_is_one_row_its_person_its_folders_its_pen_downs_by_stroke_id_timed_from_zero(tmp_path) -> None:
    line, ring = [(10.0 + 12 * i, 40.0 + i) for i in range(12)], _ring()
    mirrors, head = commit_mirror(tmp_path, REPO, {
        "datasets/2D/SIGN/writer001/sessionA/circle_left-1-0.json": _gesture("circle_left", [ring], "ST5022"),
        "datasets/2D/SIGN/writer001/sessionB/left-1-0.json": _gesture("left", [line], "ST5022"),
        "datasets/2D/SIGN/writer002/sessionA/x-1-0.json": _gesture("x", [line[:6], line[6:]], "X61"),
        "datasets/2D/SIGN/writer002/sessionA/snail-1-0.json": _gesture("snail", [_ring(r=30)], "X61"),
        "datasets/2D/$1/s05/circle-0.json": _gesture("circle", [_ring(r=50)]),  # another folder: never read
    })
    rows = entry_rows(Entry("sign", REPO, head, "datasets/2D/SIGN", "pen on a {os}", ONE, "{0}", form=GESTER),
                      mirrors, set(), {}, [])
    assert [(source_of(r, "person"), r["label"], len(r["strokes"]), r["device"]) for r in rows] == [
        ("sign:writer001", "circle_left", 1, "pen on a ST5022"), ("sign:writer001", "left", 1, "pen on a ST5022"),
        ("sign:writer002", "snail", 1, "pen on a X61"), ("sign:writer002", "x", 2, "pen on a X61")]
    assert rows[0]["strokes"][0][:2] == [[280.0, 150.0, 0.0], [pytest.approx(277.274, abs=1e-3),
                                                               pytest.approx(20.706 + 150, abs=1e-3), 15.0]]
    assert [len(s) for s in rows[3]["strokes"]] == [6, 6] and rows[3]["strokes"][1][0][2] == 0.0
    assert rows[0]["file"] == f"{REPO}@{head[:7]}:datasets/2D/SIGN/writer001/sessionA/circle_left-1-0.json"
    assert scored_rows(rows)[0] == []  # sign, opened from the fifth group: out of every run but --sign
    assert scored_rows(rows, fifth=True)[0] == []
    kept, left = scored_rows(rows, sign=True)
    assert [(r["label"], sorted(r["accepts"])) for r in kept] == [("circle_left", ["circle", "ellipse"]),
                                                                   ("left", ["line"])]
    assert left == {"sign snail: no kind stands for it": 1, "sign x: no kind stands for it": 1}


def test_only_the_named_subfolders_are_read_and_one_person_on_two_devices_is_one_source(tmp_path) -> None:
    files = {f"datasets/2D/MMG+/{device}/7/line1-{k}.json": _gesture("line", [[(0.0, 0.0), (40.0 + k, 3.0 * k)]],
                                                                     path="Finger")
             for device in ("Smartphone", "Tablet") for k in range(2)}
    files["datasets/2D/RMMG+/Smartphone/7/line-0-0.json"] = _gesture("line", [[(1.0, 1.0), (9.0, 9.0)]])
    mirrors, head = commit_mirror(tmp_path, REPO, files)
    rows = []
    for device, sub in (("finger on a smartphone", "Smartphone"), ("finger on a tablet", "Tablet")):
        rows += entry_rows(Entry("mmgplus", REPO, head, "datasets/2D/MMG+", device, ONE, "{1}", (sub,), GESTER),
                           mirrors, set(), {}, [])
    assert [(source_of(r, "person"), r["device"]) for r in rows] == [
        ("mmgplus:7", "finger on a smartphone"), ("mmgplus:7", "finger on a smartphone"),
        ("mmgplus:7", "finger on a tablet"), ("mmgplus:7", "finger on a tablet")]
    with pytest.raises(ValueError, match=r"fewer folders than '\{2\}'"):
        entry_rows(Entry("mmgplus", REPO, head, "datasets/2D/MMG+", "finger", ONE, "{2}", form=GESTER), mirrors,
                   set(), {}, [])


def test_a_gesture_kept_twice_is_read_once_and_one_copied_from_another_source_is_skipped(tmp_path) -> None:
    ring, other = _ring(), _ring(r=60, cx=300)
    mirrors, head = commit_mirror(tmp_path, REPO, {
        "d/101/circle1-0.json": _gesture("circle", [ring]),
        "d/101/circle1-0(1).json": _gesture("circle", [ring]),  # the same file twice under one person
        "d/101/circle1-1.json": _gesture("circle", [other]),
        "d/102/circle1-0.json": _gesture("circle", [other]),  # another person's gesture again
    })
    skipped: list[str] = []
    rows = entry_rows(Entry("lowvision", REPO, head, "d", "finger", ONE, "{0}", form=GESTER), mirrors, set(), {},
                      skipped)
    assert [(r["subject"], r["file"].rsplit("/", 1)[1]) for r in rows] == [("101", "circle1-0(1).json"),
                                                                         ("101", "circle1-1.json")]
    at = f"{REPO}@{head[:7]}:d/"
    assert skipped == [f"{at}101/circle1-0.json (the same gesture as {at}101/circle1-0(1).json)",
                       f"{at}102/circle1-0.json (a stroke of lowvision:101 again)"]


def test_a_file_not_in_the_form_is_named_and_a_clock_that_runs_backwards_times_nothing() -> None:
    with pytest.raises(ValueError, match=r"g\.json: not a Gester gesture"):
        gester_gesture("g.json", b"{}")
    two = json.loads(_gesture("line", [[(0.0, 0.0), (9.0, 9.0)]]))
    two["paths"]["Finger"] = two["paths"]["Pen"]
    with pytest.raises(ValueError, match=r"g\.json: not a Gester gesture \(2 input paths"):
        gester_gesture("g.json", json.dumps(two).encode())
    backwards = json.loads(_gesture("line", [[(0.0, 0.0), (5.0, 5.0), (9.0, 9.0)]]))
    backwards["paths"]["Pen"]["strokes"][2]["t"] = 0
    label, device, strokes = gester_gesture("g.json", json.dumps(backwards).encode())
    assert (label, device, [p[2] for p in strokes[0]]) == ("line", "Tablet PC", [None, None, None])


def test_the_pinned_fifth_entries_are_the_fifth_group_each_read_from_its_own_folder() -> None:
    table = read_table()
    assert {e.set_name for e in FIFTH_ENTRIES} == FIFTH_SETS | SIGN_SETS and not FIFTH_SETS & SIGN_SETS
    assert not (FIFTH_SETS | SIGN_SETS) & (THIRD_SETS | FOURTH_SETS | {"dollar1", "itt", "hcira", "mmg", "ahmadosama",
                                                                       "gtiwari"})
    for entry in FIFTH_ENTRIES:
        assert entry.form == GESTER and len(entry.commit) == 40 and table.of_set(entry.set_name)
        assert entry.folder.startswith("datasets/2D/") and entry.folder not in ("datasets/2D/$1", "datasets/2D/MMG")


def test_every_kind_the_table_accepts_is_one_the_recogniser_can_name() -> None:
    """A class accepting a kind the recogniser never names would count its strokes wrong whatever they look like (the
    fifth search added ``bow``: arc or curve, for a parenthesis)."""
    kinds = read_table().kinds
    assert kinds["bow"] == {"arc", "curve"}
    assert set().union(*kinds.values()) <= set(KINDS)


def test_the_fifth_group_is_left_out_of_every_run_but_its_own(tmp_path, capsys, monkeypatch) -> None:
    """The default run, `--heldback`, `--third`, `--fourth`, the ranker's training (even when writing the shipped
    model), the contradiction tests and the readings compared never see the fifth group; `--fifth` scores it alone,
    pooled apart, and never together with another group's flag."""
    import bench_generalisation
    import label_contradictions
    from compare_readings import strokes
    from train_ranker import rows_read

    table = read_table()

    def row(set_name: str, person: str, label: str | None = None, r: float = 40.0) -> dict:
        label = label or next(lab for lab in sorted(table.of_set(set_name)))
        return {"source": set_name, "subject": person, "label": label, "file": f"{set_name}-{person}-{label}",
                "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_ring(48, r))]]}

    earlier = [row("dollar1", "s02", "circle"), row("dollar1", "s03", "circle", 50), row("itt", "DerD4n", "circle")]
    fifth = [row("homus", "7", "Whole-Note"), row("lowvision", "with_impairment/101", "circle", 45),
             row("eds", "EDS-1/1", "circle", 55)]
    sign = [row("sign", "writer001", "circle_left", 47)]  # opened from the fifth group (`SIGN_SETS`): its own flag
    others = [row("hcira3", "team/user01", "circle", 41), row("hcira3", "team/user02", "circle", 42),
              row("quickdraw", "US", "circle", 43), row("quickdraw", "FI", "circle", 44)]
    everything = earlier + fifth + sign + others
    for flags in ({}, {"third": True}, {"fourth": True}):
        kept, left = scored_rows(everything, **flags)
        assert kept and {r["source"] for r in kept}.isdisjoint(FIFTH_SETS)
        assert sum(n for why, n in left.items() if "fifth held-back group" in why) == len(fifth)
        assert sum(n for why, n in left.items() if "sign held-back group" in why) == len(sign)
    only, left = scored_rows(everything, fifth=True)
    assert [r["source"] for r in only] == ["homus", "lowvision", "eds"] and sum(left.values()) == 8
    assert [r["source"] for r in scored_rows(everything, sign=True)[0]] == ["sign"]
    with pytest.raises(SystemExit, match="--fourth and --fifth: each held-back group is scored alone"):
        scored_rows(everything, fourth=True, fifth=True)
    for heldback, write in ((False, False), (True, False), (False, True), (True, True)):
        read, first, new = rows_read(everything, heldback, write)
        assert read and {r["source"] for r in read}.isdisjoint(FIFTH_SETS)
        assert not any(s.split(":")[0] in FIFTH_SETS for s in first | new)
    sources = {source_of(r, "person") for r in fifth}
    assert {group_of(s, set()) for s in sources} == {"fifth held back"} and not second_group(fifth)
    path = tmp_path / "sets.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in everything))
    assert {name for name, _, _ in strokes([path])} == {"dollar1", "itt"}  # compare_readings, profiling
    monkeypatch.setattr(sys, "argv", ["label_contradictions.py", str(path), "--invariants", "--files", "none"])
    label_contradictions.main()
    out = capsys.readouterr().out
    assert "dollar1:s02" in out and not any(f"{name}:" in out for name in FIFTH_SETS)
    for flags in ([], ["--heldback"], ["--third"], ["--fourth"]):
        monkeypatch.setattr(sys, "argv", ["bench_generalisation.py", str(path), "--defaults", *flags])
        bench_generalisation.main()
        out = capsys.readouterr().out
        assert not any(f"| {name}:" in out for name in FIFTH_SETS)
        assert "fifth held-back group (`FIFTH_SETS`; --fifth scores it alone)" in out.split("### Leave")[0]
    monkeypatch.setattr(sys, "argv", ["bench_generalisation.py", str(path), "--fifth", "--defaults"])
    bench_generalisation.main()
    out = capsys.readouterr().out.split("### Leave one source out")[1]
    assert "| homus:7 | 1 |" in out and "| lowvision:with_impairment/101 | 1 |" in out and "sign:" not in out
    assert "| eds:EDS-1/1 | 1 |" in out and "dollar1:" not in out and "hcira3:" not in out and "quickdraw:" not in out
    assert "The fifth held-back group (`FIFTH_SETS`): 3/3 = 100.00 %." in out
