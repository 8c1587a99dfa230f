"""The session journal (``.physink.jsonl``): entries, their JSON lines, durable appending and reading back;
replaying is the session's job.

`entries.py` (frozen entries and header, the header's defaults; `CommandEntry.project` holds a `load` line's
embedded project), `value_checks.py` (the journal's own words for single values — times, commands, hex reports —
over `json_checks`, shared by writer and reader so anything written reads back), `header_checks.py` (devices — of
the header and of `device` hot-plug lines —, the tablet-to-canvas `mapping` key by key, the `vocabulary`),
`codec.py` / `header_codec.py` (the only JSON code), `writer.py` (`JournalWriter`: O_APPEND, one write per batch,
fsync when 100 ms have passed and at close; `check` says whether an entry would be taken; on a write error it
truncates back to the last whole line and refuses further appends with one `JournalError`), `reader.py`
(`read_journal`, `iter_journal`: names path, line and key of the first error; an incomplete last line is reported as
`truncated`, everything before it is read; a UTF-8 BOM is skipped; `looks_like_journal` tells a journal from a
capture by its first bytes). Composing journals from captures is `input/journal_compose.py`'s.

Lines are compact JSON in a fixed key order, `t` first: `hid` (a report from a device), `pen` (a canvas sample),
`cmd` with `args` (`mode`, `play`, `pause`, `stop`, `seek`, `clear`, `undo`, `redo`, `label`, `simulate`, `save`,
`load`, `end`), `say`, and `device` (a tablet plugged in, or back in, during the session, with its descriptor). A
`load` line embeds the loaded project's JSON object (`"project": {...}`), checked as a project file is, so a replay
needs no other file; a `load` without it is refused, naming the line. `end` (no arguments) says the session ended at
t: a session with a journal attached writes it when it finishes, so a replay runs the physics exactly as long.
Journals composed from captures (the demo's, `tests/journals/`) may end without one; a replay then ends at the last
entry.

Journals come from other programs and people too, so reading asks only for DESIGN.md's four header keys (`format`,
`version`, `canvas`, `devices`). The rest default: `program` "unknown", `mapping` `{}` — every missing mapping key
takes the identity (canvas size from the header, the tablet's proportions the canvas's, the whole area), so tablet
(x, y) lands on canvas (x, y) — `tip_thresholds` libinput's 5 % down / 1 % up, no `vocabulary` (checked with the
core's `timeline.phrases.parse_vocabulary`). Unknown keys (also inside `canvas`, `devices`, `mapping`,
`tip_thresholds`, `pen`) are ignored and reported as warnings, which `physink replay` prints on stderr with its
notes. Every present value is checked by type and range and refused as one `JournalError` naming file, line and key
path (`mapping.area[0]`); `t` must be finite, never decreasing and at most a year and a day (`MAX_SECONDS`); NaN,
Infinity and a key twice in one object are refused. A descriptor the decoder cannot use is named with file, line (1,
or the `device` line's) and device id by `input/journal_replay.py`. `tests/test_journal_fuzz.py` mutates a valid
journal 2,000 ways and sees only `JournalError`s.
"""
