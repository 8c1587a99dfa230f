"""The session's modes as objects (sketch, adjust, demo), each with its own world, behind one small interface
(`base.Mode`); they see the session only through `base.Host` and never import it.

Modes are objects behind `modes/base.py`, which has no behaviour of its own:

- **`Mode`** (what a mode offers the session): `name` (a `ModeName`: `sketch`, `adjust`, `demo`), `finished` (it
  ended by itself: back to sketching), `gesture(g)` (act on a pen gesture; return the mode to continue in when it
  changes), `advance(t)` (True when anything changed), `close(t)` (finish and commit what it was doing), `poses()`,
  `timeline()`, `scene()`.
- **`Host`** (what the session offers a mode, and all a mode sees of it): `document`, `canvas`, `tell`, `commit`,
  `amend`, `select`. The second layers contract keeps modes from importing the session.

- `sketch.py`: `SketchMode` (thesis 3.2): a finished stroke is recognised (the pen's noise taken as one pixel of a
  1600-pixel view of the canvas) and interpreted into the scene, one undoable action each; a short nearly straight
  stroke waits as a possible half-X (`PendingStroke`) for the next; an eraser stroke removes the topmost body it
  passes over and what holds on to it; a tap selects; a dwell takes any waiting half-X on its own and starts
  adjusting; a stroke that began with a dwell was a drag and draws nothing. A body drawn into others waits one
  stroke before it is pushed clear (a pin or an X drawn next may join it where it is). It owns the sketch's
  `LiveWorld`, the scene's spatial index
- `adjust.py`: `AdjustMode` (thesis 3.2.4): `AdjustMode.start` grabs the body under a dwell (none there: sketching
  goes on) in a gravity-free `World` of the scene with the others frozen; the world steps with the input's time;
  pen-up (or `close`) puts it down (`physics/stepping.put_down`) and commits the move. Then `finished` is true
- `demo.py`: `DemoMode` (thesis 3.3): the `demo_world` of the document's scene, a `Recorder` continuing the
  document's timeline (`timeline/demo_setup.recorder_for`), playback and narration. Below

Demo mode keeps timeline time (`DemoMode.clock`): it runs while the pen holds a body, while a recorded movement is
still open, and during playback; otherwise it stands still, and the next run starts counting its steps from the
input time it starts at. Each step is `step_and_observe` on the world, fed to the recorder as an `Observation`.
Pressing on a movable body grabs it (on a fixed one, a message says so); `seek T` closes open movements and puts
every recorded body at its taped pose (`Tape`); `play`, `pause`, `stop` move the clock; grabbing a body at time t
re-demonstrates it from t (`Recorder.redemonstrate`, the assisted edit) while every other recorded body follows the
tape kinematically (it pushes what it meets; a contact with it splits its movement). What was demonstrated since the
last commit is a *take*: it becomes one undoable action of the document at `seek`, `play`, `stop`, a mode change,
undo, redo, clear, load and the end. Phrases said in demo mode label the nearest event involving what they name
(`timeline/phrase_events.label_event`).
"""
