"""What a video file will be (container, codec, size, frame rate), checked before any frame is drawn; writes nothing."""

from __future__ import annotations

import os
from dataclasses import dataclass
from numbers import Integral

from physink_tui.errors import RenderError
from physink_tui.render.limits import MAX_FPS, MAX_SIDE, MIN_SIDE

GIF_MAX_FPS = 30
"""A GIF is written at no more than this rate: its frame delays are whole hundredths of a second and players
stretch delays under 2/100 s to 1/10 s, so 60 fps would play slower, not smoother."""


@dataclass(frozen=True, slots=True)
class Container:
    """One supported kind of video file, chosen by the path's suffix."""

    suffix: str
    """Lower-case file name suffix with its dot, e.g. ``".mp4"``."""
    format: str
    """FFmpeg muxer name."""
    codec: str
    """FFmpeg encoder name."""
    pix_fmt: str
    """Pixel format handed to the encoder."""
    description: str
    """What a user is told the file holds."""


CONTAINERS: dict[str, Container] = {
    ".mp4": Container(".mp4", "mp4", "libx264", "yuv420p", "MP4 (H.264, yuv420p)"),
    ".webm": Container(".webm", "webm", "libvpx-vp9", "yuv420p", "WebM (VP9, yuv420p)"),
    ".gif": Container(".gif", "gif", "gif", "pal8", "GIF (256-colour palette)"),
}


@dataclass(frozen=True, slots=True)
class VideoSpec:
    """A checked description of the video to write; constructing one raises `RenderError` on a bad value.

    >>> spec = VideoSpec("demo.mp4", 1280, 720, 30)
    >>> spec.container.codec, spec.output_fps
    ('libx264', 30)
    >>> VideoSpec("demo.gif", 640, 360, 60).output_fps
    30
    """

    path: str
    """Where the video goes; its suffix (.mp4, .webm, .gif, any case) chooses the container and codec."""
    width: int
    """Frame width in pixels, MIN_SIDE..MAX_SIDE; even for MP4 and WebM (yuv420p halves the colour resolution)."""
    height: int
    """Frame height in pixels, with the same bounds as width."""
    fps: int
    """Frames per second of the frames the caller draws, 1..MAX_FPS."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "path", os.fspath(self.path))
        container_for(self.path)
        check_fps(self.fps)
        for name in ("width", "height"):
            check_side(name, getattr(self, name), self.container)

    @property
    def container(self) -> Container:
        """The container and codec chosen by the path's suffix."""
        return container_for(self.path)

    @property
    def output_fps(self) -> int:
        """Frames per second written to the file: ``fps``, or at most GIF_MAX_FPS for a GIF."""
        if self.container.format == "gif":
            return min(self.fps, GIF_MAX_FPS)
        return self.fps

    def output_count(self, count: int) -> int:
        """How many frames the file holds when the caller has ``count`` frames (fewer when a GIF drops some)."""
        return -(-count * self.output_fps // self.fps)

    def source_index(self, j: int) -> int:
        """Which of the caller's frames is the file's frame ``j`` (the same index unless a GIF drops frames)."""
        return j * self.fps // self.output_fps

    @property
    def notes(self) -> tuple[str, ...]:
        """What the user should be told about how the file differs from what was asked."""
        if self.output_fps != self.fps:
            return (f"{os.path.basename(self.path)}: GIF written at {self.output_fps} fps instead of {self.fps} "
                    "(GIF frame delays are whole hundredths of a second; players slow shorter ones down)",)
        return ()


def container_for(path: str | os.PathLike[str]) -> Container:
    """The container chosen by ``path``'s suffix; `RenderError` naming the suffix when none fits."""
    suffix = os.path.splitext(os.fspath(path))[1].lower()
    try:
        return CONTAINERS[suffix]
    except KeyError:
        known = ", ".join(CONTAINERS)
        raise RenderError(f"cannot tell the video format of {os.fspath(path)!r}: "
                          f"suffix {suffix!r} is not one of {known}") from None


def check_fps(fps: object) -> int:
    """``fps`` as an int when it is a whole number of frames per second from 1 to MAX_FPS; else `RenderError`."""
    if isinstance(fps, bool) or not isinstance(fps, Integral):
        if isinstance(fps, float) and fps.is_integer():
            fps = int(fps)
        else:
            raise RenderError(f"frame rate {fps!r} is not a whole number of frames per second "
                              f"(expected 1 to {MAX_FPS}, usually 30 or 60)")
    if not 1 <= int(fps) <= MAX_FPS:
        raise RenderError(f"frame rate {fps!r} is out of range (expected 1 to {MAX_FPS} fps, usually 30 or 60)")
    return int(fps)


def check_side(name: str, value: object, container: Container) -> int:
    """``value`` as an int when it is a usable ``name`` (width or height) for ``container``; else `RenderError`."""
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise RenderError(f"video {name} {value!r} is not a whole number of pixels")
    if not MIN_SIDE <= int(value) <= MAX_SIDE:
        raise RenderError(f"video {name} {value!r} is out of range (expected {MIN_SIDE} to {MAX_SIDE} pixels)")
    if container.pix_fmt == "yuv420p" and value % 2:
        raise RenderError(f"video {name} {value!r} must be even for {container.description}: yuv420p stores colour "
                          f"at half resolution (try {value - 1} or {value + 1})")
    return int(value)
