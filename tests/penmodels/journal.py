"""A scenario's drawing by the hurried pen as journal ``pen`` lines plus what is said and typed, for a session."""

from __future__ import annotations

import os
import random
from collections.abc import Sequence
from dataclasses import dataclass, replace

from penmodels.hurried import HurriedPen, PenPoint, touching
from penmodels.shapes import CANVAS, Shape, group_scenario_strokes
from physink_tui.formats.journal.entries import CommandEntry, JournalEntry, JournalHeader, PenEntry, SayEntry
from physink_tui.input.journal_compose import write_journal
from physink_tui.session.session import Session

SPEECH_DELAY = 0.12
"""Seconds after the pen leaves range at which a step's utterances and commands come (then this far apart)."""


@dataclass(frozen=True, slots=True)
class Drawn:
    """One shape as the hurried pen drew it.

    Attributes:
        steps: indices of the scenario steps it stands for (two for an X).
        what: the steps' descriptions.
        shape: the shape meant, in canvas pixels.
        strokes: per pen-down, the ``(x, y, t)`` the tip touched (canvas pixels, seconds).
    """

    steps: tuple[int, ...]
    what: str
    shape: Shape
    strokes: tuple[tuple[tuple[float, float, float], ...], ...]


def header() -> JournalHeader:
    """A journal header for the scenarios' canvas with no HID devices (only ``pen`` lines)."""
    return JournalHeader(CANVAS[0], CANVAS[1], (), {}, 0.05, 0.01)


def _entry(r: PenPoint) -> PenEntry:
    x = min(max(r.x / CANVAS[0], 0.0), 1.0)
    y = min(max(r.y / CANVAS[1], 0.0), 1.0)
    return PenEntry(round(r.t, 6), round(x, 7), round(y, 7), round(r.p, 4), r.tip, r.in_range, False, False, False)


def hurried_drawing(steps: Sequence, seed: int, start_t: float = 0.3) -> tuple[list[JournalEntry], list[Drawn]]:
    """Journal entries for the scenario ``steps`` drawn by the hurried pen seeded ``seed``, and what it drew.

    Each step needs ``what``, ``stroke.points`` (tablet fractions), ``say`` and ``commands`` (`scenarios.thesis.Step`).
    """
    rng = random.Random(seed)
    pen = HurriedPen(rng)
    entries: list[JournalEntry] = []
    drawn: list[Drawn] = []
    free_at = start_t  # when the pen may next come into range
    for indices, shape in group_scenario_strokes([step.stroke.points for step in steps]):
        strokes = pen.draw(shape, free_at + 0.05)  # hovering in takes at most 8 reports (0.04 s)
        for reports in strokes:
            entries += [_entry(r) for r in reports]
        drawn.append(Drawn(indices, "; ".join(steps[i].what for i in indices), shape,
                           tuple(tuple(touching(r)) for r in strokes)))
        t = strokes[-1][-1].t
        last = steps[indices[-1]]
        for text in last.say:
            t += SPEECH_DELAY
            entries.append(SayEntry(round(t, 6), text))
        for name, args in last.commands:
            t += SPEECH_DELAY
            entries.append(CommandEntry(round(t, 6), name, args))
        free_at = t + rng.uniform(0.25, 0.7)
    return entries, drawn


def hurried_session(steps: Sequence, seed: int) -> tuple[Session, list[JournalEntry], list[Drawn]]:
    """The session the hurried drawing of ``steps`` ends in, the entries fed to it, and what was drawn."""
    entries, drawn = hurried_drawing(steps, seed)
    return Session.from_header(header()).run(entries), entries, drawn


def write_hurried_journal(steps: Sequence, seed: int, path: str | os.PathLike[str]) -> None:
    """Write the hurried drawing of ``steps`` as a journal at ``path`` (which must not exist), to replay with
    ``physink replay PATH --out DIR`` or open in the TUI."""
    entries, _ = hurried_drawing(steps, seed)
    write_journal(path, header(), entries)


def demonstration_entries(scenario, seed: int) -> list[JournalEntry]:
    """A `scenarios.thesis.Scenario` drawn and then demonstrated by the hurried pen seeded ``seed``: its drawing,
    ``mode demo`` after the last drawing step, the demonstration, and ``mode sketch`` `settle_s` after it."""
    steps = list(scenario.steps)
    last = steps[-1]
    steps[-1] = replace(last, commands=(*last.commands, ("mode", ("demo",))))
    entries, _ = hurried_drawing((*steps, *scenario.demo), seed)
    entries.append(CommandEntry(round(entries[-1].t + scenario.settle_s, 6), "mode", ("sketch",)))
    return entries


def write_hurried_demonstration(scenario, seed: int, path: str | os.PathLike[str]) -> None:
    """Write `demonstration_entries` as a journal at ``path`` (which must not exist), for ``physink replay``."""
    write_journal(path, header(), demonstration_entries(scenario, seed))
