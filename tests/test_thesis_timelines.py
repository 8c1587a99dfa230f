"""The thesis machines' demonstrations (``tests/journals/``, drawn and demonstrated with the virtual pen) give
the timelines the thesis describes: the egg cracker's figure 3-4, the pinball's assisted edit with the second ball
untouched (figures 3-14 to 3-18), the basketball's concurrent movement (figure 4-2), the cup dispenser's
end-contact (section 4.3) and the golf ball helper's chain (section 4.2); and each replays to identical files."""

from __future__ import annotations

import pytest
from scenarios.bouncing import all_scenarios as bouncing_scenarios
from scenarios.make_journals import journal_path, replayed
from scenarios.thesis import PINBALL_EDIT_T, all_scenarios
from test_thesis_scenarios import session_over

from physink_tui.cli import main
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.session.session import Session
from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.graph import ancestors, check_acyclic, descendants
from physink_tui.timeline.narrate import timeline_text

SCENARIOS = {s.name: s for s in all_scenarios()}


def names_of(session: Session) -> dict[str, str]:
    return session.scene.names()


def text_of(name: str) -> list[str]:
    session = session_over(name)
    return timeline_text(session.timeline, names_of(session)).splitlines()


def by_label(session: Session) -> dict[str, str]:
    return {label: cid for cid, label in names_of(session).items()}


def contacts(timeline: Timeline, *bodies: str, kind: str = "contact") -> list[Event]:
    return [e for e in timeline.events if e.type == kind and set(bodies) <= set(e.components)]


def first_movement(timeline: Timeline, body: str) -> Event:
    return next(e for e in timeline.events if e.type == "movement" and e.components[0] == body)


@pytest.mark.parametrize("name", SCENARIOS)
def test_every_demonstration_gives_a_well_formed_timeline(name: str) -> None:
    timeline = session_over(name).timeline
    assert timeline is not None and len(timeline) > 3
    check_acyclic(timeline)
    start = [e for e in timeline.events if e.type == "start"]
    assert len(start) == 1 and not start[0].causes
    for event in timeline.events:
        if event.type == "movement":  # thesis 3.3.1: driven by exactly one other event
            assert len(event.causes) == 1, event
            assert timeline.event(event.causes[0]).type in ("start", "contact", "end_contact")
            assert all(p.t >= event.t0 - 1e-9 for p in event.trajectory)
        elif event.type == "contact":
            assert event.causes and all(timeline.event(c).type == "movement" for c in event.causes)
            assert len(event.sides) == 2 and event.point is not None


def test_the_egg_cracker_timeline_has_the_structure_of_figure_3_4() -> None:
    lines = text_of("egg_cracker")
    assert lines[:7] == [
        "Movement of ball CAUSES",
        "-- the ball hits the lever CAUSES",  # the user's phrase replaced "Contact between ball and lever"
        "---- Movement of ball",
        "---- Movement of lever [attached to rope, knife] CAUSES",
        "------ Contact between knife and egg CAUSES",
        "-------- Movement of knife [attached to rope, lever]",
        "-------- Movement of egg CAUSES",
    ]
    session = session_over("egg_cracker")
    timeline, ids = session.timeline, by_label(session)
    pairs = {frozenset(e.components) for e in timeline.events if e.type == "contact"}
    assert pairs == {frozenset((ids["ball"], ids["lever"])), frozenset((ids["knife"], ids["egg"])),
                     frozenset((ids["egg"], ids["left paddle"])), frozenset((ids["egg"], ids["right paddle"])),
                     frozenset((ids["egg"], ids["pan"]))}
    # one push through the paddles (thesis 2.3.3): the held egg catching up with the paddle it pushed is no second
    # contact, though the paddle swung ahead of it in gravity-free demo mode
    assert [len(contacts(timeline, ids["egg"], ids[p])) for p in ("left paddle", "right paddle")] == [1, 1]
    landing = contacts(timeline, ids["egg"], ids["pan"])[0]
    assert dict(landing.sides)[ids["pan"]] == "inside"  # the egg lands *inside* the frying pan
    before = {timeline.event(e).components for e in ancestors(timeline, landing.id)}
    assert {(ids["ball"], ids["lever"]), (ids["knife"], ids["egg"])} <= before
    assert any(ids["egg"] in c and (ids["left paddle"] in c or ids["right paddle"] in c) for c in before)
    assert [e.label for e in timeline.events if e.label] == ["the ball hits the lever", "the egg lands in the pan"]


def pinball_before_the_edit() -> tuple[Session, Timeline]:
    """The pinball session fed up to the rewind before the edit, and what the timeline was then."""
    journal = read_journal(journal_path(SCENARIOS["pinball"]))
    session = Session.from_header(journal.header)
    for entry in journal.entries:
        session.handle(entry)
        if isinstance(entry, CommandEntry) and entry.name == "seek" and entry.args == (PINBALL_EDIT_T,):
            break
    return session, session.timeline


