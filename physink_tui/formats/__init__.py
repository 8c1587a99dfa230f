"""File formats in one place: journal, project and timeline codecs, their JSON checks and versions; reading and
writing, no session logic.

Every file format in one package: reading and writing, no session logic, no meaning. Each format carries its
version; every value read is checked by the one JSON checker and named by its place when it is wrong.

- `journal/`: the session journal (`.physink.jsonl`), below
- `project/codec.py`, `project/scene_fields.py`, `project/files.py`: the project file (`.physink.json`, format
  `physink-project`, version 2; version 1 upgraded through `migrations.upgrade`): `Project(scene, vocabulary,
  timeline, canvas, demonstration)`, ``demonstration`` the demonstrated timeline an adopted simulation
  (``timeline``) was found for, kept so the two can be compared again (the TUI's adopt, `physink simulate`'s
  project.json; the session's `Document` carries it, sketch edits keep it, a new demonstration drops it), else null;
  deterministic indented JSON, one component per line, fixed key order; `scene_fields` knows the components' keys
  and references (a joint's or spring's bodies, a rope's ends) and the id counters; `timeline` is a typed `Timeline`
  (decoded through `timeline_json`, its component names from the scene) or null; `vocabulary` holds the user's
  vocabulary-file lines (`verb plummets topples`, `prep amid`), each checked as such, with `vocabulary_lines` /
  `project_vocabulary` to and from the session's `Vocabulary`; `decode_project_object` for a project embedded in a
  journal's `load` line; `save_project` (atomic) and `load_project`. Reading names the first bad field by its JSON
  path (`project.json: components[3].material.friction: expected a number >= 0, got "high"`); unknown keys are
  ignored with a warning; errors are `SceneError`
- `timeline_json.py`: the timeline as JSON, both ways: a file is `{"format": "physink-timeline", "version": 2,
  "events": [...]}`, a project embeds the `{"events": [...]}` object alone (`timeline_object`, versioned by the
  project); every key present for every event type, floats rounded to 6 decimals, so the same timeline always gives
  the same bytes; NaN, Infinity and numbers beyond 1e9 refused; `in_contact`: the start's pairs that began in
  contact, each two `{"id", "label"}` (empty elsewhere); the unversioned file of before reads as version 0 upgraded
  to 1, version 1 upgraded to 2 with no pair in contact
- `timeline_dot.py`, `timeline_text.py`: write-only: the Graphviz digraph of `physink timeline --format dot`; the
  thesis's narration (the core's `timeline/narrate.py`) framed as `timeline.txt`
- `json_checks.py`: the one JSON checker of every format: each check takes a `Place` (which file or line, which
  error class, how keys read: the journal's `key "pen.x"` or the project's and timeline's bare
  `components[3].radius`), a key path and a value, returns the value checked and raises `<place>: <key>: expected
  <what>, got <value>` (or `..., but it is missing`)
- `migrations.py`: `upgrade`: a document of an earlier version brought to the current one a step at a time, on plain
  JSON before any check; a document from a newer program refused, naming both versions
- `strict_json.py`: `unique_pairs`: a key twice in one JSON object is an error, not the last one silently
- `atomic_write.py`: `write_text_atomic`: a complete new file or the old one untouched (temporary file, fsync,
  rename, directory fsync)
- `outputs.py`: the one way commands write results: `OutputFolder` (prepared per run: made, cleared of this program's
  own outputs (`OWN_FILES`) and leftover `.*.tmp`; each file atomic; every `OSError` one `PhysinkError` naming path and
  cause; or `staged` + `commit`, `physink simulate`'s: the new files beside the last run's, renamed over them at the
  end, so a kill leaves the last complete result), `check_outputs` (before anything is written: refuses an output that
  is an input of the run, a file that is not a regular one -- device, FIFO, symlink, folder -- or another output of the
  run)
- `stdout_guard.py`: `StdoutGuard` (a broken pipe silences stdout, a full one is reported at the end; files are still
  written) and `reason` (an OS error's cause in words); apart from `outputs.py` so every command's start-up imports
  only this
- `project/sanity.py`: `check_project`, the one check of a project's values every command makes before using it
  (`load_project`: export, simulate, the TUI's start and Load; the session's `load` command), so all accept and
  refuse the same projects: canvas sides, positions, radii, outlines the physics can build
  (`scene.physics.outlines.outline_problem`), densities, frictions, spring constants and times bounded; each refusal
  names the file and the JSON path. A timeline naming a component the scene lacks still loads (the user's work):
  `named` lists them, `export` says so and `simulate` refuses it
- `session_outputs.py`: the one output path of a session, shared by `physink demo` and `physink replay`:
  `write_session_outputs` writes `timeline.json` and `timeline.txt` (after a demonstration) and `project.json` (with
  the user's vocabulary lines); `session_output_texts` gives the same texts by name, which the tests compare replays
  by. Printing stays with the commands
"""
