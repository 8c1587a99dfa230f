"""The generalisation benchmark reads the public sets in the forms their authors publish (made here in miniature),
maps labels only through benchmarks/label_kinds.tsv, and holds each source out in turn."""

from __future__ import annotations

import itertools
import json
import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_generalisation import (
    FIRST_STUDENTS,
    FOURTH_SETS,
    SECOND_GROUP_OPEN,
    THIRD_SETS,
    group_of,
    held_back,
    held_back_new,
    is_held_back_new,
    leave_one_source_out,
    scored_rows,
    second_group,
)
from bench_recognition import ACCEPTS, LABEL_CLASS
from label_kinds import read_table
from stroke_sets import read_set, source_of

from physink_tui.scene.recognition.recognize import DEFAULT_WEIGHTS


def _circle(r: float = 40.0, n: int = 48) -> list[tuple[float, float]]:
    return [(100 + r * math.cos(2 * math.pi * k / n), 100 + r * math.sin(2 * math.pi * k / n)) for k in range(n + 1)]


def _square(s: float = 80.0) -> list[tuple[float, float]]:
    corners = [(0, 0), (s, 0), (s, s), (0, s), (0, 0)]
    out = []
    for (ax, ay), (bx, by) in itertools.pairwise(corners):
        out += [(ax + (bx - ax) * i / 20, ay + (by - ay) * i / 20) for i in range(20)]
    return [*out, corners[-1]]


def _points_xml(points) -> str:
    return "".join(f'<Point X="{x:.1f}" Y="{y:.1f}" T="{10 * i}"/>' for i, (x, y) in enumerate(points))


def test_the_dollar1_logs_read_by_person_with_labels_without_numbers(tmp_path) -> None:
    folder = tmp_path / "s05" / "medium"
    folder.mkdir(parents=True)
    (folder / "circle01.xml").write_text(f'<?xml version="1.0"?><Gesture Name="circle01" Subject="5" Speed="medium" '
                                         f'Number="1" NumPts="49">{_points_xml(_circle())}</Gesture>')
    (row,) = read_set(tmp_path)
    assert (row["source"], row["subject"], row["label"], len(row["strokes"])) == ("dollar1", "s05", "circle", 1)
    assert source_of(row, "person") == "dollar1:s05" and row["strokes"][0][1][2] == 10.0


def test_the_mmg_set_keeps_its_strokes_device_and_person(tmp_path) -> None:
    folder = tmp_path / "10-stylus-FAST"
    folder.mkdir()
    strokes = "".join(f'<Stroke index="{k}">{_points_xml(part)}</Stroke>'
                      for k, part in enumerate(([(0, 0), (50, 50)], [(50, 0), (0, 50)]), 1))
    (folder / "10-stylus-fast-X-01.xml").write_text(f'<Gesture Name="X~01" Subject="10" InputType="stylus" '
                                                    f'Speed="FAST" NumPts="4">{strokes}</Gesture>')
    line = f'<Stroke index="1">{_points_xml([(0, 0), (30, 1), (60, 2), (90, 3)])}</Stroke>'
    (folder / "10-stylus-fast-line-01.xml").write_text(f'<Gesture Name="line~01" Subject="10" InputType="stylus" '
                                                       f'Speed="FAST" NumPts="4">{line}</Gesture>')
    rows = {r["label"]: r for r in read_set(tmp_path)}
    assert len(rows["X"]["strokes"]) == 2 and rows["line"]["device"] == "stylus"
    kept, left = scored_rows(list(rows.values()))
    assert [r["label"] for r in kept] == ["line"] and sum(left.values()) == 1  # the X: two strokes, no kind


def test_the_drawn_shapes_set_is_one_source_with_string_coordinates(tmp_path) -> None:
    for shape, points in (("circle", _circle()), ("square", _square())):
        (tmp_path / "paths" / shape).mkdir(parents=True)
        (tmp_path / "paths" / shape / "1.json").write_text(json.dumps([[[f"{x}", f"{y}"] for x, y in points]]))
    rows = read_set(tmp_path)
    assert {source_of(r, "person") for r in rows} == {"bouchal"}
    kept, _ = scored_rows(rows)
    assert {r["label"]: sorted(r["accepts"]) for r in kept} == {"circle": ["circle", "ellipse"], "square": ["box"]}


