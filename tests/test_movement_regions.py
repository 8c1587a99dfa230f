"""A movement skips testing a body's regions only while the answer cannot have changed: on random walks, the regions
it records are exactly those of testing every body at every frame (`qualitative.regions_at`)."""

from __future__ import annotations

import math
import random

import pytest

from physink_tui.scene.physics.state import Motion
from physink_tui.timeline.movement_record import OpenMovement, Regions
from physink_tui.timeline.qualitative import BodyOutline, bounds, placed, regions_at

OUTLINES = {
    "ball": BodyOutline("ball", tuple((10 * math.cos(k * math.pi / 8), 10 * math.sin(k * math.pi / 8))
                                      for k in range(16)), False),
    "plank": BodyOutline("plank", ((-60.0, -5.0), (60.0, -5.0), (60.0, 5.0), (-60.0, 5.0)), False),
    "box": BodyOutline("box", ((-20.0, -20.0), (20.0, -20.0), (20.0, 20.0), (-20.0, 20.0)), False),
    "peg": BodyOutline("peg", ((-3.0, -3.0), (3.0, -3.0), (0.0, 4.0)), False),
}
REACH = 150.0


def walk(rng: random.Random, frames: int) -> list[dict[str, Motion]]:
    """Every body's pose per frame: some still, some drifting and turning, with jumps now and then."""
    poses = {b: [rng.uniform(0, 400), rng.uniform(0, 300), rng.uniform(-3, 3)] for b in OUTLINES}
    steps = {b: (rng.choice((0.0, 0.5, 3.0)), rng.choice((0.0, 0.02, 0.2))) for b in OUTLINES}
    out = []
    for _ in range(frames):
        for b, pose in poses.items():
            size, turn = steps[b]
            pose[0] += rng.gauss(0, size)
            pose[1] += rng.gauss(0, size)
            pose[2] += rng.gauss(0, turn)
            if rng.random() < 0.01:
                pose[0], pose[1] = rng.uniform(0, 400), rng.uniform(0, 300)
        out.append({b: Motion(p[0], p[1], p[2], 0.0, 0.0, 0.0) for b, p in poses.items()})
    return out


@pytest.mark.parametrize("seed", range(20))
def test_skipping_records_the_regions_of_testing_every_frame(seed: int) -> None:
    rng = random.Random(seed)
    radius = {b: max(math.hypot(x, y) for x, y in o.hull) for b, o in OUTLINES.items()}
    regions = Regions(OUTLINES, REACH, radius)
    movement = OpenMovement("e1", ("ball",), {"ball": []})
    expected: dict[str, set[str]] = {}
    for t, poses in enumerate(walk(rng, 400)):
        regions.next_frame(poses)
        movement.record(t / 120, poses, False, radius, regions, 5.0)
        mover = poses["ball"]
        for other in sorted(OUTLINES.keys() - {"ball"}):
            found = regions_at((mover.x, mover.y), bounds(placed(OUTLINES[other], poses[other])), REACH)
            if found:
                expected.setdefault(other, set()).update(found)
    assert movement.crossed == expected
