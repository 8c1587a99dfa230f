"""The causal timeline as the thesis's text, as written to ``timeline.txt``; the narration is the core's
(`physink_tui.timeline.narrate.timeline_text`), this only frames it as a file. Write-only, no file I/O."""

from __future__ import annotations

from collections.abc import Mapping

from physink_tui.timeline.events import Timeline
from physink_tui.timeline.narrate import timeline_text


def encode_timeline_text(timeline: Timeline, names: Mapping[str, str]) -> str:
    """The narration of the timeline, ending in a newline (what ``timeline.txt`` holds)."""
    return timeline_text(timeline, names) + "\n"
