"""Writes a video file from a frame-drawing callback, drawing, converting and encoding at once; draws no frame.

The caller's thread draws frame i+2 while one worker converts frame i+1 (RGBA->yuv420p in swscale) and another
encodes frame i (x264/libvpx); conversion and encoding release the GIL in C, so two cores are kept busy. The file
is written under a temporary name in the target folder and renamed only when complete: an error leaves no file.
"""

from __future__ import annotations

import os
import queue
import sys
import tempfile
import threading
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import av
import numpy as np

from physink_tui.errors import RenderError
from physink_tui.formats.atomic_write import fsync_directory
from physink_tui.progress import Progress
from physink_tui.render.video_encode import FrameEncoder
from physink_tui.render.video_spec import VideoSpec, check_fps, container_for

PIPELINE_DEPTH = 3
"""Staged frames that may wait for the encoder; the drawing thread blocks when all are taken."""

SWITCH_INTERVAL = 0.0005
"""Seconds a thread may hold the GIL while another waits for it (`sys.setswitchinterval`) during a pipelined
export. Python's default, 5 ms, lets the drawing thread keep the encoder waiting up to 5 ms each time a C call
(conversion, encoding, muxing) returns; 0.5 ms lets them resume almost at once (about 8% faster exports in
benchmarks/bench_video.py). The previous interval is restored when the export ends."""


@dataclass(frozen=True, slots=True)
class VideoReport:
    """What `write_video` wrote."""

    path: str
    """The finished file."""
    frames: int
    """Frames in the file (fewer than asked for when a GIF's frame rate is capped)."""
    seconds: float
    """Playing time of the file in seconds (frames / frame rate)."""
    bytes: int
    """Size of the file in bytes."""
    notes: tuple[str, ...] = ()
    """What the user should be told about how the file differs from what was asked (e.g. a GIF's lower rate)."""


FrameSource = Callable[[int], np.ndarray]
"""frame_at(i) -> (H, W, 4) uint8 RGBA for frame i; the array may be reused by the next call."""


def write_video(path: str | os.PathLike[str], count: int, frame_at: FrameSource, fps: int, *,
                progress: Progress | None = None, pipelined: bool = True) -> VideoReport:
    """Writes ``count`` frames, frame i being ``frame_at(i)``, to ``path`` at ``fps`` frames per second.

    The suffix of ``path`` chooses the format (.mp4: H.264 yuv420p; .webm: VP9 yuv420p; .gif: palette, at most
    30 fps, so some frames are skipped and never asked for); the first frame's shape sets the size, and every
    frame must have it. ``frame_at`` is called on the caller's thread, in order.

    Args:
        progress: told (frames written, frames in the file) as the file grows, e.g. a `ProgressBar`.
        pipelined: False draws, converts and encodes everything on the caller's thread (for benchmarks).

    Raises:
        RenderError: a bad path suffix, frame rate, count or frame size, or a file that cannot be written (one
            line naming the path and the cause); no file is left behind, not even the temporary one.
        Exception: whatever ``frame_at`` raises, unchanged, also leaving no file.
    """
    target = os.path.abspath(os.fspath(path))
    container_for(target)
    fps = check_fps(fps)
    if isinstance(count, bool) or not isinstance(count, int) or count < 1:
        raise RenderError(f"frame count {count!r} is not a positive whole number")
    directory, base = os.path.split(target)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{base}.", suffix=".part", dir=directory)
    except OSError as error:
        raise _write_error(target, error) from None
    os.close(fd)
    try:
        first = _checked_frame(frame_at(0), 0, None)
        spec = VideoSpec(target, first.shape[1], first.shape[0], fps)
        frames = _encode_file(tmp, spec, count, frame_at, first, progress, pipelined)
        _finish_file(tmp, target)
    except BaseException as error:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        if isinstance(error, (OSError, av.FFmpegError)):
            raise _write_error(target, error) from None
        raise
    fsync_directory(directory)
    return VideoReport(target, frames, frames / spec.output_fps, os.path.getsize(target), spec.notes)


