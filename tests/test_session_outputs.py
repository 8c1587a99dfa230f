"""The one output path of demo and replay: project.json, and timeline.json and timeline.txt after a demonstration."""

from __future__ import annotations

from physink_tui.formats.outputs import OutputFolder
from physink_tui.formats.project.codec import Project, encode_project
from physink_tui.formats.session_outputs import write_session_outputs
from physink_tui.formats.timeline_json import encode_timeline_json
from physink_tui.scene.components import MATERIALS, Body, Scene
from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.narrate import timeline_text

SCENE = Scene({"b1": Body("b1", "circle", (), 10.0, (5.0, 5.0), 0.0, MATERIALS["round"], "ball")}, {"b": 2})
TIMELINE = Timeline((Event("e1", "start"), Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0)))


def test_with_a_timeline_all_three_files_are_written_as_their_codecs_write_them(tmp_path) -> None:
    folder = OutputFolder.prepare(tmp_path / "out")

    target = write_session_outputs(folder, SCENE, TIMELINE, (100.0, 80.0), ("verb rolls",))

    assert target == tmp_path / "out" / "project.json"
    project = Project(SCENE, ("verb rolls",), TIMELINE, (100.0, 80.0))
    assert target.read_text(encoding="utf-8") == encode_project(project)
    assert (tmp_path / "out" / "timeline.json").read_text(encoding="utf-8") == encode_timeline_json(
        TIMELINE, {"b1": "ball"})
    assert (tmp_path / "out" / "timeline.txt").read_text(encoding="utf-8") == timeline_text(
        TIMELINE, {"b1": "ball"}) + "\n"


def test_without_a_timeline_only_the_project_is_written(tmp_path) -> None:
    folder = OutputFolder.prepare(tmp_path)

    write_session_outputs(folder, SCENE, None, (100.0, 80.0))

    assert sorted(p.name for p in tmp_path.iterdir()) == ["project.json"]
