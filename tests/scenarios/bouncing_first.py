"""The ball-and-platforms machine as first drawn (tests/scenarios/bouncing.py before commit 0909bba), kept so that
SIMULATE is measured on a drawing nobody redrew for it (issue 27): B lower and further right, the basket's rim 36
canvas units right of B's end. Its eight demonstrations are named ``bouncing_first_<behaviour>`` and recorded into
tests/journals/restored/ (`make_journals`). The code below is that of the first drawing, unchanged but for the names.

"Consider the simple mechanism in Figure 2-12, where a ball can take a number of different paths before landing in
a basket" (thesis 2.4). The machine is drawn once (`machine`): the ball top left, platform A on the left, platform B
to its right and higher, and the basket, an open cup, at the bottom right; the platforms and the basket welded to
the background. Each demonstration drags the ball along one stroke: a sharp corner of the stroke is where the pen
bounces the ball off a platform, and the stroke ends with the ball resting on the basket's floor.
"""

from __future__ import annotations

from physink_tui.input.virtual_pen import Stroke
from scenarios.thesis import BACKGROUND, BodyX, Expected, JointX, Scenario, Step, _x_steps, ball

Point = tuple[float, float]

BALL = (0.10, 0.10)
"""The ball's centre, where every demonstration's stroke begins (the pen grabs the ball there)."""
RADIUS = 0.035
"""The ball's radius, a fraction of the tablet's height (35 canvas units)."""
PLATFORM_A = (0.14, 0.62, 0.40, 0.665)
"""Platform A: left, top, right, bottom (tablet fractions)."""
PLATFORM_B = (0.50, 0.34, 0.74, 0.385)
"""Platform B, right of A and higher."""
BASKET = ((0.76, 0.68), (0.78, 0.90), (0.94, 0.90), (0.96, 0.68))
"""The basket's outline: an open cup, rim first."""
PRESS = 0.012
"""How far past touching (a fraction of the tablet's height, 4 canvas units) the pen pushes the ball into a
platform at a corner of its stroke."""
FLOOR = BASKET[1][1] - RADIUS + PRESS
"""Where the pen leaves the ball in the basket: pressed onto its floor, as onto a platform."""


def on_top(x: float, box: tuple[float, float, float, float]) -> Point:
    """Where the pen stops to put the ball on the top of ``box`` at ``x``."""
    return (x, box[1] - RADIUS + PRESS)


def under(x: float, box: tuple[float, float, float, float]) -> Point:
    """Where the pen stops to put the ball against the bottom of ``box`` at ``x``."""
    return (x, box[3] + RADIUS - PRESS)


def machine() -> tuple[tuple[Step, ...], Expected]:
    """The drawing (thesis figure 2-12) and the scene it must become."""
    steps = (
        Step("the ball, top left", ball(BALL, RADIUS), say=("label ball",)),
        Step("platform A", Stroke.box(*PLATFORM_A), say=("label platform a",)),
        *_x_steps("platform A", (0.27, 0.6425)),
        Step("platform B, right of A and higher", Stroke.box(*PLATFORM_B), say=("label platform b",)),
        *_x_steps("platform B", (0.62, 0.3625)),
        Step("the basket, bottom right", Stroke(BASKET), say=("label basket",)),
        *_x_steps("basket", (0.86, 0.90)),
    )
    expect = Expected(
        bodies=(BodyX("ball", "circle", "ball"), BodyX("a", "box", "platform a"), BodyX("b", "box", "platform b"),
                BodyX("basket", "polyline", "basket")),
        joints=(JointX("weld", "a", BACKGROUND), JointX("weld", "b", BACKGROUND),
                JointX("weld", "basket", BACKGROUND)),
        fixed=("a", "b", "basket"),
    )
    return steps, expect


def _scenario(behaviour: str, source: str, what: str, path: tuple[Point, ...], seed: int) -> Scenario:
    steps, expect = machine()
    demo = (Step(what, Stroke((BALL, *path))),)
    return Scenario(f"bouncing_first_{behaviour}", source, steps, expect, seed=seed, demo=demo)


