"""The headless kiosk recording service (`physink kiosk`): a driver of the session with no UI, never Textual.

`physink kiosk` is a driver of the session with no UI. `commands/kiosk.py` opens the tablet (waiting for it;
`ReconnectingSource` for unplugging) or a capture (`CaptureReplaySource`, realtime, `--speed` times faster). A replay's
clock is the capture's own: the source pump keeps each report's time (`keep_time`), the kiosk's clock is the latest
report's and `--idle` is measured between reports, so the sessions (their journals, byte for byte) are the same at any
speed; an end stops the ended session's clock at that moment (`_Live.end_now`); a mode press reads the mode from the
session's view once the runner has handled every input before it (`SessionRunner.wait_handled`). A `--device` value that
can name no tablet is refused at once. It builds the journal header (the canvas mapped onto the tablet's area beside the
hot zones), installs the SIGTERM handler and runs `kiosk.service.Kiosk`:

- `hot_zones.py`: `HotZones`: rectangles of the tablet that are buttons (`mode`, `sketch`, `demo`, `undo`, `redo`,
  `clear`, `play`, `stop`, `end`) and the drawing `area` beside them; the default strip along the top edge; the JSON
  zones file, its mistakes named
- `controls.py`: `ControlFilter`: decodes each report a second time (the session's decoder and tip thresholds) to
  tell a press (a touch that begins in a zone: held back from the session until the lift; the lift inside fires it)
  from drawing (a touch that begins on the canvas is the session's, wherever it goes); pad reports
  (`input/hid/pad.py`'s `PadDecoder`: Button-page bits of a Keypad/Tablet Function Keys collection, or the
  Huion/UC-Logic vendor 0xE0 frame) are held back and a button going down is a press
- `service.py`: `Kiosk`: reports from the source thread go through the filter; the first touch starts a session (a
  folder, and a `Session` journaling there with its `SessionRunner`: `session.journaled.Journaled`); presses become
  the commands they trigger (journaled as such, so replays never look at zones); the main thread ends a session on
  its `end` zone, `--idle` seconds of input time without a report, the capture's end or SIGTERM; a finaliser thread
  writes the ended sessions in order while the next one records, then retires old ones; `recover` finishes, from
  their journals, the sessions a killed run left
- `finalise.py`: a finished session's `project.json`, `timeline.json`/`.txt`, `narration.txt`, `video.mp4` (960x600)
  and, last, `session.json` (its presence marks the folder complete)
- `speech.py`: `KioskSpeech` (`--speech`): `input/speech`'s `MicrophoneListener` listening all the time (its
  voice-activity detector cuts utterances, no push-to-talk); each utterance goes to `Kiosk.hear`, which says an
  accepted one to the session being recorded, stamped when it began (session time), counts it as input for `--idle`,
  and logs a rejected one; no microphone or model: one log line, recording goes on
- `store.py`: `SessionStore`: folders named by UTC start, `index.jsonl` appended one fsynced line at a time (never twice
  for a session), unfinished and finished folders, `retire` for `--keep`/`--max-disk` (never the session just written
  nor the one recording, which still count), free space
- `folder_files.py`: the names of the files in a session's folder (so the store and the command need not load the
  renderer to know them)

Recovery reads a journal with `read_journal(salvage=True)`: every entry before the first malformed line is kept and
`Journal.dropped` says from which line on what was left out and why (logged, and `dropped` in `session.json`), so a
garbage line loses only what follows it and the session is finished once, never retried at every start; a journal
whose header cannot be read is set aside as `journal.physink.jsonl.unreadable` (`SessionStore.set_aside`). The TUI's
`storage.unfinished_journals` reads the same way and its recovery question says what is dropped.

Crash safety comes from the session's journal: every handled entry is written and flushed at once (fsync paced by
`FSYNC_INTERVAL`), so SIGKILL loses only the entries still queued for the runner's next tick (under 10 ms at 120
Hz); tests/test_kiosk_crash.py kills a kiosk 20 times at random moments and measures it in input time. The kiosk
never imports Textual (an import-linter contract and a test).
"""
