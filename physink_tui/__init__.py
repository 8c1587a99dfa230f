"""PhysInk TUI: sketch a machine with a pen tablet, demonstrate it, simulate it; this file names the version.

Importing the package imports nothing else, so the pure core (scene, timeline, sim) stays cheap to load. Below: the
layers and what each package may import (docs/ARCHITECTURE.md is the short map).

Each package imports only packages below it. Six import-linter contracts in `pyproject.toml` say so (two `layers`
contracts, the core's `forbidden` one, the kiosk's (it never imports Textual), "only the TUI imports Textual" and
"only `scene.physics` imports pymunk"), `./check` runs them (`lint-imports`), and a test forbids import cycles:

     each layer may import the layers below it, never one above
      cli                      argparse, dispatch
       │
      commands                 one run(args) per subcommand
       │
      tui | kiosk              the Textual control panel (imported lazily by commands.tui and commands.demo) |
                               the headless recording service (a driver of the session); independent of each other
       │
      sim_run                  executors (serial, process pool, Dask) and the search driver
       │
      render                   frames, terminal images
       │
      session                  ┌─ journaled : runner : source_pump : replay_driver   the drivers
       │                       ├─ session.session                        the Session
       │                       ├─ session.command_handling               its commands (`Commands`, owned by the Session)
       │                       ├─ session.labelling                      typed and spoken labels put on components
       │                       ├─ session.view                           SessionView snapshots
       │                       ├─ session.modes | session.simulation     sketch, adjust, demo (never the session);
       │                       │   | session.speech_target               SIMULATE run for the session; whom a
       │                       │                                          spoken label names
       │                       └─ history : inbox                        the document's undo; stamped arrivals
      input                    devices, decoding, captures, gestures
       │
      formats                  journal, project, timeline files; output folder
     ══╪══════════════════════ the core below: the forbidden contract (no edge package, no UI/device library) ══
      sim                      SIMULATE: parameters, seeding, rollouts, the search (leg by leg, or the thesis grid)
       │
      timeline                 events, recorder, tape, narration, equivalence
       │
      scene.physics            pymunk world, stepping, contacts, overlaps
       │
      scene.interpretation     strokes in context → components
       │
      scene.recognition        stroke → primitive
       │
      scene.components | errors   frozen scene values; the error hierarchy (independent of each other)

- **Layers** (`type = "layers"`): `cli` → `commands` → `tui | kiosk` → `sim_run` → `render` → `session` → `input` →
  `formats` → `sim` → `timeline` → `scene.physics` → `scene.interpretation` → `scene.recognition` →
  `scene.components | errors`, highest first. A layer may import any layer below it, never one above. `|` makes
  `scene.components` and `errors` independent siblings: neither imports the other.
- **Inside the session** (a second `layers` contract): `session.journaled : session.runner : session.source_pump :
  session.replay_driver` (the drivers; `:` lets siblings import each other) → `session.session` →
  `session.command_handling` → `session.labelling` → `session.view` → `session.modes | session.simulation |
  session.speech_target` (independent) → `session.history : session.inbox`. So a mode never imports the session or
  its view: it sees the session only through the `Host` protocol (`session/modes/base.py`).
- **Core purity** (`type = "forbidden"`): `physink_tui.scene`, `physink_tui.timeline` and `physink_tui.sim` import
  none of `textual`, `rich`, `skia`, `av`, `hid`, `usb`, `serial`, `sounddevice`, `pocketsphinx`, `vosk`,
  `physink_tui.input`, `physink_tui.render`, `physink_tui.commands`, `physink_tui.cli`, `physink_tui.formats`,
  `physink_tui.session`, directly or indirectly. `include_external_packages = true` lets third-party packages be
  named; a forbidden package that is not installed is fine (nothing can import it).
- **Only the TUI imports Textual** (`type = "forbidden"`, `allow_indirect_imports = true`): every package but
  `physink_tui.tui` imports `textual` nowhere, directly. `commands.tui` and `commands.demo` import `physink_tui.tui`
  inside the function that opens it, so `physink --help` and the headless commands never load Textual
  (`tests/test_tui_parts.py` checks it in a fresh interpreter).
- **No import cycles**: `tests/test_import_cycles.py` builds the import graph with grimp (installed with
  import-linter), function-level imports included, and fails on any strongly connected component of more than one
  module. None is allowed (`ALLOWED_CYCLE_MODULES` is empty). Two modules that import each other are one design
  decision waiting to be made (STYLE.md).
- **`tests/test_core_purity.py`**: imports each core package in a fresh interpreter and checks that none of the
  forbidden modules ended up in `sys.modules` (this also catches imports made *through* third-party code, which
  import-linter does not follow), and scans the core's source with `ast` for clocks and I/O: importing `time`, `os`,
  `pathlib`, `socket`, `subprocess`, `shutil`, `tempfile`, `select`, `selectors`, calling `open()` or `input()`, or
  `.now()` / `.utcnow()` / `.today()` / `.fromtimestamp()`. Time reaches the core as a field of its inputs; files
  reach it as parsed values.

"May import" is what the contracts allow; what a package uses today is narrower, and said where it matters.

- `physink_tui/__init__.py`: names `__version__` — everything — nothing
- `errors.py`: the error hierarchy — handling (the CLI) — stdlib
- `scene/components.py` *(core)*: the sketch as frozen values: `Scene` of `Body`, `Joint`, `Rope`, `Spring`, labels,
  id counters — recognition, physics, files — stdlib
- `scene/recognition/` *(core)*: one stroke (or an X's two) → a primitive with beautified geometry — what the stroke
  means — stdlib, numpy (uses no other package of ours)
- `scene/interpretation/` *(core)*: a recognised stroke in the context of the scene → the new scene (bodies, joints,
  springs, ropes, X pairs), body outlines — physics, I/O — stdlib, numpy, shapely; `scene.recognition`,
  `scene.components`, `errors`
- `scene/physics/` *(core)*: the pymunk world mirroring a scene, the live world, contacts, speed limits, pushing
  clear, stepping and observing, world states as values — when to step and what contacts mean — pymunk, shapely; the
  scene layers below, `errors`
- `timeline/` *(core)*: demonstration → causal event DAG: events, graph functions, qualitative geometry, recorder,
  playback tape, edits, narration, phrases, equivalence — I/O, clock, drawing, stepping — stdlib, numpy, shapely;
  `scene.*` (from `scene.physics` only the values `Motion`, `Pose`, `Velocity` and `ContactRecord`), `errors`
- `sim/` *(core)*: SIMULATE: parameters, seeding, headless rollouts, scoring a candidate, the parameter search as a
  machine of generations — I/O, clock, drawing, the session — `scene` (incl. `scene.physics`), `timeline`, `errors`
- `formats/` *(edge)*: every file format: journal, project, timeline JSON/DOT/text, their one JSON checker and
  version migrations; atomic writes; the output folder and stdout guard; the session's outputs — what the contents
  mean — stdlib; the core (`scene.components`, `timeline`), `errors`
- `input/` *(edge)*: HID descriptors and decoding, vendor protocols, captures, devices and readers, serial ISDV4,
  mapping, pen state machine, gestures, virtual pen, journals composed from captures and replayed through the input
  side; speech (`input/speech/`: WAV reading, voice activity, the grammar, recognisers, the microphone) — scene
  logic, UI — stdlib, numpy, hidapi, pyusb, pyserial, pocketsphinx, vosk, sounddevice (each imported only where
  used, lazily); `formats`, the core, `errors`
- `demo_data.py`: the bundled demo drawing, its capture and what is typed in between — decoding — `input`, `formats`
  (it is outside the layers contract)
- `session/` *(edge)*: the single consumer of journal entries: modes, time (from the entries), selection, the
  document and its undo history, messages, views; its drivers (live runner, source pump, replay driver) — decoding,
  geometry, file formats — `input`, `formats`, the core, `errors`
- `render/` *(edge)*: pictures of snapshots: frame content from a timeline at t or a `SessionView`, the skia
  renderer, PNG, MP4/WebM/GIF (PyAV), the braille plot — deciding anything about the scene; choosing files —
  everything below it; skia, av, numpy
- `sim_run/` *(edge)*: runs a `sim.search.Search`: executors (`SerialExecutor`, `ProcessExecutor`, `DaskExecutor`;
  results in candidate order) and `run_search` — what a candidate is, scoring — `sim` and everything below it;
  concurrent.futures, multiprocessing; `distributed` (the `dask` extra) in `dask_executor.py` only
- `kiosk/` *(edge)*: the headless recording service: hot zones, the controls found in the tablet's reports, one
  session per visitor on its runner, finalising (outputs, `session.json`), the session store (`index.jsonl`,
  recovery, retiring) — opening devices and signals (`commands/kiosk.py`), what the pen drew (the session) —
  `sim_run` and everything below it; never Textual (a contract)
- `commands/` *(edge)*: one `run(args) -> int` per subcommand, driving the session — argument parsing — everything
  below it
- `tui/` *(edge)*: the Textual control panel: app, screens, widgets over `SessionView`s, the live session (runner,
  mouse pen, journal feed), the tablet watcher, XDG journal folders — what any input means (the session's), drawing
  (the renderer's) — `textual`, `rich`; `render`, `session`, `input`, `formats`, the core, `errors`
- `cli.py` *(edge)*: argparse, dispatch, exit statuses — any behaviour of a command — everything below it (uses
  `errors`, `formats.outputs`; `commands` lazily)
- `__main__.py` *(edge)*: `python -m physink_tui` runs the command line — everything — `cli`
- `progress.py` *(edge)*: a one-line progress bar with counts and ETA on a terminal, silent elsewhere — what the
  task is — stdlib

`input/` is an edge, not core: it is allowed I/O (reading devices and files), but its decoding functions are pure
over a parsed descriptor (see STYLE.md, "Input"). `formats/` knows file formats and nothing of a session; the core
knows no format (serialisation lives in one edge module per format, STYLE.md "Data").

The CLI resolves a subcommand through `cli.HANDLERS` (`name → "module:function"`, imported with `importlib` only
when that subcommand runs), so `physink --help` loads no heavy library.
"""

__version__ = "0.1.0"
