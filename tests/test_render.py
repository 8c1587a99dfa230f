"""The renderer as a user sees it: the canvas's aspect kept, themes, bodies where their poses say, trails, sizes,
frames past the end, session views, PNG files; and the frames a video is made of."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from physink_tui.errors import RenderError
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.render.attachments import RopeShape, carried
from physink_tui.render.frame import FrameContent, TimeBar, Trail, frame_times
from physink_tui.render.frames import Demonstration, demonstration_frame, view_frame
from physink_tui.render.images import decode_png, encode_png, write_png
from physink_tui.render.renderer import Renderer, load_typeface
from physink_tui.render.theme import DARK, LIGHT
from physink_tui.scene.components import BACKGROUND, MATERIALS, Body, Joint, Rope, Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session

JOURNALS = Path(__file__).parent / "journals"
CANVAS = (1600.0, 1000.0)


def rgb(color: int) -> tuple[int, int, int]:
    return ((color >> 16) & 255, (color >> 8) & 255, color & 255)


def at(pixels: np.ndarray, renderer: Renderer, x: float, y: float) -> tuple[int, int, int]:
    """The pixel showing canvas point (x, y)."""
    left, top, _, _ = renderer.box
    px, py = int(left + x * renderer.scale), int(top + y * renderer.scale)
    return tuple(int(v) for v in pixels[py, px, :3])


def strongest(pixels: np.ndarray, renderer: Renderer, x: float, y: float) -> tuple[int, int, int]:
    """The pixel most unlike the paper within two pixels of canvas point (x, y) (a thin line is anti-aliased
    over the rows it straddles)."""
    left, top, _, _ = renderer.box
    px, py = int(left + x * renderer.scale), int(top + y * renderer.scale)
    window = pixels[py - 2: py + 3, px - 2: px + 3, :3].reshape(-1, 3).astype(int)
    best = np.abs(window - np.array(rgb(renderer.theme.background))).sum(axis=1).argmax()
    return tuple(int(v) for v in window[best])


def ball_scene() -> Scene:
    return Scene().add(Body("b1", "circle", (), 80.0, (300.0, 300.0), 0.0, MATERIALS["round"], "ball"))


def test_the_canvas_keeps_its_aspect_between_bars() -> None:
    renderer = Renderer(400, 100, CANVAS, controls=False)
    pixels = renderer.render(FrameContent(Scene(), CANVAS))
    assert renderer.box == pytest.approx((120.0, 0.0, 160.0, 100.0))
    assert tuple(pixels[50, 10, :3]) == rgb(LIGHT.bars)
    assert tuple(pixels[50, 390, :3]) == rgb(LIGHT.bars)
    assert tuple(pixels[50, 200, :3]) == rgb(LIGHT.background)
    tall = Renderer(100, 400, CANVAS, controls=False).render(FrameContent(Scene(), CANVAS))
    assert tuple(tall[5, 50, :3]) == rgb(LIGHT.bars) and tuple(tall[200, 50, :3]) == rgb(LIGHT.background)


def test_the_narration_and_time_bar_sit_below_the_canvas_never_over_it() -> None:
    renderer = Renderer(320, 220, CANVAS)
    _, top, width, height = renderer.box
    assert top + height <= 220 - 22 + 0.5 and width / height == pytest.approx(CANVAS[0] / CANVAS[1])
    bare = renderer.render(FrameContent(Scene(), CANVAS)).copy()
    told = renderer.render(FrameContent(Scene(), CANVAS, subtitle="Movement of ball CAUSES",
                                        time_bar=TimeBar(1.0, 2.0, (0.5, 1.5))))
    changed = (told[..., :3] != bare[..., :3]).any(axis=2)
    assert changed[int(top + height):].any()  # drawn in the strip
    assert not changed[: int(top + height)].any()  # the canvas untouched


def test_an_empty_scene_is_a_blank_canvas() -> None:
    renderer = Renderer(160, 100, CANVAS, controls=False)
    pixels = renderer.render(FrameContent(Scene(), CANVAS))
    assert (pixels[..., :3] == rgb(LIGHT.background)).all()
    assert (pixels[..., 3] == 255).all()


def test_the_dark_theme_is_dark_and_the_light_one_light() -> None:
    dark = Renderer(160, 100, CANVAS, "dark", controls=False).render(FrameContent(ball_scene(), CANVAS)).copy()
    light = Renderer(160, 100, CANVAS, "light", controls=False).render(FrameContent(ball_scene(), CANVAS)).copy()
    assert dark[..., :3].mean() < 60 < 200 < light[..., :3].mean()
    assert tuple(dark[90, 150, :3]) == rgb(DARK.background)


def test_a_body_is_drawn_where_its_pose_says() -> None:
    renderer = Renderer(320, 200, CANVAS)
    scene = ball_scene()
    drawn = renderer.render(FrameContent(scene, CANVAS)).copy()
    moved = renderer.render(FrameContent(scene, CANVAS, {"b1": Pose(1200.0, 700.0, 1.0)})).copy()
    fill, paper = rgb(LIGHT.body_fill), rgb(LIGHT.background)
    assert at(drawn, renderer, 320, 330) == fill and at(drawn, renderer, 1200, 730) == paper
    assert at(moved, renderer, 1200, 730) == fill and at(moved, renderer, 320, 330) == paper


def test_fixed_bodies_are_drawn_apart_from_the_ones_that_move() -> None:
    square = ((-100.0, -100.0), (100.0, -100.0), (100.0, 100.0), (-100.0, 100.0))
    scene = Scene().add(Body("b1", "box", square, 0.0, (400.0, 500.0), 0.0, MATERIALS["box"]))
    scene = scene.add(Body("b2", "box", square, 0.0, (1200.0, 500.0), 0.0, MATERIALS["box"]))
    scene = scene.add(Joint("j1", "weld", "b2", BACKGROUND, (1200.0, 500.0)))
    renderer = Renderer(320, 200, CANVAS)
    pixels = renderer.render(FrameContent(scene, CANVAS))
    assert at(pixels, renderer, 350, 450) == rgb(LIGHT.body_fill)
    assert at(pixels, renderer, 1150, 450) == rgb(LIGHT.fixed_fill)


@pytest.mark.parametrize("kind", ["demonstration", "simulation"])
def test_trails_are_green_for_a_demonstration_and_red_for_a_simulation(kind: str) -> None:
    renderer = Renderer(320, 200, CANVAS)
    trail = Trail(((200.0, 800.0), (800.0, 800.0), (1400.0, 800.0)), kind, 2, (1100.0, 800.0))
    pixels = renderer.render(FrameContent(Scene(), CANVAS, trails=(trail,)))
    r, g, b = strongest(pixels, renderer, 500, 800)
    if kind == "demonstration":
        assert g > r + 60 and g > b + 60
    else:
        assert r > g + 60 and r > b + 60
    assert strongest(pixels, renderer, 1000, 800) == (r, g, b)  # up to the head, between two recorded points
    assert strongest(pixels, renderer, 1300, 800) == rgb(LIGHT.background)  # not beyond it


@pytest.mark.parametrize("size", [0, 15, 7681, 12.5, "640", True, None])
def test_bad_sizes_are_refused_naming_the_value(size: object) -> None:
    with pytest.raises(ValueError, match=re.escape(repr(size))):
        Renderer(size, 200, CANVAS)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="height"):
        Renderer(320, size, CANVAS)  # type: ignore[arg-type]


def test_a_bad_canvas_or_theme_is_refused() -> None:
    with pytest.raises(ValueError, match="canvas"):
        Renderer(320, 200, (0.0, 1000.0))
    with pytest.raises(ValueError, match="'sepia'"):
        Renderer(320, 200, CANVAS, "sepia")
    with pytest.raises(RenderError, match="canvas"):
        Renderer(320, 200, CANVAS).render(FrameContent(Scene(), (800.0, 600.0)))


def test_a_missing_font_is_named() -> None:
    with pytest.raises(RenderError, match=re.escape("'/nowhere/DejaVuSans.ttf'")):
        load_typeface("/nowhere/DejaVuSans.ttf")


def test_render_reuses_one_buffer() -> None:
    renderer = Renderer(64, 40, CANVAS)
    first = renderer.render(FrameContent(Scene(), CANVAS))
    second = renderer.render(FrameContent(ball_scene(), CANVAS))
    assert first is second and first.shape == (40, 64, 4) and first.dtype == np.uint8


def replayed(name: str) -> Session:
    journal = read_journal(JOURNALS / f"{name}.physink.jsonl")
    return replay(Session.from_header(journal.header), journal.entries)


def test_a_frame_past_the_end_shows_the_end() -> None:
    session = replayed("bouncing_hits_a")
    assert session.timeline is not None
    demo = Demonstration(session.scene, session.timeline, session.canvas)
    end, later = demo.frame(demo.duration), demo.frame(demo.duration + 5.0)
    assert later.time_bar == TimeBar(demo.duration, demo.duration, demo.ticks)
    assert dict(later.poses) == dict(end.poses)
    renderer = Renderer(320, 200, session.canvas)
    assert np.array_equal(renderer.render(end).copy(), renderer.render(later))


def test_a_demonstration_frame_follows_the_tape_the_session_seeks_with() -> None:
    session = replayed("egg_cracker")
    timeline = session.timeline
    assert timeline is not None
    demo = Demonstration(session.scene, timeline, session.canvas)
    frame = demonstration_frame(session.scene, timeline, session.canvas, 2.0)
    assert dict(frame.poses) == {b: demo.tape.pose(b, 2.0) for b in demo.tape.bodies}
    assert frame.subtitle is not None and frame.time_bar is not None and frame.time_bar.t == 2.0
    assert {m.sides for m in frame.contacts} == {"ball bottom / lever top"}  # named as timeline.txt names them
    assert all(trail.kind == "demonstration" for trail in frame.trails) and frame.trails
    assert demonstration_frame(session.scene, timeline, session.canvas, 2.0, with_trails=False).trails == ()
    start = demo.frame(0.0)
    assert start.subtitle is None or start.subtitle.startswith("Movement")


def test_a_rope_stays_tied_to_its_bodies_and_over_its_pulley() -> None:
    session = replayed("egg_cracker")
    scene = session.scene
    rope = scene.components["r1"]
    assert isinstance(rope, Rope)
    shape = RopeShape(rope, scene)
    assert np.allclose(shape.at(scene, {}), shape.points)
    knife = scene.components["b5"]
    assert isinstance(knife, Body)
    poses = {"b5": Pose(knife.position[0], knife.position[1] + 100.0, knife.angle)}
    moved = shape.at(scene, poses)
    assert moved[-1] == pytest.approx(carried(tuple(shape.points[-1]), "b5", scene, poses))
    on_pulley = [k for k, body in shape.pins if body == "b4"]
    assert on_pulley and np.allclose(moved[on_pulley], shape.points[on_pulley])
    assert np.allclose(moved[0], shape.points[0])


def test_a_joint_turns_with_its_body() -> None:
    scene = ball_scene().add(Joint("j1", "pivot", "b1", BACKGROUND, (350.0, 300.0)))
    point = carried((350.0, 300.0), "b1", scene, {"b1": Pose(300.0, 300.0, math.pi / 2)})
    assert point == pytest.approx((300.0, 350.0))


def test_a_session_view_is_drawn_with_its_trails_and_time_bar() -> None:
    journal = read_journal(JOURNALS / "egg_cracker.physink.jsonl")
    entries = journal.entries
    start = next(i for i, e in enumerate(entries) if isinstance(e, CommandEntry) and e.args == ("demo",))
    session = Session.from_header(journal.header)
    for entry in entries[: start + (len(entries) - start) // 2]:
        session.handle(entry)
    view = session.view()
    assert view.mode == "demo"
    frame = view_frame(view, session.canvas)
    assert frame.poses == view.poses and frame.time_bar is not None and frame.trails
    pixels = Renderer(320, 200, session.canvas, "dark").render(frame)
    assert (pixels[..., :3] == rgb(DARK.demonstration)).all(axis=2).any()


def test_a_sketch_view_shows_the_ink_being_drawn() -> None:
    scene = Scene()
    frame = FrameContent(scene, CANVAS, ink=(((100.0, 502.5), (1500.0, 502.5)),))
    renderer = Renderer(320, 200, CANVAS)
    pixels = renderer.render(frame)
    assert np.abs(np.array(strongest(pixels, renderer, 800, 502.5)) - rgb(LIGHT.ink)).max() < 8


def test_png_round_trips_and_is_written_atomically(tmp_path: Path) -> None:
    pixels = Renderer(64, 40, CANVAS).render(FrameContent(ball_scene(), CANVAS)).copy()
    data = encode_png(pixels)
    assert data.startswith(b"\x89PNG") and np.array_equal(decode_png(data), pixels)
    target = tmp_path / "frame.png"
    write_png(target, pixels)
    assert np.array_equal(decode_png(target.read_bytes()), pixels)
    assert [p.name for p in tmp_path.iterdir()] == ["frame.png"]
    with pytest.raises(RenderError, match=re.escape("frame.png")):
        write_png(tmp_path / "missing" / "frame.png", pixels)
    with pytest.raises(RenderError, match="uint8"):
        encode_png(np.zeros((4, 4, 3), dtype=np.uint8))
    with pytest.raises(RenderError, match="decode"):
        decode_png(b"not a png")


def test_frame_times_cover_the_whole_demonstration_once() -> None:
    assert frame_times(1.0, 4) == (0.0, 0.25, 0.5, 0.75, 1.0)
    assert frame_times(0.0, 30) == (0.0,)
    times = frame_times(5.891666, 30)
    assert times[-1] == 5.891666 and len(times) == 178 and list(times) == sorted(set(times))
    for bad in (0, -1, math.inf, math.nan):
        with pytest.raises(ValueError, match="fps"):
            frame_times(1.0, bad)
    with pytest.raises(ValueError, match="duration"):
        frame_times(-0.5, 30)


def test_a_trail_knows_what_it_shows() -> None:
    trail = Trail(((0.0, 0.0), (1.0, 0.0), (2.0, 0.0)), "demonstration", 2, (1.5, 0.0))
    assert trail.visible() == ((0.0, 0.0), (1.0, 0.0), (1.5, 0.0))
    with pytest.raises(ValueError, match="'sketch'"):
        Trail((), "sketch", 0)
    with pytest.raises(ValueError, match="4"):
        Trail(((0.0, 0.0),), "demonstration", 4)


def test_a_demonstration_frame_shows_what_the_session_shows_after_a_seek() -> None:
    journal = read_journal(JOURNALS / "egg_cracker.physink.jsonl")
    entries = [e for e in journal.entries if not (isinstance(e, CommandEntry) and e.name == "end")]
    session = Session.from_header(journal.header)
    for entry in entries:
        session.handle(entry)
    later = entries[-1].t + 1.0
    session.handle(CommandEntry(later, "mode", ("demo",)))
    session.handle(CommandEntry(later, "seek", (2.0,)))
    view = session.view()
    assert view.mode == "demo" and view.clock == 2.0 and view.timeline is not None
    frame = demonstration_frame(view.scene, view.timeline, session.canvas, 2.0)
    for body, pose in frame.poses.items():
        assert tuple(pose) == pytest.approx(tuple(view.poses[body]), abs=1e-6), body
    shown = view_frame(view, session.canvas)
    assert (shown.trails, shown.contacts, shown.subtitle, shown.time_bar) == (
        frame.trails, frame.contacts, frame.subtitle, frame.time_bar)


def test_a_trail_leaving_the_canvas_is_cut_at_its_edge() -> None:
    renderer = Renderer(320, 220, CANVAS)
    _, top, _, height = renderer.box
    bare = renderer.render(FrameContent(Scene(), CANVAS)).copy()
    gone = ((800.0, 500.0), (800.0, 3 * CANVAS[1]))  # falls off the bottom of the canvas
    for shown in (1, 2):  # growing, and finished (drawn into the cached layer)
        pixels = renderer.render(FrameContent(Scene(), CANVAS, trails=(Trail(gone, "simulation", shown),)))
        below = int(top + height) + 1
        assert (pixels[below:, :, :3] == bare[below:, :, :3]).all()


def test_highlighted_bodies_are_outlined_in_the_emphasis_colour() -> None:
    """``FrameContent.highlight`` (the TUI's chosen timeline event) outlines those bodies; nothing else changes."""
    from dataclasses import replace as _replace

    from physink_tui.render.frame import FrameContent
    from physink_tui.render.renderer import Renderer
    from physink_tui.render.theme import theme_named
    from physink_tui.scene.components import MATERIALS, Body, Scene

    box = Body("b1", "box", ((-50.0, -30.0), (50.0, -30.0), (50.0, 30.0), (-50.0, 30.0)), 0.0, (400.0, 300.0), 0.0,
               MATERIALS["box"])
    scene = Scene().add(box)
    renderer = Renderer(200, 150, (800.0, 600.0), "light", controls=False)
    plain = renderer.render(FrameContent(scene, (800.0, 600.0))).copy()
    marked = renderer.render(_replace(FrameContent(scene, (800.0, 600.0)), highlight=frozenset({"b1"}))).copy()
    colour = theme_named("light").contact_recent
    rgb = ((colour >> 16) & 255, (colour >> 8) & 255, colour & 255)
    differs = (plain != marked).any(axis=2)
    assert differs.any() and differs[:, :60].sum() == 0  # only round the box (x 75..125 px of 200)
    close = (abs(marked[..., :3].astype(int) - rgb).sum(axis=2) < 60) & differs
    assert close.sum() > 20
