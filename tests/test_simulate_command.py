"""`physink simulate`: the files it writes, determinism whatever the worker count, bad input."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from physink_tui import cli
from physink_tui.formats.project.codec import Project
from physink_tui.formats.project.files import load_project, save_project
from physink_tui.formats.timeline_json import decode_timeline_json
from physink_tui.scene.components import MATERIALS, Body
from physink_tui.timeline.events import Event, Timeline, TrajectoryPoint
from tests.sim_scenes import CANVAS, ball_floor_wall, demonstration


def project(tmp_path: Path, *, timeline: bool = True, ball_welded: bool = False) -> str:
    path = tmp_path / "machine.physink.json"
    save_project(Project(ball_floor_wall(ball_welded=ball_welded), (), demonstration() if timeline else None,
                         CANVAS), path)
    return str(path)


def simulate(tmp_path: Path, name: str, *extra: str) -> tuple[int, Path]:
    out = tmp_path / name
    status = cli.main(["simulate", project(tmp_path), "--out", str(out), "--seed", "3", *extra])
    return status, out


def test_writes_result_timeline_and_project(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, out = simulate(tmp_path, "out", "--budget", "6", "--workers", "1")
    assert status == 0
    result = json.loads((out / "result.json").read_text())
    assert set(result) >= {"found", "qualitative_distance", "quantitative_distance", "rollouts", "wall_seconds",
                           "parameters", "verdict"}
    assert result["rollouts"] <= 6
    assert result["found"] == (result["qualitative_distance"] == 0)
    assert set(result["parameters"]["velocities"]) == {"b1"}
    assert isinstance(result["verdict"], str) and result["verdict"]
    timeline, names = decode_timeline_json((out / "timeline.json").read_text())
    assert names["b1"] == "ball" and timeline.events
    saved = load_project(out / "project.json")
    assert saved.timeline is not None and saved.canvas == CANVAS
    assert "rollouts" in capsys.readouterr().out


def test_same_files_whatever_the_worker_count(tmp_path: Path) -> None:
    texts = []
    for workers in ("1", "2"):
        status, out = simulate(tmp_path, f"w{workers}", "--budget", "12", "--workers", workers)
        assert status == 0
        result = json.loads((out / "result.json").read_text())
        del result["wall_seconds"]
        texts.append((result, (out / "timeline.json").read_text(), (out / "project.json").read_text()))
    assert texts[0] == texts[1]


def test_grid_strategy(tmp_path: Path) -> None:
    status, out = simulate(tmp_path, "grid", "--budget", "8", "--workers", "1", "--strategy", "grid")
    assert status == 0
    result = json.loads((out / "result.json").read_text())
    assert result["strategy"] == "grid" and result["rollouts"] <= 8


@pytest.mark.parametrize(("kwargs", "words"), [({"timeline": False}, "no demonstration"),
                                               ({"ball_welded": True}, "no movable body")])
def test_refuses_a_project_with_nothing_to_simulate(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                    kwargs: dict, words: str) -> None:
    path = project(tmp_path, **kwargs)
    assert cli.main(["simulate", path, "--out", str(tmp_path / "o")]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err


@pytest.mark.parametrize("bad", [["--budget", "0"], ["--workers", "-1"], ["--workers", "0"],
                                 ["--strategy", "random"], ["--seed", "-1"], ["--seed", "1.5"],
                                 ["--seed", str(2**31)]])
def test_bad_usage_exits_2(tmp_path: Path, bad: list[str]) -> None:
    assert cli.main(["simulate", project(tmp_path), "--out", str(tmp_path / "o"), *bad]) == 2


def rising_by_itself() -> Project:
    """The ball rolls into the wall, and a second ball drawn resting on the floor rises from rest at t = 1 with
    nothing causing it (a movement with no cause: no start, no contact) -- behaviour no physics produces."""
    scene = ball_floor_wall().add(Body("b4", "circle", (), 20.0, (300.0, 660.0), 0.0, MATERIALS["round"], "pebble"))
    scene = replace(scene, next_id={**scene.next_id, "b": 5})
    path = tuple(TrajectoryPoint(1.0 + 0.1 * k, 300.0, 660.0 - 30.0 * k, 0.0, 0.0, -300.0) for k in range(6))
    rising = Event("r1", "movement", ("b4",), (), 1.0, 1.5, trajectory=path)
    return Project(scene, (), Timeline((*demonstration().events, rising)), CANVAS)


def test_behaviour_no_physics_produces_gets_a_verdict_naming_it(tmp_path: Path) -> None:
    path = tmp_path / "impossible.physink.json"
    save_project(rising_by_itself(), path)
    out = tmp_path / "out"
    assert cli.main(["simulate", str(path), "--out", str(out), "--budget", "30", "--workers", "1"]) == 0
    result = json.loads((out / "result.json").read_text())
    assert result["found"] is False and result["qualitative_distance"] > 0
    verdict = result["verdict"]
    assert '"Movement of pebble"' in verdict and "t=1.00" in verdict, verdict
    assert "nothing sets the pebble moving" in verdict
    assert any("pebble" in line for line in result["differences"])


def test_a_missing_second_touch_is_named_as_such_in_the_verdict() -> None:
    from physink_tui.scene.components import Scene
    from physink_tui.sim.evaluate import make_problem
    from physink_tui.sim.verdict import verdict
    from physink_tui.timeline.equivalence import compare
    from tests.test_equivalence import NAMES, behaviour

    scene = Scene()
    for body, name in NAMES.items():
        scene = scene.add(Body(body, "box", ((-10, -10), (10, -10), (10, 10), (-10, 10)), 0.0, (0.0, 0.0), 0.0,
                               MATERIALS["box"], name))
    twice = behaviour([("b3", "bottom", "top"), ("b3", "bottom", "top")])  # figure 2-12, green: B twice
    once = behaviour([("b3", "bottom", "top")])
    problem = make_problem(scene, twice, CANVAS)
    comparison = compare(twice, once, NAMES, NAMES, simulation=True)
    text = verdict(problem, once, comparison, found=False, rollouts=12)
    assert "the ball touches the platform B once in the best candidate; this is the second touch" in text, text
    never = behaviour([])
    text = verdict(problem, never, compare(twice, never, NAMES, NAMES, simulation=True), found=False, rollouts=12)
    assert "the ball never reaches the platform B" in text, text


def test_equiv_up_to_demonstrated_gives_the_verdict_and_distances_of_result_json(tmp_path: Path, capsys) -> None:
    status, out = simulate(tmp_path, "out", "--budget", "12", "--workers", "1")
    assert status == 0
    result = json.loads((out / "result.json").read_text())
    assert result["rule"] == "equivalent up to the last demonstrated event"
    kept = load_project(out / "project.json")
    assert kept.demonstration == load_project(tmp_path / "machine.physink.json").timeline  # kept beside it
    capsys.readouterr()
    for files in ([str(out / "project.json")], [str(tmp_path / "machine.physink.json"), str(out / "timeline.json")]):
        assert cli.main(["equiv", *files, "--up-to-demonstrated", "--json"]) == 0
        said = json.loads(capsys.readouterr().out)
        assert said["equivalent"] == result["found"]
        assert said["qualitative_distance"] == result["qualitative_distance"]
        assert said["quantitative_distance"] == pytest.approx(result["quantitative_distance"], abs=1e-3)
        assert said["rule"] == "up to the last demonstrated event" and said["afterwards"] == result["afterwards"]
    assert cli.main(["equiv", str(out / "project.json"), "--up-to-demonstrated"]) == 0
    verdict = capsys.readouterr().out.splitlines()[0]
    assert verdict == ("equivalent" if result["found"] else "not equivalent") + " up to the last demonstrated event"


def test_equiv_of_one_project_that_kept_no_demonstration_says_so(tmp_path: Path, capsys) -> None:
    assert cli.main(["equiv", project(tmp_path), "--up-to-demonstrated"]) == 1
    err = capsys.readouterr().err
    assert "machine.physink.json" in err and "keeps no demonstration" in err and err.count("\n") == 1
