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
- `storage.py`: the XDG folders (`$XDG_DATA_HOME/physink/sessions/`, `…/exports/`, `$XDG_CONFIG_HOME`), journal
  names, unfinished journals (no `end` line, at least one input), renaming a recovered one `….recovered`
- `push_to_talk.py`: `PushToTalk`: `v` toggles a `MicrophoneListener` (`input/speech`) on the session's runner clock
  (terminals send no key release), and holding the pen's barrel button listens until it is released (the screen sees
  the button in the view's pen states, `barrel_held`; it sets `button_pressed` on the UI thread and a worker
  reconciles with it under a lock, so workers running out of order still end in the latest state); the grammar takes
  the scene's labels when listening starts; an accepted utterance becomes `runner.say(text, began)`; its status
  (listening, heard, not understood, no microphone) goes to the status bar; loading the recogniser and stopping
  (which decodes the last utterance) run in a worker thread
- `halfblocks.py`: RGBA pixels → `Strip`s of `▀` cells (two pixels a cell), runs of equal colour pairs merged,
  styles cached
- `graphics.py`: which picture the terminal shows — `kitty`, `sixel` or `halfblocks` — from `TERM`, `TERM_PROGRAM`,
  `KITTY_WINDOW_ID` (half-blocks under tmux/screen; `PHYSINK_GRAPHICS` forces one; no escape query, which would cost
  a timeout at every start and could eat a key), and a cell's pixel size from `TIOCGWINSZ`; read by
  `commands/tui.py` before Textual owns the terminal
- `displays.py`: which display a pen display covers: X monitors from `xrandr --listmonitors`, the terminal window
  from `xwininfo -id $WINDOWID`, the canvas's rectangle on the screen from the scene view's cells, and that
  rectangle as a tablet area (fractions of the monitor)
- `screens/background.py`: `BackgroundWork`, a helper `MainScreen` owns (it sees the screen through a typed `Host`):
  SIMULATE in a thread worker (`SearchJob` on the latest view's document; `SearchProgressed` after each rollout into
  the `SearchBar`; escape or Cancel stops it keeping the best so far; when it ends, the result goes to the session
  as a `Searched` entry if the latest view still shows the document searched, else it is dropped and the status says
  so) and the video export worker
- `pacing.py`: `FramePacer`: every view is drawn while the UI keeps up; while views reach it late (more than 25 ms
  after the runner posted them: a starved machine) one every 1/32 s, the latest caught up by a timer, so keys are
  handled between frames
- `widgets/search_bar.py`: `SearchBar`: the search's progress line (a `ProgressBar` of rollouts, the best distances,
  Cancel), shown only while a search runs
- `screens/main.py`: `MainScreen`: the layout, every key binding, actions → commands; Save (atomic `save_project`
  from the latest view, then a journaled `save PATH`), Load (read and checked first: a broken project is an error
  modal and the work stays; then a journaled `load` with the project embedded), Simulate (`screens/background.py`;
  its result's paths are drawn in red; a replay can end with it, `TuiOptions.simulate_after`), Adopt (`a`: the
  result's parameters applied to the scene with `sim.parameters.apply` and its simulated timeline, as a journaled
  `load` with the project embedded: one undoable action that a replay rebuilds), Export (`screens/background.py`: a
  thread worker writing an MP4 of the timeline to `…/exports/`, cancellable with escape); the too-small notice
- `screens/modals.py`: help (every binding), error, yes/no, one line of text, the timeline as text
- `widgets/scene_view.py`: `SceneView`: `view_frame` of the view (plus the SIMULATE result's paths in red), rendered
  at 2x2 pixels per half-block pixel and averaged, drawn as half blocks — or, with a graphics protocol, rendered at
  the terminal's pixel size and sent as Kitty escapes (one image id replaced frame after frame, shown through
  placeholder cells that Textual lays out as text) or as Sixel drawn over blank cells after each refresh, both
  written through Textual's driver so they stay in order with its output; the mouse as a pen (`SceneView.Pen`
  messages in canvas fractions; left draws, right erases)
- `widgets/timeline_tree.py`, `widgets/bars.py`, `widgets/controls.py`: the timeline as a `Tree` (rebuilt only when
  the events, causes, starts or names change, not while a recording lengthens movements; each event under its first
  cause; choosing one posts `Seek`: the playback goes there and the scene view outlines the event's bodies until the
  scene changes), the narration bar (the event at the playback clock, else the last message), the status bar (both
  repainted only when their text changes, without a layout of the screen: Textual's `Static.update` lays out the
  whole screen by default, which at 60 views a second was most of the UI thread's time), the buttons
- `physink.tcss`: the styles: package data read through `importlib.resources` (`PhysinkApp.CSS`), so an installed
  wheel has them (`tests/test_wheel.py`)

The session gained one field for it: `SessionView.pens` (each input device's pen state and the pressure of its
stroke), and `save PATH` is now journaled without a message (the driver writes the file, a replay writes none).
Tests: `tests/test_tui_controls.py` (every button and key through Pilot), `test_tui_drawing.py` (a box, a circle and
an X drawn with the mouse become a welded box and a circle), `test_tui_session_files.py`, `test_tui_parts.py`,
`test_tui_snapshots.py` (SVG snapshots in `tests/__snapshots__/`), `test_tui_tmux.py` (`physink demo` in tmux,
120x40; skipped without tmux), `test_tui_simulate.py` (progress, keys during a search, cancel, a search dropped
after an edit, adopt, undo, playback, a replay ending with SIMULATE; each journal replayed to the same result),
`test_tui_graphics.py` (the scene view under Kitty and Sixel), `test_tui_graphics_pty.py` (`physink tui` in a real
pty with TERM a Kitty, Sixel or other terminal: the escapes Textual's driver writes decode to the scene; Kitty's
placeholder cells carry the image id in the colour Textual writes, 24-bit or 8-bit), `test_tui_displays.py`,
`test_tui_pacing.py`, `test_tui_exit.py` (a crash of the app exits 1 with its traceback, in a pty; a session or
background job stopped by a bug is said in a dialog and quitting exits 1: `PhysinkApp.failed`, `open_tui` returns
`App.return_code`). The app collects and freezes the startup heap once the session runs (`gc.freeze`), so full
collections — which stop every thread — skip it. Figures in docs/BENCHMARKS.md.
"""
