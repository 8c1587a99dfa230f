"""`physink equiv A B [--json]`: timelines or projects in, the verdict, distances and reasons out; exit 0 either way,
one line naming the file for a bad one."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from test_demo_mode import block_demo_journal
from test_equivalence import FIG_2_15, NAMES, ON_A, ON_B, UNDER_B, behaviour, landed, renamed

from physink_tui.cli import main
from physink_tui.formats.project.codec import Project
from physink_tui.formats.project.files import save_project
from physink_tui.formats.timeline_json import encode_timeline_json
from physink_tui.scene.components import MATERIALS, Body, Scene
from physink_tui.timeline.events import Timeline


def write_timeline(path: Path, timeline: Timeline, names: dict[str, str] = NAMES) -> str:
    path.write_text(encode_timeline_json(timeline, names), encoding="utf-8")
    return str(path)


def write_project(path: Path, timeline: Timeline | None, labels: dict[str, str] = NAMES) -> str:
    bodies = {bid: Body(bid, "circle", (), 10.0, (100.0 + 50 * i, 100.0), 0.0, MATERIALS["round"], label)
              for i, (bid, label) in enumerate(sorted(labels.items()))}
    save_project(Project(Scene(bodies, {"b": len(bodies) + 1}), (), timeline, (800.0, 600.0)), path)
    return str(path)


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    status = main(["equiv", *argv])
    out, err = capsys.readouterr()
    return status, out, err


def test_equivalent_timelines_print_the_verdict_and_distances(tmp_path, capsys) -> None:
    a = write_timeline(tmp_path / "a.json", behaviour(FIG_2_15))
    b = write_timeline(tmp_path / "b.json", behaviour(FIG_2_15, wobble=10.0, pace=0.5))
    status, out, err = run(capsys, a, b)
    assert (status, err) == (0, "")
    lines = out.splitlines()
    assert lines[0] == "equivalent"
    assert lines[1] == "qualitative distance: 0"
    assert lines[2].startswith("quantitative distance: ") and float(lines[2].split(": ")[1]) > 0
    assert len(lines) == 3


def test_inequivalent_timelines_list_the_reasons_and_still_exit_0(tmp_path, capsys) -> None:
    a = write_timeline(tmp_path / "a.json", behaviour(ON_B))
    b = write_timeline(tmp_path / "b.json", behaviour(UNDER_B))
    status, out, _ = run(capsys, a, b)
    assert status == 0
    lines = out.splitlines()
    assert re.fullmatch(r"quantitative distance: \d+\.\d{3}", lines.pop(2))
    assert lines == [
        "not equivalent",
        "qualitative distance: 1",
        "- Contact between ball and platform B (t=1.00): ball's side is bottom in A, top in B",
        "- Contact between ball and platform B (t=1.00): platform B's side is top in A, bottom in B",
    ]


def test_json_is_exactly_one_object_and_a_newline(tmp_path, capsys) -> None:
    a = write_timeline(tmp_path / "a.json", behaviour(ON_A))
    b = write_timeline(tmp_path / "b.json", behaviour(ON_B))
    status, out, _ = run(capsys, a, b, "--json")
    assert status == 0 and out.endswith("}\n") and out.count("\n") == 1
    doc = json.loads(out)
    assert list(doc) == ["equivalent", "qualitative_distance", "quantitative_distance", "reasons"]
    assert doc["equivalent"] is False and doc["qualitative_distance"] == 2
    assert isinstance(doc["quantitative_distance"], float)
    assert doc["reasons"] == ['"Contact between ball and platform A" only in A (t=1.00)',
                              '"Contact between ball and platform B" only in B (t=1.00)']


def test_a_project_compares_with_a_timeline_by_label(tmp_path, capsys) -> None:
    ids = {"b1": "b4", "b2": "b3", "b3": "b2", "b4": "b1"}  # drawn in another order: other ids, same labels
    project = write_project(tmp_path / "p.physink.json", renamed(behaviour(FIG_2_15), ids),
                            {ids[k]: v for k, v in NAMES.items()})
    timeline = write_timeline(tmp_path / "t.json", behaviour(FIG_2_15))
    status, out, _ = run(capsys, project, timeline, "--json")
    assert status == 0 and json.loads(out)["equivalent"] is True


def test_a_replayed_demonstration_is_equivalent_to_its_own_timeline_file(tmp_path, capsys) -> None:
    journal = block_demo_journal(tmp_path / "demo.physink.jsonl")
    assert main(["replay", str(journal), "--out", str(tmp_path / "out")]) == 0
    capsys.readouterr()
    status, out, _ = run(capsys, str(tmp_path / "out" / "project.json"), str(tmp_path / "out" / "timeline.json"))
    assert status == 0
    assert out.splitlines()[:3] == ["equivalent", "qualitative distance: 0", "quantitative distance: 0.000"]


def test_a_missing_file_is_one_line_naming_it(tmp_path, capsys) -> None:
    a = write_timeline(tmp_path / "a.json", behaviour(ON_A))
    missing = str(tmp_path / "nope.json")
    status, out, err = run(capsys, a, missing)
    assert (status, out) == (1, "")
    assert err.count("\n") == 1 and missing in err and "cannot read" in err


@pytest.mark.parametrize(("text", "fragment"), [
    ("{not json", "not valid JSON"),
    ('{"events": [{"id": "e1"}]}', "events[0].components: expected a list, but it is missing"),
    ('{"format": "physink-project", "version": 1}', "missing"),
    (b"\xff\xfe".decode("latin-1"), "not UTF-8"),
])
def test_a_malformed_file_is_one_line_naming_it(tmp_path, capsys, text: str, fragment: str) -> None:
    bad = tmp_path / "bad.json"
    bad.write_bytes(text.encode("latin-1") if text.startswith("\xff") else text.encode("utf-8"))
    good = write_timeline(tmp_path / "a.json", behaviour(ON_A))
    status, out, err = run(capsys, good, str(bad))
    assert (status, out) == (1, "")
    assert err.count("\n") == 1 and str(bad) in err and fragment in err, err


def test_a_project_without_a_timeline_is_a_clear_one_line_error(tmp_path, capsys) -> None:
    project = write_project(tmp_path / "p.physink.json", None)
    good = write_timeline(tmp_path / "a.json", behaviour(ON_A))
    status, out, err = run(capsys, project, good)
    assert (status, out) == (1, "")
    assert err.count("\n") == 1 and project in err and "holds no timeline" in err


def test_up_to_demonstrated_forgives_the_simulation_bouncing_on_after_the_demonstration_and_says_so(
        tmp_path, capsys) -> None:
    # the two answers of issue 26: the search said equivalent, a plain comparison "not equivalent, distance 4"
    demonstrated = write_timeline(tmp_path / "demo.json", landed(behaviour(ON_B)))
    simulated = write_timeline(tmp_path / "sim.json", landed(behaviour(ON_B), bounces=2))
    status, out, _ = run(capsys, demonstrated, simulated)
    assert status == 0 and out.splitlines()[:2] == ["not equivalent", "qualitative distance: 4"]
    status, out, _ = run(capsys, demonstrated, simulated, "--up-to-demonstrated")
    lines = out.splitlines()
    assert status == 0 and lines[0] == "equivalent up to the last demonstrated event"
    assert lines[1] == "qualitative distance: 0" and lines[2].startswith("quantitative distance: ")
    assert lines[3:] == ["afterwards the simulation goes on: the ball bounces on the basket twice more"]
    status, out, _ = run(capsys, demonstrated, simulated, "--up-to-demonstrated", "--json")
    doc = json.loads(out)
    assert list(doc) == ["equivalent", "qualitative_distance", "quantitative_distance", "reasons", "rule",
                         "afterwards"]
    assert (doc["equivalent"], doc["qualitative_distance"], doc["rule"]) == (True, 0,
                                                                             "up to the last demonstrated event")
    assert doc["afterwards"] == "afterwards the simulation goes on: the ball bounces on the basket twice more"


def test_up_to_demonstrated_still_names_what_the_simulation_does_otherwise(tmp_path, capsys) -> None:
    demonstrated = write_timeline(tmp_path / "demo.json", landed(behaviour(ON_B)))
    simulated = write_timeline(tmp_path / "sim.json", landed(behaviour(UNDER_B)))
    status, out, _ = run(capsys, demonstrated, simulated, "--up-to-demonstrated")
    lines = out.splitlines()
    assert status == 0 and lines[:2] == ["not equivalent up to the last demonstrated event", "qualitative distance: 1"]
    assert lines[3].startswith("- Contact between ball and platform B")


def test_one_file_alone_must_be_a_project_that_kept_its_demonstration(tmp_path, capsys) -> None:
    timeline = write_timeline(tmp_path / "a.json", behaviour(ON_A))
    status, _, err = run(capsys, timeline, "--up-to-demonstrated")
    assert status == 1 and "a.json" in err and "must be a project that adopted a simulation" in err
