"""One module per ``physink`` subcommand, each a ``run(args) -> int`` driving the session; cli parses.

Reachable from the command line today: `physink decode`, `devices`, `record`, `recognize`, `replay` (captures to
gestures; journals through the whole session, `--ticks HZ` to advance the clock between inputs as a live driver
does, `--video --frames` to draw the demonstration), `timeline`, `equiv`, `export`, `demo`, `simulate`, `kiosk`,
`tui` and `listen`, through `physink_tui/commands/` (`demo` on a terminal and `tui` open the Textual app): every
subcommand of the DESIGN.md table is built (one whose module is missing says `physink <command>: not available yet
(… is not written yet)` on stderr and exits 2). `physink replay` of a capture runs only the input side (`PenInput`,
no session).

`physink decode` (`decode.py`) takes one of two paths, writing the same bytes: a capture of at most 8 MB whose every
line is plain (`input/captures/plain.py` says) goes through `decode_plain.py` without numpy (each distinct report
decoded once by `input/hid/distinct.py`, formatted once; the times from their stamps' digits), since numpy's import
alone costs more than a small capture's decoding; any other streams through the numpy path (`input/captures/parser.py`,
`input/hid/chunks.py`, `decode_jsonl.py`), whose memory stays flat in the capture's size.

Shared by several commands: `input_file.py` reads a command's input file once (so pipes and FIFOs work) and names
its kind; `timeline_source.py` reads the timeline a command is pointed at (a timeline JSON file or a project holding
one, with its labels); `gesture_output.py` formats gestures as text lines and JSON Lines for `physink replay`.
"""
