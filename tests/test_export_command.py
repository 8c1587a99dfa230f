"""Issue 13 through the command line: `physink export` of the thesis scenes (video probed and decoded back, frames,
a still, the timeline), `physink replay --video --frames`, the demo's video and picture, and bad input named."""

from __future__ import annotations

import json
from pathlib import Path

import av
import pytest
from test_outputs_inputs import one_line_error

from physink_tui.cli import main
from physink_tui.formats.project.files import load_project
from physink_tui.render.frame import frame_times
from physink_tui.render.images import decode_png

JOURNALS = Path(__file__).parent / "journals"


@pytest.fixture(scope="module")
def egg(tmp_path_factory) -> Path:
    """The egg cracker's project, as `physink replay` writes it."""
    out = tmp_path_factory.mktemp("egg")
    assert main(["replay", str(JOURNALS / "egg_cracker.physink.jsonl"), "--out", str(out)]) == 0
    return out / "project.json"


def probe(path: Path) -> tuple[str, int, int, int, float, list]:
    """Codec, width, height, frames decoded, duration (s) and the decoded frames as RGB arrays."""
    with av.open(str(path)) as container:
        stream = container.streams.video[0]
        codec, width, height = stream.codec_context.name, stream.width, stream.height
        frames = [f.to_ndarray(format="rgb24") for f in container.decode(stream)]
        duration = float(container.duration / av.time_base) if container.duration else 0.0
    return codec, width, height, len(frames), duration, frames


def test_export_writes_a_video_frames_a_still_and_the_timeline(egg: Path, tmp_path, capsys) -> None:
    video, frames, still, text = tmp_path / "egg.mp4", tmp_path / "frames", tmp_path / "egg.png", tmp_path / "t.txt"
    assert main(["export", str(egg), "--video", str(video), "--frames", str(frames), "--still", str(still),
                 "--timeline", str(text), "--size", "640x400", "--fps", "30"]) == 0
    project = load_project(egg)
    expected = len(frame_times(max(ev.t1 for ev in project.timeline.events), 30))
    codec, width, height, count, duration, decoded = probe(video)
    assert (codec, width, height, count) == ("h264", 640, 400, expected)
    assert duration == pytest.approx(expected / 30, abs=0.05)
    assert decoded[0].std() > 5 and (decoded[0] != decoded[-1]).any()  # a picture, and it changes
    pngs = sorted(frames.iterdir())
    assert [p.name for p in pngs[:2]] == ["00000.png", "00001.png"] and len(pngs) == expected
    assert decode_png(still.read_bytes()).shape == (400, 640, 4)
    assert main(["timeline", str(egg)]) == 0
    assert text.read_text() == capsys.readouterr().out


def test_a_gif_and_a_webm_at_60_fps_in_the_dark_theme(egg: Path, tmp_path) -> None:
    for name, codec in (("egg.webm", "vp9"), ("egg.gif", "gif")):
        assert main(["export", str(egg), "--video", str(tmp_path / name), "--size", "320x200", "--fps", "60",
                     "--theme", "dark"]) == 0
        found, width, height, count, _, decoded = probe(tmp_path / name)
        assert (found, width, height) == (codec, 320, 200) and count > 30
        assert decoded[0].mean() < 80  # dark


def test_a_project_without_a_timeline_is_a_one_second_still_and_says_so(tmp_path, capsys) -> None:
    out = tmp_path / "sketch"
    assert main(["replay", str(JOURNALS / "egg_cracker.physink.jsonl"), "--out", str(out)]) == 0
    doc = json.loads((out / "project.json").read_text())
    doc["timeline"] = None
    (out / "project.json").write_text(json.dumps(doc))
    capsys.readouterr()
    assert main(["export", str(out / "project.json"), "--video", str(tmp_path / "s.mp4"), "--size", "320x200"]) == 0
    assert "no timeline" in capsys.readouterr().err
    assert probe(tmp_path / "s.mp4")[3] == 30


