"""Files written before a format change keep loading: fixtures made by the program at earlier commits.

``tests/data/formats/`` holds what ``physink replay tests/journals/bouncing_hits_a.physink.jsonl`` wrote at
866b8de: ``v1_bouncing.physink.json`` (project version 1, its timeline then an untyped object),
``v0_bouncing_timeline.json`` (the timeline file before it carried a version) and the narration; and what
``physink replay tests/journals/cup_dispenser.physink.jsonl`` wrote at a6c5aca:
``v1_cup_dispenser_timeline.json`` (timeline version 1, before the start named the pairs in contact).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physink_tui.cli import main
from physink_tui.errors import SceneError
from physink_tui.formats.project.codec import decode_project, encode_project
from physink_tui.formats.project.files import load_project
from physink_tui.formats.timeline_json import FORMAT, FORMAT_VERSION, decode_timeline_json, encode_timeline_json
from physink_tui.timeline.events import TimelineError

DATA = Path(__file__).parent / "data" / "formats"
PROJECT_V1 = DATA / "v1_bouncing.physink.json"
TIMELINE_V0 = DATA / "v0_bouncing_timeline.json"
NARRATION = DATA / "v1_bouncing_timeline.txt"
TIMELINE_V1 = DATA / "v1_cup_dispenser_timeline.json"


def with_in_contact(events: list[dict]) -> list[dict]:
    """Events of before ``in_contact`` as the current version writes them: none names a pair in contact."""
    return [{**ev, "in_contact": []} for ev in events]


def test_a_version_1_project_loads_with_a_typed_timeline_and_writes_back_as_the_current_version() -> None:
    project = load_project(PROJECT_V1)
    timeline, _ = decode_timeline_json(TIMELINE_V0.read_text(encoding="utf-8"))

    assert project.timeline == timeline and len(timeline) > 3 and project.demonstration is None
    old = json.loads(PROJECT_V1.read_text(encoding="utf-8"))
    new = json.loads(encode_project(project))
    old_events = old["timeline"]["events"]
    assert new == {**old, "version": 2, "timeline": {"events": with_in_contact(old_events)}, "demonstration": None}
    assert decode_project(encode_project(project), "again.json") == project


def test_an_unversioned_timeline_file_reads_and_is_written_again_with_its_version() -> None:
    old = TIMELINE_V0.read_text(encoding="utf-8")
    timeline, names = decode_timeline_json(old)

    new = encode_timeline_json(timeline, names)

    assert json.loads(new) == {"format": FORMAT, "version": FORMAT_VERSION,
                               "events": with_in_contact(json.loads(old)["events"])}


def test_a_version_1_timeline_reads_with_no_pair_in_contact_at_the_start() -> None:
    old = TIMELINE_V1.read_text(encoding="utf-8")
    timeline, names = decode_timeline_json(old)

    assert [ev.in_contact for ev in timeline.events if ev.type == "start"] == [()]
    doc = json.loads(old)
    assert json.loads(encode_timeline_json(timeline, names)) == {**doc, "version": FORMAT_VERSION,
                                                                  "events": with_in_contact(doc["events"])}


@pytest.mark.parametrize("source", [PROJECT_V1, TIMELINE_V0])
def test_physink_timeline_narrates_the_old_files_as_they_were(source: Path, capsys) -> None:
    assert main(["timeline", str(source)]) == 0
    assert capsys.readouterr().out == NARRATION.read_text(encoding="utf-8")


def test_a_newer_project_is_refused_naming_the_file_and_both_versions() -> None:
    raw = json.loads(PROJECT_V1.read_text(encoding="utf-8"))
    raw["version"] = 3
    with pytest.raises(SceneError, match=r"^new\.json was written by format version 3; this program reads version 2"):
        decode_project(json.dumps(raw), "new.json")


def test_a_newer_timeline_file_is_refused_naming_the_file_and_both_versions(tmp_path, capsys) -> None:
    raw = {"format": FORMAT, "version": FORMAT_VERSION + 1, **json.loads(TIMELINE_V0.read_text(encoding="utf-8"))}
    newer = tmp_path / "newer.json"
    newer.write_text(json.dumps(raw), encoding="utf-8")

    assert main(["timeline", str(newer)]) == 1
    err = capsys.readouterr().err
    assert str(newer) in err and f"version {FORMAT_VERSION + 1}; this program reads version {FORMAT_VERSION}" in err
    with pytest.raises(TimelineError):
        decode_timeline_json(json.dumps(raw))
