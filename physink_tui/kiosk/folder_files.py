"""The names of the files in a kiosk session's folder; no behaviour (so the store and the command need not load
the renderer to know them)."""

JOURNAL = "journal.physink.jsonl"
"""The session's journal in its folder (written from the session's first input)."""
SUMMARY = "session.json"
"""Written last: its presence says the folder is complete."""
NARRATION = "narration.txt"
VIDEO = "video.mp4"
OUTPUTS = ("project.json", "timeline.json", "timeline.txt", NARRATION, VIDEO, SUMMARY)
"""Every file a finished session folder has besides the journal (no timeline files without a demonstration)."""
