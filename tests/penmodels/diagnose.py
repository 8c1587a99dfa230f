"""Which shapes of a hurried drawing the recogniser reads differently from the virtual pen's; no session."""

from __future__ import annotations

from collections.abc import Sequence

from penmodels.journal import Drawn
from physink_tui.scene.recognition.recognize import recognize_stroke, recognize_strokes

Points = Sequence[tuple[float, ...]]


def reading(strokes: Sequence[Points]) -> str:
    """What the recogniser makes of one stroke, or of two that should make an X."""
    pts = [[(p[0], p[1]) for p in stroke] for stroke in strokes]
    if len(pts) == 1:
        r = recognize_stroke(pts[0])
        return r.kind or f"nothing ({r.reason})"
    pair = recognize_strokes(pts)
    if pair.kind == "x":
        return "x"
    kinds = ", ".join(recognize_stroke(s).kind or "nothing" for s in pts)
    return f"no X: {kinds} ({pair.reason})"


def virtual_strokes(scenario) -> list[list[tuple[float, float]]]:
    """The virtual pen's touching positions per stroke of a `scenarios.thesis.Scenario`, in canvas pixels."""
    out: dict[int, list[tuple[float, float]]] = {}
    for s in scenario.pen().samples(scenario.strokes, gap_s=scenario.gap_s):
        if s.phase == "touch":
            out.setdefault(s.stroke, []).append((s.state.x * 1600.0, s.state.y * 1000.0))
    return [out[i] for i in sorted(out)]


def misread(drawn: Sequence[Drawn], virtual: Sequence[Points]) -> list[str]:
    """One line per shape the recogniser read differently from the virtual pen's drawing of it: both pens'
    strokes go through `recognize_stroke` (`recognize_strokes` for an X's two)."""
    out = []
    for d in drawn:
        mine, theirs = reading(d.strokes), reading([virtual[i] for i in d.steps])
        if mine != theirs:
            out.append(f"{d.what}: hurried pen -> {mine}; virtual pen -> {theirs}")
    return out
