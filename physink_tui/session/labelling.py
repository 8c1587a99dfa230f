"""Puts labels on components for the session — typed (``label TARGET TEXT``) or spoken (``label X``, thesis 3.2.5);
which component a spoken label names comes from the pen's recent history (`speech_target.PenWatch`), the words
from the recogniser, and the undoable change from the session's history."""

from __future__ import annotations

from dataclasses import replace
from typing import Protocol

from physink_tui.input.speech.dictionary import guessed_words, unspeakable_words
from physink_tui.scene.components import Body, Rope, Scene, Spring
from physink_tui.scene.physics.live import LiveWorld
from physink_tui.session.history import Document
from physink_tui.session.modes.base import ModeName
from physink_tui.session.outcomes import labelled
from physink_tui.session.speech_target import PenWatch


class LabelHost(Protocol):
    """What labelling needs of the session."""

    canvas: tuple[float, float]
    selected: str | None
    watch: PenWatch

    @property
    def document(self) -> Document: ...

    @property
    def scene(self) -> Scene: ...

    @property
    def mode(self) -> ModeName: ...

    @property
    def last_created(self) -> str | None: ...

    @property
    def world(self) -> LiveWorld: ...

    @property
    def stroke_pending(self) -> bool:
        """A stroke has ended but the sketch has not yet decided what it makes (an X's first half)."""

    def tell(self, text: str, t: float | None = None, kind: str = "note") -> None: ...

    def commit(self, document: Document, description: str) -> None: ...


def spoken_label(host: LabelHost, text: str, t: float) -> None:
    """``label X`` said at ``t`` names the selected component, else the one drawn in the last few seconds, else the
    one being drawn (once it exists), else the one under the hovering pen (thesis 3.2.5). Speech lags the pen: a
    label begun just after one stroke, while the next is under way, is the finished stroke's."""
    watch = host.watch
    if host.selected is not None:
        label(host, host.selected, text)
    elif (recent := watch.recent(t)) is not None and recent in host.scene.components:
        label(host, recent, text)
    elif (watch.drawing and host.mode == ModeName.SKETCH) or host.stroke_pending:
        watch.wait(text, t)
    elif watch.hover is not None and (under := body_under(host, *watch.hover)) is not None:
        label(host, under, text)
    else:
        host.tell(f"label {text!r}: say it while drawing the part or just after, or tap or hover over it first")


def body_under(host: LabelHost, x: float, y: float) -> str | None:
    """The topmost body at canvas fractions (x, y) in the sketch, or None."""
    return host.world.body_at((x * host.canvas[0], y * host.canvas[1]))


def label(host: LabelHost, target: str, text: str) -> None:
    """Label ``target`` (a component id, ``last`` or ``selected``) ``text``, undoably; say why not when it cannot
    be, and when speech will not be able to say the label."""
    component_id = {"last": host.last_created, "selected": host.selected}.get(target, target)
    if component_id is None:
        host.tell(f"label {text!r}: nothing is {target} — tap a body first, or draw one")
        return
    component = host.scene.components.get(component_id)
    if component is None:
        known = ", ".join(host.scene.components) or "none"
        host.tell(f"label {text!r}: there is no component {component_id!r} (components: {known})")
        return
    if not isinstance(component, Body | Rope | Spring):
        host.tell(f"label {text!r}: joints take no labels")
        return
    before = host.scene
    scene = before.update(replace(component, label=text))
    host.commit(replace(host.document, scene=scene), f"label {component_id} {text}")
    host.tell(labelled(before, component_id, text), kind="outcome")
    unsayable = unspeakable_words(text)
    if unsayable:
        host.tell(f"label {text!r}: {', '.join(map(repr, unsayable))} cannot be said (not in the speech "
                  "dictionary); the label is kept, and speech cannot name this part")
    elif guessed := guessed_words(text):
        said = ", ".join(f"{w!r} as {p}" for w, p in guessed.items())
        host.tell(f"label {text!r}: not in the speech dictionary, so speech hears {said} (guessed from the "
                  "spelling)")