def hits_a() -> Scenario:
    """Figure 2-12, blue: the ball hits platform A, then lands in the basket (passing below B)."""
    return _scenario("hits_a", "thesis 2.4, figure 2-12 (blue)", "drag the ball onto A, then into the basket",
                     (on_top(0.30, PLATFORM_A), (0.50, 0.50), (0.86, 0.62), (0.86, FLOOR)), 2410)


def hits_b_once() -> Scenario:
    """Figures 2-12 red, 2-13 red and 3-21: the ball bounces once off the top of B, then lands in the basket."""
    return _scenario("hits_b_once", "thesis 2.4, 3.4.6, figures 2-12 (red), 2-13 (red), 3-21",
                     "drag the ball onto the top of B, then into the basket",
                     ((0.45, 0.10), on_top(0.60, PLATFORM_B), (0.78, 0.12), (0.86, FLOOR)), 2411)


def hits_b_twice() -> Scenario:
    """Figure 2-12, green: the ball bounces twice off the top of B, then lands in the basket."""
    return _scenario("hits_b_twice", "thesis 2.4, figure 2-12 (green)",
                     "drag the ball onto the top of B twice, then into the basket",
                     ((0.40, 0.10), on_top(0.55, PLATFORM_B), (0.62, 0.20), on_top(0.69, PLATFORM_B),
                      (0.80, 0.12), (0.86, FLOOR)), 2412)


def hits_b_bottom() -> Scenario:
    """Figure 2-13, blue: the ball bounces once off the bottom of B, then lands in the basket."""
    return _scenario("hits_b_bottom", "thesis 2.4, figure 2-13 (blue)",
                     "drag the ball up against the bottom of B, then into the basket",
                     ((0.45, 0.56), under(0.60, PLATFORM_B), (0.76, 0.56), (0.86, FLOOR)), 2413)


def above_b() -> Scenario:
    """Figure 2-14: the ball lands straight in the basket, passing above B."""
    return _scenario("above_b", "thesis 2.4, figure 2-14 (above)", "drag the ball over B into the basket",
                     ((0.40, 0.16), (0.62, 0.22), (0.80, 0.30), (0.86, 0.45), (0.86, FLOOR)), 2414)


def below_b() -> Scenario:
    """Figures 2-14 and 3-22: the ball lands straight in the basket, passing above A and below B."""
    return _scenario("below_b", "thesis 2.4, 3.4.6, figures 2-14 (below), 3-22",
                     "drag the ball down over A and under B into the basket",
                     ((0.30, 0.40), (0.55, 0.52), (0.75, 0.58), (0.86, 0.70), (0.86, FLOOR)), 2415)


def a_then_b_bottom() -> Scenario:
    """Figure 2-15, first: the ball bounces off the top of A, rebounds off the bottom of B, lands in the basket."""
    return _scenario("a_then_b_bottom", "thesis 2.4, figure 2-15 (first)",
                     "drag the ball onto A, up against the bottom of B, then into the basket",
                     (on_top(0.25, PLATFORM_A), under(0.58, PLATFORM_B), (0.80, 0.60), (0.86, FLOOR)), 2416)


def a_then_b_bottom_again() -> Scenario:
    """Figure 2-15, second: the same events as `a_then_b_bottom` along another path, at other times."""
    return _scenario("a_then_b_bottom_again", "thesis 2.4, figure 2-15 (second)",
                     "drag the ball onto A further left, against B further right, then into the basket",
                     ((0.13, 0.30), on_top(0.20, PLATFORM_A), (0.30, 0.50), (0.56, 0.56), under(0.66, PLATFORM_B),
                      (0.92, 0.50), (0.88, FLOOR)), 2417)


SCENARIOS = (hits_a, hits_b_once, hits_b_twice, hits_b_bottom, above_b, below_b, a_then_b_bottom,
             a_then_b_bottom_again)
"""Every demonstrated behaviour of the machine."""


def all_scenarios() -> tuple[Scenario, ...]:
    return tuple(make() for make in SCENARIOS)
