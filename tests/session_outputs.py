"""The files a session's end writes (project, timeline JSON and text), as text, for tests comparing sessions."""

from __future__ import annotations

import json

from physink_tui.formats.project.codec import Project, encode_project
from physink_tui.formats.timeline_formats import timeline_json
from physink_tui.session.session import Session
from physink_tui.timeline.narrate import timeline_text


def outputs(session: Session) -> dict[str, str]:
    names = session.scene.names()
    timeline = session.timeline
    files = {}
    doc = None
    if timeline is not None:
        files["timeline.json"] = timeline_json(timeline, names)
        files["timeline.txt"] = timeline_text(timeline, names)
        doc = json.loads(files["timeline.json"])
    files["project.json"] = encode_project(Project(session.scene, (), doc, session.canvas))
    return files
