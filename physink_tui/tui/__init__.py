"""The Textual control panel (`physink tui`, `physink demo` on a terminal); the only package that imports Textual.

The TUI is one more driver of the session (STYLE.md "Textual UI": App → Screens → Widgets): every key, button, mouse
movement and tablet report becomes a journal entry submitted to a `SessionRunner`; every widget draws the latest
`SessionView`. It keeps no state of the machine, so the session's journal rebuilds what it showed
(`tests/test_tui_session_files.py` replays a TUI session's journal to the same scene).

- `app.py`: `PhysinkApp`, `TuiOptions`, `make_app` (the one factory of the CLI and the tests): on mount asks whether
  to recover an unfinished journal, then starts the `LiveSession`; passes views on (`ViewUpdated`, only views of a
  new revision, posted from the runner's thread); asks before quitting with unsaved work (the document differs from
  the one last saved or opened); stops the sources and the runner (the journal gets its `end`) and removes a journal
  in which nothing happened
- `live.py`: `LiveSession` (a journaling `Session` and its runner, wired by `session.journaled`, the mouse
  `ProgrammaticPenSource` through a `SourcePump`; `prior` entries handled at once before the runner starts:
  recovery, tests), `JournalFeed` (a recorded session's entries submitted when due, at a speed: `physink demo`,
  `--replay`)
- `tablet.py`: `TabletWatch`: looks for the tablet every 2 s until one opens (hot-plug), announces it with a
  `device` entry, reads it through `ReconnectingSource` + `SourcePump` (unplugging ends the stroke, plugging back
  carries on), says what it found on the status bar; `--serial` reads an ISDV4 tablet, mapped with the session's
  mapping
- `config.py`: the settings file `$XDG_CONFIG_HOME/physink/config.json` (`Config`: mapping — used area, rotation,
  left-handed, keep aspect, pen display —, tip thresholds, theme), checked with the mapping's and thresholds' own
  checks, written atomically; `Config.header()` is a new session's journal header, so the mapping a session used is
  in its journal and changed settings apply from the next session
- `screens/settings.py`: the settings form (F2); the theme applies at once; which monitor a pen display is, and a
  button fitting the area to where the canvas is drawn on it (`displays.py`)
- `widgets/time_slider.py`: the playback clock on a bar; a click seeks
- `storage.py`: the XDG folders (`$XDG_DATA_HOME/physink/sessions/`, `…/exports/`, `…/projects/`, `$XDG_CONFIG_HOME`),
  journal names, unfinished journals (no `end` line, at least one input), renaming a recovered one `….recovered`;
  where Save writes (`new_project_path`, `project_target`: a bare name goes in the projects folder)
- `push_to_talk.py`: `PushToTalk`: `v` toggles a `MicrophoneListener` (`input/speech`) on the session's runner clock
  (terminals send no key release), and holding the pen's barrel button listens until it is released (the screen sees
  the button in the view's pen states, `barrel_held`; it sets `button_pressed` on the UI thread and a worker
  reconciles with it under a lock, so workers running out of order still end in the latest state); the grammar takes
  the scene's labels when listening starts; an accepted utterance becomes `runner.say(text, began)`; its status
  (listening, heard, not understood, no microphone) goes to the status bar; loading the recogniser and stopping
  (which decodes the last utterance) run in a worker thread
- `halfblocks.py`: RGBA pixels → `Strip`s of `▀` cells (two pixels a cell), runs of equal colour pairs merged,
  styles cached
- `graphics.py`: which picture the terminal shows — `kitty`, `sixel` or `halfblocks` — from what the terminal
  answers (`probe`: Kitty's graphics query, XTVERSION, then DA1, which every terminal answers, ending the wait at
  once; `TerminalReply`): Kitty graphics when it answers the graphics query (half-blocks and a note for kitty before
  0.28, which has no Unicode placeholders: Debian 12's 0.26), Sixel when DA1 announces attribute 4; only a terminal
  that answers nothing within a second is judged by `TERM`, `TERM_PROGRAM`, `KITTY_WINDOW_ID`; half-blocks under
  tmux/screen without asking; `PHYSINK_GRAPHICS` forces one; a cell's pixel size from `TIOCGWINSZ`; asked by
  `commands/tui.py` before Textual owns the terminal. A Sixel picture is drawn again whenever Textual writes cells
  over it (`PhysinkApp._display` → `SceneView.painted`): a full repaint, such as the tree filling, wiped it in a real
  xterm, which decoding the escapes had never shown
- `displays.py`: which display a pen display covers: X monitors from `xrandr --listmonitors`, the terminal window
  from `xwininfo -id $WINDOWID`, the canvas's rectangle on the screen from the scene view's cells, and that
  rectangle as a tablet area (fractions of the monitor)
- `screens/background.py`: `BackgroundWork`, a helper `MainScreen` owns (it sees the screen through a typed `Host`):
  SIMULATE in a thread worker (`SearchJob` on the latest view's document; `SearchProgressed` after each rollout into
  the `SearchBar`; escape or Cancel stops it keeping the best so far; when it ends, the result goes to the session
  as a `Searched` entry if the latest view still shows the document searched, else it is dropped; the first view
  showing another document — an edit — stops it before its next rollout, the one under way ends, and the status
  says it is discarded: `drop_changed_search`) and the export workers (the video; the picture, `picture.py`); a
  worker that dies on a bug is said in a dialog (`PhysinkApp.failed`)
- `pacing.py`: `FramePacer`: every view is drawn while the UI keeps up; while views reach it late (more than 25 ms
  after the runner posted them: a starved machine) one every 1/32 s, the latest caught up by a timer, so keys are
  handled between frames
- `widgets/search_bar.py`: `SearchBar`: the search's progress line (a `ProgressBar` of rollouts, the best distances,
  Cancel), shown only while a search runs
- `screens/project_files.py`: `ProjectFiles`, a helper `MainScreen` owns (typed `Host`): Save (default in the projects
  folder, says where), Load (`load_project`, the one read and check every command makes, embedded in a ``load``) and
  adopting a simulation
- `screens/playback_keys.py`: `PlaybackKeys`, a helper `MainScreen` owns: the seeks of the arrow, home and end keys
  and of the tree and slider (`SEEK_STEP` from the last seek sent, so every press counts)
- `screens/speech_keys.py`: `SpeechKeys`, a helper `MainScreen` owns: push-to-talk (the `v` key toggles; holding the
  pen's barrel button listens until it is released), its starts and stops in the screen's ``speech`` workers and
  what it is doing or heard as `SpeechStatus` messages for the status bar
- `screens/main.py`: `MainScreen`: the layout (the scene; beside it the tree, the chosen event's full name below it — a
  deep event's name is cut in the tree — and the narration log), every key binding, actions → commands; the playback
  keys (space, ←, →, home, end) are priority bindings, so they work whichever widget has focus (the tree, a button, the
  log), and `check_action` hands them back to a focused text input; each arrow press seeks `SEEK_STEP` from where the
  last seek went while the session has not handled it yet (the entry's `t` against the latest view's), so four quick
  presses are four seeks, 2 s; ctrl+c quits as q does, on every screen (an app priority binding; a text input keeps it
  for copying), ends a drag under way first (`SceneView.lift`), asks when there is unsaved work (a stroke being drawn
  counts), and pressed again while asking quits; Save (offers
  `$XDG_DATA_HOME/physink/projects/machine-<time>.physink.json`, then the last place saved; atomic `save_project` from
  the latest view, then a journaled `save PATH`; the status bar and a notification say the absolute path), Load (read
  and checked first: a broken project is an error modal and the work stays; then a journaled `load` with the project
  embedded), Simulate (`screens/background.py`; its result's paths are drawn in red; a replay can end with it,
  `TuiOptions.simulate_after`), Adopt (`a`: the result's parameters applied to the scene with `sim.parameters.apply` and
  its simulated timeline, as a journaled `load` with the project embedded: one undoable action that a replay rebuilds),
  Export (`screens/background.py`: a thread worker writing an MP4 of the timeline to `…/exports/`, cancellable with
  escape); the too-small notice
- `screens/modals.py`: help (the drawing vocabulary, `drawing_help.py`, then every binding), error, yes/no, one line of
  text, the timeline as text
- `widgets/scene_view.py`: `SceneView`: `view_frame` of the view (plus the SIMULATE result's paths in red), rendered
  at 2x2 pixels per half-block pixel and averaged, drawn as half blocks — or, with a graphics protocol, rendered at
  the terminal's pixel size and sent as Kitty escapes (one image id replaced frame after frame, shown through
  placeholder cells that Textual lays out as text) or as Sixel drawn over blank cells after each refresh, both
  written through Textual's driver so they stay in order with its output; the mouse as a pen (`SceneView.Pen`
  messages in canvas fractions; left draws, right erases)
- `widgets/timeline_tree.py`, `widgets/bars.py`, `widgets/controls.py`: the timeline as a `Tree` (rebuilt only when the
  events, causes, starts or names change, not while a recording lengthens movements; each event under its first cause;
  choosing one posts `Seek`: the playback goes there and the scene view outlines the event's bodies until the scene
  changes), the narration bar (the event at the playback clock, else the last message — passing over a SIMULATE verdict
  once the view no longer shows that search: the machine it was about has changed), the status bar (mode, the clock
  never past the duration, the latest message — what the last stroke became —, activity, pen, device, speech, journal;
  both repainted only when their text changes, without a layout of the screen: Textual's `Static.update` lays out the
  whole screen by default, which at 60 views a second was most of the UI thread's time), the buttons
- `widgets/message_log.py`: `MessageLog`, the narration log under the tree: every message of the view
  (`SessionView.messages`: what each stroke became, selections, erases, refusals, SIMULATE's verdicts) with its input
  time, appending only the new ones
- `drawing_help.py`: the drawing vocabulary of the help screen: each gesture (a line through a body, a small circle,
  an X, a zigzag, round and straight bodies, a rope, dwell-and-drag, tap) as a small braille drawing with what it
  makes and the sizes that count, written from the constants the interpretation (`JOINT_MAX_SIZE`, `INSIDE_SHARE`),
  the X pairing (`MIN_ANGLE`), sketch mode (`X_CANDIDATE`, `X_WAIT`) and the gesture engine (`GestureConfig`) use
- `picture.py`: `write_picture`: the view shown (any mode; the narration and time bar below the canvas in demo mode,
  a SIMULATE result's paths in red) drawn at 1280x800 as a PNG (`i`, the Picture button), beside the videos
- `physink.tcss`: the styles: package data read through `importlib.resources` (`PhysinkApp.CSS`), so an installed
  wheel has them (`tests/test_wheel.py`)

The session gained one field for it: `SessionView.pens` (each input device's pen state and the pressure of its stroke),
and `save PATH` is now journaled without a message (the driver writes the file, a replay writes none). Tests:
`tests/test_tui_controls.py` (every button and key through Pilot), `test_tui_drawing.py` (a box, a circle and an X drawn
with the mouse become a welded box and a circle), `test_tui_session_files.py`, `test_tui_parts.py`,
`test_tui_snapshots.py` (SVG snapshots in `tests/__snapshots__/`), `test_tui_tmux.py` (`physink demo` in tmux, 120x40;
skipped without tmux), `test_tui_simulate.py` (progress, keys during a search, cancel, a search dropped after an edit,
adopt, undo, playback, a replay ending with SIMULATE; each journal replayed to the same result), `test_tui_graphics.py`
(the scene view under Kitty and Sixel), `test_tui_graphics_pty.py` (`physink tui` in a real pty with TERM a Kitty, Sixel
or other terminal: the escapes Textual's driver writes decode to the scene; Kitty's placeholder cells carry the image id
in the colour Textual writes, 24-bit or 8-bit), `test_tui_displays.py`, `test_tui_pacing.py`, `test_tui_exit.py` (a
crash of the app exits 1 with its traceback, in a pty; a session or background job stopped by a bug is said in a dialog
and quitting exits 1: `PhysinkApp.failed`, `open_tui` returns `App.return_code`), `test_tui_feedback.py` (the session's
messages in the status line and the log, the help's vocabulary, an event's full name, the save folder, the picture
export, the clock at the end), `test_tui_keys.py` (the playback keys whatever has focus, a text input keeping them,
every arrow press counting while the session is held busy, ctrl+c with and without unsaved work and mid-drag),
`test_wheel.py` (the wheel built from a clean copy, installed in a fresh virtualenv, every command run from there, the
TUI in a pty read through pyte), `test_real_terminals.py` (`physink tui` in Debian's xterm as a VT340 and kitty under
Xvfb, photographed, the scene's pixels found: Sixel at full resolution, half-blocks in kitty 0.26; the X tools installed
by `.ci/run` and required under `PHYSINK_REQUIRE_GUI=1`). The app collects and freezes the startup heap once the session
runs (`gc.freeze`), so full collections — which stop every thread — skip it. Figures in docs/BENCHMARKS.md.
"""
