"""The thesis's event chains through the whole pipeline: a journal drawn and demonstrated by a pen model (our virtual
pen, `physink_tui.input.virtual_pen`, or the hurried hand of `tests/penmodels`), replayed by ``physink replay``,
read back from the ``timeline.json`` it writes. The stopper of figure 3-9 with the ball drawn a few pixels into
the stopper or short of it, the egg cracker of figure 3-4, the pinball of figures 3-10 and 3-13, the cup dispenser
of section 4.3. The recorder's own rules are tested on hand-made observations in ``test_recorder.py``; these show
that a session drawn as people draw records them."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest
from penmodels.journal import write_hurried_demonstration
from scenarios.make_journals import journal_path, write_scenario_journal
from scenarios.stopper import DROP, stopper
from scenarios.thesis import Scenario, cup_dispenser, egg_cracker, pinball

from physink_tui.cli import main
from physink_tui.formats.timeline_json import decode_timeline_json
from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.graph import ancestors, descendants


class Replayed:
    """What ``physink replay`` wrote for a journal: the timeline (from timeline.json), the project and what it
    printed of the session's messages."""

    def __init__(self, journal: Path, out: Path, capsys: pytest.CaptureFixture[str]) -> None:
        assert main(["replay", str(journal), "--out", str(out)]) == 0
        self.told = capsys.readouterr().out  # what the session told the user
        self.timeline, names = decode_timeline_json((out / "timeline.json").read_text(encoding="utf-8"))
        self.ids = {label: cid for cid, label in names.items()}
        self.project = json.loads((out / "project.json").read_text(encoding="utf-8"))

    def events(self, kind: str, *labels: str) -> list[Event]:
        """Events of ``kind`` naming every body of ``labels`` (and, for contacts, nothing else)."""
        want = {self.ids[label] for label in labels}
        return [ev for ev in self.timeline.events if ev.type == kind and want <= set(ev.components)
                and (kind == "movement" or len(labels) < 2 or set(ev.components) == want)]

    def movements(self, label: str) -> list[Event]:
        return [ev for ev in self.timeline.events if ev.type == "movement" and ev.components[0] == self.ids[label]]

    def start(self) -> Event:
        (start,) = [ev for ev in self.timeline.events if ev.type == "start"]
        return start

    def cause(self, ev: Event) -> Event:
        (cause,) = ev.causes
        return self.timeline.event(cause)


def virtual(scenario: Scenario, tmp_path: Path) -> Path:
    return write_scenario_journal(scenario, tmp_path / f"{scenario.name}.physink.jsonl")


def hurried(seed: int) -> Callable[[Scenario, Path], Path]:
    def write(scenario: Scenario, tmp_path: Path) -> Path:
        path = tmp_path / f"{scenario.name}-hurried-{seed}.physink.jsonl"
        write_hurried_demonstration(scenario, seed, path)
        return path
    return write


def replay(journal: Path, tmp_path: Path, capsys) -> Replayed:
    return Replayed(journal, tmp_path / "out", capsys)


# -- figure 3-9: the stopper pulled out from under a resting ball -------------------------------------------------

STOPPER_CASES = [pytest.param(into, virtual, id=f"virtual-pen-{'into' if into >= 0 else 'short'}-{abs(into)}px")
                 for into in (-2, -1, 0, 1, 2, 6)]
STOPPER_CASES += [pytest.param(into, hurried(seed), id=f"hurried-{seed}-{'into' if into >= 0 else 'short'}-"
                                                       f"{abs(into)}px")
                  for into in (-2, -1, 0, 1, 2) for seed in (1, 5, 7)]  # 5 and 7: a hook as the pen takes hold


@pytest.mark.parametrize(("into", "drawn_by"), STOPPER_CASES)
def test_pulling_the_stopper_from_under_the_ball_ends_their_contact_which_lets_the_ball_fall(
        into: int, drawn_by, tmp_path, capsys) -> None:
    # the ball drawn `into` px into the stopper's outline (negative: a gap); 6 px is pushed clear when drawn
    run = replay(drawn_by(stopper(into), tmp_path), tmp_path, capsys)
    ball, plug = run.ids["ball"], run.ids["stopper"]
    if drawn_by is virtual:  # 6 px in is more than a small overlap: the ball is pushed clear, flush on the stopper
        assert ("the physics pushed it clear" in run.told) == (into == 6), run.told
    start = run.start()
    assert start.in_contact == (tuple(sorted((ball, plug))),), "the pair begins in contact"
    pulled = run.movements("stopper")[0]
    assert run.cause(pulled) is start
    (ended,) = run.events("end_contact", "stopper", "ball")
    assert ended.causes == (pulled.id,)
    assert not run.events("contact", "stopper", "ball"), "the stopper sliding out from under the ball is no contact"
    falls = run.movements("ball")
    assert falls and all(ev.causes == (ended.id,) for ev in falls), "the end of contact lets the ball move"
    dragged = max(p.y for ev in falls for p in ev.trajectory) - min(p.y for ev in falls for p in ev.trajectory)
    assert dragged > 0.6 * DROP * 1000, "the ball's fall is that movement's trajectory"
    first = [e for e in run.timeline.events if e.type != "start"][:3]
    assert [(e.type, e.components[0]) for e in first] == [("movement", plug), ("end_contact", ended.components[0]),
                                                          ("movement", first[2].components[0])]


