"""The ball-and-platforms machine as first drawn (tests/scenarios/bouncing.py before commit 0909bba), kept so that
SIMULATE is measured on a drawing nobody redrew for it (issue 27): B lower and further right, the basket's rim 36 canvas
units right of B's end. Its eight demonstrations are named ``bouncing_first_<behaviour>`` and recorded into
tests/journals/restored/ (`make_journals`). Its drawing and paths are the first drawing's, unchanged; the shared code is
bouncing.py's.

"Consider the simple mechanism in Figure 2-12, where a ball can take a number of different paths before landing in
a basket" (thesis 2.4). The machine is drawn once (`machine`): the ball top left, platform A on the left, platform B
to its right and higher, and the basket, an open cup, at the bottom right; the platforms and the basket welded to
the background. Each demonstration drags the ball along one stroke: a sharp corner of the stroke is where the pen
bounces the ball off a platform, and the stroke ends with the ball resting on the basket's floor.
"""

from __future__ import annotations

from scenarios.bouncing import PRESS, RADIUS, Point, demonstration, drawn_machine, on_top, under
from scenarios.thesis import Expected, Scenario, Step

PLATFORM_A = (0.14, 0.62, 0.40, 0.665)
"""Platform A: left, top, right, bottom (tablet fractions)."""
PLATFORM_B = (0.50, 0.34, 0.74, 0.385)
"""Platform B, right of A and higher."""
BASKET = ((0.76, 0.68), (0.78, 0.90), (0.94, 0.90), (0.96, 0.68))
"""The basket's outline: an open cup, rim first."""
FLOOR = BASKET[1][1] - RADIUS + PRESS
"""Where the pen leaves the ball in the basket: pressed onto its floor, as onto a platform."""


def machine() -> tuple[tuple[Step, ...], Expected]:
    """The first drawing (thesis figure 2-12) and the scene it must become."""
    return drawn_machine(PLATFORM_A, PLATFORM_B, BASKET, ((0.27, 0.6425), (0.62, 0.3625), (0.86, 0.90)))


def _scenario(behaviour: str, source: str, what: str, path: tuple[Point, ...], seed: int) -> Scenario:
    return demonstration(f"bouncing_first_{behaviour}", machine(), source, what, path, seed)


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
