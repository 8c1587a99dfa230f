"""Where a simulation's contacts differ from the drawing's (issue 27): the metric compares contact sides, not
positions, so an equivalent simulation may meet a surface far from where the pen did ("the ball meets the platform
a at its right corner, not at its middle as you showed"); no search, no I/O.

A contact's place on the touched body is read in the body's own frame, along its longer extent (left to right
for a wide body, top to bottom for a tall one): at a corner (within `CORNER_SHARE` of the body's length of one of
its outline's vertices), else near an end (the outer `END_SHARE` of its length), at its middle (the middle
`MIDDLE_SHARE`), or a share of the way from the start of that extent. Two places are told apart only when the points
lie more than `APART_SHARE` of the body's length apart, so that a contact a little off the pen's is not reported.
The touched body is the contact's body other than its mover (`evaluate.mover`); round bodies are not described
(they have no ends).
"""

from __future__ import annotations

import math

from physink_tui.scene.components import Body, Scene
from physink_tui.sim.evaluate import mover
from physink_tui.timeline.equivalence import Comparison
from physink_tui.timeline.events import Event, Timeline

CORNER_SHARE = 0.08
END_SHARE = 0.2
MIDDLE_SHARE = 0.2
APART_SHARE = 0.25


def differences_in_place(scene: Scene, demonstrated: Timeline, simulated: Timeline,
                         comparison: Comparison) -> tuple[str, ...]:
    """One sentence per matched contact whose simulated point lies far from the demonstrated one, in the
    demonstration's comparison order."""
    names = scene.names()
    out = []
    for a_id, b_id in comparison.matches:
        a, b = demonstrated.event(a_id), simulated.event(b_id)
        if a.type != "contact" or b.type != "contact" or a.point is None or b.point is None:
            continue
        text = _difference(scene, demonstrated, a, b, names)
        if text:
            out.append(text)
    return tuple(out)


def _difference(scene: Scene, timeline: Timeline, a: Event, b: Event, names: dict[str, str]) -> str | None:
    moving = mover(timeline, a)
    touched = next((c for c in a.components if c != moving), None)
    body = scene.components.get(touched) if touched is not None else None
    if not isinstance(body, Body) or body.shape == "circle" or not body.outline or a.point is None or b.point is None:
        return None
    length, shown = place(body, a.point)
    _, made = place(body, b.point)
    if math.dist(a.point, b.point) <= APART_SHARE * length or shown == made:
        return None
    who, what = names.get(moving) or moving, names.get(body.id) or body.id
    return f"the {who} meets the {what} {made}, not {shown} as you showed"


def place(body: Body, point: tuple[float, float]) -> tuple[float, str]:
    """The body's length along its longer extent and where on it ``point`` lies, in words ("at its right
    corner", "near its left end", "at its middle", "40% of the way from its left end")."""
    c, s = math.cos(body.angle), math.sin(body.angle)
    dx, dy = point[0] - body.position[0], point[1] - body.position[1]
    local = (dx * c + dy * s, -dx * s + dy * c)
    xs = [x for x, _ in body.outline]
    ys = [y for _, y in body.outline]
    wide = max(xs) - min(xs) >= max(ys) - min(ys)
    lo, hi = (min(xs), max(xs)) if wide else (min(ys), max(ys))
    length = max(hi - lo, 1e-9)
    u = ((local[0] if wide else local[1]) - lo) / length
    low, high = ("left", "right") if wide else ("top", "bottom")
    near = min(body.outline, key=lambda v: math.dist(v, local))
    if math.dist(near, local) <= CORNER_SHARE * length:
        vu = ((near[0] if wide else near[1]) - lo) / length
        return length, f"at its {low if vu < 0.5 else high} corner"
    if u < END_SHARE:
        return length, f"near its {low} end"
    if u > 1 - END_SHARE:
        return length, f"near its {high} end"
    if abs(u - 0.5) <= MIDDLE_SHARE / 2:
        return length, "at its middle"
    return length, f"{round(u * 100)}% of the way from its {low} end"
