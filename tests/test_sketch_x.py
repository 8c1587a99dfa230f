"""An X drawn by a person welds what it is drawn on: arms half a second apart, bowed, hooked, spilling over a thin
platform; the first arm waits for the second instead of becoming a body that is pushed away."""

from __future__ import annotations

import math
import random

import pytest
from hand_x import hand_x
from strokegen.strokes import circle, line
from test_session import circle_points, pen_header, pen_stroke

from physink_tui.formats.journal.entries import CommandEntry, PenEntry
from physink_tui.scene.components import BACKGROUND, Body, Joint, Scene
from physink_tui.scene.interpretation.interpret import interpret
from physink_tui.scene.recognition.primitives import Box, Recognition
from physink_tui.session.history import Document
from physink_tui.session.session import Session

W, H = 1600, 1000
PLATFORM = (800.0, 500.0)


def canvas_stroke(t0: float, points: list[tuple[float, float]]) -> list[PenEntry]:
    """A stroke given in canvas units, drawn in 0.25 s."""
    return pen_stroke(t0, [(x / W, y / H) for x, y in points], dt=0.25 / len(points))


def on_thin_platform() -> Session:
    """A session whose sketch holds a 300 x 12 platform (as the recogniser beautifies a box), id ``b1``."""
    platform = Recognition("box", 1.0, Box(PLATFORM, 300.0, 12.0, 0.0))
    return Session.from_header(pen_header(), Document(interpret(Scene(), platform, []).scene))


def draw_x(session: Session, t0: float, seed: str, centre: tuple[float, float], size: float, gap: float) -> float:
    """Draws a hand-made X: the second arm begins ``gap`` seconds after the first ends. Returns when it ended."""
    first, second = hand_x(seed, centre, size)
    entries = canvas_stroke(t0, first)
    entries += canvas_stroke(entries[-1].t + gap, second)
    for entry in entries:
        session.handle(entry)
    return entries[-1].t


@pytest.mark.parametrize("gap", [0.2, 0.5, 0.8, 1.2])
@pytest.mark.parametrize("size", [25.0, 50.0, 90.0])
def test_an_x_on_a_thin_platform_welds_it_to_the_background(gap: float, size: float) -> None:
    for k in range(4):
        session = on_thin_platform()
        centre = (PLATFORM[0] - 100 + 60 * k, PLATFORM[1] + (-3, 3)[k % 2])
        draw_x(session, 1.0, f"{size}:{gap}:{k}", centre, size, gap)
        session.finish()
        parts = [c for c in session.scene.components.values() if not isinstance(c, Body)]
        assert [(j.kind, j.a, j.b) for j in parts if isinstance(j, Joint)] == [("weld", "b1", BACKGROUND)], (k, parts)
        assert [b.id for b in session.scene.bodies()] == ["b1"]
        assert session.scene.components["b1"].position == PLATFORM


def test_the_first_arm_waits_on_the_platform_until_the_second_arrives() -> None:
    session = on_thin_platform()
    first, second = hand_x("wait", PLATFORM, 40.0)
    before = session.scene
    for entry in canvas_stroke(1.0, first):
        session.handle(entry)
    assert session.scene == before  # not a body yet, so nothing is pushed clear of the platform
    for entry in canvas_stroke(2.3, second):  # begun 1.2 s later, ended after the wait for an X would have run out
        session.handle(entry)
    assert [c.kind for c in session.scene.components.values() if isinstance(c, Joint)] == ["weld"]


def test_a_short_stroke_that_no_second_stroke_pairs_is_kept_on_its_own() -> None:
    session = on_thin_platform()
    first, _ = hand_x("alone", (PLATFORM[0], PLATFORM[1] - 60), 40.0)  # above the platform, touching nothing
    for entry in canvas_stroke(1.0, first):
        session.handle(entry)
    session.handle(PenEntry(3.0, 0.9, 0.9, 0.0, False, True, False, False, False))  # the wait runs out
    assert [b.shape for b in session.scene.bodies()] == ["box", "polyline"]


