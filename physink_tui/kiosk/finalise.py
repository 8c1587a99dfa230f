"""Writes a finished kiosk session's outputs into its folder (project, timeline, narration, video, summary);
keeps no state, reads no device. Which folders exist and the index are `store`'s.

Every file is written atomically, the summary ``session.json`` last: a folder with a summary is complete, one
without is unfinished and is finalised again (from its journal) when the kiosk starts, so a kill at any moment
of finalising loses nothing.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from physink_tui.formats.outputs import OutputFolder
from physink_tui.formats.session_outputs import write_session_outputs
from physink_tui.render.export import Export, Look
from physink_tui.scene.components import Body
from physink_tui.session.session import Session
from physink_tui.timeline.events import Timeline, event_label

JOURNAL = "journal.physink.jsonl"
"""The session's journal in its folder (written from the session's first input)."""
SUMMARY = "session.json"
"""Written last: its presence says the folder is complete."""
NARRATION = "narration.txt"
VIDEO = "video.mp4"
OUTPUTS = ("project.json", "timeline.json", "timeline.txt", NARRATION, VIDEO, SUMMARY)
"""Every file a finished session folder has besides the journal (no timeline files without a demonstration)."""


@dataclass(frozen=True, slots=True)
class Ending:
    """How a session ended: ``reason`` (``end zone``, ``end button``, ``idle``, ``capture ended``, ``stopped``,
    ``recovered``), when it started (the folder's UTC name) and whether its journal was all it left (recovered after
    a crash)."""

    reason: str
    session: str
    recovered: bool = False


def narration_lines(timeline: Timeline | None, names: Mapping[str, str]) -> str:
    """One line per event (the start excluded) in time order: its time in seconds and its narration."""
    if timeline is None:
        return ""
    events = sorted((ev for ev in timeline.events if ev.type != "start"), key=lambda ev: (ev.t0, int(ev.id[1:])))
    return "".join(f"{ev.t0:8.2f} s  {event_label(ev, names)}\n" for ev in events)


def finalise(folder: Path, session: Session, ending: Ending, look: Look) -> dict[str, object]:
    """Write the outputs of ``session`` (finished) into ``folder``; return the summary (also ``session.json``).

    Raises:
        PhysinkError: a file cannot be written (a full disk); what was written before stays valid.
    """
    out = OutputFolder(folder)
    scene, timeline = session.scene, session.timeline
    write_session_outputs(out, scene, timeline, session.canvas, session.vocabulary_lines())
    out.write(NARRATION, narration_lines(timeline, scene.names()))
    Export(scene, timeline, session.canvas, look).video(out.file(VIDEO))
    events = [] if timeline is None else [ev for ev in timeline.events if ev.type != "start"]
    summary: dict[str, object] = {
        "session": ending.session,
        "ended": ending.reason,
        "recovered": ending.recovered,
        "seconds": round(session.t, 3),
        "bodies": sum(1 for c in scene.components.values() if isinstance(c, Body)),
        "components": len(scene.components),
        "events": len(events),
        "labels": sorted({c.label for c in scene.components.values() if getattr(c, "label", None)}),
        "files": sorted({JOURNAL, SUMMARY, *(name for name in OUTPUTS if out.file(name).exists())}),
        "messages": len(session.messages),
    }
    out.write(SUMMARY, json.dumps(summary, sort_keys=True) + "\n")
    return summary
