"""Reads the timeline a command is pointed at: a timeline JSON file or a project holding one, with its labels;
the formats themselves are `timeline_json`'s and the project codec's."""

from __future__ import annotations

import json
from pathlib import Path

from physink_tui.errors import PhysinkError
from physink_tui.formats.project.codec import FORMAT as PROJECT_FORMAT
from physink_tui.formats.project.codec import decode_project
from physink_tui.formats.timeline_json import decode_timeline_json
from physink_tui.timeline.events import Timeline, TimelineError


def _is_project(text: str) -> bool:
    try:
        doc = json.loads(text)
    except (ValueError, RecursionError):
        return False  # decode_timeline_json says what is wrong with it
    return isinstance(doc, dict) and doc.get("format") == PROJECT_FORMAT


def _refuse_other_kinds(text: str, path: Path) -> None:
    """A journal, a capture or an empty file named as such: none holds a timeline."""
    takes = "this command takes a timeline JSON file or a project (.physink.json)"
    body = text.lstrip()
    if not body:
        raise TimelineError(f"{path}: empty file; {takes}")
    first = body.split("\n", 1)[0]
    if first.startswith(("#", "R:", "N:", "I:", "P:", "D:", "E:")):
        raise TimelineError(f"{path}: this is a capture (.hid); {takes}")
    try:
        head = json.loads(first)
    except (ValueError, RecursionError):
        return
    if isinstance(head, dict) and head.get("format") == "physink-journal":
        raise TimelineError(f"{path}: this is a journal (.physink.jsonl); {takes}")


def _read(path: Path) -> str:
    try:
        text = path.read_bytes().decode("utf-8")
    except OSError as e:
        raise TimelineError(f"cannot read {path}: {e.strerror or e}") from None
    except UnicodeDecodeError as e:
        raise TimelineError(f"{path}: not UTF-8 text (byte {e.start})") from None
    text = text.removeprefix("\ufeff")
    _refuse_other_kinds(text, path)
    return text


Named = tuple[Timeline, dict[str, str]]


def load_kept_demonstration(path: Path) -> tuple[Named, Named]:
    """The demonstration a project keeps and its (adopted, simulated) timeline, each with the scene's names.

    Raises:
        PhysinkError: one line naming the file: as `load_timeline`, or it is no project, or it keeps no
            demonstration (no simulation was adopted).
    """
    text = _read(path)
    if not _is_project(text):
        raise PhysinkError(f"{path}: one file alone must be a project that adopted a simulation; name the "
                           "demonstration and the simulation to compare two timelines")
    project = decode_project(text, path)
    if project.demonstration is None or project.timeline is None:
        raise PhysinkError(f"{path}: the project keeps no demonstration (no simulation was adopted in it); name the "
                           "demonstration and the simulation to compare")
    names = project.scene.names()
    return (project.demonstration, names), (project.timeline, dict(names))


def load_timeline(path: Path) -> tuple[Timeline, dict[str, str]]:
    """The timeline in a timeline JSON or project file, with its component labels (id -> label).

    Raises:
        PhysinkError: one line naming the file: it cannot be read, is not UTF-8, is no valid project or timeline,
            or is a project without a timeline.
    """
    text = _read(path)
    if not _is_project(text):
        try:
            return decode_timeline_json(text)
        except TimelineError as e:
            raise TimelineError(f"{path}: {e}", e.event_id) from None
    project = decode_project(text, path)  # SceneError names the file and the bad field; the file is read once
    if project.timeline is None:
        raise PhysinkError(f"{path}: the project holds no timeline (demonstrate the machine in demo mode first)")
    # the scene's names: its labels, and what an unlabelled spring or rope is
    return project.timeline, project.scene.names()
