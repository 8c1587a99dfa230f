"""Issue 14: a journal's ``simulate [SEED [BUDGET]]`` runs SIMULATE in the session, journals both numbers, and
shows its result in the view until the document changes; a replay gives the same result."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest
from session_outputs import outputs
from test_session import box_points, pen_header, pen_stroke
from test_session_modes import drag, live, replayed

from physink_tui.cli import main
from physink_tui.commands.simulate import parameters_object
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.formats.project.codec import Project, decode_project, encode_project
from physink_tui.scene.components import Scene
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import compare_rollout, make_problem, simulate
from physink_tui.sim.search import Search
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import SerialExecutor
from physink_tui.timeline.events import Timeline
from tests.sim_scenes import CANVAS, ball_floor_wall, demonstration


def project(scene: Scene | None = None, timeline: Timeline | None = None) -> dict:
    """A project as a ``load`` line embeds it: by default the ball rolling into the wall, demonstrated."""
    return json.loads(encode_project(Project(scene or ball_floor_wall(), (), timeline, CANVAS)))


def load(t: float = 0.5, **kwargs) -> CommandEntry:
    return CommandEntry(t, "load", ("machine.physink.json",), project(**kwargs))


def wall_out_of_the_way() -> Scene:
    """The machine with its wall lifted above the ball's path: the demonstrated contact cannot happen."""
    scene = ball_floor_wall()
    scene = scene.update(replace(scene.components["b3"], position=(1100.0, 200.0)))
    return scene.update(replace(scene.components["j2"], anchor=(1100.0, 200.0)))


def searched_directly(scene: Scene, timeline: Timeline, seed: int, budget: int):
    """`Search` driven by `physink simulate`'s driver (`run_search`) on a serial executor."""
    search = Search(scene, timeline, CANVAS, seed=seed, budget=budget)
    problem = make_problem(scene, timeline, CANVAS)
    run_search(search, problem, SerialExecutor())
    rollout = simulate(problem, search.best)
    return search, rollout, compare_rollout(problem, rollout, explain=True)


@pytest.mark.parametrize("scene", [None, wall_out_of_the_way()], ids=["found", "not found"])
def test_simulate_shows_what_the_search_finds_run_directly(tmp_path: Path, scene: Scene | None) -> None:
    session = live([load(timeline=demonstration(), scene=scene), CommandEntry(1.0, "simulate", (3, 20))],
                   tmp_path / "s.physink.jsonl")
    result = session.view().search
    document = session.document  # the project as loaded (its JSON rounds the demonstration's numbers)
    search, rollout, comparison = searched_directly(document.scene, document.timeline, 3, 20)
    assert result is not None and not session.errors
    assert (result.seed, result.budget, result.rollouts) == (3, 20, search.rollouts)
    assert result.parameters == search.best and result.timeline == rollout.timeline
    assert result.found == comparison.equivalent == (scene is None)
    assert (result.qualitative_distance, result.quantitative_distance) == (comparison.qualitative_distance,
                                                                           comparison.quantitative_distance)
    assert result.reasons == (() if result.found else comparison.reasons) and (result.found or result.reasons)
    told = session.messages[-1].text
    if result.found:
        assert told.startswith(f"simulation found in {search.rollouts} rollout") and "qualitative distance 0" in told
    else:
        assert told.startswith("no simulation reproduces the demonstration within 20 rollouts")
        assert f"first difference: {comparison.reasons[0]}" in told
    with pytest.raises(AttributeError):
        result.found = not result.found  # type: ignore[misc]


