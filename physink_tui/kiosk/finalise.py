"""Writes a finished kiosk session's outputs into its folder (project, timeline, narration, video, summary);
keeps no state, reads no device. Which folders exist and the index are `store`'s.

Every file is written atomically, the summary ``session.json`` last: a folder with a summary is complete, one
without is unfinished and is finalised again (from its journal) when the kiosk starts, so a kill at any moment
of finalising loses nothing.

A session is always finalised from its journal (`finalise_journal`): the outputs are then what ``physink replay``
of that journal gives, whether the session ended normally or was recovered after a crash. The kiosk runs it in a
child process at a lower priority (``python -m physink_tui.kiosk.finalise FOLDER REASON WxH``, `child_command`), so
drawing a video never takes the processor or the interpreter lock from the session being recorded.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from physink_tui.errors import PhysinkError
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.outputs import OutputFolder
from physink_tui.formats.session_outputs import write_session_outputs
from physink_tui.kiosk.folder_files import JOURNAL, NARRATION, OUTPUTS, SUMMARY, VIDEO
from physink_tui.render.export import Export, Look
from physink_tui.scene.components import Body
from physink_tui.session.session import Session
from physink_tui.timeline.events import Timeline, event_label


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


def finalise(folder: Path, session: Session, ending: Ending, look: Look,
             dropped: str | None = None) -> dict[str, object]:
    """Write the outputs of ``session`` (finished) into ``folder``; return the summary (also ``session.json``).
    ``dropped`` says which journal lines a recovery left out (a ``dropped`` key of the summary).

    Raises:
        PhysinkError: a file cannot be written (a full disk); what was written before stays valid.
    """
    out = OutputFolder(folder)
    scene, timeline = session.scene, session.timeline
    write_session_outputs(out, scene, timeline, session.canvas, session.vocabulary_lines(), session.demonstration)
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
        "labels": sorted(set(scene.labels().values())),
        "files": sorted({JOURNAL, SUMMARY, *(name for name in OUTPUTS if out.file(name).exists())}),
        "messages": len(session.messages),
    }
    if dropped is not None:
        summary["dropped"] = dropped
    out.write(SUMMARY, json.dumps(summary, sort_keys=True) + "\n")
    return summary


NICENESS = 10
"""How much lower than the kiosk's the finalising child's scheduling priority is."""


def finalise_journal(folder: Path, ending: Ending, look: Look) -> dict[str, object]:
    """Replay the folder's journal (up to its last whole line, and up to its first malformed one: what is dropped
    is said in the summary) and `finalise` the session it gives.

    Raises:
        PhysinkError: the journal's header cannot be read (torn or malformed) or a file cannot be written.
    """
    journal = read_journal(folder / JOURNAL, salvage=True)
    session = Session.from_header(journal.header).run(journal.entries)
    return finalise(folder, session, ending, look, None if journal.dropped is None else str(journal.dropped))


def child_command(folder: Path, ending: Ending, look: Look) -> list[str]:
    """The command line of a child process that finalises ``folder`` (see the module docstring)."""
    return [sys.executable, "-m", "physink_tui.kiosk.finalise", str(folder), ending.reason,
            f"{look.width}x{look.height}", "recovered" if ending.recovered else "live"]


def _child(argv: list[str]) -> int:
    folder, reason, size, how = argv
    width, height = (int(v) for v in size.split("x"))
    try:
        os.nice(NICENESS)
    except OSError:
        pass  # not allowed here: finalise at the same priority
    try:
        finalise_journal(Path(folder), Ending(reason, Path(folder).name, how == "recovered"), Look(width, height))
    except PhysinkError as exc:
        print(f"{folder}: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(_child(sys.argv[1:]))
