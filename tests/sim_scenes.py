"""A synthetic machine whose answer is known, for the search's and the simulate command's tests: a ball (b1) on a
welded floor (b2) rolls into a welded wall (b3); its demonstration is the rollout of a known initial velocity."""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cache

from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Scene
from physink_tui.sim.parameters import BodyParameters, Parameters
from physink_tui.sim.rollout import rollout
from physink_tui.timeline.events import Timeline

CANVAS = (1600.0, 1000.0)
TRUE_VELOCITY = (400.0, 0.0)


def square(w: float, h: float) -> tuple[tuple[float, float], ...]:
    return ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))


def ball_floor_wall(*, ball_welded: bool = False) -> Scene:
    scene = Scene().add(Body("b1", "circle", (), 25.0, (500.0, 655.0), 0.0, MATERIALS["round"], "ball"))
    scene = scene.add(Body("b2", "box", square(1200, 40), 0.0, (800.0, 700.0), 0.0, MATERIALS["freeform"], "floor"))
    scene = scene.add(Joint("j1", "weld", "b2", BACKGROUND, (800.0, 700.0)))
    scene = scene.add(Body("b3", "box", square(40, 200), 0.0, (1100.0, 580.0), 0.0, MATERIALS["box"], "wall"))
    scene = scene.add(Joint("j2", "weld", "b3", BACKGROUND, (1100.0, 580.0)))
    if ball_welded:
        scene = scene.add(Joint("j3", "weld", "b1", BACKGROUND, (500.0, 655.0)))
    return replace(scene, next_id={"b": 4, "j": 4, "r": 1, "s": 1})


def parameters(velocity: tuple[float, float]) -> Parameters:
    return Parameters({"b1": BodyParameters(math.pi * 25.0**2, 1.0)}, {}, {"b1": velocity})


@cache
def demonstration() -> Timeline:
    """The ball rolls into the wall (start, movement, contact with the floor, movement, contact with the wall...)."""
    return rollout(ball_floor_wall(), CANVAS, parameters(TRUE_VELOCITY), max_seconds=4.0).timeline