def test_the_journal_holds_seed_and_budget_and_replays_to_the_same_result(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    session = live([load(timeline=demonstration()), CommandEntry(1.0, "simulate", (3, 20)),
                    CommandEntry(1.5, "simulate", (5,)), CommandEntry(2.0, "simulate")], path)
    journaled = [e.args for e in read_journal(path).entries if e.name == "simulate"]
    assert journaled == [(3, 20), (5, 200), (0, 200)]
    lines = [json.loads(line) for line in path.read_text().splitlines()[1:]]
    assert [line["args"] for line in lines if line.get("cmd") == "simulate"] == [[3, 20], [5, 200], [0, 200]]
    again = replayed(path)
    assert again.view().search == session.view().search and again.view().search.seed == 0
    assert [m.text for m in again.messages] == [m.text for m in session.messages]


def test_a_missing_budget_is_the_sessions_and_journaled_as_used(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    session = Session.from_header(pen_header())
    session.simulation_budget = 7  # what a test does to keep an unbudgeted simulate short
    session.journal = JournalWriter.create(path, pen_header())
    session.run([load(timeline=demonstration()), CommandEntry(1.0, "simulate", (4,))])
    assert [e.args for e in read_journal(path).entries if e.name == "simulate"] == [(4, 7)]
    assert session.view().search.budget == 7 and Session.simulation_budget == 200


@pytest.mark.parametrize(("args", "shown"), [((-1,), "-1"), ((1.5,), "1.5"), (("x",), '"x"'), ((True,), "true"),
                                             ((3, 0), "0"), ((3, 2.0), "2.0"), ((1, 2, 3), "[1, 2, 3]")])
def test_a_bad_seed_or_budget_is_refused_naming_it_and_not_journaled(tmp_path: Path, args: tuple,
                                                                      shown: str) -> None:
    path = tmp_path / "s.physink.jsonl"
    session = live([load(timeline=demonstration()), CommandEntry(1.0, "simulate", args)], path)
    told = session.messages[-1].text
    assert told.startswith("input refused: ") and 'cmd entry: key "args' in told and told.endswith(f"got {shown}")
    assert session.view().search is None
    assert [e.name for e in read_journal(path).entries] == ["load", "end"]


@pytest.mark.parametrize(("entry", "told"), [
    (load(), "simulate: nothing has been demonstrated: in demo mode (mode demo), move the bodies"),
    (load(scene=ball_floor_wall(ball_welded=True), timeline=demonstration()), "simulate: no body can move"),
    (load(scene=ball_floor_wall().remove("b1"), timeline=demonstration()),
     "simulate: the demonstration moves b1, no longer in the sketch"),
], ids=["no demonstration", "nothing movable", "moved body gone"])
def test_simulate_without_something_to_simulate_says_what_to_do(tmp_path: Path, entry: CommandEntry,
                                                                 told: str) -> None:
    path = tmp_path / "s.physink.jsonl"
    before = live([entry], tmp_path / "before.physink.jsonl")
    session = live([entry, CommandEntry(1.0, "simulate", (3, 20))], path)
    assert session.messages[-1].text.startswith(told) and not session.errors
    assert session.view().search is None and session.document == before.document
    assert session.history.last_description() == before.history.last_description()
    assert [e.args for e in read_journal(path).entries if e.name == "simulate"] == [(3, 20)]


@pytest.mark.parametrize("edit", [
    lambda t: pen_stroke(t, box_points(0.1, 0.1, 0.2, 0.2)),
    lambda t: [CommandEntry(t, "undo")],
    lambda t: [CommandEntry(t, "clear")],
    lambda t: [load(t, timeline=demonstration())],
    lambda t: [CommandEntry(t, "label", ("b1", "marble"))],
    lambda t: [CommandEntry(t, "mode", ("demo",)), *drag(t + 0.1, (500 / 1600, 655 / 1000), (0.4, 0.5))],
], ids=["stroke", "undo", "clear", "load", "label", "new take"])
def test_an_edit_of_the_document_clears_the_result(tmp_path: Path, edit) -> None:
    start = [load(timeline=demonstration()), CommandEntry(1.0, "simulate", (3, 20))]
    kept = live([*start, CommandEntry(1.5, "mode", ("demo",)), CommandEntry(2.0, "mode", ("sketch",))],
                tmp_path / "kept.physink.jsonl")
    assert kept.view().search is not None  # changing modes edits nothing
    session = Session.from_header(pen_header())
    for entry in [*start, *edit(2.0)]:
        session.handle(entry)
    assert session.view().search is None and not session.errors
    session.handle(CommandEntry(9.0, "undo" if session.history.can_undo else "redo"))
    assert session.view().search is None  # a result once forgotten does not come back


def test_simulate_in_demo_mode_commits_the_take_then_simulates_it_and_stays_in_demo_mode(tmp_path: Path) -> None:
    entries = [load(), CommandEntry(1.0, "mode", ("demo",)), *drag(1.5, (500 / 1600, 655 / 1000), (0.45, 0.6)),
               CommandEntry(5.0, "simulate", (1, 3))]
    session = Session.from_header(pen_header())
    session.journal = JournalWriter.create(tmp_path / "s.physink.jsonl", pen_header())
    for entry in entries:
        session.handle(entry)
    assert session.history.last_description() == "demonstrate" and session.document.timeline is not None
    assert session.mode == "demo" and not session.errors
    session.finish()
    result = session.view().search
    assert result is not None and result.rollouts <= 3 and (result.seed, result.budget) == (1, 3)
    again = replayed(tmp_path / "s.physink.jsonl")
    assert again.view().search == result and outputs(again) == outputs(session)


def test_physink_replay_of_a_journal_with_simulate_writes_its_usual_files(tmp_path: Path, capsys) -> None:
    path = tmp_path / "s.physink.jsonl"
    live([load(timeline=demonstration()), CommandEntry(1.0, "simulate", (3, 20))], path)
    assert main(["replay", str(path), "--out", str(tmp_path / "out")]) == 0
    assert {p.name for p in (tmp_path / "out").iterdir()} >= {"project.json", "timeline.json", "timeline.txt"}


@pytest.mark.parametrize("scene", [None, wall_out_of_the_way()], ids=["found", "not found"])
def test_the_session_finds_what_physink_simulate_finds_on_the_same_project(tmp_path: Path, scene) -> None:
    path = tmp_path / "machine.physink.json"
    path.write_text(json.dumps(project(scene, demonstration())))
    assert main(["simulate", str(path), "--out", str(tmp_path / "sim"), "--seed", "3", "--budget", "20",
                 "--workers", "1"]) == 0
    written = json.loads((tmp_path / "sim" / "result.json").read_text())
    session = live([CommandEntry(0.5, "load", (str(path),), json.loads(path.read_text())),
                    CommandEntry(1.0, "simulate", (3, 20))], tmp_path / "s.physink.jsonl")
    result = session.view().search
    assert (result.found, result.rollouts) == (written["found"], written["rollouts"])
    assert parameters_object(result.parameters) == written["parameters"]
    assert (round(result.qualitative_distance, 6), round(result.quantitative_distance, 6)) == (
        written["qualitative_distance"], written["quantitative_distance"])


def test_a_loaded_adopted_simulation_keeps_its_demonstration_until_the_machine_is_demonstrated_again() -> None:
    simulated = Timeline(demonstration().events[:2])
    adopted = json.loads(encode_project(Project(ball_floor_wall(), (), simulated, CANVAS, demonstration())))
    read = decode_project(json.dumps(adopted), "adopted.physink.json")  # its numbers to 6 decimals
    simulated, kept = read.timeline, read.demonstration
    session = Session.from_header(pen_header())
    session.handle(CommandEntry(0.5, "load", ("adopted.physink.json",), adopted))
    assert session.timeline == simulated and session.demonstration == kept
    session.handle(CommandEntry(0.6, "label", ("b3", "the wall")))  # editing the sketch keeps it
    assert session.scene.components["b3"].label == "the wall" and session.demonstration == kept
    assert session.view().demonstration == kept
    assert decode_project(outputs(session)["project.json"], "out.json").demonstration == kept  # and is saved
    session.handle(CommandEntry(0.7, "mode", ("demo",)))
    for entry in drag(0.8, (500 / 1600, 655 / 1000), (700 / 1600, 655 / 1000)):
        session.handle(entry)
    session.handle(CommandEntry(2.0, "mode", ("sketch",)))  # a new demonstration: its timeline is what was shown
    assert session.timeline != simulated and session.demonstration is None
    session.handle(CommandEntry(2.1, "undo", ()))
    assert session.timeline == simulated and session.demonstration == kept
