"""The thesis's ball-and-platforms machine (figures 2-12 to 2-15, 3-21, 3-22) and the behaviours demonstrated on it.

"Consider the simple mechanism in Figure 2-12, where a ball can take a number of different paths before landing in
a basket" (thesis 2.4). The machine is drawn once (`machine`): the ball top left, platform A on the left, platform B
to its right and higher (so that a ball bouncing off the top of A can rebound off the bottom of B, figure 2-15, and
a ball descending straight into the basket can pass above A and below B, figure 3-22), and the basket, an open cup,
at the bottom right; the platforms and the basket welded to the background. Each behaviour is one scenario over the
same drawing, named ``bouncing_<behaviour>``, whose demonstration drags the ball along one stroke: a sharp corner of
the stroke is where the pen bounces the ball off a platform (the pen slows to a stop there, a few canvas units past
the point where the ball's rim meets the surface, so the ball touches it once, gently), and the stroke ends with the
ball resting on the basket's floor. The strokes are placed relative to the platforms and the basket.

The proportions are chosen so that every path the thesis's simulator found exists under gravity with some room:
A reaches under B's left end, B is high, and the basket lies under B's right end, its rim well below B. (An
earlier drawing, with B lower and the basket's rim 36 canvas units right of B's end, left a ball passing under B
into the basket, figure 3-22, and a ball rebounding off A and B's bottom into it, figure 2-15, a sliver of throws
each: a ball entering under B from the top left descends on a line that meets the rim.)
"""

from __future__ import annotations

from physink_tui.input.virtual_pen import Stroke
from scenarios.thesis import BACKGROUND, BodyX, Expected, JointX, Scenario, Step, _x_steps, ball

Point = tuple[float, float]

BALL = (0.10, 0.10)
"""The ball's centre, where every demonstration's stroke begins (the pen grabs the ball there)."""
RADIUS = 0.035
"""The ball's radius, a fraction of the tablet's height (35 canvas units)."""
PLATFORM_A = (0.14, 0.62, 0.52, 0.665)
"""Platform A: left, top, right, bottom (tablet fractions)."""
PLATFORM_B = (0.48, 0.30, 0.72, 0.345)
"""Platform B, right of A (its left end over A's right end) and higher."""
BASKET = ((0.62, 0.74), (0.64, 0.96), (0.84, 0.96), (0.86, 0.74))
"""The basket's outline: an open cup, rim first, its left part under B's right end."""
PRESS = 0.012
"""How far past touching (a fraction of the tablet's height, 4 canvas units) the pen pushes the ball into a
platform at a corner of its stroke."""
FLOOR = BASKET[1][1] - RADIUS + PRESS
"""Where the pen leaves the ball in the basket: pressed onto its floor, as onto a platform."""
RIM = BASKET[0][1]
"""The height of the basket's rim."""
BASKET_X = (BASKET[0][0] + BASKET[3][0]) / 2
"""The middle of the basket."""


def on_top(x: float, box: tuple[float, float, float, float]) -> Point:
    """Where the pen stops to put the ball on the top of ``box`` at ``x``."""
    return (x, box[1] - RADIUS + PRESS)


def under(x: float, box: tuple[float, float, float, float]) -> Point:
    """Where the pen stops to put the ball against the bottom of ``box`` at ``x``."""
    return (x, box[3] + RADIUS - PRESS)


def along(box: tuple[float, float, float, float], fraction: float) -> float:
    """The x of ``box`` at ``fraction`` of its length from its left end."""
    return box[0] + fraction * (box[2] - box[0])


def middle(box: tuple[float, float, float, float]) -> Point:
    return ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)


OVER_BASKET = max(BASKET[0][0] + 0.02, PLATFORM_B[2] + 0.05)
"""An x from which the pen can lower the ball into the basket without touching B."""
OPEN_X = (max(BASKET[0][0], PLATFORM_B[2]) + BASKET[3][0]) / 2
"""The middle of the part of the basket open to the sky (right of B): where a ball coming over B is put."""
BETWEEN = (PLATFORM_B[3] + PLATFORM_A[1]) / 2
"""Halfway down from B's bottom to A's top: the height of the gap a ball passes through below B."""


