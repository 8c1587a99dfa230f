"""The thesis's parameter grid (3.4.5), the baseline SIMULATE is measured against; it runs nothing itself.

"Parameters are adjusted one at a time so that all combinations of values can be tried": every combination of the
grid values of every parameter, in odometer order (the first coordinate changes fastest: initial velocities, then
masses and frictions by body, then natural lengths and spring constants by spring), `GENERATION` combinations at
a time. The values (`grid_values`): an initial velocity's angle from -45° to +45° of the seeded one in 15° steps
and a spring's natural length from l0/2 to 2·l0 in l0/4 steps (thesis 3.4.5). Steps the thesis does not give,
chosen here: an initial velocity's magnitude x0.5…x2 of the seeded one in x0.25 steps (like the natural length;
`ZERO_SPEEDS` for a velocity seeded at 0); mass and spring constant x¼, x½, x1, x2, x4 of the seeded one; friction
0 to 1 in 0.25 steps. The search stops early once a candidate is qualitatively equivalent (the thesis halts once
the qualitative score crosses a threshold), else at its budget or after the last combination.
"""

from __future__ import annotations

import math

from physink_tui.errors import SimulationError
from physink_tui.sim.coordinates import Coordinate, coordinates, get_value, set_value
from physink_tui.sim.evaluate import Score
from physink_tui.sim.parameters import Parameters

ANGLE_STEPS = tuple(range(-45, 46, 15))
"""Degrees added to a seeded velocity's angle (thesis 3.4.5)."""
MAGNITUDE_FACTORS = (0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0)
"""Factors of a seeded speed (not in the thesis: the natural length's steps)."""
ZERO_SPEEDS = (0.0, 100.0, 200.0, 300.0, 400.0)
"""Speeds tried for a velocity seeded at 0 (units/s; not in the thesis)."""
LENGTH_FACTORS = (0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0)
"""Factors of a seeded natural length l0: l0/2 to 2·l0 in l0/4 steps (thesis 3.4.5)."""
SCALE_FACTORS = (0.25, 0.5, 1.0, 2.0, 4.0)
"""Factors of a seeded mass or spring constant (not in the thesis)."""
FRICTIONS = (0.0, 0.25, 0.5, 0.75, 1.0)
"""Frictions tried (not in the thesis)."""
GENERATION = 16
"""Combinations handed out at a time (a generation the executor evaluates in parallel)."""


def grid_values(kind: str, seeded: float) -> tuple[float, ...]:
    """The thesis grid's values of one parameter seeded at ``seeded`` (an angle in radians for "angle")."""
    if kind == "angle":
        return tuple(seeded + math.radians(d) for d in ANGLE_STEPS)
    if kind == "speed":
        return ZERO_SPEEDS if seeded == 0 else tuple(seeded * f for f in MAGNITUDE_FACTORS)
    if kind == "rest_length":
        return tuple(seeded * f for f in LENGTH_FACTORS)
    if kind in ("mass", "k"):
        return tuple(seeded * f for f in SCALE_FACTORS)
    if kind == "friction":
        return FRICTIONS
    raise SimulationError(f"no grid for {kind!r}")


class ThesisGrid:
    """Every combination of the grid values around ``start``, in odometer order (see the module docstring)."""

    def __init__(self, start: Parameters) -> None:
        self.start = start
        self.coords: tuple[Coordinate, ...] = tuple(coordinates(start, ("angle", "speed")))
        self.values = tuple(grid_values(c.kind, get_value(start, c)) for c in self.coords)
        self.combinations = math.prod(len(v) for v in self.values)
        self.index = 0

    @property
    def finished(self) -> bool:
        return self.index >= self.combinations

    def combination(self, index: int) -> Parameters:
        """The ``index``-th combination (0-based; the first coordinate is the fastest digit)."""
        chosen: dict[Coordinate, float] = {}
        for c, values in zip(self.coords, self.values, strict=True):
            index, digit = divmod(index, len(values))
            chosen[c] = values[digit]
        p = self.start
        for c in sorted(chosen, key=lambda c: c.kind == "angle"):  # a speed before its angle: 0 has no direction
            p = set_value(p, c, chosen[c])
        return p

    def generation(self, best: Parameters | None) -> list[Parameters]:
        del best  # the grid does not move with the best
        end = min(self.index + GENERATION, self.combinations)
        out = [self.combination(i) for i in range(self.index, end)]
        self.index = end
        return out

    def told(self, generation: list[Parameters], scores: list[Score]) -> None:
        pass