def test_an_empty_project_is_an_empty_canvas_and_says_so(tmp_path, capsys) -> None:
    out = tmp_path / "empty"
    journal = tmp_path / "e.physink.jsonl"
    journal.write_text('{"format": "physink-journal", "version": 1, "canvas": {"width": 1600, "height": 1000}, '
                       '"devices": {}}\n')
    assert main(["replay", str(journal), "--out", str(out)]) == 0
    capsys.readouterr()
    assert main(["export", str(out / "project.json"), "--still", str(tmp_path / "e.png"), "--size", "160x100"]) == 0
    assert "nothing in it" in capsys.readouterr().err
    canvas = decode_png((tmp_path / "e.png").read_bytes())[5:85, 15:145]
    assert (canvas == canvas[0, 0]).all()  # the canvas is one colour


@pytest.mark.parametrize(("option", "value"), [("--size", "0x0"), ("--size", "=-640x400"), ("--size", "99999x400"),
                                                ("--size", "big"), ("--fps", "0"), ("--fps", "-1"),
                                                ("--fps", "1000"), ("--fps", "abc")])
def test_absurd_sizes_and_rates_are_named(egg: Path, tmp_path, capsys, option: str, value: str) -> None:
    assert main(["export", str(egg), "--video", str(tmp_path / "v.mp4"), option + value if value[0] == "=" else option,
                 *([] if value[0] == "=" else [value])]) == 2
    assert repr(value.lstrip("=")) in capsys.readouterr().err
    assert not list(tmp_path.iterdir())


def test_an_unwritable_video_path_is_one_line_and_leaves_no_file(egg: Path, tmp_path, capsys) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert main(["export", str(egg), "--video", str(blocker / "v.mp4"), "--size", "320x200"]) == 1
    one_line_error(capsys.readouterr().err, str(blocker / "v.mp4"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]
    assert main(["export", str(egg), "--video", str(tmp_path / "v.avi")]) == 1
    one_line_error(capsys.readouterr().err, "v.avi")


def test_export_needs_something_to_write(egg: Path, capsys) -> None:
    assert main(["export", str(egg)]) == 1
    one_line_error(capsys.readouterr().err, "nothing to write")


def test_replay_writes_the_demonstrations_video_and_frames(tmp_path) -> None:
    out = tmp_path / "out"
    assert main(["replay", str(JOURNALS / "cup_dispenser.physink.jsonl"), "--out", str(out), "--video", "--frames",
                 "--size", "320x200"]) == 0
    codec, width, height, count, _, _ = probe(out / "video.mp4")
    assert (codec, width, height) == ("h264", 320, 200)
    assert count == len(list((out / "frames").iterdir())) > 30
    assert main(["replay", str(JOURNALS / "cup_dispenser.physink.jsonl"), "--out", str(out)]) == 0
    assert not (out / "video.mp4").exists()  # a run without --video leaves no video of an earlier run


def test_the_demo_adds_its_video_and_picture(tmp_path) -> None:
    assert main(["demo", "--headless", "--out", str(tmp_path)]) == 0
    assert probe(tmp_path / "demo.mp4")[:3] == ("h264", 1280, 800)
    assert decode_png((tmp_path / "scene.png").read_bytes()).shape == (800, 1280, 4)


def test_a_simulated_timeline_is_drawn_in_red_over_the_demonstration(egg: Path, tmp_path) -> None:
    sim = tmp_path / "sim"
    assert main(["simulate", str(egg), "--out", str(sim), "--budget", "4", "--workers", "1"]) == 0
    plain, overlaid = tmp_path / "plain.png", tmp_path / "overlaid.png"
    assert main(["export", str(egg), "--still", str(plain), "--size", "640x444"]) == 0
    assert main(["export", str(egg), "--still", str(overlaid), "--size", "640x444",
                 "--overlay", str(sim / "timeline.json")]) == 0

    def reds(path: Path) -> int:
        rgb = decode_png(path.read_bytes())[..., :3].astype(int)
        return int(((rgb[..., 0] > 150) & (rgb[..., 1] < 90) & (rgb[..., 2] < 90)).sum())

    assert reds(plain) < 20 < reds(overlaid)  # the simulation's paths, in the theme's simulation red
