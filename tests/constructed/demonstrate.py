"""A layout drawn and a path demonstrated on it, by the virtual pen or the hurried hand (tests/penmodels): the
session they end in; no generation, no search.

The demonstration drags the ball along ``path`` (canvas units) in demo mode, one stroke from the ball's centre; the
stroke's sharp corners are where the pen presses the ball onto a surface (as tests/scenarios/bouncing.py does).
"""

from __future__ import annotations

from dataclasses import replace

from penmodels.journal import header as hurried_header
from penmodels.journal import hurried_drawing
from scenarios.thesis import MAPPING, Scenario, Step

from constructed.layouts import Layout, frac
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import Stroke
from physink_tui.scene.components import Scene
from physink_tui.session.session import Session

PENS = ("virtual", "hurried")
SETTLE_S = 1.0
"""Seconds after the demonstration's stroke before demo mode ends."""


def scenario(layout: Layout, path: tuple[tuple[float, float], ...], seed: int, name: str = "constructed") -> Scenario:
    """The virtual pen's scenario: the drawing, then (when ``path`` is not empty) the demonstration."""
    demo = (Step("drag the ball", Stroke(tuple(frac(p) for p in path))),) if path else ()
    return Scenario(name, "tests/constructed", layout.steps(), layout.expected(), seed=seed, demo=demo,
                    settle_s=SETTLE_S)


def session(layout: Layout, path: tuple[tuple[float, float], ...], pen: str, seed: int) -> Session:
    """The session of ``layout`` drawn and ``path`` demonstrated (none when empty) by ``pen`` seeded ``seed``."""
    if pen == "virtual":
        sc = scenario(layout, path, seed)
        capture = sc.capture()
        entries = sorted([*capture_entries(capture), *sc.spoken_and_typed()], key=lambda e: e.t)
        return Session.from_header(header_for_capture(capture, MAPPING)).run(entries)
    if pen != "hurried":
        raise ValueError(f"unknown pen {pen!r}; expected one of {PENS}")
    steps = list(layout.steps())
    if path:
        steps[-1] = replace(steps[-1], commands=(*steps[-1].commands, ("mode", ("demo",))))
        steps.append(Step("drag the ball", Stroke(tuple(frac(p) for p in path))))
    entries, _ = hurried_drawing(steps, seed)
    if path:
        entries.append(CommandEntry(round(entries[-1].t + SETTLE_S, 6), "mode", ("sketch",)))
    return Session.from_header(hurried_header()).run(entries)


def recognised(layout: Layout, scene: Scene) -> bool:
    """Whether the session made the drawing's bodies: the ball, every platform and the basket, labelled, the
    platforms and basket welded and the ball free."""
    got = sorted((b.shape, b.label or "", scene.is_fixed(b.id)) for b in scene.bodies())
    want = sorted([("circle", "ball", False), ("polyline", "basket", True),
                   *(("box", p.name, True) for p in layout.platforms)])
    return got == want


def body_id(scene: Scene, label: str) -> str:
    return next(b.id for b in scene.bodies() if b.label == label)
