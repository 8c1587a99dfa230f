"""The files a session's end writes (project, timeline JSON and text), as text, for tests comparing sessions."""

from __future__ import annotations

from physink_tui.formats.session_outputs import session_output_texts
from physink_tui.session.session import Session


def outputs(session: Session) -> dict[str, str]:
    return session_output_texts(session.scene, session.timeline, session.canvas, session.vocabulary_lines(),
                                session.demonstration)