def test_the_pinball_edit_deletes_what_the_old_movement_caused_and_nothing_else() -> None:
    session, before = pinball_before_the_edit()
    ids = by_label(session)
    hit = [next(iter(set(e.components) - {ids["ball"]})) for e in before.events
           if e.type == "contact" and ids["ball"] in e.components]
    assert [h for h in hit if h in (ids["paddle a"], ids["paddle b"], ids["paddle c"])][:1] == [ids["paddle a"]]
    assert {ids["paddle b"], ids["paddle c"]} <= set(hit)  # figure 3-13: A, B and C
    assert text_of("pinball") == [  # figure 3-17
        "Movement of ball CAUSES",
        "-- Contact between ball and paddle a CAUSES",
        "---- Movement of ball CAUSES",
        "------ Contact between ball and paddle b CAUSES",
        "-------- Movement of ball",
        "-------- Movement of paddle b",
        "---- Movement of paddle a",
        "Movement of ball two",
    ]
    after = session_over("pinball").timeline
    ball_two = [e for e in before.events if e.type == "movement" and e.components[0] == ids["ball two"]]
    assert ball_two and all(after.event(e.id) == e for e in ball_two)  # untouched, to the frame
    for e in before.events:  # everything before the rewind is as it was (the cut movement aside)
        if e.t1 <= PINBALL_EDIT_T and e.id in after:
            assert after.event(e.id) == e
    edit = contacts(after, ids["ball"], ids["paddle b"])[0]
    pivot = session.scene.components[ids["paddle b"]].position
    assert edit.point[0] > pivot[0]  # figure 2-11: right of B's pivot
    assert not contacts(after, ids["paddle c"])


def test_the_basketball_collision_splits_both_movements_and_each_ball_lands_in_its_basket() -> None:
    session = session_over("basketball")
    timeline, ids = session.timeline, by_label(session)
    one, two = ids["ball one"], ids["ball two"]
    (collision,) = contacts(timeline, one, two)
    assert collision.t0 > 0.5 and len(collision.causes) == 2  # both balls' movements bring them together
    for ball, basket in ((one, ids["basket one"]), (two, ids["basket two"])):
        pre = timeline.event(next(c for c in collision.causes if timeline.event(c).components[0] == ball))
        assert pre.t1 <= collision.t0 + 1e-9
        post = next(e for e in timeline.events if e.type == "movement" and e.components[0] == ball
                    and e.causes == (collision.id,))
        (landing,) = contacts(timeline, ball, basket)
        assert landing.id in descendants(timeline, post.id) and landing.t0 > collision.t0
        assert dict(landing.sides)[basket] == "inside"
    # ball one was not demonstrated again: its recorded path goes on after the collision as it was drawn
    first_pass = first_movement(timeline, one)
    assert first_pass.causes == (next(e.id for e in timeline.events if e.type == "start"),)


def test_the_cup_dispenser_peg_is_moved_by_the_end_of_its_contact_with_the_platform() -> None:
    session = session_over("cup_dispenser")
    timeline, ids = session.timeline, by_label(session)
    # the first time they part (later, the pen's push over the platform's top may end in a parting too)
    released = min(contacts(timeline, ids["platform"], ids["peg"], kind="end_contact"), key=lambda e: e.t0)
    pushed_down = timeline.event(released.causes[0])
    assert pushed_down.type == "movement" and pushed_down.components[0] == ids["platform"]
    chain = {timeline.event(e).components for e in ancestors(timeline, released.id)}
    assert any({ids["ball"], ids["cup"]} == set(c) for c in chain)  # the ball weighs the cup down
    assert any({ids["cup"], ids["platform"]} == set(c) for c in chain)  # the cup presses on the platform
    peg = first_movement(timeline, ids["peg"])
    assert peg.causes == (released.id,)  # not an exogenous force
    assert any(ids["cup"] in e.components for e in map(timeline.event, descendants(timeline, released.id))
               if e.type == "contact" and ids["peg"] in e.components)  # the peg pushes the cup off


def test_the_golf_ball_helper_chain_runs_from_the_peg_to_the_tee() -> None:
    lines = text_of("golf_ball_helper")
    assert lines[:5] == [
        "Movement of peg [attached to spring] CAUSES",
        "-- Contact between peg and arm CAUSES",
        "---- Movement of peg [attached to spring]",
        "---- Movement of arm CAUSES",
        "------ Contact between arm and golf ball CAUSES",
    ]
    session = session_over("golf_ball_helper")
    timeline, ids = session.timeline, by_label(session)
    (tee,) = contacts(timeline, ids["golf ball"], ids["tee"])
    assert tee.label == "the golf ball lands on the tee" and dict(tee.sides)[ids["tee"]] == "top"
    assert contacts(timeline, ids["peg"], ids["arm"])[0].id in ancestors(timeline, tee.id)


@pytest.mark.parametrize("name", ["egg_cracker", "pinball", "basketball", "cup_dispenser"])
def test_a_demonstration_replays_to_identical_timeline_files(name: str, tmp_path, capsys) -> None:
    journal = journal_path(SCENARIOS[name])
    for run in ("a", "b"):
        assert main(["replay", str(journal), "--out", str(tmp_path / run)]) == 0
    capsys.readouterr()
    for file in ("timeline.json", "timeline.txt", "project.json"):
        assert (tmp_path / "a" / file).read_bytes() == (tmp_path / "b" / file).read_bytes(), file
    assert (tmp_path / "a" / "timeline.txt").read_text().splitlines() == text_of(name)


@pytest.mark.parametrize("scenario", [*all_scenarios(), *bouncing_scenarios()], ids=lambda s: s.name)
def test_only_the_cup_dispenser_begins_with_movable_bodies_in_contact(scenario) -> None:
    # figure 3-9's rule on the thirteen journals: the cup drawn into its platform and the peg into the platform's
    # side, both pushed flush, begin in contact; nothing else does (the egg is drawn above its paddles)
    session = replayed(scenario.name, journal_path(scenario))
    (start,) = [e for e in session.timeline.events if e.type == "start"]
    names = session.scene.names()
    pairs = {frozenset(names[c] for c in pair) for pair in start.in_contact}
    cup = scenario.name == "cup_dispenser"
    assert pairs == ({frozenset({"platform", "cup"}), frozenset({"platform", "peg"})} if cup else set())
    ended = {frozenset(names[c] for c in e.components) for e in session.timeline.events if e.type == "end_contact"}
    assert ended == ({frozenset({"platform", "peg"})} if cup else set())
