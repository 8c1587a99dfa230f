"""Words for what a stroke or a label made of the sketch ("circle → body b3", "X → platform b2 fixed", "erased box b4
— u to undo"), one line each, for the session's messages; reads scenes, changes nothing.

>>> from physink_tui.scene.components import MATERIALS, Body
>>> body = Body("b2", "box", ((-150, -6), (150, -6), (150, 6), (-150, 6)), 0.0, (800, 500), 0.0, MATERIALS["box"])
>>> called(Scene().add(body), "b2")
'platform b2'
"""

from __future__ import annotations

from physink_tui.scene.components import BACKGROUND, Body, Joint, Rope, Scene, Spring
from physink_tui.scene.interpretation.interpret import Interpretation

PLATFORM_ASPECT = 4.0
"""A box at least this many times longer than it is thick is called a platform."""
UNDO_HINT = "u to undo"
"""How an erase reminds the user that it can be taken back (the TUI's undo key)."""
KIND_WORDS = {"x": "X", "line": "line", "polyline": "polyline", "box": "box", "polygon": "polygon",
              "circle": "circle", "ellipse": "ellipse", "curve": "curve", "arc": "arc", "helix": "helix"}
"""How a message names what a stroke was recognised as."""


def called(scene: Scene, component_id: str) -> str:
    """How an outcome names a component: its label or its kind of shape, then its id (``platform b2``,
    ``ball b1``, ``the background``)."""
    if component_id == BACKGROUND:
        return "the background"
    component = scene.components.get(component_id)
    if component is None:
        return component_id
    label = getattr(component, "label", None)
    if label:
        return f"{label} {component_id}"
    if isinstance(component, Body):
        return f"{_shape_word(component)} {component_id}"
    if isinstance(component, Rope):
        return f"rope {component_id}"
    if isinstance(component, Spring):
        return f"spring {component_id}"
    if isinstance(component, Joint):
        return f"{'weld' if component.kind == 'weld' else 'pin'} {component_id}"
    return component_id


def _shape_word(body: Body) -> str:
    if body.shape == "box" and body.outline:
        xs, ys = [p[0] for p in body.outline], [p[1] for p in body.outline]
        w, h = max(xs) - min(xs), max(ys) - min(ys)
        if min(w, h) > 0 and max(w, h) >= PLATFORM_ASPECT * min(w, h):
            return "platform"
    if body.shape == "polyline" and len(body.outline) == 2:
        return "line"
    return body.shape


def stroke_outcome(kind: str | None, result: Interpretation, before: Scene) -> str | None:
    """What a stroke recognised as ``kind`` did (``result``, applied to ``before``), or None when it made nothing
    (the interpretation's own message says why)."""
    after = result.scene
    what = KIND_WORDS.get(kind or "", kind or "stroke")
    if result.action == "erase" and result.removed:
        return erased(before, result.removed)
    if result.action == "body" and result.created:
        bodies = [i for i in result.created if isinstance(after.components.get(i), Body)]
        if len(bodies) == 1:
            return f"{what} → body {bodies[0]}"
        return f"{what} → bodies {', '.join(bodies)}"
    created = [after.components[i] for i in result.created if i in after.components]
    if not created:
        return None
    made = created[0]
    if isinstance(made, Joint) and made.kind == "weld":
        if made.b == BACKGROUND:
            return f"{what} → {called(after, made.a)} fixed"
        return f"{what} → {called(after, made.a)} welded to {called(after, made.b)}"
    if isinstance(made, Joint):
        return f"{what} → pin {made.id}: {called(after, made.a)} turns on {called(after, made.b)}"
    if isinstance(made, Spring):
        return (f"{what} → spring {made.id} ({made.axis}) from {called(after, made.a)} to "
                f"{called(after, made.b)}")
    if isinstance(made, Rope):
        ends = [called(after, e) for e in (made.start_body, made.end_body) if e is not None]
        held = f"tied to {' and '.join(ends)}" if ends else "both ends free"
        return f"{what} → rope {made.id}, {held}"
    return None


def erased(before: Scene, removed: tuple[str, ...]) -> str:
    """``erased box b4 — u to undo`` (with what held on to it, when that went too)."""
    first, rest = removed[0], removed[1:]
    also = f" and {', '.join(rest)}" if rest else ""
    return f"erased {called(before, first)}{also} — {UNDO_HINT}"


def labelled(scene: Scene, component_id: str, text: str) -> str:
    """``label 'ball' → circle b3`` (``scene`` before the label)."""
    return f"label {text!r} → {called(scene, component_id)}"
