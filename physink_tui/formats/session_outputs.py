"""Writes what a session leaves in an output folder: ``project.json`` and, after a demonstration,
``timeline.json`` and ``timeline.txt``; the one path `physink demo` and `physink replay` share. Printing is theirs."""

from __future__ import annotations

from pathlib import Path

from physink_tui.formats.outputs import OutputFolder
from physink_tui.formats.project.codec import Project, encode_project
from physink_tui.formats.timeline_json import encode_timeline_json
from physink_tui.formats.timeline_text import encode_timeline_text
from physink_tui.scene.components import Scene
from physink_tui.timeline.events import Timeline


def session_output_texts(scene: Scene, timeline: Timeline | None, canvas: tuple[float, float],
                         vocabulary: tuple[str, ...] = (), demonstration: Timeline | None = None) -> dict[str, str]:
    """The text of each file `write_session_outputs` writes, by file name (what a replay is compared by)."""
    names = scene.names()
    texts = {}
    if timeline is not None:
        texts["timeline.json"] = encode_timeline_json(timeline, names)
        texts["timeline.txt"] = encode_timeline_text(timeline, names)
    texts["project.json"] = encode_project(Project(scene, vocabulary, timeline, canvas, demonstration))
    return texts


def write_session_outputs(folder: OutputFolder, scene: Scene, timeline: Timeline | None,
                          canvas: tuple[float, float], vocabulary: tuple[str, ...] = (),
                          demonstration: Timeline | None = None) -> Path:
    """Writes the timeline files (when there is a timeline), then the project; returns the project's path.

    Args:
        folder: the run's output folder, prepared.
        scene: the session's sketch; its names label the timeline's components.
        timeline: the demonstrated timeline, or None before any demonstration (then no timeline file is written).
        canvas: (width, height) of the canvas, in canvas units.
        vocabulary: the user's vocabulary lines (`physink_tui.formats.project.codec.vocabulary_lines`).
        demonstration: when ``timeline`` is a simulation adopted for a demonstration, that demonstration (the
            project keeps it), else None.

    Raises:
        PhysinkError: a file cannot be written (its path and the cause named); `SceneError` for a bad project.
    """
    names = scene.names()
    if timeline is not None:
        folder.write("timeline.json", encode_timeline_json(timeline, names))
        folder.write("timeline.txt", encode_timeline_text(timeline, names))
    target = folder.file("project.json")
    project = Project(scene, vocabulary, timeline, canvas, demonstration)
    folder.write("project.json", encode_project(project, where=str(target)))
    return target
