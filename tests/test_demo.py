"""`physink demo` on the bundled drawing, and the bundled capture staying what the virtual pen makes."""

from __future__ import annotations

import itertools
import json

from physink_tui.cli import main
from physink_tui.demo_data import DEMONSTRATION, EGG_CRACKER, demo_capture_text, expected_demo_capture_text
from physink_tui.render.braille import braille_plot


def test_bundled_capture_is_what_the_virtual_pen_draws() -> None:
    # regenerate with `python -m physink_tui.demo_data` after changing the drawing or the pen
    assert demo_capture_text() == expected_demo_capture_text()


def test_demo_writes_samples_and_summary(tmp_path, capsys) -> None:
    out = tmp_path / "demo"
    assert main(["demo", "--headless", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    strokes = len(EGG_CRACKER) + len(DEMONSTRATION)
    assert f"{strokes} strokes" in printed
    lines = (out / "samples.jsonl").read_text().splitlines()
    samples = [json.loads(line) for line in lines]
    assert len(samples) > 1000
    downs = sum(1 for a, b in itertools.pairwise(samples) if b["tip"] and not a["tip"])
    assert downs + samples[0]["tip"] == strokes
    assert all(0 <= s["x"] <= 1 and 0 <= s["y"] <= 1 and 0 <= s["p"] <= 1 for s in samples)
    project = json.loads((out / "project.json").read_text())
    shapes = [c.get("shape", c["kind"] if "kind" in c else c["type"]) for c in project["components"]]
    # ramp (welded by its X), ball, lever (pinned by its small circle), egg, pan (welded): thesis figure 2-4
    assert shapes == ["polyline", "weld", "circle", "box", "pivot", "circle", "polyline", "weld"]
    narration = (out / "timeline.txt").read_text()
    assert narration.startswith("Movement of ball CAUSES\n-- Contact between ball and lever CAUSES\n")
    assert "Contact between egg and pan" in narration and narration in printed + "\n"
    assert project["timeline"]["events"][0]["type"] == "start"
    summary = (out / "summary.txt").read_text()
    assert "pen samples" in summary and "ignored" not in summary


def test_demo_twice_gives_identical_files(tmp_path) -> None:
    for name in ("a", "b"):
        assert main(["demo", "--headless", "--out", str(tmp_path / name)]) == 0
    for file in ("samples.jsonl", "summary.txt", "project.json", "session.physink.jsonl", "timeline.json",
                 "timeline.txt"):
        assert (tmp_path / "a" / file).read_bytes() == (tmp_path / "b" / file).read_bytes()


def test_demo_names_an_unusable_output_folder(tmp_path, capsys) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    assert main(["demo", "--headless", "--out", str(blocker / "sub")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "cannot create the output folder" in err[0]


def test_braille_plot_places_dots() -> None:
    text = braille_plot([(0.0, 0.0), (0.99, 0.99)], width=3, height=2)
    rows = text.splitlines()
    assert len(rows) == 2 and all(len(r) == 3 for r in rows)
    assert rows[0][0] == "\u2801" and rows[1][2] == "\u2880"