def test_a_welded_platform_stays_put_when_the_ball_is_pushed_into_it_in_demo_mode() -> None:
    session = on_thin_platform()
    t = draw_x(session, 1.0, "demo", (PLATFORM[0] + 40, PLATFORM[1] + 2), 45.0, 0.5)
    ball = circle_points(0.5, 0.35, 0.04)
    for entry in pen_stroke(t + 0.5, ball):
        session.handle(entry)
    session.handle(CommandEntry(t + 2.0, "mode", ("demo",)))
    t += 2.5
    session.handle(PenEntry(t, 0.5, 0.35, 0.0, False, True, False, False, False))
    for k in range(1, 101):  # push the ball down hard into the platform
        session.handle(PenEntry(t + 0.01 * k, 0.5, 0.35 + 0.0025 * k, 0.6, True, True, False, False, False))
    session.handle(PenEntry(t + 1.02, 0.5, 0.6, 0.0, False, True, False, False, False))
    for k in range(30):
        session.handle(PenEntry(t + 1.1 + 0.1 * k, 0.9, 0.9, 0.0, False, False, False, False, False))
    assert session.view().poses["b1"] == (*PLATFORM, 0.0)
    session.handle(CommandEntry(t + 5.0, "mode", ("sketch",)))
    events = session.timeline.events
    assert any(e.type == "contact" and set(e.components) == {"b1", "b2"} for e in events)
    assert not [e for e in events if e.type == "movement" and "b1" in e.components]


@pytest.mark.parametrize("seed", range(8))
def test_a_hand_drawn_ball_two_platforms_and_basket_get_both_platforms_welded(seed: int) -> None:
    rng = random.Random(seed)
    session = Session.from_header(pen_header())
    t = 0.0

    def draw(points: list[tuple[float, float]], gap: float = 1.0) -> None:
        nonlocal t
        entries = canvas_stroke(t + gap, points)
        for entry in entries:
            session.handle(entry)
        t = entries[-1].t

    platforms = (((500.0, 400.0), 0.25), ((1000.0, 600.0), -0.25))
    for centre, tilt in platforms:
        draw([(x, y) for x, y, _ in line(rng, size=300, angle=tilt, center=centre)])
    draw([(x, y) for x, y, _ in circle(rng, size=50, center=(420, 250))])
    draw([(1250.0, 620 + 2.0 * i) for i in range(40)] + [(1250 + 2.0 * i, 700.0) for i in range(60)]
         + [(1370.0, 700 - 2.0 * i) for i in range(40)])
    for (cx, cy), tilt in platforms:
        x = cx + rng.uniform(-80, 80)
        first, second = hand_x(f"scene:{seed}:{cx}", (x, cy + math.tan(tilt) * (x - cx)), rng.uniform(25, 60))
        draw(first)
        draw(second, rng.uniform(0.2, 1.2))
    session.finish()
    welds = [(c.a, c.b) for c in session.scene.components.values() if isinstance(c, Joint) and c.kind == "weld"]
    assert welds == [("b1", BACKGROUND), ("b2", BACKGROUND)]
    assert [b.shape for b in session.scene.bodies()] == ["polyline", "polyline", "circle", "polyline"]


def test_both_arms_of_an_x_reach_the_recogniser_with_the_pens_times(monkeypatch: pytest.MonkeyPatch) -> None:
    """The X pairing reads each arm with the journal's times, as a lone stroke is read (so the learned ranker sees
    the pen slow at corners in both paths, and a replay decides the same)."""
    import physink_tui.scene.recognition.recognize as recognize

    seen: list[tuple[int, tuple[float, ...] | None]] = []
    real = recognize.recognize_stroke

    def spy(points, times=None, **kw):  # type: ignore[no-untyped-def]
        seen.append((len(points), None if times is None else tuple(times)))
        return real(points, times, **kw)

    monkeypatch.setattr(recognize, "recognize_stroke", spy)  # what `recognize_strokes` reads an X's arms with
    session = on_thin_platform()
    first, second = hand_x("times", PLATFORM, 40.0)
    one, two = canvas_stroke(1.0, first), canvas_stroke(2.0, second)
    for entry in one + two:
        session.handle(entry)
    assert [c.kind for c in session.scene.components.values() if isinstance(c, Joint)] == ["weld"]
    assert len(seen) == 2 and all(times is not None and len(times) == n for n, times in seen), seen
    (_, a), (_, b) = seen
    assert a is not None and b is not None
    assert one[0].t <= a[0] and a[-1] <= one[-1].t < two[0].t <= b[0] and b[-1] <= two[-1].t
    assert list(a) == sorted(a) and list(b) == sorted(b)
