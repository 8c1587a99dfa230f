"""The thesis's machines drawn with the virtual pen (``tests/scenarios/thesis.py``), journalled under
``tests/journals/``: each journal becomes the machine the thesis describes (bodies, joints, springs, ropes,
labels, nothing else said), is exactly what its scenario records, and replays to the same project bytes.

Regenerate the journals with ``python tests/scenarios/make_journals.py`` after changing a drawing.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import pytest
from scenarios.make_journals import journal_path, replayed, write_scenario_journal
from scenarios.thesis import BACKGROUND, Scenario, all_scenarios

from physink_tui.cli import main
from physink_tui.scene.components import Joint, Rope, Scene, Spring
from physink_tui.session.session import Session

SCENARIOS = {s.name: s for s in all_scenarios()}
MAX_JOURNAL_BYTES = 400_000
REGENERATE = "regenerate with `python tests/scenarios/make_journals.py`"


def session_over(name: str) -> Session:
    return replayed(name, journal_path(SCENARIOS[name]))


def described(scene: Scene, names: dict[str, str], told: list[str], expected_messages: tuple[str, ...]) -> dict:
    """The scene in the terms of `thesis.Expected`: bodies by name (their drawing order), joints, springs and
    ropes by the names of what they hold, the fixed bodies, and the messages (an expected one by its
    expected words)."""

    def name(component_id: str | None) -> str | None:
        return component_id if component_id in (None, BACKGROUND) else names.get(component_id, component_id)

    parts = list(scene.components.values())
    messages = [want if want in text else text for text, want in zip(told, expected_messages, strict=False)]
    return {
        "bodies": [(name(b.id), b.shape, b.label) for b in scene.bodies()],
        "joints": in_order((j.kind, name(j.a), name(j.b)) for j in parts if isinstance(j, Joint)),
        "springs": in_order((s.axis, name(s.a), name(s.b), s.label) for s in parts if isinstance(s, Spring)),
        "ropes": in_order((name(r.start_body), name(r.end_body), r.label) for r in parts if isinstance(r, Rope)),
        "fixed": in_order(name(b.id) for b in scene.bodies() if scene.is_fixed(b.id)),
        "messages": messages + told[len(expected_messages):],
    }


def expected(scenario: Scenario) -> dict[str, Any]:
    x = scenario.expect
    return {
        "bodies": [(b.name, b.shape, b.label) for b in x.bodies],
        "joints": in_order((j.kind, j.a, j.b) for j in x.joints),
        "springs": in_order((s.axis, s.fixed, s.other, s.label) for s in x.springs),
        "ropes": in_order((r.start, r.end, r.label) for r in x.ropes),
        "fixed": in_order(x.fixed),
        "messages": list(x.messages),
    }


def in_order(items: Iterable[Any]) -> list[Any]:
    """Sorted the same way on both sides, whatever they hold (None for a free rope end or no label)."""
    return sorted(items, key=lambda item: repr(item))


@pytest.mark.parametrize("name", SCENARIOS)
def test_the_drawing_becomes_the_machine_the_thesis_describes(name: str) -> None:
    scenario = SCENARIOS[name]
    session = session_over(name)
    scene = session.scene
    # bodies are known by their drawing order: the n-th body drawn is the n-th expected one
    names = {b.id: want.name for b, want in zip(scene.bodies(), scenario.expect.bodies, strict=False)}
    told = [m.text for m in session.messages  # the demonstration's are checked apart; each stroke's outcome too
            if m.t < scenario.demo_start and m.kind == "note"]
    actual = described(scene, names, told, scenario.expect.messages)
    assert actual == expected(scenario)
    assert [b.id for b in scene.bodies()] == [f"b{i}" for i in range(1, len(scenario.expect.bodies) + 1)]
    springs = {(names.get(c.a, c.a), names.get(c.b, c.b)): c
               for c in scene.components.values() if isinstance(c, Spring)}
    for want in scenario.expect.springs:
        spring = springs[(want.fixed, want.other)]
        assert scene.is_fixed(spring.a), f"{spring.id}'s first end must hold a fixed body"
        if want.length is not None:  # the sketched length is the natural length (thesis 4.2)
            assert spring.rest_length == pytest.approx(want.length, rel=0.05)


@pytest.mark.parametrize("name", SCENARIOS)
def test_the_stored_journal_is_exactly_what_the_scenario_records(name: str, tmp_path) -> None:
    scenario = SCENARIOS[name]
    stored = journal_path(scenario)
    fresh = write_scenario_journal(scenario, tmp_path / stored.name)
    assert stored.read_bytes() == fresh.read_bytes(), f"{stored} differs from its scenario; {REGENERATE}"
    assert stored.stat().st_size < MAX_JOURNAL_BYTES


@pytest.mark.parametrize("name", SCENARIOS)
def test_replaying_a_thesis_journal_twice_gives_identical_project_files(name: str, tmp_path, capsys) -> None:
    journal = journal_path(SCENARIOS[name])
    for run in ("a", "b"):
        assert main(["replay", str(journal), "--out", str(tmp_path / run)]) == 0
    capsys.readouterr()
    first = (tmp_path / "a" / "project.json").read_bytes()
    assert first == (tmp_path / "b" / "project.json").read_bytes()
    assert b'"physink-project"' in first