Box = tuple[float, float, float, float]


def drawn_machine(platform_a: Box, platform_b: Box, basket: tuple[Point, ...], welds: tuple[Point, Point, Point]
                  ) -> tuple[tuple[Step, ...], Expected]:
    """A ball-and-platforms drawing (thesis figure 2-12) and the scene it must become: the ball at `BALL`, the two
    platforms and the basket, each welded to the background by an X at ``welds`` (A's, B's, the basket's)."""
    steps = (
        Step("the ball, top left", ball(BALL, RADIUS), say=("label ball",)),
        Step("platform A", Stroke.box(*platform_a), say=("label platform a",)),
        *_x_steps("platform A", welds[0]),
        Step("platform B, right of A and higher", Stroke.box(*platform_b), say=("label platform b",)),
        *_x_steps("platform B", welds[1]),
        Step("the basket, bottom right", Stroke(basket), say=("label basket",)),
        *_x_steps("basket", welds[2]),
    )
    expect = Expected(
        bodies=(BodyX("ball", "circle", "ball"), BodyX("a", "box", "platform a"), BodyX("b", "box", "platform b"),
                BodyX("basket", "polyline", "basket")),
        joints=(JointX("weld", "a", BACKGROUND), JointX("weld", "b", BACKGROUND),
                JointX("weld", "basket", BACKGROUND)),
        fixed=("a", "b", "basket"),
    )
    return steps, expect


def demonstration(name: str, drawing: tuple[tuple[Step, ...], Expected], source: str, what: str,
                  path: tuple[Point, ...], seed: int) -> Scenario:
    """The scenario ``name``: ``drawing``, then the pen dragging the ball from `BALL` along ``path``."""
    steps, expect = drawing
    demo = (Step(what, Stroke((BALL, *path))),)
    return Scenario(name, source, steps, expect, seed=seed, demo=demo)


def machine() -> tuple[tuple[Step, ...], Expected]:
    """The drawing (thesis figure 2-12) and the scene it must become."""
    return drawn_machine(PLATFORM_A, PLATFORM_B, BASKET,
                         (middle(PLATFORM_A), middle(PLATFORM_B), (BASKET_X, BASKET[1][1])))


def _scenario(behaviour: str, source: str, what: str, path: tuple[Point, ...], seed: int) -> Scenario:
    return demonstration(f"bouncing_{behaviour}", machine(), source, what, path, seed)


def hits_a() -> Scenario:
    """Figure 2-12, blue: the ball hits platform A, then lands in the basket (passing below B)."""
    return _scenario("hits_a", "thesis 2.4, figure 2-12 (blue)", "drag the ball onto A, then into the basket",
                     (on_top(along(PLATFORM_A, 0.6), PLATFORM_A), (PLATFORM_B[0], BETWEEN), (BASKET_X, RIM - 0.06),
                      (BASKET_X, FLOOR)), 2410)


def hits_b_once() -> Scenario:
    """Figures 2-12 red, 2-13 red and 3-21: the ball bounces once off the top of B, then lands in the basket."""
    return _scenario("hits_b_once", "thesis 2.4, 3.4.6, figures 2-12 (red), 2-13 (red), 3-21",
                     "drag the ball onto the top of B, then into the basket",
                     ((PLATFORM_B[0] - 0.05, 0.10), on_top(along(PLATFORM_B, 0.42), PLATFORM_B),
                      (OVER_BASKET, 0.12), (OPEN_X, FLOOR)), 2411)


