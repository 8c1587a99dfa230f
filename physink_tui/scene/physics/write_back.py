"""Writes a world's poses back into its scene: bodies where they are now, and the joint anchors, spring ends and
rope points they carry moved along; stepping and queries are world.py's."""

from __future__ import annotations

import math
from dataclasses import replace

import pymunk

from physink_tui.scene.components import Body, Joint, Point, Rope, Scene, Spring
from physink_tui.scene.physics.build import Built


def scene_from(built: Built, scene: Scene) -> Scene:
    """``scene`` with its bodies at their current poses in ``built``, and the joints, springs and ropes that they
    carry moved along (anchors follow their bodies; a rope's points become its link ends). Components the world does
    not know are left as they are; nothing moved, nothing changes (values come back bit for bit).
    """
    out = dict(scene.components)
    for cid, c in scene.components.items():
        if isinstance(c, Body) and cid in built.z:
            body = built.bodies[cid]
            pose = (body.position.x, body.position.y, body.angle)
            if pose != built.rest_pose[body]:
                out[cid] = replace(c, position=pose[:2], angle=pose[2])
        elif cid in built.carriers:
            carriers = built.carriers[cid]
            if isinstance(c, Joint):
                out[cid] = replace(c, anchor=_carry(built, c.anchor, carriers[0]))
            elif isinstance(c, Spring):
                out[cid] = replace(c, anchor_a=_carry(built, c.anchor_a, carriers[0]),
                                   anchor_b=_carry(built, c.anchor_b, carriers[1]))
            elif isinstance(c, Rope):
                path = built.paths[cid]
                out[cid] = replace(c, points=tuple(_carry(built, p, link) for p, link in zip(path, carriers,
                                                                                             strict=True)))
    return replace(scene, components=out)


def _carry(built: Built, point: Point, body: pymunk.Body) -> Point:
    """Where ``point`` (where it was when built, fixed to ``body``) is now."""
    x0, y0, a0 = built.rest_pose[body]
    x, y, a = body.position.x, body.position.y, body.angle
    if (x, y, a) == (x0, y0, a0):
        return point
    dx, dy = point[0] - x0, point[1] - y0
    c, s = math.cos(a - a0), math.sin(a - a0)
    return x + c * dx - s * dy, y + s * dx + c * dy
