"""`physink export PROJECT --timeline graph.svg|graph.png`: the causal timeline drawn as the thesis draws timelines —
causes left of their effects, each event type in its colour, the user's names — through Graphviz's dot; the same
project gives the same bytes; without dot, one clear line."""

from __future__ import annotations

import dataclasses
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from physink_tui.cli import main
from physink_tui.commands.demo import demo_journal
from physink_tui.formats.project.codec import Project
from physink_tui.formats.project.files import load_project, save_project
from physink_tui.render.images import decode_png
from physink_tui.render.timeline_graph import TYPE_STYLES
from physink_tui.session.session import Session
from physink_tui.timeline.events import Timeline, default_label

SVG = "{http://www.w3.org/2000/svg}"
PHRASE = "the egg lands in the pan"


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bundled egg cracker, demonstrated, with the user's phrase on the egg's landing."""
    header, entries = demo_journal()
    session = Session.from_header(header).run(entries)
    timeline = session.timeline
    landing = next(ev for ev in reversed(timeline.events) if ev.type == "contact")
    named = Timeline(tuple(dataclasses.replace(ev, label=PHRASE) if ev is landing else ev for ev in timeline.events))
    path = tmp_path_factory.mktemp("timeline") / "egg.physink.json"
    save_project(Project(session.scene, session.vocabulary_lines(), named, session.canvas), path)
    return path


def nodes(svg: Path) -> dict[str, tuple[float, str, str]]:
    """Each event node's id -> (its x in the picture, its fill colour, its text)."""
    found = {}
    for group in ET.parse(svg).getroot().iter(f"{SVG}g"):
        if group.get("class") != "node":
            continue
        title = group.find(f"{SVG}title").text
        shape = group.find(f"{SVG}path")
        if shape is None:
            shape = group.find(f"{SVG}polygon")
        xs = [float(x) for x in re.findall(r"(-?[\d.]+),(-?[\d.]+)", shape.get("d") or shape.get("points"))[0][:1]]
        texts = " ".join(t.text or "" for t in group.iter(f"{SVG}text"))
        found[title] = (xs[0], shape.get("fill"), texts)
    return found


def test_the_svg_draws_causes_left_of_effects_in_the_colours_of_their_types(project: Path, tmp_path: Path) -> None:
    out = tmp_path / "graph.svg"
    assert main(["export", str(project), "--timeline", str(out)]) == 0
    timeline = load_project(project).timeline
    names = load_project(project).scene.names()
    drawn = nodes(out)
    for ev in timeline.events:
        x, fill, text = drawn[ev.id]
        assert fill == TYPE_STYLES[ev.type][0]
        assert default_label(ev, names) in text and f"{ev.t0:.2f} s" in text
        for cause in ev.causes:
            assert drawn[cause][0] < x, (cause, ev.id)  # left to right, from cause to effect
    landing = next(ev for ev in timeline.events if ev.label == PHRASE)
    assert PHRASE in drawn[landing.id][2]  # the user's name for the event, with the narration under it
    legend = {k for k in drawn if k.startswith("legend ")}
    assert legend == {f"legend {t}" for t in {ev.type for ev in timeline.events}}


def test_the_png_is_the_same_graph_and_the_same_project_gives_the_same_bytes(project: Path, tmp_path: Path) -> None:
    first, second = tmp_path / "a.png", tmp_path / "b.png"
    assert main(["export", str(project), "--timeline", str(first)]) == 0
    assert main(["export", str(project), "--timeline", str(second)]) == 0
    assert first.read_bytes() == second.read_bytes()
    pixels = decode_png(first.read_bytes())
    assert pixels.shape[1] > 2 * pixels.shape[0]  # a row of events, left to right
    colours = {tuple(p) for p in pixels[..., :3].reshape(-1, 3)[::7]}
    for kind in ("movement", "contact"):
        fill = TYPE_STYLES[kind][0]
        rgb = tuple(int(fill[i:i + 2], 16) for i in (1, 3, 5))
        assert rgb in colours, kind
    svgs = [tmp_path / "c.svg", tmp_path / "d.svg"]
    for svg in svgs:
        assert main(["export", str(project), "--timeline", str(svg)]) == 0
    assert svgs[0].read_bytes() == svgs[1].read_bytes()


def test_without_graphviz_the_export_says_what_to_install(project: Path, tmp_path: Path, monkeypatch,
                                                          capsys) -> None:
    monkeypatch.setenv("PATH", str(tmp_path))  # no dot on it
    assert main(["export", str(project), "--timeline", str(tmp_path / "graph.svg")]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Graphviz" in err and "apt install graphviz" in err
    assert not (tmp_path / "graph.svg").exists()


def test_a_project_without_a_timeline_has_nothing_to_draw(project: Path, tmp_path: Path, capsys) -> None:
    bare = tmp_path / "bare.physink.json"
    loaded = load_project(project)
    save_project(Project(loaded.scene, (), None, loaded.canvas), bare)
    assert main(["export", str(bare), "--timeline", str(tmp_path / "graph.png")]) == 1
    assert "no timeline" in capsys.readouterr().err
    assert not (tmp_path / "graph.png").exists()
