"""The stopper of thesis figure 3-9, drawn as a hand draws it: a ball resting on a movable stopper, its outline a
few pixels into the stopper's or a few pixels short of it, then demonstrated (the stopper pulled out from under the
ball, the ball dragged down where it falls).

"Initially, the ball rests on top of the stopper, in contact. When the user moves the stopper to the right, the
absence of contact causes the ball to fall downwards" (3.3.1). Neither body is welded: both are movable, so the
pair begins in contact and pulling the stopper away ends that contact.
"""

from __future__ import annotations

from physink_tui.input.virtual_pen import Stroke
from scenarios.thesis import BodyX, Expected, Scenario, Step, ball

STOPPER = (0.40, 0.50, 0.55, 0.54)
"""The stopper: left, top, right, bottom (tablet fractions; 240 x 40 canvas units)."""
RADIUS = 0.04
"""The ball's radius, a fraction of the tablet's height (40 canvas units)."""
BALL_X = (STOPPER[0] + STOPPER[2]) / 2
"""The ball sits over the stopper's middle."""
PULL = 0.15
"""How far the stopper is dragged to the right (a fraction of the tablet's width: 240 canvas units, its length)."""
DROP = 0.25
"""How far the ball is dragged down once the stopper is gone (250 canvas units)."""
CANVAS_HEIGHT = 1000.0


def ball_y(into_px: float) -> float:
    """The ball's centre when its outline is drawn ``into_px`` canvas units into the stopper (negative: short)."""
    return STOPPER[1] - RADIUS + into_px / CANVAS_HEIGHT


def stopper(into_px: float, seed: int = 3909) -> Scenario:
    """Figure 3-9 with the ball drawn ``into_px`` canvas units into the stopper's outline (a gap when negative)."""
    cy = ball_y(into_px)
    middle = (STOPPER[1] + STOPPER[3]) / 2
    steps = (
        Step("the stopper", Stroke.box(*STOPPER), say=("label stopper",)),
        Step("the ball, resting on the stopper", ball((BALL_X, cy), RADIUS), say=("label ball",)),
    )
    demo = (
        Step("pull the stopper to the right, out from under the ball",
             Stroke(((STOPPER[2] - 0.03, middle), (STOPPER[2] - 0.03 + PULL, middle)))),
        Step("drag the ball down, where it falls", Stroke(((BALL_X, cy), (BALL_X, cy + DROP)))),
    )
    expect = Expected(bodies=(BodyX("stopper", "box", "stopper"), BodyX("ball", "circle", "ball")))
    name = f"stopper_{'into' if into_px >= 0 else 'short'}_{abs(into_px):g}px"
    return Scenario(name, "thesis 3.3.1, figure 3-9", steps, expect, seed=seed, demo=demo)
