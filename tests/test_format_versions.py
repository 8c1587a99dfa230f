"""Files written before a format change keep loading: fixtures made by the program at commit 866b8de.

``tests/data/formats/`` holds what ``physink replay tests/journals/bouncing_hits_a.physink.jsonl`` wrote at
866b8de: ``v1_bouncing.physink.json`` (project version 1, its timeline then an untyped object),
``v0_bouncing_timeline.json`` (the timeline file before it carried a version) and the narration.
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


def test_a_version_1_project_loads_with_a_typed_timeline_and_writes_back_the_same_bytes() -> None:
    project = load_project(PROJECT_V1)
    timeline, _ = decode_timeline_json(TIMELINE_V0.read_text(encoding="utf-8"))

    assert project.timeline == timeline and len(timeline) > 3
    assert encode_project(project) == PROJECT_V1.read_text(encoding="utf-8")


def test_an_unversioned_timeline_file_reads_and_is_written_again_with_its_version() -> None:
    old = TIMELINE_V0.read_text(encoding="utf-8")
    timeline, names = decode_timeline_json(old)

    new = encode_timeline_json(timeline, names)

    assert json.loads(new) == {"format": FORMAT, "version": FORMAT_VERSION, **json.loads(old)}
    assert new == old.replace("{\n", f'{{\n "format": "{FORMAT}",\n "version": {FORMAT_VERSION},\n', 1)


@pytest.mark.parametrize("source", [PROJECT_V1, TIMELINE_V0])
def test_physink_timeline_narrates_the_old_files_as_they_were(source: Path, capsys) -> None:
    assert main(["timeline", str(source)]) == 0
    assert capsys.readouterr().out == NARRATION.read_text(encoding="utf-8")


def test_a_newer_project_is_refused_naming_the_file_and_both_versions() -> None:
    raw = json.loads(PROJECT_V1.read_text(encoding="utf-8"))
    raw["version"] = 2
    with pytest.raises(SceneError, match=r"^new\.json was written by format version 2; this program reads version 1"):
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