def test_a_label_missing_from_the_table_stops_the_scoring_by_name() -> None:
    row = {"source": "bouchal", "label": "hexagon", "strokes": [[[0, 0, None], [1, 1, None]]], "file": "h.json"}
    with pytest.raises(SystemExit, match=r"'hexagon'.*label_kinds\.tsv"):
        scored_rows([row])


def test_each_source_is_held_out_and_scored_with_weights_chosen_on_the_others(tmp_path, capsys) -> None:
    rows = []
    for person in ("a", "b"):
        rows += [{"source": "dollar1", "subject": person, "label": "circle", "file": f"{person}c",
                  "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_circle(30 + 10 * k))]]} for k in range(3)]
        rows += [{"source": "dollar1", "subject": person, "label": "rectangle", "file": f"{person}r",
                  "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_square(60 + 20 * k))]]} for k in range(3)]
    kept, _ = scored_rows(rows)
    leave_one_source_out(kept, "person", [DEFAULT_WEIGHTS])
    out = capsys.readouterr().out
    assert "| dollar1:a | 6 | 100.00 |" in out and "| dollar1:b | 6 | 100.00 |" in out
    assert "targets (every source >= 98.6 %; every label with >= 50 strokes in a source >= 97 %): met" in out


def test_the_table_is_the_one_the_people_tests_score_with(tmp_path) -> None:
    table = read_table()
    assert LABEL_CLASS == table.of_set("dollar1")
    assert all(set(table.kinds[c]) == ACCEPTS[c] for c in ACCEPTS)
    bad = tmp_path / "bad.tsv"
    bad.write_text("set\tlabel\tclass\taccepts\twhy\na\tcircle\tround\tcircle\tx\nb\toval\tround\tellipse\ty\n")
    with pytest.raises(ValueError, match=r"bad.tsv:3: class 'round' accepts \['ellipse'\]"):
        read_table(bad)


def test_the_held_back_students_are_four_fixed_by_their_names_alone() -> None:
    """The held-back group (issue 25) depends on the students' names only, not on their strokes or their order; a
    student outside it can leave the set without changing it; the three people of the $1 logs are never in it."""
    names = ["Alphazerfall", "Bam33751", "Coldjack007", "DerD4n", "Ferdi-FM", "GixD42", "JonasBachmeier-UNI",
             "LeS-crypto", "LucaEscher", "MaximilianKilger", "lvht1203", "marcel-moz", "martinarobyculasso",
             "michaelpickl", "realdegrees", "uniUbungsAccount"]
    rows = [{"source": "itt", "subject": n, "label": "circle"} for n in names]
    rows += [{"source": "dollar1", "subject": s, "label": "circle"} for s in ("s02", "s03", "s04")]
    group = held_back(rows)
    assert group == {"itt:Ferdi-FM", "itt:marcel-moz", "itt:martinarobyculasso", "itt:michaelpickl"}
    assert held_back(list(reversed(rows))) == group
    assert held_back([r for r in rows if r["subject"] != "Alphazerfall"]) == group


def test_sources_found_later_are_held_back_by_their_name_alone_apart_from_the_first_group() -> None:
    """The second held-back group (issue 25, the second search): a source found after the first 19 is held back
    when the sha256 of the seed and its name is even; the first 19 are never in it, and adding sources changes
    neither group."""
    first = [{"source": "itt", "subject": n, "label": "circle"} for n in FIRST_STUDENTS]
    first += [{"source": "dollar1", "subject": s, "label": "circle"} for s in ("s02", "s03", "s04")]
    later = [{"source": "itt", "subject": f"student{k}", "label": "circle"} for k in range(40)]
    later += [{"source": "someset", "subject": f"p{k}", "label": "circle"} for k in range(40)]
    assert second_group(first) == set()
    group = second_group(first + later)
    assert 20 <= len(group) <= 60 and group == second_group(list(reversed(later)))
    assert all(s.startswith(("itt:student", "someset:p")) for s in group)
    assert held_back(first + later) == held_back(first)  # the first group is drawn among the first 16 only
    assert {group_of(s, held_back(first)) for s in ("itt:Ferdi-FM", "itt:DerD4n", "dollar1:s03")} == {
        "first held back", "first design"}
    assert {group_of(s, set()) for s in group} == {"new held back"}


def test_the_opened_second_group_is_read_by_every_run_and_fitted_on_but_still_named() -> None:
    """Since the second group was opened as design material (`SECOND_GROUP_OPEN`), no run leaves it out: the
    default run scores it, the ranker's folds and the written model read it; its sources are still named
    (`second_group`), so their pooled figure is printed apart; the third group stays out."""
    from train_ranker import rows_read

    assert SECOND_GROUP_OPEN
    rows = [{"source": "hcira", "subject": f"team/user{k}", "label": "circle", "file": f"c{k}",
             "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_circle())]]} for k in range(40)]
    group = second_group(rows)
    assert 5 <= len(group) <= 35
    assert held_back_new(rows) == set() and not any(is_held_back_new(s) for s in group)
    for heldback, write in ((False, False), (False, True)):
        read, _, new = rows_read(rows, heldback, write)
        assert len(read) == len(rows) and new == set()


def test_strokes_whose_label_contradicts_their_geometry_are_counted_beside_the_raw_figure(capsys) -> None:
    """A source's strokes the contradiction tests convict stay in its raw figure (the headline); they are counted
    apart, and the targets are re-stated without them, labelled as such."""
    rows = []
    for person in ("a", "b"):
        rows += [{"source": "dollar1", "subject": person, "label": "circle", "file": f"{person}c",
                  "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_circle(30 + 10 * k))]]} for k in range(3)]
    # a's third "circle" is a square: read as a box, wrong by its label, and convicted (here by hand)
    rows[2] = {**rows[2], "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_square(80))]]}
    kept, _ = scored_rows(rows)
    contradicted = np.array([r["file"] == "ac" and r["strokes"][0][0][:2] == [0, 0] for r in kept])
    assert contradicted.sum() == 1
    leave_one_source_out(kept, "person", [DEFAULT_WEIGHTS], contradicted)
    out = capsys.readouterr().out
    assert "| dollar1:a | 3 | 66.67 | 66.67 | 2.5, 0.003, 0.8 | 1 | 100.00 |" in out  # raw 2 of 3; 2 of 2 agree
    assert "| dollar1:b | 3 | 100.00 | 100.00 | 2.5, 0.003, 0.8 | 0 | 100.00 |" in out
    assert "Issue 25 targets (every source >= 98.6 %; every label with >= 50 strokes in a source >= 97 %): not met: " \
           "dollar1:a: 66.67 % < 98.6 %" in out
    assert "Not the headline: on the strokes whose label agrees with their geometry (5/5 = 100.00 % pooled; 1 " \
           "strokes whose label the contradiction tests convict" in out
    assert out.rstrip().endswith("left out), the same targets: met")


def test_the_third_search_sets_are_left_out_of_every_run_but_their_own_and_never_fitted_on() -> None:
    """The third held-back group (issue 25's third search) is held back whole by its sets' names: the default run,
    `--heldback` and the ranker's training (even when writing the shipped model) never see it; `--third` scores it
    alone. Its sources are in neither earlier group."""
    from train_ranker import rows_read

    table = read_table()

    def row(set_name: str, person: str) -> dict:
        label = next(lab for lab, cls in sorted(table.of_set(set_name).items()) if cls != "-")
        return {"source": set_name, "subject": person, "label": label, "file": f"{set_name}-{person}",
                "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_circle())]]}

    assert THIRD_SETS and not THIRD_SETS & {"dollar1", "itt", "hcira", "mmg", "ahmadosama", "gtiwari", "bouchal"}
    earlier = [row("dollar1", "s02"), row("itt", "Ferdi-FM"), row("itt", "DerD4n")]
    earlier += [row("hcira", f"team/user{k}") for k in range(12)]
    third = [row(name, f"team/user{k}") for name in sorted(THIRD_SETS) for k in range(12)]
    kept, left = scored_rows(earlier + third)
    assert {r["source"] for r in kept}.isdisjoint(THIRD_SETS) and len(kept) == len(earlier)
    assert sum(n for why, n in left.items() if "third held-back group" in why) == len(third)
    only, left_third = scored_rows(earlier + third, third=True)
    assert {r["source"] for r in only} == set(THIRD_SETS) and len(only) == len(third)
    assert sum(left_third.values()) == len(earlier)
    for heldback, write in ((False, False), (True, False), (False, True), (True, True)):
        read, first, new = rows_read(earlier + third, heldback, write)
        assert read and {r["source"] for r in read}.isdisjoint(THIRD_SETS)
        assert not any(s.split(":")[0] in THIRD_SETS for s in first | new)
    sources = {source_of(r, "person") for r in third}
    assert not any(is_held_back_new(s) for s in sources)
    assert {group_of(s, set()) for s in sources} == {"third held back"}


def test_the_third_search_sets_are_read_by_person_across_devices_and_held_back(tmp_path) -> None:
    """The third search's form (a team's $1-form XML files, a folder a person and device, e.g.
    ``user_logs_mouse/user01mouse/zig_zag01.xml``), made here in miniature: one person's folders on two devices are
    one source, another study of the same team is another source, its spellings become the $1 set's labels, and
    every row is of a `THIRD_SETS` set, so the default run leaves it out."""
    from mirror_repo import commit_mirror
    from public_sets import PER_FOLDER, THIRD_ENTRIES, Entry, entry_rows

    def gesture(name: str, points) -> str:
        return (f'<?xml version="1.0"?><Gesture Name="{name}" Subject="1" Date="Saturday, February 25, 2023">'
                f"{_points_xml(points)}</Gesture>")

    mirrors, head = commit_mirror(tmp_path, "team/recogniser", {
        "p2/user_logs_mouse/user01mouse/zig_zag01.xml": gesture("zig_zag01", [(0, 0), (20, 30), (40, 0), (60, 30)]),
        "p2/user_logs_stylus/user01/left_square_bracket01.xml": gesture("left_square_bracket01",
                                                                         [(40, 0), (0, 0), (0, 80), (40, 80)]),
        "p1/user_logs/user1/delete01.xml": gesture("delete01", [(0, 0), (50, 50), (0, 50), (50, 0)]),
        "p1/user_logs/user1/xml_logs/s05/circle01.xml": gesture("circle01", _circle()),  # deeper: never read
    })
    repo = "team/recogniser"
    entries = [Entry("hcira3", repo, head, "p2/user_logs_mouse", "mouse", PER_FOLDER, rename=("", "mouse")),
               Entry("hcira3", repo, head, "p2/user_logs_stylus", "stylus", PER_FOLDER),
               Entry("hcira3", repo, head, "p1/user_logs", "trackpad", PER_FOLDER, rename=("trackpad-", ""))]
    rows = [r for e in entries for r in entry_rows(e, mirrors, set(), {}, [])]
    assert [(r["subject"], r["device"], r["label"]) for r in rows] == [
        ("team/user01", "mouse", "zigzag"), ("team/user01", "stylus", "left_sq_bracket"),
        ("team/trackpad-user1", "trackpad", "delete_mark")]
    assert rows[0]["strokes"] == [[[0.0, 0.0, 0.0], [20.0, 30.0, 10.0], [40.0, 0.0, 20.0], [60.0, 30.0, 30.0]]]
    assert {source_of(r, "person") for r in rows} == {"hcira3:team/user01", "hcira3:team/trackpad-user1"}
    kept, _ = scored_rows(rows)
    assert kept == []
    third, _ = scored_rows(rows, third=True)
    assert [sorted(r["accepts"]) for r in third] == [["polyline"], ["polyline"], ["polyline"]]
    assert {e.set_name for e in THIRD_ENTRIES} <= THIRD_SETS


def test_an_inkml_diagram_gives_one_row_a_symbol_of_its_writer(tmp_path) -> None:
    """The FC flowchart database's form (InkML: traces of "x y" pairs, symbols as trace groups with a truth label,
    the writer in an annotation), made here in miniature: a one-stroke box is one scored row, a two-stroke arrow is
    counted as drawn in two strokes, and both belong to the third held-back group."""
    from mirror_repo import commit_mirror
    from public_sets import INKML, ONE, Entry, entry_rows, inkml_symbols

    def trace(k: int, points) -> str:
        return f'<trace id="{k}">' + ", ".join(f"{x:g} {y:g}" for x, y in points) + "</trace>"

    box = _square(60)
    ink = ('<ink xmlns="http://www.w3.org/2003/InkML"><annotation type="writer">writer7</annotation>'
           + trace(0, box) + trace(1, [(0, 100), (80, 100)]) + trace(2, [(70, 95), (80, 100), (70, 105)])
           + '<traceGroup><annotation type="truth">From ITF</annotation>'
           '<traceGroup><annotation type="truth">process</annotation><traceView traceDataRef="0"/></traceGroup>'
           '<traceGroup><annotation type="truth">arrow</annotation><traceView traceDataRef="1"/>'
           '<traceView traceDataRef="2"/></traceGroup></traceGroup></ink>')
    symbols = inkml_symbols("d.inkml", ink.encode())
    assert [(w, label, len(strokes)) for w, label, strokes in symbols] == [("writer7", "process", 1),
                                                                          ("writer7", "arrow", 2)]
    assert symbols[0][2][0][:2] == [[0.0, 0.0, None], [3.0, 0.0, None]]
    with pytest.raises(ValueError, match=r"e\.inkml: trace group 'process' refers to traces \['9'\]"):
        inkml_symbols("e.inkml", ink.replace('traceDataRef="0"', 'traceDataRef="9"').encode())
    mirrors, head = commit_mirror(tmp_path, "someone/flowcharts", {"sources/writer7_1.inkml": ink})
    rows = entry_rows(Entry("fc", "someone/flowcharts", head, "sources", "pen", ONE, form=INKML), mirrors, set(), {},
                      [])
    assert [(source_of(r, "person"), r["label"]) for r in rows] == [("fc:writer7", "process"), ("fc:writer7", "arrow")]
    assert scored_rows(rows)[0] == []
    third, left = scored_rows(rows, third=True)
    assert [(r["label"], r["accepts"]) for r in third] == [("process", frozenset({"box"}))]
    assert sum(left.values()) == 1  # the arrow: no kind stands for a flowchart's arrow


def test_the_third_flag_scores_the_third_group_alone_and_the_default_run_never(tmp_path, capsys, monkeypatch) -> None:
    """`bench_generalisation.py SETS --third --defaults` (the lead's one run) scores only the third group's sources,
    pooled apart; the same sets without it score none of them (strokes made here, not any set's)."""
    import bench_generalisation

    def row(set_name: str, person: str, label: str, points) -> dict:
        return {"source": set_name, "subject": person, "label": label, "file": f"{set_name}-{person}-{label}",
                "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(points)]]}

    rows = [row("hcira3", f"team/user0{k}", "circle", _circle(30 + 5 * k)) for k in (1, 2)]
    rows += [row("fc", "writer3", "process", _square(70)), row("dollar1", "s02", "circle", _circle(50)),
             row("dollar1", "s03", "rectangle", _square(90))]
    path = tmp_path / "sets.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in rows))
    monkeypatch.setattr(sys, "argv", ["bench_generalisation.py", str(path), "--third", "--defaults"])
    bench_generalisation.main()
    out = capsys.readouterr().out
    assert "| hcira3:team/user01 | 1 |" in out and "| fc:writer3 | 1 |" in out and "dollar1:" not in out.split(
        "### Leave one source out")[1]
    assert "The third held-back group (`THIRD_SETS`): 3/3 = 100.00 %." in out
    monkeypatch.setattr(sys, "argv", ["bench_generalisation.py", str(path), "--defaults"])
    bench_generalisation.main()
    out = capsys.readouterr().out
    assert "| dollar1:s02 | 1 |" in out and "hcira3:" not in out.split("### Leave one source out")[1]
    assert "fc:" not in out.split("### Leave one source out")[1] and "third held-back group" not in out.split(
        "### Leave one source out")[1]


def test_the_fourth_search_sets_are_left_out_of_every_run_but_their_own_and_never_fitted_on(tmp_path, capsys,
                                                                                            monkeypatch) -> None:
    """The fourth held-back group (issue 25's fourth search) is held back whole by its sets' names: the default run,
    `--heldback`, `--third`, the ranker's training (even when writing the shipped model), the contradiction tests and
    the readings compared or profiled never see it; `--fourth` scores it alone, and never with `--third`."""
    import label_contradictions
    from compare_readings import strokes
    from train_ranker import rows_read

    table = read_table()

    def row(set_name: str, person: str) -> dict:
        label = next(lab for lab, cls in sorted(table.of_set(set_name).items()) if cls != "-")
        return {"source": set_name, "subject": person, "label": label, "file": f"{set_name}-{person}",
                "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(_circle())]]}

    assert FOURTH_SETS and not FOURTH_SETS & (THIRD_SETS | {"dollar1", "itt", "hcira", "mmg", "ahmadosama", "gtiwari",
                                                             "bouchal"})
    earlier = [row("dollar1", "s02"), row("itt", "Ferdi-FM"), row("itt", "DerD4n")]
    earlier += [row("hcira", f"team/user{k}") for k in range(12)]
    third = [row(name, f"team/user{k}") for name in sorted(THIRD_SETS) for k in range(3)]
    fourth = [row(name, f"p{k}") for name in sorted(FOURTH_SETS) for k in range(12)]
    everything = earlier + third + fourth
    kept, left = scored_rows(everything)
    assert len(kept) == len(earlier) and {r["source"] for r in kept}.isdisjoint(FOURTH_SETS)
    assert sum(n for why, n in left.items() if "fourth held-back group" in why) == len(fourth)
    only_third, _ = scored_rows(everything, third=True)
    assert {r["source"] for r in only_third} == set(THIRD_SETS)
    only, left_fourth = scored_rows(everything, fourth=True)
    assert {r["source"] for r in only} == set(FOURTH_SETS) and len(only) == len(fourth)
    assert sum(left_fourth.values()) == len(earlier) + len(third)
    with pytest.raises(SystemExit, match="each held-back group is scored alone"):
        scored_rows(everything, third=True, fourth=True)
    for heldback, write in ((False, False), (True, False), (False, True), (True, True)):
        read, first, new = rows_read(everything, heldback, write)
        assert read and {r["source"] for r in read}.isdisjoint(FOURTH_SETS | THIRD_SETS)
        assert not any(s.split(":")[0] in FOURTH_SETS for s in first | new)
    sources = {source_of(r, "person") for r in fourth}
    assert not any(is_held_back_new(s) for s in sources) and not second_group(fourth)
    assert {group_of(s, set()) for s in sources} == {"fourth held back"}
    path = tmp_path / "sets.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in everything))
    assert {name for name, _, _ in strokes([path])} == {"dollar1", "itt", "hcira"}  # compare_readings, profiling
    monkeypatch.setattr(sys, "argv", ["label_contradictions.py", str(path), "--invariants", "--files", "none"])
    label_contradictions.main()
    out = capsys.readouterr().out
    assert "dollar1:s02" in out and not any(name in out for name in FOURTH_SETS | THIRD_SETS)


def test_the_fourth_flag_scores_the_fourth_group_alone_and_no_other_run_does(tmp_path, capsys, monkeypatch) -> None:
    """`bench_generalisation.py SETS --fourth --defaults` (the lead's one run) scores only the fourth group's sources,
    pooled apart; the same sets with `--third`, with `--heldback` or alone score none of them (strokes made here)."""
    import bench_generalisation

    def row(set_name: str, person: str, label: str, points) -> dict:
        return {"source": set_name, "subject": person, "label": label, "file": f"{set_name}-{person}-{label}",
                "strokes": [[[x, y, 10 * i] for i, (x, y) in enumerate(points)]]}

    rows = [row("quickdraw", country, "circle", _circle(30 + 5 * k)) for k, country in enumerate(("US", "FI"))]
    rows += [row("tutorboard", "captured-chromium-v1", "square", _square(70)), row("dollar1", "s02", "circle",
                                                                                  _circle(50)),
             row("dollar1", "s03", "rectangle", _square(90))]
    rows += [row("hcira3", f"team/user0{k}", "circle", _circle(40 + k)) for k in (1, 2)]
    path = tmp_path / "sets.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in rows))
    monkeypatch.setattr(sys, "argv", ["bench_generalisation.py", str(path), "--fourth", "--defaults"])
    bench_generalisation.main()
    out = capsys.readouterr().out.split("### Leave one source out")[1]
    assert "| quickdraw:US | 1 |" in out and "| tutorboard:captured-chromium-v1 | 1 |" in out
    assert "dollar1:" not in out and "hcira3:" not in out
    assert ("The fourth held-back group (`FOURTH_SETS`) (opened as design material: not a held-out figure): "
            "3/3 = 100.00 %.") in out
    for flags in ([], ["--heldback"], ["--third"]):
        monkeypatch.setattr(sys, "argv", ["bench_generalisation.py", str(path), "--defaults", *flags])
        bench_generalisation.main()
        out = capsys.readouterr().out
        assert "quickdraw:" not in out.split("### Leave one source out")[1] and "tutorboard:" not in out
        assert "fourth held-back group (`FOURTH_SETS`; --fourth scores it alone)" in out.split("### Leave")[0]
