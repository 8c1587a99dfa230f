"""The live world follows the sketch through strokes, welds, pins, ropes, springs, erasing, moving, undo and redo,
and always holds what a world built afresh from the same scene would hold."""

from __future__ import annotations

import random

import pymunk
import pytest

from physink_tui.scene.components import BACKGROUND, Body, Scene
from physink_tui.scene.interpretation.interpret import interpret
from physink_tui.scene.physics.live import LiveWorld
from physink_tui.scene.physics.world import World
from physink_tui.scene.recognition.primitives import Box, Circle, Curve, Helix, Line, Recognition, XSymbol


def describe(world: World, scene: Scene) -> dict:
    """What a world holds, by component id (pymunk objects compared through what they do)."""
    space = world.pymunk_parts.space
    live = set(space.constraints)
    out = {"bodies": [], "holders": {}, "counts": (len(space.bodies), len(space.shapes), len(live))}
    for bid in world.body_ids():
        b = world.pymunk_parts.bodies[bid]
        mass = round(b.mass, 6) if b.body_type == pymunk.Body.DYNAMIC else None
        out["bodies"].append((bid, b.body_type, round(b.position.x, 6), round(b.position.y, 6), round(b.angle, 9),
                              len(world.pymunk_parts.shapes[bid]), mass))
    for cid, c in scene.components.items():
        if not isinstance(c, Body):
            parts = world.pymunk_parts.constraints.get(cid, ())
            out["holders"][cid] = sorted((type(p).__name__, p in live) for p in parts)
    return out


def random_action(rng: random.Random, scene: Scene) -> Scene:
    bodies = scene.bodies()
    roll = rng.random()
    x, y = rng.uniform(100, 1500), rng.uniform(100, 900)
    if not bodies or roll < 0.3:
        shape = rng.choice(("box", "circle", "line"))
        geometry = {"box": Box((x, y), rng.uniform(30, 200), rng.uniform(10, 60), rng.uniform(-1, 1)),
                    "circle": Circle((x, y), rng.uniform(10, 40)),
                    "line": Line((x, y), (x + rng.uniform(-200, 200), y + rng.uniform(-100, 100)))}[shape]
        return interpret(scene, Recognition(shape, 1.0, geometry), []).scene
    body = rng.choice(bodies)
    bx, by = body.position
    if roll < 0.45:  # an X on a body
        x_symbol = XSymbol((bx, by), Line((bx - 8, by - 8), (bx + 8, by + 8)), Line((bx - 8, by + 8), (bx + 8, by - 8)))
        return interpret(scene, Recognition("x", 1.0, x_symbol), [[(bx - 8, by - 8), (bx + 8, by + 8)]]).scene
    if roll < 0.55:  # a pin
        ring = [(bx + 3, by), (bx, by + 3), (bx - 3, by), (bx, by - 3)]
        return interpret(scene, Recognition("circle", 1.0, Circle((bx, by), 3.0)), [ring]).scene
    if roll < 0.65:  # a rope from this body to another (or nowhere)
        other = rng.choice(bodies).position
        path = [(bx + (other[0] - bx) * k / 10, by + (other[1] - by) * k / 10 + 30 * (k * (10 - k)) / 25)
                for k in range(11)]
        curve = Curve(tuple(path[:1] + path[3:4] + path[6:7] + path[10:]))
        return interpret(scene, Recognition("curve", 1.0, curve), [path]).scene
    if roll < 0.7:  # a spring hanging from a fixed body
        fixed = [b for b in bodies if scene.is_fixed(b.id)]
        if fixed:
            fx, fy = fixed[0].position
            path = [(fx, fy + 6 * k) for k in range(20)]
            return interpret(scene, Recognition("helix", 1.0, Helix(path[0], path[-1], 8, 4)), [path]).scene
        return scene
    if roll < 0.8:  # erase it (and what holds on to it)
        return scene.remove(body.id, *scene.attached_to(body.id))
    if roll < 0.9:  # move it, as adjusting does: through a world, which carries what it holds
        world = World.from_scene(scene, gravity=(0.0, 0.0))
        world.place(body.id, (bx + rng.uniform(-50, 50), by + rng.uniform(-50, 50), rng.uniform(-0.5, 0.5)))
        return world.to_scene(scene)
    from dataclasses import replace
    return scene.update(replace(body, label=f"thing {rng.randrange(100)}"))


@pytest.mark.parametrize("seed", range(6))
def test_the_live_world_matches_a_world_built_afresh_through_edits_undo_and_redo(seed: int) -> None:
    rng = random.Random(seed)
    scenes = [Scene()]
    live = LiveWorld.from_scene(scenes[0])
    for _ in range(60):
        if len(scenes) > 2 and rng.random() < 0.15:  # undo a few steps, or redo to a later one
            scene = scenes[rng.randrange(len(scenes))]
        else:
            scene = random_action(rng, scenes[-1])
        scenes.append(scene)
        live.sync(scene)
        assert describe(live, scene) == describe(World.from_scene(scene, gravity=(0.0, 0.0)), scene)
        assert live.scene is scene
    assert any(c for s in scenes for c in s.components.values() if getattr(c, "b", None) == BACKGROUND)


