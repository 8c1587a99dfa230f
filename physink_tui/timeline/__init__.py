"""Demonstration to causal timeline (recorder, event DAG, equivalence); no I/O, clock or UI.

- `events.py`: frozen `Event` (start, movement, contact, end_contact; sides, regions, trajectory, tracks of tied
  bodies, point, label), `TrajectoryPoint`, `Timeline` (a DAG as a tuple in creation order); default narration
- `graph.py`: networkx-style free functions: `ancestors`, `descendants`, `topological_generations`, `check_acyclic`
  (`CausalCycleError` naming the cycle)
- `qualitative.py`: qualitative geometry: `BodyOutline` (convex hull, container or not), sides from the contact
  normal (canvas frame; `inside` when the other body's centre is in a container's hull), `regions_at` (the
  above/below/left/right strips of a body, up to a reach), separation of hulls
- `observation.py`: `Observation`: what one physics step shows the recorder (every body's `Motion`, the
  `ContactRecord`s begun, the pairs touching, the grabbed body, the bodies playing back), built by demo mode and by
  SIMULATE's rollouts
- `mechanisms.py`: `Mechanisms`: which movable things move as one (a body and what ropes, springs and joints tie it
  to): a movement's chain of components, nearest first, and one key per mechanism, which the recorder keeps one open
  movement for
- `recorder.py`: pure `Recorder.observe(Observation)` per physics step: start on the first grab; one open movement
  per group (a body and what ropes, springs and joints tie to it: "Movement of lever [attached to rope, knife]");
  contacts cause new movements of each movable body (a resting or sliding contact is one: `touches.py`); movable
  bodies that began in contact are named by the start and stay in that contact until a movement parts them (an
  end-contact caused by it, causing a movement of each) or one drives into the other (a contact;
  `begun_in_contact.py`); a body moving by itself is explained by the moving body it touches (a contact), a recent
  separation (an end-contact) or its latest movement; regions accumulate per movement; contacts with bodies playing
  back split their recorded movements; `redemonstrate(body, t)` is the assisted edit
- `touches.py`: whether a contact report continues the pair's recorded contact: within 15 frames of the last report
  (DESIGN.md), or before the two bodies' hulls have got further apart than half the smaller one's size (the diameter
  of a disc of its area, at least 4 units); an end-contact ends it; a body set moving in a contact that goes on is
  moved by that contact, not a new one; `pushed_again`: the body the pen holds touching again a body it set moving,
  which nothing else has touched since, continues that contact (the egg pushed through a paddle that swung ahead in
  gravity-free demo mode: one push, as thesis 2.3.3 has it; a fixed body touched twice is touched twice)
- `movement_record.py`: one movement being recorded: frames of the moving body and what is tied to it, regions
  passed, stillness; written back into its event
- `edits.py`: pure timeline edits: `cut_from` (a body's behaviour from t on taken out, with what it caused) and
  `split_at` (a recorded movement interrupted by a contact)
- `demo_setup.py`: what a recorder needs from a scene: outlines, movable bodies, the link graph, the pairs that
  begin in contact (movable, of two mechanisms, within `BEGIN_IN_CONTACT` = 6 units or overlapping; for SIMULATE
  both as drawn and as settled), the regions' reach (a quarter of the canvas diagonal)
- `begun_in_contact.py`: movable bodies that begin a demonstration in contact (thesis figure 3-9): `drives_into` (a
  body moving towards the other, across their contact -- the physics' normal, or `facing`: from the point of its
  hull nearest the other's centre -- at more than 30 units/s and not almost along the contact: a push, so a
  contact; otherwise their touches are the contact they began in, and a body jostled by its moving partner is not
  set moving), `parted` (4 units further apart than they began: the end-contact)
- `tape.py`: playback: every body's recorded frames (trajectories and tracks) interpolated at timeline time t
- `narrate.py`: the thesis's "X CAUSES / -- Y" text; components named as `Scene.names()` gives them (the label; an
  unlabelled spring or rope as what it is, `spring`, `rope`; an unlabelled body by its id), in the text and in
  timeline JSON alike
- `phrases.py`: `<object> <verb> [<prep>] [<object>]` phrases against the labels, a vocabulary extensible by a text
  file
- `phrase_events.py`: labelling the temporally nearest event involving a phrase's objects
- `prepared.py`: `prepare(timeline, names)`: each event's signature, causes, qualitative geometry and trajectory
  resampled by duration, in comparison order (t0, causal depth, signature), computed once
- `equivalence.py`: `compare(a, b)`: events aligned by signature (`difflib`), costs for missing events, differing
  sides (a body landing *inside* a container may touch it with any side), regions passed on opposite sides (above vs
  below, left vs right; relative to bodies not moving meanwhile) and causes (qualitative distance; 0 = equivalent),
  trajectories and contact points (quantitative), one reason per mismatch; `simulation=True` (B simulates
  demonstration A) leaves out what B does after its last event matched with A and bounces coming to rest, which
  split no movement (`resting.py`), and lists them (`Comparison.after_b`); `compare_prefixes` charges one matching
  to each prefix of A (the legs of the search)
- `up_to_demonstrated.py`: the one rule a simulation is judged by, in the words every driver uses: *equivalent up to
  the last demonstrated event* (`RULE`, `verdict`), and `afterwards`, what the simulation does after it ("afterwards
  the simulation goes on: the ball bounces on the basket twice more"); SIMULATE's message in the TUI, `result.json`,
  its verdict and `physink equiv --up-to-demonstrated` all say it, so they never disagree
- `resting.py`: `coming_to_rest`: a simulation's bounces of a body on what it landed on, once its demonstrated
  behaviour has ended, are part of the landing; `continued`: the movements such a bounce split off stand for the
  ones they go on from (the cup a ball rattles in moves on)

The timeline's file formats live in `formats/` (`timeline_json.py`, `timeline_dot.py`, `timeline_text.py`);
`commands/timeline_source.py` reads a timeline JSON file or a project for `timeline` and `equiv` (and, for `equiv`
of one adopted project, its kept demonstration and its timeline). Stepping the world and feeding the recorder is
demo mode's (`session/modes/demo.py`).
"""
