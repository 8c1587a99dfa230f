"""What an export shows: a project's demonstration (or a still of its scene) at a size, frame rate and theme, as a
video, numbered PNG frames or one picture; drawing is the renderer's job, encoding `video.write_video`'s, and the
choice of files and folders the command's."""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

from physink_tui.render.frame import FrameContent, frame_times
from physink_tui.render.frames import Demonstration
from physink_tui.render.images import write_png
from physink_tui.render.renderer import Renderer
from physink_tui.render.video import write_video
from physink_tui.scene.components import Scene
from physink_tui.timeline.events import Timeline

STILL_SECONDS = 1.0
"""How long the video of a project without a timeline shows its scene."""
FRAME_NAME = "{:05d}.png"
"""Frame files: ``00000.png``, ``00001.png``, ... in time order."""


@dataclass(frozen=True, slots=True)
class Look:
    """How pictures are drawn: pixel size, frames a second, theme."""

    width: int = 1280
    height: int = 800
    fps: int = 30
    theme: str = "light"


class Export:
    """One project's pictures: `video`, `frames` and `still` share one renderer and one prepared timeline.

    ``overlay``: another timeline of the same scene (a simulation's) whose paths are drawn in the theme's
    simulation colour over the demonstration (thesis figures 2-17 and 3-21: demonstration green, simulation red).

    ``notes`` collects what the user should be told (an empty project, no timeline, a GIF's capped rate).
    """

    def __init__(self, scene: Scene, timeline: Timeline | None, canvas: tuple[float, float], look: Look,
                 overlay: Timeline | None = None) -> None:
        self.scene, self.canvas, self.look = scene, canvas, look
        self.renderer = Renderer(look.width, look.height, canvas, look.theme)
        self.notes: list[str] = []
        if not scene.components:
            self.notes.append("the project has nothing in it: the pictures show an empty canvas")
        recorded = timeline if timeline is not None and any(ev.type != "start" for ev in timeline.events) else None
        self.demonstration = Demonstration(scene, recorded, canvas) if recorded is not None else None
        self.overlay = Demonstration(scene, overlay, canvas) if overlay is not None and overlay.events else None
        if self.demonstration is None:
            self.times: tuple[float, ...] = tuple(k / look.fps for k in range(max(1, round(STILL_SECONDS * look.fps))))
        else:
            longest = max(self.demonstration.duration, self.overlay.duration if self.overlay else 0.0)
            self.times = frame_times(longest, look.fps)

    def content(self, t: float) -> FrameContent:
        """What the picture at time ``t`` shows (the scene as drawn when there is no timeline)."""
        if self.demonstration is None:
            return FrameContent(self.scene, self.canvas)
        frame = self.demonstration.frame(t)
        if self.overlay is None:
            return frame
        return replace(frame, trails=(*frame.trails, *self.overlay.trails_at(t, "simulation")))

    def video(self, path: str | os.PathLike[str], progress: Callable[[int, int], None] | None = None) -> None:
        """The demonstration as a video at ``path`` (a one-second still without a timeline)."""
        if self.demonstration is None:
            self.notes.append(f"{os.fspath(path)}: the project has no timeline (nothing was demonstrated), so the "
                              f"video is a {STILL_SECONDS:g}-second still of the scene")
        report = write_video(path, len(self.times), lambda i: self.renderer.render(self.content(self.times[i])),
                             self.look.fps, progress=progress)
        self.notes.extend(f"{os.fspath(path)}: {note}" for note in report.notes)

    def frames(self, folder: str | os.PathLike[str], progress: Callable[[int, int], None] | None = None) -> int:
        """Every frame of the video as ``folder/NNNNN.png``; returns how many."""
        out = Path(folder)
        for i, t in enumerate(self.times):
            write_png(out / FRAME_NAME.format(i), self.renderer.render(self.content(t)))
            if progress is not None:
                progress(i + 1, len(self.times))
        return len(self.times)

    def still(self, path: str | os.PathLike[str], at: float | None = None) -> float:
        """One picture at timeline time ``at`` (default: the end, where everything has happened); returns the time
        drawn."""
        t = self.times[-1] if at is None else min(max(at, 0.0), self.times[-1])
        write_png(path, self.renderer.render(self.content(t)))
        return t