def test_the_sessions_world_follows_strokes_erasing_adjusting_undo_and_redo() -> None:
    from test_session import box_points, circle_points, pen_header, pen_stroke

    from physink_tui.formats.journal.entries import CommandEntry, PenEntry
    from physink_tui.session.session import Session

    entries = pen_stroke(0.0, box_points(0.1, 0.6, 0.4, 0.7))                      # a platform
    entries += pen_stroke(1.0, [(0.23 + 0.004 * k, 0.63 + 0.004 * k) for k in range(11)])
    entries += pen_stroke(1.5, [(0.27 - 0.004 * k, 0.63 + 0.004 * k) for k in range(11)])  # welded by an X
    entries += pen_stroke(3.5, circle_points(0.6, 0.3, 0.05))                        # a ball
    entries += pen_stroke(4.5, circle_points(0.3, 0.58, 0.04))                       # a ball drawn into the platform
    entries += pen_stroke(6.0, [(0.55 + 0.01 * k, 0.3) for k in range(11)], eraser=True)  # the first ball erased
    t = 7.0  # dwell on the second ball, then drag it
    entries.append(PenEntry(t, 0.3, 0.55, 0.0, False, True, False, False, False))
    entries += [PenEntry(t + 0.01 * k, 0.3, 0.55, 0.5, True, True, False, False, False) for k in range(1, 51)]
    entries += [PenEntry(t + 0.5 + 0.01 * k, 0.3 + 0.003 * k, 0.55 - 0.002 * k, 0.5, True, True, False, False, False)
                for k in range(1, 51)]
    entries.append(PenEntry(t + 1.1, 0.45, 0.45, 0.0, False, True, False, False, False))
    entries += [CommandEntry(9.0, "undo", ()), CommandEntry(9.1, "undo", ()), CommandEntry(9.2, "redo", ()),
                CommandEntry(9.3, "undo", ()), CommandEntry(9.4, "undo", ()), CommandEntry(9.5, "redo", ()),
                CommandEntry(9.6, "clear", ()), CommandEntry(9.7, "undo", ())]
    session = Session.from_header(pen_header())
    seen = set()
    for entry in sorted(entries, key=lambda e: e.t):
        session.handle(entry)
        scene = session.scene
        assert describe(session.world, scene) == describe(World.from_scene(scene, gravity=(0.0, 0.0)), scene)
        seen.add(len(scene.bodies()))
    assert {0, 1, 2, 3} <= seen and session.history.last_description() is not None


def test_a_spring_or_rope_between_fixed_bodies_builds_a_world() -> None:
    scene = interpret(Scene(), Recognition("box", 1.0, Box((100.0, 100.0), 60.0, 20.0, 0.0)), []).scene
    scene = interpret(scene, Recognition("box", 1.0, Box((300.0, 100.0), 60.0, 20.0, 0.0)), []).scene
    for x in (100.0, 300.0):
        arms = XSymbol((x, 100.0), Line((x - 8, 92.0), (x + 8, 108.0)), Line((x - 8, 108.0), (x + 8, 92.0)))
        scene = interpret(scene, Recognition("x", 1.0, arms), [[(x - 8, 92.0), (x + 8, 108.0)]]).scene
    coil = [(100.0, 100.0 + 6 * k) for k in range(20)]  # hangs from a fixed box, its end on nothing
    scene = interpret(scene, Recognition("helix", 1.0, Helix(coil[0], coil[-1], 8, 4)), [coil]).scene
    path = [(100.0 + 20 * k, 100.0 + 40 - abs(k - 5) * 8) for k in range(11)]  # from one fixed box to the other
    scene = interpret(scene, Recognition("curve", 1.0, Curve((path[0], path[3], path[7], path[10]))), [path]).scene
    assert {type(c).__name__ for c in scene.components.values()} == {"Body", "Joint", "Spring", "Rope"}
    world = World.from_scene(scene)
    world.step(10)
    assert world.pose("b1") == (100.0, 100.0, 0.0)


@pytest.mark.parametrize("seed", range(3))
def test_the_live_worlds_index_gives_interpretation_the_same_answers_as_trying_every_body(seed: int) -> None:
    from physink_tui.scene.interpretation.interpret import bodies_at
    from physink_tui.scene.physics.overlaps import overlapped

    rng = random.Random(seed)
    scene = Scene()
    live = LiveWorld.from_scene(scene)
    for _ in range(40):
        scene = random_action(rng, scene)
        live.sync(scene)
        for _ in range(10):
            x, y = rng.uniform(0, 1600), rng.uniform(0, 1000)
            reach = rng.choice((0.0, 30.0))
            assert bodies_at(scene, (x, y), reach=reach) == bodies_at(scene, (x, y), reach=reach, near=live.bodies_in)
            d = rng.uniform(5, 40)
            arms = XSymbol((x, y), Line((x - d, y - d), (x + d, y + d)), Line((x - d, y + d), (x + d, y - d)))
            strokes = [[(x - d, y - d), (x + d, y + d)], [(x - d, y + d), (x + d, y - d)]]
            ring = [(x + d / 4, y), (x, y + d / 4), (x - d / 4, y), (x, y - d / 4)]
            for rec, points in ((Recognition("x", 1.0, arms), strokes),
                                (Recognition("circle", 1.0, Circle((x, y), d / 4)), [ring]),
                                (Recognition("line", 1.0, Line((x - d, y), (x + d, y))), [[(x - d, y), (x + d, y)]])):
                assert interpret(scene, rec, points) == interpret(scene, rec, points, near=live.bodies_in)
        for body in scene.bodies():
            assert overlapped(scene, body.id) == overlapped(scene, body.id, near=live.bodies_in)


def test_the_index_finds_the_edge_of_a_very_long_lines_strip() -> None:
    from physink_tui.scene.interpretation.interpret import bodies_at

    scene = interpret(Scene(), Recognition("line", 1.0, Line((0.0, 500.0), (6000.0, 500.0))), []).scene
    live = LiveWorld.from_scene(scene)  # the strip is 24 units either side; the collision segment 2
    assert [b.id for b in bodies_at(scene, (3000.0, 522.0), near=live.bodies_in)] == ["b1"]