def hits_b_twice() -> Scenario:
    """Figure 2-12, green: the ball bounces twice off the top of B, then lands in the basket."""
    return _scenario("hits_b_twice", "thesis 2.4, figure 2-12 (green)",
                     "drag the ball onto the top of B twice, then into the basket",
                     ((PLATFORM_B[0] - 0.10, 0.10), on_top(along(PLATFORM_B, 0.21), PLATFORM_B),
                      (along(PLATFORM_B, 0.5), PLATFORM_B[1] - 0.14), on_top(along(PLATFORM_B, 0.79), PLATFORM_B),
                      (OVER_BASKET + 0.02, 0.12), (OPEN_X, FLOOR)), 2412)


def hits_b_bottom() -> Scenario:
    """Figure 2-13, blue: the ball bounces once off the bottom of B, then lands in the basket."""
    return _scenario("hits_b_bottom", "thesis 2.4, figure 2-13 (blue)",
                     "drag the ball up against the bottom of B, then into the basket",
                     ((PLATFORM_B[0] - 0.05, PLATFORM_B[3] + 0.175), under(along(PLATFORM_B, 0.42), PLATFORM_B),
                      (BASKET[0][0], PLATFORM_B[3] + 0.175), (BASKET_X, FLOOR)), 2413)


def above_b() -> Scenario:
    """Figure 2-14: the ball lands straight in the basket, passing above B."""
    return _scenario("above_b", "thesis 2.4, figure 2-14 (above)", "drag the ball over B into the basket",
                     ((PLATFORM_B[0] - 0.10, PLATFORM_B[1] - 0.18), (along(PLATFORM_B, 0.5), PLATFORM_B[1] - 0.12),
                      (OVER_BASKET + 0.01, PLATFORM_B[1] - 0.04),
                      (OPEN_X, PLATFORM_B[3] + 0.065), (OPEN_X, FLOOR)), 2414)


def below_b() -> Scenario:
    """Figures 2-14 and 3-22: the ball lands straight in the basket, passing above A and below B."""
    return _scenario("below_b", "thesis 2.4, 3.4.6, figures 2-14 (below), 3-22",
                     "drag the ball down over A and under B into the basket",
                     ((0.30, 0.40), (along(PLATFORM_B, 0.2), BETWEEN + 0.02), (BASKET[0][0] - 0.01, RIM - 0.10),
                      (BASKET_X, RIM + 0.02), (BASKET_X, FLOOR)), 2415)


def a_then_b_bottom() -> Scenario:
    """Figure 2-15, first: the ball bounces off the top of A, rebounds off the bottom of B, lands in the basket."""
    return _scenario("a_then_b_bottom", "thesis 2.4, figure 2-15 (first)",
                     "drag the ball onto A, up against the bottom of B, then into the basket",
                     (on_top(along(PLATFORM_A, 0.42), PLATFORM_A), under(along(PLATFORM_B, 0.33), PLATFORM_B),
                      (BASKET[0][0] + 0.04, RIM - 0.08), (BASKET_X, FLOOR)), 2416)


def a_then_b_bottom_again() -> Scenario:
    """Figure 2-15, second: the same events as `a_then_b_bottom` along another path, at other times."""
    return _scenario("a_then_b_bottom_again", "thesis 2.4, figure 2-15 (second)",
                     "drag the ball onto A further left, against B further right, then into the basket",
                     ((0.13, 0.30), on_top(along(PLATFORM_A, 0.23), PLATFORM_A), (0.30, 0.50),
                      (along(PLATFORM_B, 0.25), PLATFORM_A[1] - 0.06), under(along(PLATFORM_B, 0.67), PLATFORM_B),
                      (BASKET[3][0] - 0.04, RIM - 0.18), (BASKET_X + 0.02, FLOOR)), 2417)


SCENARIOS = (hits_a, hits_b_once, hits_b_twice, hits_b_bottom, above_b, below_b, a_then_b_bottom,
             a_then_b_bottom_again)
"""Every demonstrated behaviour of the machine."""


def all_scenarios() -> tuple[Scenario, ...]:
    return tuple(make() for make in SCENARIOS)
