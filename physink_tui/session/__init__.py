"""The session: the single consumer of timestamped inputs and the only writer of state; no UI of its own.

One `Session` (`session/session.py`) is the state machine every driver feeds: `physink replay`, `physink demo` and
the tests directly, the TUI and the kiosk through the runner. It is single-threaded and has no clock: time is always
the input's.

- **`handle(entry)`** takes one journal entry (`hid`, `pen`, `cmd`, `say`, `device`). With a journal attached, the
  entry is first checked against what the journal can hold (`JournalWriter.check`: a value out of range, time going
  backwards, a device neither in the header nor in an earlier `device` line); one it cannot hold is refused with a
  message *before* it is acted on, and not journaled, so a replay of the journal sees what the session saw.
  Otherwise the session first advances to the entry's `t`, then acts on it, then journals it (entries the session
  refuses — `seek` while sketching, a phrase it cannot parse — are journaled too). Nothing raises out of `handle`: a
  `PhysinkError` an input causes (an unknown device, a bad descriptor, a bad embedded project) becomes a message;
  any other exception is a bug, recorded with its traceback in `session.errors` and told as `internal error handling
  the input at … (reported; carrying on)`. Tests set `Session.raise_internal_errors` (`tests/conftest.py`), which
  raises it after journaling. A journal that cannot be written (a full disk) is dropped with one message; the
  session carries on.
- **`advance(t)`**: time passes to input time `t` (no earlier than before). The input side ticks (`PenInput.tick`):
  a dwell that completed in the meantime comes out stamped with the moment it completed, so ticking often, seldom or
  never gives the same gestures; the mode's world is advanced to that gesture's time before the gesture is acted on.
  Then the current mode advances to `t`: a world steps on its fixed dt, the steps counted from the start of each run
  of timeline time (demo) or of the drag (adjust), so n small advances end exactly where one large one does, step
  for step; a possible half-X that has waited `X_WAIT` with no second stroke begun is taken on its own, at the time
  it stopped waiting.
- **`view()`** returns a frozen `SessionView` (`session/view.py`, built by `snapshot`): `revision` (grows whenever the
  session changed), `t`, `mode`, the document's `scene`, `poses` (where the mode's world shows each body), `ink`
  (strokes being drawn, canvas units), `pending` (a waiting half-X), `selected`, `can_undo` (a demonstration's
  uncommitted take counts), `can_redo`, `timeline` (while demonstrating, what has been recorded so far), `clock`,
  `duration`, `playing`, `messages` (each `Message` an `outcome` of a stroke or label, or a `note`), `pens` (each input
  device's pen state and its stroke's pressure, for a status line), and `search` (the last `simulate`'s `SearchResult`
  for the document shown, or None). Every field is immutable. `benchmarks/bench_view.py` measures it.
- **`finish(t)`**: time advances to `t`, what the current mode was doing is committed to the document, and a journal
  gets a `cmd` `end` line at that time and is closed. An `end` entry in the input does the same work at its time
  (the driver then calls `finish`, which journals nothing twice).

**The document.** `history.Document(scene, timeline)` is what the user made; `History` keeps the documents before
each action (undo) and the ones undone (redo). The document changes only through the history: a mode calls `commit`
(a new undoable action) or `amend` (finishing the last one, e.g. pushing a new body clear). Undo, redo and clear act
on it in every mode: the current mode is closed first (sketch takes a waiting half-X on its own, adjust puts its
body down, demo commits its take), the history changes, and in demo mode the demonstration then starts again from
the resulting document. A selection or "last created" component that is gone is forgotten.

**Commands and speech** (`session/command_handling.py`: `Commands`, which the session owns and which sees it
only through the typed `CommandHost`; `session/labelling.py`). `label TARGET TEXT` (the target an
id, `last` or `selected`; a label with a word the speech dictionary lacks is kept and told how speech will hear it,
a pronunciation guessed from its spelling, or as not speakable when it is not spelled with letters,
`input/speech/dictionary.py`) and the spoken `label NAME`, which names the selected component, else the one drawn in
the last 5 s (`speech_target.RECENT`; speech lags the pen, so this comes before the stroke under way), else the one
being drawn — the label waits for the component its stroke makes, and is told when it makes none —, else the body
under the hovering pen, else it is told (`session/speech_target.PenWatch` follows the gestures for this;
`session/labelling.py` applies both kinds); `mode sketch` / `mode demo`; `play`, `pause`, `stop`, `seek T` (demo
mode only; otherwise a message); `undo`, `redo`, `clear`; `load PATH`, whose journal line embeds the project: the
project's scene and timeline become the document (one undoable action), its vocabulary joins the session's, a canvas
of another size is told, and a load without the project embedded is told and does nothing; `end`; `simulate [SEED
[BUDGET]]` (below); `save PATH` is journaled and tells nothing (the driver, the TUI, writes the file; a replay
writes none). Said phrases label timeline events in demo mode. The session's words are `DEFAULT_VOCABULARY` extended
by the journal header's vocabulary, `physink replay --vocabulary` and loaded projects; `vocabulary_lines()` gives
the user's own lines for the project file. A `device` entry adds a tablet's decoder; one for a device already known
is a reconnection, and the gesture it was making ends there.

**SIMULATE** (`session/simulation.py`). `simulate SEED BUDGET` closes the modes as undo does (a demonstration's take
is committed first; demo mode then starts again), then runs the default search (`sim.search.Search`) on the
document's scene and timeline here and now: every candidate evaluated in turn with `evaluate_problem`, no executor,
no clock (the search `physink simulate --seed S --budget N` runs, serially), so a replay gives the same result. The
result, a frozen `SearchResult` (found, both distances, rollouts, budget, seed, the best `Parameters`, its simulated
timeline, and the reasons it differs), is `SessionView.search` until the document changes (any commit, undo, redo,
load, or a take being recorded; it does not come back on undo), and is told in one message. A missing seed or budget
is filled in before journaling (`sim/defaults.py`: 0 and 200, shared with `physink simulate`; the budget is
`Session.simulation_budget`, which tests lower), so the journal line always carries both numbers. Seeds below 0 and
budgets below 1 (or non-integers) are refused like any value the journal cannot hold. A document without a
demonstration, without a movable body, or whose demonstration moves an erased body is told what to do. Running it
changes no document, so undo and redo do not see it; cancelling and progress are a driver's (`search_job`, below).

**SIMULATE run by a driver** (`session/search_job.py`). A driver that must not block the session's thread (the TUI)
runs a `SearchJob` on a snapshot of the document (scene and timeline of the latest view) in a thread of its own:
`simulation.run` with an evaluator that reports `Progress` (rollouts, budget, best distances) after every rollout
and stops before the next once `stop()` is called. A search stopped after k rollouts is the search of budget k
(`Search` truncates its last generation to the budget, so its first k candidates are those of any larger budget);
its result is computed as `run(..., budget=k)` computes it, the k known scores taken from a memo (a candidate that
differs is simulated again). The job's result goes to the session as a `simulation.Searched` entry, which the
session journals as the plain `simulate SEED k` and takes as its own only if its document at that moment is the one
searched (equal scene and timeline); otherwise it searches itself, as for the command. A replay of the journal
therefore searches again and finds the same. `tests/test_session_search_job.py` checks both, a stop from another
thread, and an offer for another document being ignored.

`session/replay_driver.replay(session, entries, ticks=None)` is the thread-free driver (`physink replay`, tests): it
hands each entry to `handle` in order and calls `finish`. With `ticks` (Hz; `physink replay --ticks HZ`) it also
advances the session to every multiple of 1/ticks seconds before each entry, as a live driver does; the outputs must
be, and are, the same (`tests/test_session_machine.py`, a hypothesis state machine of strokes, taps, drags, dwells,
mode changes, undo/redo/clear, seeks, labels, speech and silences through a journaling session, checks that its
journal replays to byte-identical outputs with no ticks and at 10, 30 and 120 Hz). `physink demo` runs its composed
journal with `Session.run(entries)`.

The kiosk and the TUI (`physink_tui.kiosk`, `physink_tui.tui`) drive the session through `session/runner.py`: the
runner and the sources' readers are the only threads around the session.

- `outcomes.py`: words for what a stroke or a label made of the sketch ("circle → body b3", "X → platform b2
  fixed", "erased box b4 — u to undo"), one line each, for the session's messages
- `journaled.py`: `Journaled.create(header, journal_path, prior=, clock=, max_fps=, on_error=)`: the one wiring of a
  live session, shared by the TUI (`tui/live.py`) and the kiosk (`kiosk/service.py`): the `Session` of the header
  journaling to a new file, earlier entries handled first, and its `SessionRunner` (not started)
- `inbox.py`: `StampingInbox`: entries stamped with seconds since the session start and queued under one lock; the
  worker reads "now" and takes the queue under the same lock, so nothing stamped at or before a time it read can
  still be missing. Stamps never decrease, are never changed, and stop at the time the inbox closes
- `runner.py`: `SessionRunner`: one worker thread, the session's only caller (any object with `t`, `handle`,
  `advance`, `view`, `finish`: `RunnableSession`): queued entries to `handle` in arrival order, `advance(now)` at
  `tick_rate` (120 Hz), `view()` to subscribers and `latest_view()` at most `max_fps` (30) a second, once after the
  last input, and at once after a command (a key's reaction waits for no frame slot); `submit`, `command`, `say`
  from any thread; `stop()` handles what arrived, `finish(stop time)` (which journals the end), publishes the last
  view, joins. An exception in the worker is recorded (`error`, `on_error`), input is refused from then on, `finish`
  is called once, and `stop()` raises it
- `source_pump.py`: `SourcePump`: a `PenSource`'s items to entries on the source's own thread (its queue's `put`
  submits): reports to `hid`, samples to `pen` (mapped with the session's `TabletMapping` when they are in tablet
  space, clamped to [0, 1]); a source's end is never submitted: a pen in range is lifted with one out-of-range `pen`
  entry, and a HID device back after an error is announced with a `device` entry before its first report

Tests: `tests/test_session.py`, `test_session_modes.py`, `test_session_machine.py`, `test_demo_mode.py`,
`test_demo_playback.py`, `test_sketch_x.py`; the runner without its thread (`step()` by hand, a fake clock) in
`tests/test_session_runner.py` (with one test on a real session journaling every entry and the end) and
`tests/test_source_pump.py`.
"""
