"""Real tablets' captures (../shared/data/hid, DIGImend dumps of what a person did, segment by segment) through
the gestures and a whole session: what the person did is what comes out."""

from __future__ import annotations

import math
import re
from functools import cache

import pytest
import shapely
from shared_data import shared_path

from physink_tui.commands.replay import replay_capture
from physink_tui.input.captures.capture import Capture
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.pen.gestures import PenMove, StrokeEnded, Tap
from physink_tui.scene.components import Body
from physink_tui.scene.interpretation.body_shapes import body_geometry
from physink_tui.session.session import Session

HID = shared_path("hid", module_level=True)
CAPTURES = sorted(p.name for p in HID.glob("digimend__*.hid"))
_SEGMENT = re.compile(r"# segment: .*?/(?:dumps\w*/)?(?:\w+/)?([\w.-]+?)(?:\.txt)?\s")


@cache
def segments(name: str) -> list[tuple[float, float, str]]:
    """(first t, last t, what the person did) per segment, from the ``# segment:`` comments and the events."""
    text = (HID / name).read_text(encoding="utf-8", errors="replace")
    capture = Capture.from_text(text)
    starts = [(i + 1, (m.group(1) if (m := _SEGMENT.match(line + " ")) else "?"))
              for i, line in enumerate(text.split("\n")) if line.startswith("# segment")]
    out = []
    for k, (line, what) in enumerate(starts):
        end = starts[k + 1][0] if k + 1 < len(starts) else math.inf
        times = [e.t for e in capture.events if line < e.line < end]
        if times:
            out.append((times[0], times[-1], what))
    return out


@cache
def gestures(name: str) -> list:
    return replay_capture(Capture.from_file(HID / name))[0]


def _in(seg: tuple[float, float, str], t: float) -> bool:
    return seg[0] <= t <= seg[1]


def test_every_capture_has_its_segments() -> None:
    assert len(CAPTURES) >= 20
    assert all(segments(name) for name in CAPTURES)


@pytest.mark.parametrize("name", CAPTURES)
def test_every_position_lies_on_the_tablet(name: str) -> None:
    moves = [g for g in gestures(name) if isinstance(g, PenMove)]
    strokes = [g.stroke for g in gestures(name) if isinstance(g, StrokeEnded)]
    assert moves, f"{name}: the pen never moved over the tablet"
    for x, y in [(m.x, m.y) for m in moves] + [(p.x, p.y) for s in strokes for p in s.points]:
        assert 0.0 <= x <= 1.0 and 0.0 <= y <= 1.0, (name, x, y)


PRESSURE = [(name, seg) for name in CAPTURES for seg in segments(name) if "pressure" in seg[2]]
KYE_PRESSURE = ("KYE sends its pen as mouse report 0x09 declared 6 bytes but sent 8: the pressure is in the 2 "
                "undeclared bytes (the kernel's hid-kye replaces the descriptor to declare it), so every touch reads "
                "full pressure")
KNOWN_FAILING = {
    ("digimend__KYE_EasyPen_M506__if0.hid", 1): KYE_PRESSURE,
    ("digimend__KYE_MousePen_i608X_v2__if0.hid", 5): KYE_PRESSURE + " (its later pressure dump, segment 8, decodes)",
}
"""Captures whose pressure test fails today, and why; strict xfails (a fix turns them red: delete the entry)."""


@pytest.mark.parametrize(("name", "segment"), PRESSURE, ids=lambda v: v if isinstance(v, str) else v[2])
def test_pressing_harder_is_a_stroke_whose_pressure_climbs(name: str, segment, request) -> None:
    """In a pen_pressure dump the person presses the tip down, harder and harder: the touch is a stroke (or a
    tap) in that segment, and its pressure spans a good part of the range."""
    key = (name, segments(name).index(segment))
    if key in KNOWN_FAILING:
        request.applymarker(pytest.mark.xfail(strict=True, reason=KNOWN_FAILING[key]))
    strokes = [g.stroke for g in gestures(name) if isinstance(g, StrokeEnded) and _in(segment, g.t)]
    taps = [g for g in gestures(name) if isinstance(g, Tap) and _in(segment, g.t)]
    assert strokes or taps, f"{name} {segment[2]}: no touch"
    if strokes:
        pressures = [p.p for s in strokes for p in s.points]
        assert max(pressures) - min(pressures) >= 0.3, (name, segment[2], min(pressures), max(pressures))


COORDS = [(name, seg) for name in CAPTURES for seg in segments(name) if "pen_coord" in seg[2]]


@pytest.mark.parametrize(("name", "segment"), COORDS, ids=lambda v: v if isinstance(v, str) else v[2])
def test_moving_round_the_tablet_covers_it(name: str, segment) -> None:
    """In a pen_coords dump the person moves the pen about the active area: it covers a good part of it."""
    xs = [g.x for g in gestures(name) if isinstance(g, PenMove) and _in(segment, g.t)]
    ys = [g.y for g in gestures(name) if isinstance(g, PenMove) and _in(segment, g.t)]
    assert xs, f"{name} {segment[2]}: no pen movement"
    assert max(max(xs) - min(xs), max(ys) - min(ys)) >= 0.4, (name, segment[2], min(xs), max(xs), min(ys), max(ys))


PUSHED_OFF: dict[str, str] = {}
"""Sessions whose bodies end off the canvas today (strict xfails). Huion K26 and W58 had a body pushed clear of
what it was drawn into right off the canvas; the session now leaves such a body where it was drawn, and says so."""


@pytest.mark.parametrize("name", CAPTURES)
def test_a_whole_capture_runs_as_a_session_and_its_bodies_stay_on_the_canvas(name: str, request) -> None:
    if name in PUSHED_OFF:
        request.applymarker(pytest.mark.xfail(strict=True, reason=PUSHED_OFF[name]))
    capture = Capture.from_file(HID / name)
    header = header_for_capture(capture)
    session = Session.from_header(header).run(capture_entries(capture))
    width, height = session.canvas
    canvas = shapely.box(0, 0, width, height)
    for body in (c for c in session.scene.components.values() if isinstance(c, Body)):
        # on the canvas: where it was drawn, or partly, when the person dragged it over the edge (a dwell-drag)
        assert body_geometry(body).intersects(canvas), (name, body)
    strokes = [g for g in gestures(name) if isinstance(g, StrokeEnded)]
    assert len(session.scene.components) <= 2 * len(strokes) + 1, name  # nothing from nowhere