def _encode_file(tmp: str, spec: VideoSpec, count: int, frame_at: FrameSource, first: np.ndarray,
                 progress: Progress | None, pipelined: bool) -> int:
    kind = spec.container
    options = {"movflags": "+faststart"} if kind.format == "mp4" else {}
    total = spec.output_count(count)
    with av.open(tmp, "w", format=kind.format, container_options=options) as container:
        encoder = FrameEncoder(container, spec)

        def frames() -> Any:
            yield first
            for j in range(1, total):
                yield _checked_frame(frame_at(spec.source_index(j)), spec.source_index(j), first.shape)

        if pipelined:
            _run_pipelined(encoder, frames(), total, progress)
        else:
            buffer = encoder.new_buffer()
            for done, rgba in enumerate(frames(), 1):
                encoder.stage(buffer, rgba)
                encoder.encode(encoder.convert(buffer))
                if progress is not None:
                    progress(done, total)
        encoder.finish()
    return total


def _run_pipelined(encoder: FrameEncoder, frames: Any, total: int, progress: Progress | None) -> None:
    """Stages frames on this thread, converts them on a second and encodes them on a third; the first error on
    any of them is raised here, after both workers have stopped."""
    free: queue.Queue[Any] = queue.Queue()
    for _ in range(PIPELINE_DEPTH):
        free.put(encoder.new_buffer())
    staged: queue.Queue[Any] = queue.Queue()
    converted: queue.Queue[Any] = queue.Queue(maxsize=PIPELINE_DEPTH)
    failure: list[BaseException] = []
    written = [0]

    def convert_all() -> None:
        while (buffer := staged.get()) is not None:
            if not failure:
                try:
                    converted.put(encoder.convert(buffer))
                except BaseException as error:  # handed to the drawing thread, which raises it
                    failure.append(error)
            free.put(buffer)  # also after a failure, so that the drawing thread never waits for ever
        converted.put(None)

    def encode_all() -> None:
        while (frame := converted.get()) is not None:
            if not failure:
                try:
                    encoder.encode(frame)
                    written[0] += 1
                except BaseException as error:
                    failure.append(error)

    workers = [threading.Thread(target=convert_all, name="physink-video-convert", daemon=True),
               threading.Thread(target=encode_all, name="physink-video-encode", daemon=True)]
    _fast_switching(True)
    for worker in workers:
        worker.start()
    try:
        for rgba in frames:
            buffer = free.get()
            if failure:
                break
            encoder.stage(buffer, rgba)
            staged.put(buffer)
            if progress is not None:
                progress(written[0], total)
    finally:
        staged.put(None)
        for worker in workers:
            worker.join()
        _fast_switching(False)
    if failure:
        raise failure[0]
    if progress is not None:
        progress(total, total)


_switching_lock = threading.Lock()
_switching_users = [0, 0.0]  # exports running, the interval before the first of them began


def _fast_switching(begin: bool) -> None:
    """Lowers the GIL switch interval while any pipelined export runs (several may overlap); restores it after."""
    with _switching_lock:
        if begin:
            if _switching_users[0] == 0:
                _switching_users[1] = sys.getswitchinterval()
                sys.setswitchinterval(min(_switching_users[1], SWITCH_INTERVAL))
            _switching_users[0] += 1
        else:
            _switching_users[0] -= 1
            if _switching_users[0] == 0:
                sys.setswitchinterval(_switching_users[1])


def _checked_frame(rgba: Any, index: int, shape: tuple[int, ...] | None) -> np.ndarray:
    if not isinstance(rgba, np.ndarray) or rgba.dtype != np.uint8 or rgba.ndim != 3 or rgba.shape[2] != 4:
        described = f"shape {rgba.shape!r} and dtype {rgba.dtype}" if isinstance(rgba, np.ndarray) else type(rgba)
        raise RenderError(f"frame {index} has {described}; expected (height, width, 4) uint8 RGBA")
    if shape is not None and rgba.shape != shape:
        raise RenderError(f"frame {index} has shape {rgba.shape!r}; the first frame had {shape!r}")
    return rgba


def _finish_file(tmp: str, target: str) -> None:
    fd = os.open(tmp, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)
    os.chmod(tmp, 0o644)
    os.replace(tmp, target)


def _write_error(target: str, error: BaseException) -> RenderError:
    cause = getattr(error, "strerror", None) or str(error) or type(error).__name__
    return RenderError(f"cannot write video {target!r}: {cause}")
