"""Pushes a body drawn into others clear of them with the physics, in a world of its neighbourhood only; no I/O.

A new body overlapping others (and not joined to them) is moved by the solver while everything else is held still
(thesis 3.2.4: bodies end flush). Only what the body can reach while being pushed out takes part: the bodies and
ropes within its own size of it, what is welded to it and what holds on to that. So the cost of a stroke does not
grow with the size of the sketch, and the result depends only on the scene, never on the history of a world.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import shapely
from shapely.geometry import LineString

from physink_tui.scene.components import BACKGROUND, Body, Joint, Rope, Scene, Spring
from physink_tui.scene.interpretation.body_shapes import body_geometry, body_size
from physink_tui.scene.interpretation.interpret import Near
from physink_tui.scene.physics.world import World

OVERLAP = 0.02
"""A new body overlapping another by more than this share of its area is pushed clear."""
OVERLAP_DONE = 0.002
"""...until it overlaps each by no more than this share."""
MAX_ROUNDS = 20
ROUND_STEPS = 30
"""Steps per round; the body's velocity is zeroed between rounds so it is put down, not thrown."""


def clear_overlaps(scene: Scene, created: tuple[str, ...], near_of: Callable[[Scene], Near],
                   canvas: tuple[float, float]) -> tuple[Scene, list[str]]:
    """Push each new body of ``created`` that overlaps others (not joined to it) clear of them, the others held
    still; a push that would leave the canvas is not made. Returns the scene and what to tell the user.

    ``near_of(scene)`` gives a spatial index of a scene's bodies (`interpret.Near`), brought in step with it.
    """
    notes = []
    for body_id in created:
        if body_id not in scene.components or scene.is_fixed(body_id):
            continue
        hit = overlapped(scene, body_id, near_of(scene))
        if not hit:
            continue
        pushed = push_clear(scene, body_id, hit)
        others, name = ", ".join(scene.called(h) for h in hit), scene.called(body_id)
        if not body_geometry(pushed.components[body_id]).intersects(shapely.box(0, 0, *canvas)):
            notes.append(f"{name} overlaps {others}; pushing it clear would put it off the canvas, so it stays "
                         "where it was drawn")
            continue
        scene = pushed
        notes.append(f"{name} overlapped {others}; the physics pushed it clear")
    return scene, notes


def overlapped(scene: Scene, body_id: str, near: Near | None = None) -> list[str]:
    """Ids of the bodies that ``body_id`` overlaps by more than `OVERLAP` of its area, not counting those joined to
    it, in scene order (``near``: a spatial index of the scene's bodies, see `interpret.Near`)."""
    area = body_geometry(scene.components[body_id])
    x0, y0, x1, y1 = area.bounds
    candidates = scene.bodies() if near is None else [scene.body(i) for i in reversed(near(area.bounds))]
    joined = {end for c in scene.components.values() if isinstance(c, Joint) and body_id in (c.a, c.b)
              for end in (c.a, c.b)}
    hit = []
    for b in candidates:
        if b.id == body_id or b.id in joined:
            continue
        geometry = body_geometry(b)
        bx0, by0, bx1, by1 = geometry.bounds
        close = bx0 <= x1 and x0 <= bx1 and by0 <= y1 and y0 <= by1
        if close and geometry.intersection(area).area > OVERLAP * area.area:
            hit.append(b.id)
    return hit


def push_clear(scene: Scene, body_id: str, hit: list[str]) -> Scene:
    """``scene`` with ``body_id`` (not fixed) pushed by the physics until it no longer overlaps the bodies ``hit``,
    everything else held still (what is welded to it moves with it).

    The world holds the neighbourhood within the body's size (`neighbourhood`); should what moves end further than
    that from where it was (so it might now meet a body the world did not hold), it is pushed again in a
    neighbourhood twice as wide, up to the whole sketch.
    """
    reach = body_size(scene.body(body_id))
    group = _weld_group(scene, body_id)
    while True:
        local = neighbourhood(scene, body_id, reach)
        world = World.from_scene(local, gravity=(0.0, 0.0))
        world.freeze_all_except(body_id)
        for _ in range(MAX_ROUNDS):  # the solver pushes a little each step; stop once it is clear
            world.step(ROUND_STEPS)
            world.set_velocity(body_id, (0.0, 0.0), 0.0)
            area = body_geometry(world.to_scene(local).components[body_id])
            if all(body_geometry(scene.components[h]).intersection(area).area <= OVERLAP_DONE * area.area
                   for h in hit):
                break
        world.unfreeze()
        moved = world.to_scene(local)
        travel = max(body_geometry(moved.components[b]).hausdorff_distance(body_geometry(scene.components[b]))
                     for b in group)
        if travel <= reach or len(local.components) == len(scene.components):
            return world.to_scene(scene)
        reach *= 2


def neighbourhood(scene: Scene, body_id: str, reach: float) -> Scene:
    """The part of ``scene`` that pushing ``body_id`` clear can touch, in scene order: bodies and ropes within
    ``reach`` of it, the bodies welded to it, whatever holds on to those (and the bodies at its other ends), and
    every joint, spring and rope among the bodies kept."""
    area = body_geometry(scene.components[body_id])
    x0, y0, x1, y1 = area.bounds
    x0, y0, x1, y1 = x0 - reach, y0 - reach, x1 + reach, y1 + reach
    group = _weld_group(scene, body_id)
    keep = set(group)
    for b in scene.bodies():
        bx0, by0, bx1, by1 = body_geometry(b).bounds
        if bx0 <= x1 and x0 <= bx1 and by0 <= y1 and y0 <= by1 and body_geometry(b).distance(area) <= reach:
            keep.add(b.id)
    holders = set()
    for c in scene.components.values():
        if isinstance(c, Body):
            continue
        if _ends(c) & group or (isinstance(c, Rope) and LineString(c.points).distance(area) <= reach):
            holders.add(c.id)
            keep.update(_ends(c) - {BACKGROUND})
    kept = {cid: c for cid, c in scene.components.items()
            if cid in keep or cid in holders or (not isinstance(c, Body) and _ends(c) <= keep | {BACKGROUND})}
    return replace(scene, components=kept)


def _ends(c: Joint | Spring | Rope) -> set[str]:
    if isinstance(c, Rope):
        return {e for e in (c.start_body, c.end_body) if e is not None}
    return {c.a, c.b}


def _weld_group(scene: Scene, body_id: str) -> set[str]:
    """``body_id`` and the bodies welded to it, directly or through others (not through the background)."""
    welds = [(c.a, c.b) for c in scene.components.values() if isinstance(c, Joint) and c.kind == "weld"
             and BACKGROUND not in (c.a, c.b)]
    group, frontier = {body_id}, [body_id]
    while frontier:
        me = frontier.pop()
        for a, b in welds:
            for x, y in ((a, b), (b, a)):
                if x == me and y not in group:
                    group.add(y)
                    frontier.append(y)
    return group
