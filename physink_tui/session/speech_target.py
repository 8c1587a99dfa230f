"""Which component a spoken ``label X`` names (thesis 3.2.5): the selected one, else the one drawn in the last few
seconds, else the one being drawn, else the one under the hovering pen; recognising speech and changing the scene
are left to others (the recogniser, the session).

The session feeds it the pen's gestures and the components its strokes make (`PenWatch.gesture`, `PenWatch.made`);
`PenWatch.recent` names the component drawn in the last few seconds before an utterance at time t and
`PenWatch.hover` where the pen hovers (`labelling.spoken_label` decides among them). A label said while a stroke is
being drawn waits for the component that stroke makes (`PenWatch.wait`, `PenWatch.take_waiting`).
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.input.pen.gestures import Gesture, PenDown, PenMove, ProximityChanged, StrokeEnded, Tap

RECENT = 5.0
"""Seconds after a component was drawn during which ``label X`` still names it."""


@dataclass(frozen=True, slots=True)
class Waiting:
    """A spoken label waiting for the stroke being drawn to become a component.

    Attributes:
        text: the label.
        t: when it was said (seconds, input time).
    """

    text: str
    t: float


class PenWatch:
    """What the pen is doing, as far as spoken labels care: drawing, hovering where, and what it made when."""

    def __init__(self) -> None:
        self.drawing = False
        self.hover: tuple[float, float] | None = None  # canvas fractions, while the pen hovers in range
        self.created: tuple[str, float] | None = None  # the last component a stroke made, and when
        self.waiting: Waiting | None = None

    def gesture(self, g: Gesture) -> None:
        if isinstance(g, PenDown):
            self.drawing, self.hover = True, None
        elif isinstance(g, StrokeEnded | Tap):
            self.drawing = False
        elif isinstance(g, PenMove):
            self.drawing = g.touching
            self.hover = None if g.touching else (g.x, g.y)
        elif isinstance(g, ProximityChanged) and not g.in_range:
            self.drawing, self.hover = False, None

    def made(self, component_id: str, t: float) -> None:
        """A stroke made ``component_id`` at ``t``."""
        self.created = (component_id, t)

    def recent(self, t: float) -> str | None:
        """The component drawn within `RECENT` seconds before ``t``, or None."""
        if self.created is not None and t - self.created[1] <= RECENT:
            return self.created[0]
        return None

    def wait(self, text: str, t: float) -> None:
        self.waiting = Waiting(text, t)

    def take_waiting(self) -> Waiting | None:
        waiting, self.waiting = self.waiting, None
        return waiting
