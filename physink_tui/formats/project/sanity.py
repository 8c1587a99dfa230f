"""The one check of a project's values every command makes before using it (`load_project`: export, simulate, the
TUI's start and Load; a session's ``load`` command: the kiosk, the TUI, replays): sizes within sane bounds, times
within the timeline's, outlines the physics accepts; reads no file (the format itself is `codec`'s).

A project can be well-formed JSON and still be unusable: a canvas 1e300 units wide overflows the recorder, a ball of
radius 1e8 never settles, an event ending at t = 1e8 asks for three billion video frames, and a zero-area outline
is refused by the physics only once a simulation starts.
`check_values` refuses each of them when the project is read, naming the file and the JSON path
(``p.json: components[1].radius: expected a number from 0.01 to 1600 (the canvas's larger side), got 100000000.0``),
so every command accepts and refuses the same projects.
"""

from __future__ import annotations

import math

from physink_tui.errors import SceneError
from physink_tui.formats.json_checks import Place
from physink_tui.formats.project.codec import Project
from physink_tui.scene.components import Body, Joint, Rope, Scene, Spring
from physink_tui.scene.physics.outlines import outline_problem
from physink_tui.timeline.events import Timeline

CANVAS_MIN = 1.0
CANVAS_MAX = 100_000.0
"""A canvas side is from 1 to 100,000 canvas units (the TUI's and the kiosk's are 800-1600)."""
MIN_SIZE = 0.01
"""The smallest radius, and the smallest extent of an outline, in canvas units."""
MARGIN = 1.0
"""Where things may be drawn: the canvas grown by this many canvas sizes on every side."""
MAX_DENSITY = 1e6
MAX_FRICTION = 1e3
MAX_K = 1e9
MAX_DURATION = 3600.0
"""The latest time a timeline may reach, in seconds (an hour of demonstration; a video of it is 108,000 frames)."""


def check_project(project: Project, where: Place | str) -> Project:
    """The project, once every value is one every command can use; else ``where.error`` (`SceneError` when
    ``where`` is a file name) naming the JSON path of the first that is not (see the module docstring).

    Args:
        project: a project as the codec read it (components in file order, so paths index ``components``).
        where: the file (or journal line) the project comes from.
    """
    if isinstance(where, str):
        where = Place(where, SceneError)
    check_values(project.scene, project.canvas, project.timeline, where)
    if project.demonstration is not None:  # an adopted simulation's demonstration, kept beside it
        _timeline(project.demonstration, project.scene, where, "demonstration.events")
    return project


def check_values(project_scene: Scene, canvas: tuple[float, float], timeline: Timeline | None, where: Place,
                 timeline_path: str = "timeline.events") -> None:
    """`check_project` of a project's parts; ``timeline_path`` is the JSON path of the timeline's event list."""
    width, height = canvas
    for key, side in (("canvas.width", width), ("canvas.height", height)):
        if not CANVAS_MIN <= side <= CANVAS_MAX:
            raise where.bad(key, f"a number from {CANVAS_MIN:g} to {CANVAS_MAX:g}", side)
    largest = max(width, height)
    box = (-MARGIN * width, -MARGIN * height, (1 + MARGIN) * width, (1 + MARGIN) * height)
    inside = f"a point within the canvas or {MARGIN:g} canvas size of it ({_box(box)})"
    for i, c in enumerate(project_scene.components.values()):
        path = f"components[{i}]"
        if isinstance(c, Body):
            _body(c, path, where, largest, box, inside)
        elif isinstance(c, Joint):
            _point(c.anchor, f"{path}.anchor", where, box, inside)
        elif isinstance(c, Rope):
            for j, p in enumerate(c.points):
                _point(p, f"{path}.points[{j}]", where, box, inside)
        elif isinstance(c, Spring):
            _point(c.anchor_a, f"{path}.anchor_a", where, box, inside)
            _point(c.anchor_b, f"{path}.anchor_b", where, box, inside)
            diagonal = math.hypot(width, height)
            if c.rest_length > 2 * diagonal:
                raise where.bad(f"{path}.rest_length", f"a number from 0 to {2 * diagonal:.6g} (twice the canvas's "
                                "diagonal)", c.rest_length)
            if c.k > MAX_K:
                raise where.bad(f"{path}.k", f"a number > 0 and at most {MAX_K:g}", c.k)
    if timeline is not None:
        _timeline(timeline, project_scene, where, timeline_path)


