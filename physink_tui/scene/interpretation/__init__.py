"""Interpretation: recognised strokes read in the context of the scene (bodies, joints, springs, ropes, X pairs).

`scene/components.py` holds the sketch as frozen values (`Scene` of `Body`, `Joint`, `Rope`, `Spring`; ids never
reused; materials by shape class from the thesis). `scene/interpretation/interpret.py` applies the thesis's rules
(3.2.2) in order to a recognised stroke and returns the new scene plus anything the user should be told;
`scene/interpretation/body_shapes.py` turns primitives into body outlines (self-crossing polygons repaired with
shapely) and bodies into shapely geometry for "inside" questions. Scenes are immutable, so undo is a stack of
documents (scene and timeline, `session/history.py`).

The X (thesis 3.2.1) is two strokes, and people draw its arms bowed, hooked at the ends and crossing off their
middles, so the recogniser often names an arm a polyline, curve or arc. `scene/interpretation/x_pairing.py` judges
arms by their extent instead: a stroke whose middle three fifths is nearly straight, whose hooks stay close to that
axis, and which is shorter than 8 % of the canvas diagonal (`session/modes/sketch.X_CANDIDATE`) — or, longer, whose
axis crosses a body no smaller than the stroke (`interpret.crossed_bodies`) — is held back as a possible half-X
(whatever it was recognised as); the next stroke pairs with it when both are arms crossing away from their ends at
40° or more. So X or erase is decided by what follows, not by size (issue 25): within the X window, `X_WAIT` (1.5 s
from the end of the first stroke to the start of the second, on the inputs' times, so a replay decides the same), a
crossing second stroke makes an X (a weld) with arms up to the crossed body's own size; with none, the stroke is
taken on its own, and a line through a body erases it (thesis 2.1). An X whose crossing falls just off a thin body
(a 12-unit platform under a 50-unit X) welds the nearest body within half an arm, anchored at its nearest point.

Every stroke's outcome is told (`session/outcomes.py`, `Message.kind == "outcome"`): "circle → body b3", "X →
platform b2 fixed", "erased box b4 — u to undo", "circle → pin j2: lever b3 turns on the background", "helix →
spring s1 (horizontal) from wall b1 to peg b2", "curve → rope r1, tied to lever b3 and knife b5", "label 'ball' →
circle b2". Repairs, refusals and odd cases stay `note`s, told after the outcome.
"""