# -- figure 3-4: the egg cracker ----------------------------------------------------------------------------------

@pytest.mark.parametrize("drawn_by", [
    pytest.param(None, id="virtual-pen-stored-journal"),
    pytest.param(hurried(5), id="hurried-5"),  # seeds whose knife reaches the egg (others miss it)
])
def test_the_egg_cracker_chain_runs_from_the_ball_to_the_egg_in_the_pan(drawn_by, tmp_path, capsys) -> None:
    scenario = egg_cracker()
    journal = journal_path(scenario) if drawn_by is None else drawn_by(scenario, tmp_path)
    run = replay(journal, tmp_path, capsys)
    (hit,) = run.events("contact", "ball", "lever")
    assert run.cause(run.cause(hit)) is run.start()  # start -> movement of ball -> contact
    lever = next(ev for ev in run.events("movement", "lever") if hit.id in ev.causes)
    assert {run.ids["rope"], run.ids["knife"]} <= set(lever.components)  # the lever pulls the rope and knife
    (knife,) = run.events("contact", "knife", "egg")
    assert lever.id in knife.causes or lever.id in ancestors(run.timeline, knife.id)
    (landing,) = run.events("contact", "egg", "pan")
    assert dict(landing.sides)[run.ids["pan"]] == "inside"
    chain = ancestors(run.timeline, landing.id)
    assert {hit.id, knife.id} <= chain
    assert any(run.events("contact", "egg", paddle)[0].id in chain for paddle in ("left paddle", "right paddle")
               if run.events("contact", "egg", paddle))


# -- figures 3-10 and 3-13: the pinball -------------------------------------------------------------------------

@pytest.mark.parametrize("drawn_by", [
    pytest.param(None, id="virtual-pen-stored-journal"),
    pytest.param(hurried(2), id="hurried-2"),
    pytest.param(hurried(3), id="hurried-3"),
])
def test_the_pinball_hits_paddle_a_then_paddle_b_and_the_second_ball_is_unrelated(drawn_by, tmp_path,
                                                                                  capsys) -> None:
    scenario = pinball()
    journal = journal_path(scenario) if drawn_by is None else drawn_by(scenario, tmp_path)
    run = replay(journal, tmp_path, capsys)
    a = run.events("contact", "ball", "paddle a")[0]
    b = run.events("contact", "ball", "paddle b")[0]
    assert run.cause(run.cause(a)) is run.start()
    between = run.cause(b)
    assert between.components[0] == run.ids["ball"] and a.id in ancestors(run.timeline, b.id)
    assert any(ev.causes == (b.id,) for ev in run.movements("paddle b"))  # B turns
    (two,) = run.movements("ball two")
    assert run.cause(two) is run.start()  # figure 3-14: unrelated to the first ball's events
    if drawn_by is None:  # the assisted edit (figure 3-17): the ball now leaves B to the right, missing C
        assert not run.events("contact", "ball", "paddle c")


# -- section 4.3: the cup dispenser -----------------------------------------------------------------------------

@pytest.mark.parametrize("drawn_by", [
    pytest.param(None, id="virtual-pen-stored-journal"),
    *(pytest.param(hurried(seed), id=f"hurried-{seed}") for seed in (1, 2, 3)),
])
def test_the_cup_dispenser_platform_weighed_down_ends_its_contact_with_the_peg_which_moves(drawn_by, tmp_path,
                                                                                           capsys) -> None:
    scenario = cup_dispenser()
    journal = journal_path(scenario) if drawn_by is None else drawn_by(scenario, tmp_path)
    run = replay(journal, tmp_path, capsys)
    ids = run.ids
    start = run.start()
    assert tuple(sorted((ids["platform"], ids["peg"]))) in start.in_contact  # drawn flush: they begin in contact
    released = min(run.events("end_contact", "platform", "peg"), key=lambda e: e.t0)
    weighed = run.cause(released)
    assert weighed.type == "movement" and weighed.components[0] == ids["platform"]
    chain = ancestors(run.timeline, released.id)
    assert run.events("contact", "ball", "cup")[0].id in chain  # the ball lands in the cup ...
    assert run.events("contact", "cup", "platform")[0].id in chain  # ... which presses the platform down
    peg = run.movements("peg")[0]
    assert peg.causes == (released.id,)  # not an exogenous force: the end of contact lets the peg go
    pushed = descendants(run.timeline, released.id)
    assert any(ev.id in pushed for ev in run.events("contact", "cup", "peg"))  # and the peg pushes the cup off


def test_a_timeline_with_no_pair_in_contact_at_the_start_names_none(tmp_path, capsys) -> None:
    run = replay(journal_path(egg_cracker()), tmp_path, capsys)
    assert run.start().in_contact == () and not [e for e in run.timeline.events if e.type == "end_contact"]
    assert isinstance(run.timeline, Timeline) and run.project["version"] == 2
