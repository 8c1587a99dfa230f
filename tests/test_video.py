"""Video export: files probed and decoded back with PyAV, frame by frame; bad input named; no file left on error."""

from __future__ import annotations

import errno
import io
import os
import sys

import av
import numpy as np
import pytest

from physink_tui.errors import RenderError
from physink_tui.progress import ProgressBar, format_line
from physink_tui.render import video_encode
from physink_tui.render.compose import side_by_side
from physink_tui.render.video import write_video
from physink_tui.render.video_spec import VideoSpec

WIDTH, HEIGHT = 320, 240
LEVELS = (0, 64, 128, 191, 255)  # exact in the GIF palette's colour cube, far apart after yuv420p
BLOCK = 32  # the frame-number block's side, a multiple of the 16-pixel macroblock
SQUARE = 40


def code_colour(i: int) -> tuple[int, int, int]:
    """The colour that encodes frame number ``i`` (0..124)."""
    return LEVELS[i % 5], LEVELS[i // 5 % 5], LEVELS[i // 25 % 5]


def square_x(i: int) -> int:
    return 48 + (i * 3) % (WIDTH - SQUARE - 64)


class MovingSquare:
    """A producer like the renderer: one reused buffer, a frame-number block and a red square moving right."""

    def __init__(self, width: int = WIDTH, height: int = HEIGHT, fail_at: int | None = None) -> None:
        self.buffer = np.empty((height, width, 4), np.uint8)
        self.fail_at = fail_at
        self.asked: list[int] = []

    def __call__(self, i: int) -> np.ndarray:
        self.asked.append(i)
        if i == self.fail_at:
            raise ValueError(f"drawing frame {i} failed")
        b = self.buffer
        b[:] = (240, 238, 230, 255)
        b[:BLOCK, :BLOCK, :3] = code_colour(i)
        x = square_x(i)
        b[120:120 + SQUARE, x:x + SQUARE, :3] = (200, 30, 30)
        return b


def decoded_index(rgb: np.ndarray) -> tuple[int, float]:
    """The frame number read from a decoded frame's block, and how far its colour was from the code."""
    seen = rgb[8:BLOCK - 8, 8:BLOCK - 8].reshape(-1, 3).mean(axis=0)
    codes = np.array([code_colour(i) for i in range(125)], float)
    distance = np.abs(codes - seen).max(axis=1)
    best = int(distance.argmin())
    return best, float(distance[best])


def leftover(directory: os.PathLike[str]) -> list[str]:
    return sorted(os.listdir(directory))


CASES = [("mp4", "h264", 30), ("mp4", "h264", 60), ("webm", "vp9", 30), ("webm", "vp9", 60),
         ("gif", "gif", 30), ("gif", "gif", 60)]


@pytest.mark.parametrize(("suffix", "codec", "fps"), CASES)
def test_video_decodes_back_to_the_drawn_frames(tmp_path, suffix, codec, fps):
    count = fps + fps // 2  # 1.5 s
    path = tmp_path / f"clip.{suffix}"
    producer = MovingSquare()
    report = write_video(path, count, producer, fps)
    spec = VideoSpec(str(path), WIDTH, HEIGHT, fps)
    expected = spec.output_count(count)
    assert report.frames == expected
    assert report.seconds == pytest.approx(count / fps, abs=1 / fps)
    assert report.bytes == path.stat().st_size > 0
    assert leftover(tmp_path) == [path.name]
    assert producer.asked == [spec.source_index(j) for j in range(expected)]
    with av.open(str(path)) as container:
        stream = container.streams.video[0]
        assert stream.codec_context.name == codec
        assert (stream.width, stream.height) == (WIDTH, HEIGHT)
        if suffix != "gif":
            assert stream.codec_context.pix_fmt == "yuv420p"
        assert container.duration / 1e6 == pytest.approx(count / fps, abs=1.5 / spec.output_fps)
        frames = list(container.decode(stream))
    assert len(frames) == expected
    tolerance = 2 if suffix == "gif" else 16
    for j, frame in enumerate(frames):
        i = spec.source_index(j)
        rgb = frame.to_ndarray(format="rgb24")
        index, distance = decoded_index(rgb)
        assert (index, j) == (i, j) and distance <= tolerance
        red = (rgb[:, :, 0].astype(int) - rgb[:, :, 1] > 100)[140]  # one row through the square
        assert abs(int(np.flatnonzero(red)[0]) - square_x(i)) <= 2
        assert frame.time == pytest.approx(j / spec.output_fps, abs=0.011)  # GIF times are in 1/100 s


def test_a_60_fps_gif_is_written_at_30_and_says_so(tmp_path):
    report = write_video(tmp_path / "clip.gif", 60, MovingSquare(), 60)
    assert report.frames == 30 and report.seconds == 1.0
    assert "30 fps instead of 60" in report.notes[0]


def test_mp4_starts_playing_at_once(tmp_path):
    path = tmp_path / "clip.mp4"
    write_video(path, 10, MovingSquare(), 30)
    data = path.read_bytes()
    assert data.index(b"moov") < data.index(b"mdat")


def test_serial_and_pipelined_write_the_same_frames(tmp_path):
    for pipelined in (False, True):
        path = tmp_path / f"clip{pipelined}.mp4"
        report = write_video(path, 20, MovingSquare(), 30, pipelined=pipelined)
        with av.open(str(path)) as container:
            decoded = [decoded_index(f.to_ndarray(format="rgb24"))[0] for f in container.decode(video=0)]
        assert report.frames == 20 and decoded == list(range(20))


@pytest.mark.parametrize("fps", [0, -1, 1000, 121, "abc", 29.5, True, None])
def test_a_bad_frame_rate_is_named(tmp_path, fps):
    with pytest.raises(RenderError, match="frame rate") as caught:
        write_video(tmp_path / "clip.mp4", 10, MovingSquare(), fps)
    assert repr(fps) in str(caught.value)
    assert leftover(tmp_path) == []


def test_a_whole_float_frame_rate_is_accepted():
    assert VideoSpec("a.mp4", 320, 240, 30.0).fps == 30


@pytest.mark.parametrize(("width", "height", "words"), [
    (0, 240, "width 0 is out of range"), (320, -2, "height -2 is out of range"),
    (9000, 240, "width 9000 is out of range"), (321, 240, "width 321 must be even"),
    (320, 241, "height 241 must be even"), (320.5, 240, "width 320.5 is not a whole number"),
])
def test_a_bad_size_is_named(width, height, words):
    with pytest.raises(RenderError, match=words):
        VideoSpec("clip.webm", width, height, 30)


def test_an_odd_size_is_fine_for_a_gif():
    assert VideoSpec("clip.gif", 321, 241, 30).width == 321


def test_odd_frames_are_refused_for_mp4_and_leave_no_file(tmp_path):
    with pytest.raises(RenderError, match="width 321 must be even"):
        write_video(tmp_path / "clip.mp4", 5, MovingSquare(width=321), 30)
    assert leftover(tmp_path) == []


@pytest.mark.parametrize("count", [0, -3, 2.5, True])
def test_a_bad_frame_count_is_named(tmp_path, count):
    with pytest.raises(RenderError, match=f"frame count {count!r}"):
        write_video(tmp_path / "clip.mp4", count, MovingSquare(), 30)


def test_an_unknown_suffix_is_named(tmp_path):
    with pytest.raises(RenderError, match=r"'\.avi' is not one of \.mp4, \.webm, \.gif"):
        write_video(tmp_path / "clip.avi", 5, MovingSquare(), 30)


def test_a_frame_of_another_shape_is_refused(tmp_path):
    big = np.zeros((HEIGHT, WIDTH, 4), np.uint8)
    small = np.zeros((HEIGHT // 2, WIDTH, 4), np.uint8)
    with pytest.raises(RenderError, match="frame 3 has shape"):
        write_video(tmp_path / "clip.mp4", 10, lambda i: small if i == 3 else big, 30)
    with pytest.raises(RenderError, match="frame 0 has shape"):
        write_video(tmp_path / "clip.mp4", 10, lambda i: big[..., :3], 30)
    assert leftover(tmp_path) == []


def test_a_path_under_a_file_is_one_line_naming_path_and_cause(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(RenderError) as caught:
        write_video(blocker / "clip.mp4", 5, MovingSquare(), 30)
    message = str(caught.value)
    assert "\n" not in message and str(blocker / "clip.mp4") in message and "Not a directory" in message
    assert leftover(tmp_path) == ["file"]


def test_a_missing_directory_is_named(tmp_path):
    with pytest.raises(RenderError, match="No such file or directory"):
        write_video(tmp_path / "nowhere" / "clip.mp4", 5, MovingSquare(), 30)


@pytest.mark.parametrize("pipelined", [True, False])
def test_a_producer_failing_midway_leaves_no_file_and_the_old_one_untouched(tmp_path, pipelined):
    path = tmp_path / "clip.mp4"
    path.write_bytes(b"old video")
    with pytest.raises(ValueError, match="drawing frame 12 failed"):
        write_video(path, 30, MovingSquare(fail_at=12), 30, pipelined=pipelined)
    assert leftover(tmp_path) == ["clip.mp4"] and path.read_bytes() == b"old video"


@pytest.mark.parametrize("pipelined", [True, False])
def test_a_full_disk_midway_is_one_line_and_leaves_no_file(tmp_path, monkeypatch, pipelined):
    real_encode = video_encode.FrameEncoder.encode

    def encode(self, buffer):
        if self.frames == 7:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        real_encode(self, buffer)

    monkeypatch.setattr(video_encode.FrameEncoder, "encode", encode)
    producer = MovingSquare()
    with pytest.raises(RenderError, match=r"cannot write video '.*clip\.webm': No space left on device$"):
        write_video(tmp_path / "clip.webm", 200, producer, 30, pipelined=pipelined)
    assert leftover(tmp_path) == []
    assert len(producer.asked) < 20  # drawing stops soon after the encoder fails


def test_an_existing_file_is_replaced_whole(tmp_path):
    path = tmp_path / "clip.gif"
    path.write_bytes(b"old")
    write_video(path, 5, MovingSquare(), 30)
    assert path.read_bytes()[:6] == b"GIF89a" and leftover(tmp_path) == ["clip.gif"]
    assert path.stat().st_mode & 0o777 == 0o644


def test_progress_is_told_every_frame_count_up_to_the_total(tmp_path):
    calls = []
    write_video(tmp_path / "clip.mp4", 12, MovingSquare(), 30, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (12, 12)
    assert all(total == 12 for _, total in calls)
    assert [done for done, _ in calls] == sorted(done for done, _ in calls)


def test_progress_bar_is_silent_off_a_terminal(tmp_path, capsys):
    with ProgressBar("Exporting", "frames") as bar:
        write_video(tmp_path / "clip.mp4", 12, MovingSquare(), 30, progress=bar)
    assert capsys.readouterr().err == ""
    stream = io.StringIO()
    with ProgressBar("Exporting", "frames", stream=stream) as bar:
        bar(1, 2)
    assert stream.getvalue() == ""


class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_bar_rewrites_one_line_on_a_terminal():
    stream, now = FakeTerminal(), [0.0]
    with ProgressBar("Exporting", "frames", stream=stream, clock=lambda: now[0]) as bar:
        for done in range(0, 301, 30):
            now[0] = done / 100
            bar(done, 300)
        bar(300, 300)
    text = stream.getvalue()
    assert text.endswith("\n") and text.count("\n") == 1
    lines = [line.removesuffix("\x1b[K") for line in text.strip("\n").split("\r") if line]
    assert lines[0].startswith("Exporting [") and "0/300 frames" in lines[0]
    assert "300/300 frames 100% ETA 0:00" in lines[-1]
    assert "150/300 frames  50% ETA 0:02" in lines[5]


def test_progress_line_fits_a_narrow_terminal():
    assert len(format_line("Exporting", "frames", 5, 10, 1.0, width=30)) <= 29


def test_side_by_side_puts_left_then_right():
    left = np.zeros((4, 3, 4), np.uint8)
    right = np.full((4, 2, 4), 9, np.uint8)
    both = side_by_side(left, right)
    assert both.shape == (4, 5, 4) and (both[:, :3] == 0).all() and (both[:, 3:] == 9).all()
    with pytest.raises(RenderError, match="heights 4 and 5"):
        side_by_side(left, np.zeros((5, 2, 4), np.uint8))


def test_the_switch_interval_is_restored_after_an_export_even_a_failed_one(tmp_path):
    before = sys.getswitchinterval()
    write_video(tmp_path / "clip.mp4", 5, MovingSquare(), 30)
    with pytest.raises(ValueError):
        write_video(tmp_path / "clip.mp4", 5, MovingSquare(fail_at=3), 30)
    assert sys.getswitchinterval() == before