def _box(box: tuple[float, float, float, float]) -> str:
    return f"x {box[0]:g} to {box[2]:g}, y {box[1]:g} to {box[3]:g}"


def _point(p: tuple[float, float], path: str, where: Place, box: tuple[float, float, float, float],
           inside: str) -> None:
    if not (box[0] <= p[0] <= box[2] and box[1] <= p[1] <= box[3]):
        raise where.bad(path, inside, list(p))


def _body(b: Body, path: str, where: Place, largest: float, box: tuple[float, float, float, float],
          inside: str) -> None:
    _point(b.position, f"{path}.position", where, box, inside)
    if b.shape == "circle":
        if not MIN_SIZE <= b.radius <= largest:
            raise where.bad(f"{path}.radius", f"a number from {MIN_SIZE:g} to {largest:g} (the canvas's larger "
                            "side)", b.radius)
    else:
        xs = [x for x, _ in b.outline]
        ys = [y for _, y in b.outline]
        extent = max(max(xs) - min(xs), max(ys) - min(ys))
        reach = max(math.hypot(x, y) for x, y in b.outline)
        if not MIN_SIZE <= extent or reach > 2 * largest:
            raise where.bad(f"{path}.outline", f"an outline at least {MIN_SIZE:g} across and within "
                            f"{2 * largest:g} of the body's position (twice the canvas's larger side)", list(b.outline))
        problem = outline_problem(b)
        if problem is not None:
            raise where.bad(f"{path}.outline", f"an outline the physics can use ({problem})", list(b.outline))
    m = b.material
    if m.density > MAX_DENSITY:
        raise where.bad(f"{path}.material.density", f"a number > 0 and at most {MAX_DENSITY:g}", m.density)
    if m.friction > MAX_FRICTION:
        raise where.bad(f"{path}.material.friction", f"a number from 0 to {MAX_FRICTION:g}", m.friction)


def named(timeline: Timeline) -> set[str]:
    """Every component id the timeline's events name (their components, sides, regions and tracks).

    A timeline may name a component the scene no longer has (the user erased it after demonstrating, and saved):
    such a project still loads (it is the user's work); `physink simulate` refuses it and `physink export` says so.
    """
    return {c for ev in timeline.events for c in (*ev.components, *(c for c, _ in ev.sides),
                                                  *(c for c, _ in ev.regions), *(c for c, _ in ev.tracks))}


def _timeline(timeline: Timeline, scene: Scene, where: Place, events: str) -> None:
    for i, ev in enumerate(timeline.events):
        path = f"{events}[{i}]"
        if ev.t1 > MAX_DURATION or ev.t0 < 0:
            key, value = (f"{path}.t1", ev.t1) if ev.t1 > MAX_DURATION else (f"{path}.t0", ev.t0)
            raise where.bad(key, f"a time from 0 to {MAX_DURATION:g} s", value)
        rows = [(f"{path}.trajectory[{j}][0]", p.t) for j, p in enumerate(ev.trajectory)]
        rows += [(f"{path}.tracks[{k}].trajectory[{j}][0]", p.t) for k, (_, frames) in enumerate(ev.tracks)
                 for j, p in enumerate(frames)]
        for key, t in rows:
            if not 0 <= t <= MAX_DURATION:
                raise where.bad(key, f"a time from 0 to {MAX_DURATION:g} s", t)

