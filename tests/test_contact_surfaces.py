"""Surface types and grips: every contact gets the larger restitution (on a fast first contact only) and the mean
friction of its two materials, however few pre-solve callbacks the world registers."""

from __future__ import annotations

import itertools

import pymunk

from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Material, Rope, Scene
from physink_tui.scene.physics.build import Built
from physink_tui.scene.physics.world import World


def test_every_pair_of_surfaces_gets_its_mean_friction_from_the_grips_or_a_callback() -> None:
    built = Built(pymunk.Space())
    for restitution, friction in ((0.3, 0.4), (0.6, 0.8), (0.0, 0.0), (0.9, 0.35)):
        built.surfaces.type_of(restitution, friction)
    for a, b in itertools.product(built.surfaces.materials, repeat=2):
        mean = (built.surfaces.materials[a][1] + built.surfaces.materials[b][1]) / 2
        called = built.surfaces.frictions.get((a, b), built.surfaces.frictions.get((b, a)))
        assert (called if called is not None else built.surfaces.grips[a] * built.surfaces.grips[b]) == mean
    n = len(built.surfaces.materials)
    assert len(built.surfaces.frictions) < n * (n + 1) // 2  # some pairs need no callback


def test_the_project_materials_need_a_callback_only_for_freeform_on_freeform_and_ropes() -> None:
    built = Built(pymunk.Space())
    kinds = {name: built.surfaces.type_of(m.restitution, m.friction) for name, m in MATERIALS.items()}
    assert built.surfaces.grips[kinds["box"]] == built.surfaces.grips[kinds["round"]] == 1.0
    assert built.surfaces.grips[kinds["freeform"]] == 0.5
    assert (kinds["freeform"], kinds["freeform"]) in built.surfaces.frictions
    assert len(built.surfaces.frictions) == 3


def pile() -> Scene:
    s = Scene()
    floor = Body("floor", "box", ((-400, -20), (400, -20), (400, 20), (-400, 20)), 0.0, (500, 900), 0.0,
                 MATERIALS["freeform"])
    s = s.add(floor).add(Joint("j", "weld", "floor", BACKGROUND, (500, 900)))
    for i in range(24):
        x, y, kind = 200 + (i % 8) * 70, 820 - (i // 8) * 70, ("box", "round", "freeform")[i % 3]
        if kind == "round":
            s = s.add(Body(f"b{i}", "circle", (), 20.0, (x, y), 0.0, MATERIALS[kind]))
        else:
            outline = ((-20, -20), (20, -20), (20, 20), (-20, 20)) if kind == "box" else \
                ((-20, -20), (20, -20), (20, -5), (-5, -5), (-5, 20), (-20, 20))
            s = s.add(Body(f"b{i}", "box" if kind == "box" else "polygon", outline, 0.0, (x, y), 0.3, MATERIALS[kind]))
    s = s.add(Body("odd", "circle", (), 15.0, (760, 600), 0.0, Material(1.0, 0.7, 0.3)))
    return s.add(Rope("r", tuple((150 + 40 * k, 600.0) for k in range(12)), None, None))


def test_contacts_in_a_pile_take_max_restitution_on_fast_first_contacts_and_mean_friction_always() -> None:
    world = World.from_scene(pile())
    bounced = held = 0
    for _ in range(360):
        world.step()
        seen: list[pymunk.Arbiter] = []
        for body in world.pymunk_parts.space.bodies:
            body.each_arbiter(seen.append)  # (each contact twice, once per body)
        for arbiter in seen:
            sa, sb = arbiter.shapes
            (ea, fa), (eb, fb) = world.pymunk_parts.surfaces.of(sa), world.pymunk_parts.surfaces.of(sb)
            assert arbiter.friction == (fa + fb) / 2
            if arbiter.restitution:
                assert arbiter.is_first_contact and arbiter.restitution == max(ea, eb)
                bounced += 1
            else:
                held += 1
    assert bounced > 0 and held > 0  # (bounces are the contacts that began faster than BOUNCE_THRESHOLD)
