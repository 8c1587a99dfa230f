"""Stroke recognition: one stroke (or an X's two) to a primitive with beautified geometry; no interpretation.

PaleoSketch's way (Paulson & Hammond 2008): interpretations compete rather than pass a cascade of cut-offs. The
stroke is moved to unit size round its centroid (no overflow on absurd input), judged, and the geometry is scaled
back. Every threshold allows for the pen's noise in absolute units (`noise`, 1 canvas pixel unless the caller says,
or with ``noise=None`` judged from the stroke in whatever units it is stored: `units`; or the stroke's own measured
jitter when that is worse, except where its points lie so far apart that the jitter may be the shape's own bends:
`recognize.SPARSE_BENDS`, a trackpad's or mouse's 8-25 events) as well as the shape's size, so a 22-pixel
gesture and a 600-pixel one are judged alike where that makes sense and differently where noise decides.

0. A stroke whose times show the pen lifted and came down to draw the mark again (some recorders keep one stroke from
   the first landing to the last lifting) is read by its last whole attempt (`pen_lifts`).
1. A line (judged on steps a few noise widths long; a stroke whose farthest point strays no farther than the pen's
   own wobble reaches, sqrt(2 ln n) noise widths, is one unless a circle explains its bow, and a hook of up to 8 noise
   widths at one end is cut first unless it is a straight arm standing off: `lines`; a tall, thin curly brace, a sharp
   point about halfway standing out of each arm's line with both ends curling back behind it, is no line:
   `thin_braces`), a spring (loops turning one way
   whose centres advance along an axis; pointed loops allowed) or a scribble (no kind, a reason) are told first; a
   stroke under three noise widths across is a dot (no kind). Before the spring test, in a stroke turning past
   `coils.COILED`, a lead the pen drew out and back along its own path at either end and drew again with the shape (a
   box's first side or a circle's first arc drawn twice over) is cut (`loop_ends.retraced_lead`).
2. Closure is judged on the raw stroke: its ends close (within 20 % of its size or four noise widths), or it is
   drawn past its start and comes back to it (cut there), or it goes round the same sides twice, or goes round again
   beside its first lap, which is the shape (`closed_loops.TWICE_ROUND`), or its ends meet once a landing or
   lifting hook that kept a small loop's ends apart is cut (`closed_loops.hook_kept_apart`). Where neither end
   comes near the other's path, the loop is cut where its first and last sixths cross (`loop_ends`: a lead-in hook
   and an overshoot both cut off); a loop so cut that is under half the stroke's size is an open mark's (an arrow's
   head closed on its shaft, an x drawn as a loop between crossing tails), and the stroke is judged open.
3. Closed strokes are **ranked**: `polygon_fit` finds, for every number of sides k = 3..10, the best k-gon by
   dynamic programming over candidate vertices (a short Douglas-Peucker pass for the big corners plus local peaks
   for small features such as a thin wall's end); each side is scored by its own total-least-squares line, and a
   vertex is where neighbouring sides' lines meet, if that is near the join and inside the stroke's bounds, else the
   join itself, so nearly parallel sides never meet far away. The loop is tried from two starts (the point farthest
   from the centre, then the sharpest corner found). `polygon_checks` keeps only fits whose vertices are real
   corners: every turn at least 35 degrees, sides not bowed (four in five points within 6 % of the side plus the
   noise of its line), no short side between two gentle turns that together make a right angle (a corner a hurried
   hand rounded or cut back); an outline that doubles back along itself at one vertex (a thin wall's end) becomes a
   flat end with two corners. Against these, a circle or ellipse (direct fit). `candidates` builds them: a
   four-sided fit with right angles is a `Box` placed where its four drawn sides lie. Each candidate's score is `64
   log(mse + sigma^2) + complexity * params * log 64` (`recognize.Weights`); candidates are built only when the
   ranking reaches them (`candidates.Pending`); the best one whose shape lies within the stroke's bounds grown by 5
   % wins, the next kinds are the alternatives. Outlines are kept as drawn (issue 25): a box squared from a drawn quad
   that pokes out of those bounds (a rhombus, a diamond) gives way to the quad itself as a polygon
   (`Candidate.fallback`), and a box that leaves more than a tenth of the stroke's points farther than 8 % of its
   diagonal from its sides is not kept (`polygon_checks.OUTLINE_FAR`; a golf tee's thin wide top on its narrow stem is
   not a box the size of the stem). A circle rounded off from an egg-shaped loop that pokes out of the bounds gives way
   to the ellipse drawn (`Candidate.fallback` again), and a loop about as wide as long turning smoothly all round (under
   `open_shapes.SMOOTH` of its coarse turning in its sharpest fifth) is offered no polygon of four sides or more
   (`closed_loops.LUMPY_SIDES`): a lumpy mouse-drawn circle fits a hexagon closely, a drawn polygon turns at corners;
   a loop whose points come in three to eight bursts joined by long jumps and lie on an ellipse, going round it one
   way (`pen_noise.round_in_bursts`: a busy mouse's events round a small note; a wobbly one's points off it by up to a
   tenth, where they lie clearly closer to it than to any outline of three or four sides or, closed, where its
   bursts are tangent to one round curve, the chords between them turning as much out of one burst as into the next:
   `burst_tangents.tangent_to_one_curve`), is offered no polygon.
   A short side where the outline turns back sharply at one end and gently at the other, its neighbours' far ends
   apart, is a hook where the pen landed or lifted (`polygon_checks.SPUR`): a box with a hooked start is a box. A
   winning polygon that crosses over itself into cancelling lobes (`stroke_features.figure_eight`: a bow tie, as
   a delete mark whose ends happen to meet) is no outline: the stroke is judged open. A winning polygon of five
   sides or more that its best four sides overlap by IoU >= 0.92 (`polygon_checks.BOX_OVERLAP`; their fitted quad, or
   the quad where those sides meet, `quads.four_sides_cover`), when those four make a box, is the box (a hook, a bowed
   side or a cut corner; a notch, T or L keeps its corners). A quad within the box's tolerance is not squared when the
   box would overlap it by under 0.90 and it is a trapezoid (both legs turned in) or a rhombus standing on a point
   (`quads`): it keeps its corners, placed where its sides meet, as every four-sided polygon's are; a parallelogram
   with unequal sides (a box leaning) or a quad with one wall askew is a box, as people draw them; a lumpy round
   loop's circle or ellipse may reach 20 % of the diagonal past the stroke, as a round shape left open may; a box may
   reach 10 % (`ranking.BOX_MARGIN`: a box whose upright sides lean, squared, pokes out). A polygon left open (its
   last side heading home, or a star's run on past its start, `closed_loops.STAR_CROSSINGS`) is judged by its sides'
   turning where an end hook undoes the path's (`closed_loops.LEFT_OPEN_WOBBLE`), and its first and last sides may
   bow (`closed_loops.LAST_SIDE_BOW`); so is a four-sided outline left open by part of its first or last side, up to
   0.7 of it (`open_boxes.box_left_open`: three corners and the fourth where those sides' lines meet near square).
   So is a star's outline left open by about a side (`open_stars.star_left_open`: points and shallower dents in
   turn along straight sides), which the learned ranker is then not asked of (`ranker.star_left`). A loop read as an
   ellipse under 0.08 as wide as long is a line drawn out and back (`open_marks.out_and_back`).
   A loop read round is read as its polygon of four sides or more after all
   (`round_or_cornered`) when that polygon leaves at most half the round shape's error and three in four of its
   vertices turn within 0.4 of their shorter side (`polygon_checks.sharp_corners`; a round loop needs 0.8): a
   hexagon or octagon whose many vertices the complexity penalty outweighed; never on points sparser than four to
   the shortest side (a circle given as a few points round it). Where the stroke's times are known, a polygon of five
   sides or more is also read so when the pen slowed at its vertices (`corner_pace`: under 0.55 of its mean pace at the
   median vertex) and its median vertex turns within half its shorter side: a mouse's octagon, its corners blurred by
   sparse points, which a person's mouse circle (drawn at an even pace) fits as closely; and where the points came in a
   busy mouse's bursts (too sparse for either), when the pen's pace fell under 0.7 of its median five times or more
   (`corner_pace.slowdowns`, `round_or_cornered.paced_corners`: it slowed into the corners). A polygon of five sides or
   more, or a loop read round with two sharp corners, is the box drawn with a corner or two rounded off
   (`rounded_corners`) when four sides of its fit run straight for most of their length, meet near right angles, and
   only bows or sharp turns lie between them (a straight stretch between two sides is a side: a pentagon's, a
   hexagon's, a cut corner's). A polygon of four sides or more (a quad past a box's tolerance too, since session 35)
   is the box one of whose sides a hand bowed out or in (`bowed_sides`) when three sides of its fit of five or six run
   straight and square and the rest of the loop is one round bow: on one side of its chord, at most 0.3 of it deep,
   filling its strip as a bow does and bending round, not at a roof's corner (a low pentagon's, a swallowtail's, a
   deep cut's). A loop still read round is the box round it when every one
   of its four corners reaches at least 0.78 of the way towards the corner of the smallest rectangle round it
   (`rounded_boxes`: an ellipse reaches 0.707, a box whose every corner is rounded by 0.375 of its side 0.78; people's
   circles at most 0.76). A closed loop its ellipse misses by more than twice `open_shapes.round_error`, or that turns
   back against its own direction by half a turn or more in all (a star's inner corners) while its ellipse misses it by
   more than a round stroke may (`closed_loops.WITHIN_ROUND`: a slow, unsteady hand's tremor turns a circle back too),
   is offered no circle or ellipse (`closed_loops.no_round_shape`); a stroke read round that runs off its loop's
   ellipse by more than 1.2 of that ellipse's half-length (`closed_loops.tail_runs_off`: a pigtail drawn loop first,
   its tail 1.6-3 half-lengths; a flick closing an oval, up to its half-length, strays at most 1.06) is read as an
   open mark, and as a curve where that reading would be round too (a polygon's loop with an overshoot past a corner,
   read as a polygon, is not asked), unless it is a round loop the pen landed on and ran on past its start
   (`run_on_loops`: the loop, where the path comes back to within 0.15 of its size of itself, holds 0.8 of the path or
   more, one end stays on its ellipse, it is at least 0.6 as wide as long and fits it round, and the path heads on
   within 60 degrees of where the loop began: a circle with a run-on tail, read as its loop also where the ends stay
   too far apart to close it; a pigtail's tails both run off and cross at a corner, nearly always round a smaller
   loop); a round reading of a stroke gone round more than once is a circle or an
   ellipse as its lap from the start and its lap to the end tell it alike, where both come back round and disagree
   (`both_laps`: by their mean width over length, so it reads the same drawn from either end; a circle rounded off
   from either lap that stays within the stroke's bounds where both laps are round enough for one);
   a long ellipse's miss (2.62 times as long as
   wide or more, `candidates.ACROSS_RATIO`) is measured square across it, as a polygon's sides' are
   (`candidates.ellipse_distances`: along the ray from its centre, a long oval's miss at its shoulders doubles, and
   its triangle through its ends won), a rounder one's along that ray as before; a
   stroke whose tails cross each other near its ends is closed however far apart its ends lifted
   (`closed_loops.ends_cross`: a triangle closed past its first corner), or one end within that gap and the other
   up to half its size past the crossing where the loop between is a polygon of four sides or more
   (`end_crossings.crossed_close`: a box or a diamond whose last side runs on past its first corner), but not one
   whose start lies on its path and whose last arm runs on past the crossing by its own length round a triangle
   (`end_crossings.x_run_past`: an x's second diagonal), and one whose
   ends a hook where the pen
   landed or lifted kept apart is judged without the hook where it does not cross itself (a 10-30 px circle's hook of
   a few pixels is a fifth of its size; a pigtail's tails cross).
4. Open strokes (`open_shapes`) are judged by how they turn, at the scale of the pen's noise: a round shape left
   open (more than 225 degrees one way, fitting an ellipse; or fitting one once a lead from inside or an end curled in
   past the start, lying inside it, is cut: `round_cores`; or once a flick where the pen lifted or landed, at most
   8 % of the path turning 45 degrees or more off the round path's own turning, is cut: `lift_hooks`; or whose points
   a busy mouse sent in a few bursts lie on an ellipse going round it: `pen_noise.round_in_bursts`; a stroke of a few
   far-apart events is judged smooth by the turns at its events, not along its chords:
   `pen_noise.turns_evenly_at_events`), a polyline (straight sides, or bowed sides meeting at
   really sharp corners; and no corner rounder than `Weights.round_corner` of its shorter side: a brace's bend is a
   curve's, but three straight sides turning one way, a square bracket, may round theirs,
   `open_shapes._rounded_bracket`; with two or more corners, no main side bowed like a quarter circle,
   `open_shapes.BOWED_SIDE`; and no brace's tip, a short pointed excursion the stroke runs on in line through,
   `open_shapes._brace_tip`: a brace or question mark drawn with a mouse is straight runs and cusps; nor one corner
   between arms running on in line in a stroke turning both ways, `open_shapes._tip_in_line`), an arc, or a
   curve of cubic pieces. A result outside the stroke's bounds falls back to the ranked polyline. Corners are found
   at every sharp dip of a run of short straws (an arrow's head, a zig-zag's small teeth: `stroke_geometry.
   find_corners(every_dip=True)`), and a one-corner stroke turning one way whose bend is short against the whole
   stroke is sharp however short its arm (a tick, `open_shapes._short_bend`), its short arm may bow into the corner
   (`open_shapes._tick_into_bend`), and a short straight arm standing off a stroke with no other corner nor point is
   an arm, not a hook cut where the pen landed (`stroke_geometry.end_arm`). Four or more sharp corners in a row
   turning each way in turn, joined by straight sides drawn alike (a zig-zag's teeth), make a polyline whatever the
   stroke does before and after them (a loose lead-in, a curled tail: `open_marks.sawtooth`). A line begun or ended
   by running back along itself is judged without that piece (`open_marks.retraced_ends`), or by a hook the pen turned
   back within 30 degrees of it where it landed or lifted, at most 12.5 % of the path where it landed (a radical's
   tick, drawn first, is longer) and 15 % where it lifted (`open_marks.BACK_HOOK_DEG`, `BACK_HOOK_LANDED_SHARE`: a
   mark's short arm stands farther off), or up to 30 % within 38 degrees where it landed before a line drawn level or
   downhill (no radical's or check's rise: `lead_ins.lead_in`) or where it lifted after one drawn level or uphill
   (the same piece, the stroke drawn backwards: a lead-in and a line read the same from either end), or by a tight
   round curl at one end, swung 125 degrees or more off it, at most 18 % of the path (`end_curls.curled_ends`: the
   rest straight by the line test); one the hand's swing bowed one way and back (turning both ways, no point, no
   circle fitting its bow beyond the pen's own wobble, straying under 9 % of its length) is a line
   (`open_marks.swung_line`), as is one whose hooks left a bow that a line fits as closely as a circle, an end curling
   as a hook does (`open_marks.hooked_straight`), and a short line hooked where the pen landed and where it lifted,
   judged with both hooks cut, unless its short ends stand off it to one side as a tiny square bracket's arms do, square
   or about parallel, or its middle keeps a small brace's lost point (`lines.unhooked`, `lines.HOOK_BACK_DEG`,
   `lines.HOOKS_SPLAY_DEG`, `lines.MIDDLE_SPREAD`). Beside a really sharp
   corner, a bend under `open_shapes.SHARP_CORNER` is an arm's wobble whose roundness does not make the mark round
   (`open_shapes._roundest_corner`). Marks these rules misjudge (`bracket_marks`): a square bracket with one corner
   rounded off (one sharp corner, half a turn one way, a straight spine) is a polyline through its rounded corner
   too; a brace whose point is a small loop, or whose curls or point were taken for corners between straight sides
   (its farthest point from its ends' line a shallow point about halfway along, the stroke on one side of that
   line), is not a polyline; a tick, check or v swung round its point
   (one bend, turning one way, between a straight long arm and a short arm, the finder finding no corner) is a
   polyline through the point farthest from its ends' line (`bracket_marks.rounded_point`), also once a hook where
   the pen landed or lifted, found as a corner within a tenth of the path from an end, is cut
   (`bracket_marks.unhooked_point`; not where its long arm curls on round the bend all along it, as a lopsided
   parenthesis' long side does: `bracket_marks.curling_arm`); a chevron swung round its corner (one bend turning
   80-150 degrees about halfway along, the outer 60 % of each side straight, their lines meeting near the bend,
   most of the turn made within 15 % of the path) is a polyline through where those lines meet
   (`rounded_chevrons`; an arc or parenthesis turning as much bows its sides). A polyline so read that
   bends at least twice inside its ends, each the other way from the one before, every bend round and the
   sides between them curving (an S each), is a wave, a squiggle: a curve (`waves`), not asked of the ranker below;
   of two bends only (an S lying down), its longest piece must curve too (a radical sign's rise runs straight).
   Bends too round to be found on the wave's 128 points are looked for on the rules' 64 (an S drawn slowly; both its
   bends round there, `waves.ROUND_S_ROUNDNESS`), and a curve the rules read that is such a wave (two bends found in
   a row the same way taken as one round bend, unless together they turn a half turn: an arrow's barb), its longest
   side between bends curving (a radical with a start hook has a straight rise), is not asked of the ranker either
   (`waves.kept_curve`).
   Any other curve, line or polyline so read that, looked at on points 1.5 of the pen's noise widths apart, is a
   chain of four or more sharp corners joined by straight sides that repeat (a staircase, a square wave, a zig-zag,
   however small its steps against the stroke) is a polyline through those corners (`stairs`), not asked either.
   A square bracket with both corners rounded off (a long straight spine, a straight arm at each end, each joined to
   it by a bend of about a right angle, 120-215 degrees in all (a mouse's wrist splays the arms), the spine with no
   brace's point in its middle, judged without a hook where the pen landed or lifted) is
   a polyline with its corners where its sides meet (`round_brackets`), not an ellipse left open, and the rules'
   square bracket whose spine turns back toward its opening halfway is kept so (`dented_spines`); a brace drawn as
   straight runs between cusps (running along its ends' line on one side of it, its arms parallel to it and off it,
   its point about halfway sticking out past them) is not a polyline (`angular_braces`), nor is a lopsided brace
   whose short half runs straight from its point back to its end (a bracket's square end and spine on the long half,
   the spine off that line all along, the point past the spine's own line: `lopsided_braces`); none, so read, is
   asked of the ranker below. A curve, arc or polyline so read whose one end is a straight short arm longer than a
   landing hook reaches (`lines.HOOK_REACH`) but within the tenth of the path the rules cut as a hook, standing off a
   straight long arm at a tick's angle, is a tick: a polyline through its start, point and end (`hooked_ticks`), not
   asked of the ranker either.
5. A polyline or a curve so read, or a polygon whose ends stay apart by the rules' closing gap (`ranker.OPEN_GAP`:
   a caret, a v or an arrow the rules closed), is re-ranked by a learned model (`ranker`, issue 25): a conditional
   logit over polyline, curve (and the polygon read) on the stroke's geometric features (and the rules' own tests),
   fitted offline on people's strokes by `benchmarks/train_ranker.py`, shipped in the package as the data module
   `ranker_model`; it overrules the rules only when it gives another kind a chance over its margin. Other kinds are
   left to the rules, and so is the rules' hurried check (one really sharp, off-centre corner in at most three
   lobes, or two corners of which the point holds a third of all the turning, never a loop's: `ranker.checked_point`),
   the rules' zig-zag (its polyline's vertices are a sawtooth: `ranker.zigzag_teeth`), and a curve the rules read
   between a few far-apart events (`recognize.sparse_bends`: a trackpad's fast stroke, `ranker.kept_curve`), and a
   one-corner mark whose arms are both straight as drawn, not in line, the longer with no point
   (`open_shapes.straight_armed_mark`: the model's curve is for bowed arms).

   lobes, or two corners of which the point holds a third of all the turning: `ranker.checked_point`), and the rules'
   zig-zag (its polyline's vertices are a sawtooth: `ranker.zigzag_teeth`) and a tick swung round its point (on the
   model's own points, no corner found there, or none but a hook's, cut: `bracket_marks.swung_tick`,
   `bracket_marks.unhooked_point`; a lopsided parenthesis whose long side curls on round its bend is asked:
   `bracket_marks.curling_arm`).

- `primitives.py`: `Recognition` and the frozen geometry of each kind (`Line`, `Polyline`, `Polygon`, `Box`,
  `Circle`, `Ellipse`, `Arc`, `Curve` as cubic Bézier control points, `Helix`, `XSymbol`)
- `recognize.py`: the public `recognize_stroke` / `recognize_strokes`, cleaning, the order above
- `open_reading.py`: an open stroke read by how it turns on points a few noise widths apart (a square-cornered
  brace, a round stroke sampled in bursts, the bounds its shape must keep)
- `closed_reading.py`: a closed stroke's loop read as the outline or round shape it best fits, then as what a person
  drew after all (the checks above on closed strokes, in order: a pigtail's loop, rounded corners, a bowed side, a
  roof, a delete mark's crossing)
- `closed_loops.py`: closure (a gap or an overshoot at the ends, a polygon left open, a lumpy circle's lumps)
- `shape_corners.py`: corners at the shape's scale (turning gathered at short bends between straight runs): a
  many-sided outline left open by one side, its corners rounded by a hurried hand
- `ranking.py`: the candidates scored (fit error against complexity, `Weights`, `DEFAULT_WEIGHTS`) and ranked: the
  best whose shape stays within the stroke's bounds and follows its outline, with the alternatives; where none
  fits, the stroke kept as drawn (`or_freeform`)
- `coils.py`: strokes that wind or scrub rather than outline: a spring drawn as one coil (a helix), a scribble
- `candidates.py`: the competing interpretations of a closed stroke with their fit error and complexity: polygonal
  ones (built only when the ranking reaches them), a circle or ellipse; a box placed where its four sides were drawn
- `polygon_fit.py`: best k-gon / k-segment chain for every k: candidate vertices, per-run line costs from prefix
  sums, dynamic programming, vertices where sides meet
- `polygon_checks.py`: whether a fit's vertices are real corners; flat ends for hairpins; how much two outlines
  overlap; whether a closed fit's corners are sharp rather than round bends
- `round_or_cornered.py`: a loop the ranking read round, read as the polygon drawn when its corners are sharp
  or the pen slowed at them
- `corner_pace.py`: the pen's pace at a closed polygon's vertices against its mean pace, and how many times its
  pace fell along the stroke (a hand slows at the corners it means, keeps its pace round a circle)
- `rounded_corners.py`: a box with a corner or two rounded off (read as a polygon or round), read as the box; a
  polygon of five sides or more its best four sides cover nearly as drawn, read as that box (`box_as_drawn`)
- `bowed_sides.py`: a box with one side bowed out or in (read as a polygon), read as the box of the loop's area
- `roofs.py`: a box read where one sharp corner stands off a side (a house roof) or is pushed in (a swallowtail
  notch), read as the pentagon drawn
- `rounded_boxes.py`: a box with all four corners rounded (read round), read as the box by how far its corners reach
- `loop_ends.py`: where a closed stroke's loop begins and ends (hooks, lead-ins, overshoots cut off; a lead drawn
  out and back and drawn again by the shape)
- `open_shapes.py`: the judgement of open strokes (line, polyline, arc, round shape left open, curve)
- `open_marks.py`: open marks a hurried hand draws loosely: a zig-zag's teeth between a lead-in and a tail, a line
  begun by sliding back along itself or bowed by the hand's swing
- `bowed_lines.py`: a line a quick wrist bowed one way, slanted or level, told from a parenthesis and an arc by
  where and how deep it bows (`open_marks.flicked` asks it)
- `bracket_marks.py`: square brackets with a rounded corner, curly braces with a looped or straight-armed point and
  ticks swung round their point, which the open-stroke rules misjudge
- `waves.py`: a wave (round bends each way in turn, curving sides) read as a curve, not a zig-zag's polyline
- `lines.py`: how far a person's line strays by the pen and hand alone (the noise's farthest reach, a hook at an
  end, the ink of a wobble), told from a bow drawn on purpose (a circle explains it) and a mark's short arm
- `stairs.py`: a chain of sharp corners joined by straight, repeating sides (staircases, square waves, zig-zags),
  judged at its sides' scale, read as a polyline through its corners
- `round_brackets.py`: a square bracket whose two corners a hand rounded off, read as the bracket (a polyline),
  judged without the pen's hooks at its ends, the same whichever end it was drawn from
- `dented_spines.py`: the rules' square bracket whose spine dents, bulges or steps back toward the opening about
  halfway (a brace's point turns with its curls instead), kept from the learned ranker
- `lift_hooks.py`: a round stroke left open whose end flicks off where the pen lifted or landed, judged round without
  the flick
- `angular_braces.py`: a curly brace drawn as straight runs and cusps (a mouse's), or askew (laid out against its
  arms' own line), read as a brace (a curve)
- `square_braces.py`: a curly brace drawn square-cornered (a square bracket with a small point on its spine), read
  as a brace
- `lopsided_braces.py`: a lopsided curly brace whose short half is a straight slant back from its point, its long
  half a bracket's square end and spine, read as a brace (a curve)
- `run_on_loops.py`: a round loop the pen landed on and ran on past its start as a long tail, read as the loop
- `round_cores.py`: a circle drawn with a lead from inside it or an end curling in past its start, read by its round
  core (the ends cut while they lie inside the core's ellipse)
- `thin_braces.py`: a tall, thin curly brace (its point and curls within a line's stray) told from a line by its one
  sharp point between arms and its ends curling back behind them
- `hooked_ticks.py`: a tick whose short arm is a few percent of the stroke (longer than a hook, shorter than the
  tenth the rules cut as one), read as a tick (a polyline)
- `stroke_geometry.py`: resampling, smoothing, turning angles, rotation-invariant size, ShortStraw/IStraw corners,
  hooks, where two lines meet (`line_meet`)
- `small_loops.py`: small loops at corners (the path crossing itself), cut out before the coil test
- `shape_turning.py`: turning at the shape's scale, on steps a few noise widths long (`coarse_turning`,
  `turning_beyond_tremor`)
- `stroke_views.py`: one stroke's resampled, smoothed and hook-cut copies that the checks after the rules (waves,
  stairs, ticks, brackets, braces) share, each made once a recognition (read-only, never shared between strokes)
- `burst_tangents.py`: whether a mouse's bursts of events are tangent to one round curve (the chords between them
  turning equally out of one burst and into the next, on the stroke's ellipse made a unit circle), not on sides
- `pen_noise.py`: the stroke's own jitter, the bends a shape its size makes between sparse points (their step
  judged along the stroke's body, not a landing's cluster), and whether a few sparse events turn at every one (a
  round shape sampled, not a polygon's sides)
- `units.py`: the pen's noise judged from a stroke when not stated (``noise=None``, `physink recognize`'s
  default): the lattice its coordinates are rounded to (whole pixels: 1), else its jitter as a rounding device's
- `landing.py`: a finger's or pen's dwell where it lands or lifts (points wandering about the end), kept as one point
- `pen_lifts.py`: a recorded stroke whose times show the pen lifted and drew the mark again (a second's silence, then
  a far landing), read by its last whole attempt
- `stroke_features.py`: features of open strokes: corner turns, bends, lobes, corner roundness, closure, retraced
  loops
- `ranker.py`: the learned ranker's features (from what recognition already measured of the stroke, `ranker.Drawn`;
  a hurried check's stop once `checked_point` can tell; the timed ones only where the model weighs them) and its
  choice; `ranker_weights.py` its model's columns and the model (read once from the package's data, checked against
  them); `ranker_pace.py` two of its features (where the sharpest corner
  falls along the path, how the pen slowed at corners)
- `shape_fits.py`: total-least-squares line, Kasa circle, Fitzgibbon direct ellipse, cubic Bézier fits
- `linalg_cores.py`: numpy.linalg's SVD, least squares, eigenvectors and solve called on LAPACK's compiled cores
  directly, without the per-call argument checks (the same results; the fits above use it)
- `beautify.py`: the clean geometry of each kind, points on it (`shape_points`, for the bounds check), mapping back
  to the stroke's units

Test-side generators live under `tests/`: `strokegen/` (seeded strokes per kind, thin boxes and U containers) and
`penmodels/` (a second, hurried pen model that draws the thesis scenes, written apart from the virtual pen).
`benchmarks/bench_recognition.py` and `bench_recognition_robust.py` (leave one person out, stress variants, thin
boxes, containers) measure what the tests only floor; `compare_readings.py` shows that a change (a speed-up) reads
every design stroke exactly as another revision does, `profile_recognition.py` where recognition's time goes, and
`ablate_rules.py` what each hand rule fixes and breaks, switched off in turn, where it was designed and elsewhere.
"""
