"""Adjust mode (thesis 3.2.4): a dwell on a body grabs it; it follows the pen with every other body frozen and is
put down flush where the pen lifts. The world steps with the input's time on the fixed dt, never by wall time."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace

from physink_tui.input.pen.gestures import Gesture, PenMove, StrokeEnded, Tap
from physink_tui.scene.components import Scene
from physink_tui.scene.interpretation.body_shapes import body_size
from physink_tui.scene.interpretation.interpret import bodies_at
from physink_tui.scene.physics.state import Pose
from physink_tui.scene.physics.stepping import put_down, steps_until
from physink_tui.scene.physics.world import World
from physink_tui.session.modes.base import Host, Mode, ModeName
from physink_tui.timeline.events import Timeline

ADJUST_CENTRE = 0.25
"""A body grabbed within this share of its size from its centre moves without turning."""


class AdjustMode:
    """One body being moved by the pen, the others frozen (see the module docstring)."""

    name = ModeName.ADJUST

    def __init__(self, host: Host, body_id: str, world: World, t: float, offset: tuple[float, float]) -> None:
        self.host = host
        self.body_id = body_id
        self.world: World | None = world
        self.origin = t  # input time of the world's first step
        self.steps = 0
        self.offset = offset

    @classmethod
    def start(cls, host: Host, point: tuple[float, float], t: float) -> AdjustMode | None:
        """Dwelling at ``point`` (canvas units) on a body grabs it: grabbed near its centre it slides, near an edge
        it turns about the pen as well. None when no body is there."""
        scene = host.document.scene
        found = bodies_at(scene, point)
        if not found:
            return None
        body = found[0]
        world = World.from_scene(scene, gravity=(0.0, 0.0))
        world.freeze_all_except(body.id)
        if math.dist(point, body.position) < ADJUST_CENTRE * body_size(body):
            offset = (point[0] - body.position[0], point[1] - body.position[1])  # the centre keeps its offset
            world.drag(body.id, body.position, body.position, rotate=False)
        else:
            offset = (0.0, 0.0)
            world.drag(body.id, point, point, rotate=True)
        host.tell(f"moving {scene.called(body.id)}", t)
        return cls(host, body.id, world, t, offset)

    def gesture(self, g: Gesture) -> Mode | None:
        if self.world is None:  # put down already: the session goes back to sketching
            return None
        if isinstance(g, PenMove) and g.touching:
            x, y = g.x * self.host.canvas[0], g.y * self.host.canvas[1]
            self.world.drag(self.body_id, (x - self.offset[0], y - self.offset[1]))
        elif isinstance(g, StrokeEnded | Tap):
            self.close(g.t)
        return None

    @property
    def finished(self) -> bool:
        """The pen lifted (or the mode was closed): the session goes back to sketching."""
        return self.world is None

    def advance(self, t: float) -> bool:
        if self.world is None:
            return False
        target = steps_until(t, self.origin, self.world.dt)
        if target <= self.steps:
            return False
        self.world.step(target - self.steps)
        self.steps = target
        return True

    def close(self, t: float) -> None:
        """Put the body down where the pen left it, flush against what it was pushed into; one undoable action."""
        if self.world is None:
            return
        world, self.world = self.world, None
        put_down(world, self.body_id)
        document = self.host.document
        moved = world.to_scene(document.scene)
        if moved != document.scene:
            self.host.commit(replace(document, scene=moved), f"adjust {self.body_id}")

    def poses(self) -> Mapping[str, Pose]:
        if self.world is None:
            return {b.id: Pose(*b.position, b.angle) for b in self.host.document.scene.bodies()}
        return {b: self.world.pose(b) for b in self.world.body_ids()}

    def timeline(self) -> Timeline | None:
        return self.host.document.timeline

    def scene(self) -> Scene:
        return self.host.document.scene
