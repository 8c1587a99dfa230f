"""The physics layer shared by sketch, adjust and demo modes and by SIMULATE: the pymunk world, settling,
pushing clear, and the step-and-observe loop; no I/O, no clock.

One package for every world the program runs: the sketch's live world, adjusting, pushing clear, demonstrating, and
later SIMULATE, which will use it without the session. No I/O, no clock: which steps to take, and what they mean, is
the caller's.

- `world.py`: `World`: one pymunk `Space` mirroring a `Scene`, a fixed dt, two-way maps between component ids and
  pymunk objects; topmost-body queries (`bodies_at`, `body_at`), `pose`, `velocity`, `motion`, `motions`; the
  questions a simulation asks (`damping`, `is_asleep`, `half_size`, `contact_between`), so no caller touches its
  `Space` or bodies (only `scene.physics` imports pymunk: an import-linter contract; `pymunk_parts` is for tests and
  benchmarks); freezing and dragging (a kinematic control body and a soft pivot), following a recording
  kinematically (`follow`, `let_go`, `place`); `take_contacts`, `touching`; `to_scene` writing poses back
  (`write_back.py`: bodies, and the anchors and rope points they carry); `state()` → a frozen `WorldState`, and
  `World.from_state(scene, state, warm=N)` forking a world from one (N steps taken and undone give resting contacts
  their impulses, which a sleeping group keeps; with none, agreeing to the solver's warm start, not bit for bit)
- `build.py`: the pymunk bodies, shapes and constraints of each component (`build`, `Built`)
- `editing.py`: `Editing`, which `World` owns: every body frozen but one (`freeze_all_except`, `unfreeze`: the
  velocities kept and given back) and the drag under way (`drag`, `release`); the world syncs the space's constraints
- `outlines.py`: whether a body's outline can become shapes (positive area, convex pieces, distinct points), pure
  geometry; `outline_problem` says what is wrong in words, for the project check (`formats/project/sanity.py`)
- `surfaces.py`: the contact materials (`Surfaces`): each material a surface type (`collision_type`), its shapes'
  grip, the bounce of every pair and the pairs whose friction needs a callback (below)
- `contacts.py`: the collision callbacks (`ContactListener`): `begin` appends a frozen `ContactRecord` (step, the
  two ids, point, normal; one per pair per step), the pairs touching now (begin/separate); `begin` also gives a fast
  first contact its pair's bounce, and `set_friction` writes the mean friction for the few pairs registered for it.
  `ContactRecord` is the one contact record: the recorder takes it as it is
- `live.py`: `LiveWorld`, the world kept in step with a changing scene by difference (below); its constructor calls
  `World`'s and adds its own state
- `speed.py`: `limit_speed`: a body's speed capped at half its half-size (its narrowest shape's) per step, at least
  1200 units/s, so nothing tunnels in a demonstration
- `overlaps.py`: `clear_overlaps`: a body drawn into others pushed clear with the physics, in a world of its
  neighbourhood only
- `stepping.py`: `demo_world` (gravity off, damping 0.1 per second so released bodies come to rest, speed limits),
  `step_and_observe(world, bodies, fixed=None)` → a frozen `Frame` (step, motions, contacts begun among the observed
  bodies, pairs touching; ``fixed`` gives the motions of bodies that cannot move, a rollout's welded ones, instead
  of reading them every step), `put_down` (an adjusted body catches up with the pen for 60 steps, is let go without
  being thrown, the world settles 30 steps)
- `state.py`: values: `Pose` (x, y, angle), `Velocity` (vx, vy, w), `Motion` (both), `WorldState` (step, every
  body's motion, gravity, every rope link's motion)
- `dragging.py`: the pen's grip for `World.drag`: a kinematic control body at the pen, a pivot of limited force (and
  a gear of limited torque when the angle is held)
- `sleeping.py`: `sleep_groups`: bodies asleep in groups (tied by constraints, or named pairs such as bodies
  touching) that a touch wakes together (Chipmunk's sleeping with a threshold never reached);
  `World.hold_until_touched` for SIMULATE's held bodies. `World.substeps` divides each step for a simulation's fast
  bodies

`build.py` mirrors a Scene into one pymunk Space (fixed dt 1/120 s, gravity 900 canvas units/s², i.e. 1 m = 100
units): boxes and ellipses as convex polys, freeform polygons triangulated with shapely's constrained Delaunay
triangulation, polylines as thin segments, pivot and weld joints, springs as a damped spring plus a groove and gear
(one axis only; `Spring.k` in the thesis's N/m, scaled by `SPRING_UNITS` = 1e4; its two bodies collide unless drawn
into each other, `SPRING_OVERLAP`), ropes as 8-40 light links with a
maximum-distance joint between their ends. Bodies welded to the background are static; `World` adds only constraints
with at least one dynamic end. Contact materials follow DESIGN.md (max restitution, mean friction) without a Python
callback on every contact: shapes carry elasticity 0.0 (so every contact after its first step is inelastic, as the
bounce rule wants) and a *grip* chosen so that Chipmunk's product of two grips is exactly the mean friction for most
pairs of materials (box and ball 1.0, freeform 0.5, rope 0.75); `begin`, which runs on a contact's first step, sets
the pair's larger restitution when the approach is fast, and a pre-solve callback is registered only for the pairs
whose product is not the mean (freeform-freeform, freeform-rope, rope-rope). A World step costs about 1.2x raw
pymunk with the same bodies (was 2.5-2.7x; `benchmarks/bench_contacts.py`). Two departures, written down because
DESIGN.md is silent on them: restitution applies only when a contact begins at more than 50 units/s (as Box2D does;
otherwise piles never settle), and a rope cannot stretch past its length.

Adjusting (thesis 3.2.4, `session/modes/adjust.py`): a dwell on a body starts a gravity-free `World` with every
other body frozen; the pen drags it (by its centre when grabbed near it, turning about the pen when grabbed near an
edge); on pen-up `put_down` lets it catch up, stop and the overlaps resolve, and the moved scene is one undo step. A
body drawn into others is pushed clear the same way (`overlaps.clear_overlaps`), in a world built of its
neighbourhood only: the bodies and ropes within its own size of it, what is welded to it and what holds on to that.
The result depends only on the scene, and a stroke costs the same in a sketch of 10 bodies or 400.

Sketch mode keeps one live world (`SketchMode.world`, also `Session.world`; `physics/live.py`) that a view shows
while sketching. It is never rebuilt: `LiveWorld.sync` compares the scene it mirrors with the new one component by
component (an unchanged component is the same immutable object) and adds, moves or removes only what changed —
strokes, welds, erasing, adjusting, pushing clear, undo and redo alike — rebuilding what holds on to a body that is
rebuilt or that becomes fixed or free. Its pymunk spatial index answers "which bodies are near this stroke" for
interpretation and for pushing clear (`interpret.Near`, `LiveWorld.bodies_in`), so a pen-up costs the same whatever
the size of the sketch. Adjusting, pushing clear and demonstrating build worlds of their own, so what they compute
never depends on the live world's history (a replay gives the same bytes whether or not a view was watching).
"""
