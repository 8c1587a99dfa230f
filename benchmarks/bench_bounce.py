"""Benchmark: one bounce of the ball in the project's physics world beside the later-leg aim's model of it
(`sim/chain.py`'s `rebound`), over incidence angles, speeds, the surfaces the project builds and the ball's friction.

Usage: .venv/bin/python benchmarks/bench_bounce.py [--angles 10,20,...] [--speeds 300,...] [--frictions 1,0.5,0]
       [--model calibrated|before] [--quick]

Each bounce: a ball (radius 25, the "round" material) launched under gravity at a level surface welded to the
background, a box (restitution 1.0, friction 1.0: the platforms) or a freeform polygon (0.2 and 0.0), arriving at
the given speed and angle from the surface, not spinning; the world stepped as a rollout steps it (`World.substeps`
from the speed, as `rollout.rollout_from` picks them). The velocity in is the ball's at the step before the
contact, the velocity out the ball's once it has left the surface, both carried to the moment of contact by
gravity. Printed per case: the normal and tangential ratios (out / in) measured and the model's (the contact's
restitution and `chain.GRIP` or 1.0 with ``--model before``; `chain.rebound` calibrated, by default), and the error of
the model's outgoing direction in degrees, with its median, 90th percentile and worst.

The aim of the later legs uses what this measures (`chain.BOUNCE_LOSS` and Coulomb friction in `chain.rebound`);
``--quick`` is for a test of this script, not for numbers.
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Material, Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.scene.physics.world import GRAVITY, World
from physink_tui.sim.chain import BOUNCE_LOSS, rebound_factors
from physink_tui.sim.rollout import MAX_SUBSTEPS

RADIUS = 25.0
TOP = 700.0
SURFACES = ("box", "polygon")


def scene_for(surface: str, friction: float) -> Scene:
    """The ball (b1, with ``friction``) above a 1400-wide level surface (b2) whose top is at `TOP`."""
    w, h = 1400.0, 40.0
    outline = ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))
    material = MATERIALS["box"] if surface == "box" else MATERIALS["freeform"]
    round_ = MATERIALS["round"]
    ball = Material(round_.density, round_.restitution, friction)
    scene = Scene().add(Body("b1", "circle", (), RADIUS, (800.0, 300.0), 0.0, ball, "ball"))
    scene = scene.add(Body("b2", surface, outline, 0.0, (800.0, TOP + h / 2), 0.0, material, "surface"))
    return scene.add(Joint("j1", "weld", "b2", BACKGROUND, (800.0, TOP + h / 2)))


def bounce(surface: str, friction: float, angle: float, speed: float) -> tuple[float, float]:
    """(normal ratio, tangential ratio) of one bounce arriving at ``speed`` units/s, ``angle`` degrees from the
    surface, moving right and down."""
    g = GRAVITY[1]
    vx, vy = speed * math.cos(math.radians(angle)), speed * math.sin(math.radians(angle))
    # start a little above the surface, on the flight that arrives with (vx, vy)
    rise = min(5.0, vy * vy / (4 * g))
    vy0 = math.sqrt(max(vy * vy - 2 * g * rise, 0.0))
    t = (vy - vy0) / g
    world = World.from_scene(scene_for(surface, friction), gravity=GRAVITY)
    world.place("b1", Pose(800.0 - vx * t, TOP - RADIUS - rise, 0.0))
    world.set_velocity("b1", (vx, vy0))
    limit = (RADIUS + 20.0) / world.dt
    before = None
    touched_at = None
    for step in range(2000):
        m = world.motion("b1")
        world.substeps = min(math.ceil(max(1.0, math.hypot(m.vx, m.vy) / limit)), MAX_SUBSTEPS)
        world.step(1)
        now = world.motion("b1")
        touching = bool(world.touching())
        if touching and touched_at is None:
            touched_at, before = step, m
        if touched_at is not None and not touching and now.vy < 0:
            dt_in = world.dt  # the step before the contact began, carried one step on
            vin = (before.vx, before.vy + g * dt_in / 2)
            vout = (now.vx, now.vy + g * world.dt * (step - touched_at + 0.5))
            return -vout[1] / vin[1], vout[0] / vin[0]
    raise RuntimeError(f"no bounce: {surface} {friction} {angle} {speed}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--angles", default="10,20,30,40,50,60,70,80")
    parser.add_argument("--speeds", default="300,600,1200,2400")
    parser.add_argument("--frictions", default="1.0,0.5,0.0")
    parser.add_argument("--model", choices=("calibrated", "before"), default="calibrated")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    angles = [float(a) for a in args.angles.split(",")]
    speeds = [float(s) for s in args.speeds.split(",")]
    frictions = [float(f) for f in args.frictions.split(",")]
    if args.quick:
        angles, speeds, frictions = [30.0, 60.0], [600.0], [1.0]
    print("| surface | ball friction | angle° | speed | normal: pymunk / model | tangential: pymunk / model "
          "| direction error°: model |")
    print("|---|---:|---:|---:|---|---|---:|")
    errors = []
    for surface in SURFACES:
        for friction in frictions:
            material = MATERIALS["box"] if surface == "box" else MATERIALS["freeform"]
            for angle in angles:
                for speed in speeds:
                    en, et = bounce(surface, friction, angle, speed)
                    loss = BOUNCE_LOSS["box" if surface == "box" else "freeform"] if args.model == "calibrated" else 0.0
                    restitution = max(MATERIALS["round"].restitution, material.restitution)
                    mean = (friction + material.friction) / 2
                    if args.model == "calibrated":
                        mn, mt = rebound_factors(restitution, mean, angle, loss=loss, speed=speed)
                    else:  # before calibration: the restitution, two thirds of the tangential speed when it grips
                        mn, mt = restitution, (2 / 3 if mean > 0 else 1.0)
                    measured = math.degrees(math.atan2(en * math.sin(math.radians(angle)),
                                                       et * math.cos(math.radians(angle))))
                    model = math.degrees(math.atan2(mn * math.sin(math.radians(angle)),
                                                    mt * math.cos(math.radians(angle))))
                    errors.append(abs(model - measured))
                    print(f"| {surface} | {friction:g} | {angle:g} | {speed:g} | {en:.3f} / {mn:.3f} "
                          f"| {et:.3f} / {mt:.3f} | {model - measured:+.1f} |")
    print(f"\nDirection error of the model: median {statistics.median(errors):.2f}°, "
          f"90th pct {sorted(errors)[int(0.9 * (len(errors) - 1))]:.2f}°, worst {max(errors):.2f}° "
          f"over {len(errors)} bounces.")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
