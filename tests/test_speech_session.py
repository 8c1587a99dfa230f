"""Spoken ``label X`` in the session (thesis 3.2.5): the selected component, else the one drawn in the last few
seconds, else the one being drawn (once it exists), else the one under the hovering pen; journaled `say` lines
replay the same."""

from __future__ import annotations

import itertools

from physink_tui.formats.journal.entries import JournalHeader, PenEntry, SayEntry
from physink_tui.session.session import Session
from physink_tui.session.speech_target import RECENT


def _header() -> JournalHeader:
    return JournalHeader(1600, 1000, (), {}, 0.05, 0.01)


def _box(x0: float, y0: float, x1: float, y1: float, n: int = 15) -> list[tuple[float, float]]:
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    pts = []
    for (ax, ay), (bx, by) in itertools.pairwise(corners):
        pts += [(ax + (bx - ax) * k / n, ay + (by - ay) * k / n) for k in range(n)]
    return [*pts, corners[0]]


def _stroke(t0: float, points: list[tuple[float, float]], dt: float = 0.01) -> list[PenEntry]:
    out = [PenEntry(t0, *points[0], 0.0, False, True, False, False, False)]
    out += [PenEntry(t0 + i * dt, x, y, 0.6, True, True, False, False, False) for i, (x, y) in enumerate(points, 1)]
    out.append(PenEntry(t0 + (len(points) + 1) * dt, *points[-1], 0.0, False, True, False, False, False))
    return out


def _hover(t: float, x: float, y: float) -> PenEntry:
    return PenEntry(t, x, y, 0.0, False, True, False, False, False)


def _away(t: float) -> PenEntry:
    return PenEntry(t, 0.5, 0.5, 0.0, False, False, False, False, False)


def _run(entries: list) -> Session:
    return Session.from_header(_header()).run(sorted(entries, key=lambda e: e.t))


def _labels(session: Session) -> dict[str, str | None]:
    return {c.id: c.label for c in session.scene.bodies()}


def test_a_label_said_while_drawing_waits_for_the_component_the_stroke_makes() -> None:
    stroke = _stroke(0.0, _box(0.1, 0.1, 0.3, 0.3))
    session = _run([*stroke, SayEntry(0.2, "label crate"), _away(2.0)])
    assert _labels(session) == {"b1": "crate"}


def test_a_label_said_just_after_drawing_names_what_was_drawn_even_while_the_next_stroke_starts() -> None:
    first = _stroke(0.0, _box(0.1, 0.1, 0.3, 0.3))
    second = _stroke(1.5, _box(0.5, 0.5, 0.7, 0.7))
    session = _run([*first, *second, SayEntry(1.6, "label crate"), _away(4.0)])
    assert _labels(session) == {"b1": "crate", "b2": None}


def test_later_a_label_names_the_body_under_the_hovering_pen() -> None:
    entries = [*_stroke(0.0, _box(0.1, 0.1, 0.3, 0.3)), *_stroke(1.0, _box(0.5, 0.5, 0.7, 0.7))]
    said = 2.0 + RECENT + 1
    entries += [_hover(said - 0.5, 0.2, 0.2), _hover(said - 0.1, 0.21, 0.2), SayEntry(said, "label crate")]
    session = _run(entries)
    assert _labels(session) == {"b1": "crate", "b2": None}


def test_later_with_the_pen_away_nothing_is_labelled_and_the_user_is_told() -> None:
    entries = [*_stroke(0.0, _box(0.1, 0.1, 0.3, 0.3)), _away(1.0), SayEntry(2.0 + RECENT, "label crate")]
    session = _run(entries)
    assert _labels(session) == {"b1": None}
    assert "tap or hover over it first" in session.messages[-1].text


def test_the_selected_body_comes_first() -> None:
    entries = [*_stroke(0.0, _box(0.1, 0.1, 0.3, 0.3)), *_stroke(1.0, _box(0.5, 0.5, 0.7, 0.7))]
    entries += [PenEntry(2.0, 0.2, 0.2, 0.0, False, True, False, False, False),
                PenEntry(2.01, 0.2, 0.2, 0.5, True, True, False, False, False),
                PenEntry(2.05, 0.2, 0.2, 0.0, False, True, False, False, False),
                SayEntry(2.2, "label crate")]
    assert _labels(_run(entries)) == {"b1": "crate", "b2": None}


def test_a_stroke_that_makes_nothing_is_told() -> None:
    stroke = _stroke(0.0, [(0.5, 0.5), (0.5005, 0.5), (0.5, 0.5005)] * 3)  # a dot: no component
    session = _run([*stroke, SayEntry(0.03, "label crate"), _away(3.0)])
    assert not session.scene.components
    assert any("made no component to label" in m.text for m in session.messages)


def test_a_typed_label_the_dictionary_lacks_is_kept_and_reported_as_not_speakable() -> None:
    from physink_tui.formats.journal.entries import CommandEntry

    entries = [*_stroke(0.0, _box(0.1, 0.1, 0.3, 0.3)), CommandEntry(1.0, "label", ("b1", "zorblax crate"))]
    session = _run(entries)
    assert _labels(session) == {"b1": "zorblax crate"}
    assert "'zorblax' as Z AO R B L AH K S (guessed from the spelling)" in session.messages[-1].text


def test_a_typed_label_no_pronunciation_can_be_guessed_for_is_kept_and_reported_as_not_speakable() -> None:
    from physink_tui.formats.journal.entries import CommandEntry

    entries = [*_stroke(0.0, _box(0.1, 0.1, 0.3, 0.3)), CommandEntry(1.0, "label", ("b1", "crate r2d2"))]
    session = _run(entries)
    assert _labels(session) == {"b1": "crate r2d2"}
    assert "'r2d2' cannot be said" in session.messages[-1].text
