"""Golden images of the thesis scenes (tests/journals/), light and dark, compared as decoded pixels with a tolerance.

Each journal is replayed through the session; its demonstration is drawn at half its duration at 320x200 (small,
to keep the repository small). A frame matches its golden image when the mean absolute difference over every
channel is under 1.0 and under 0.5 % of the pixels differ by more than 48 in some channel: anti-aliasing and
text may move by a level between skia builds, a body drawn elsewhere may not.

To regenerate after a deliberate change of the drawing, look at the new images before committing them:

    PHYSINK_UPDATE_GOLDEN=1 .venv/bin/python -m pytest -q tests/test_render_golden.py

A mismatch writes what was drawn beside the test's temporary files and names it in the failure.
"""

from __future__ import annotations

import os
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from physink_tui.formats.journal.reader import read_journal
from physink_tui.render.frames import demonstration_frame
from physink_tui.render.images import decode_png, write_png
from physink_tui.render.renderer import Renderer
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session

HERE = Path(__file__).parent
GOLDEN = HERE / "golden"
SCENES = ("egg_cracker", "pinball", "bouncing_hits_a", "cup_dispenser", "golf_ball_helper", "basketball")
THEMES = ("light", "dark")
SIZE = (320, 200)
MEAN_LIMIT, LEVEL, SHARE_LIMIT = 1.0, 48, 0.005
UPDATE = os.environ.get("PHYSINK_UPDATE_GOLDEN") == "1"


@cache
def replayed(name: str) -> Session:
    journal = read_journal(HERE / "journals" / f"{name}.physink.jsonl")
    return replay(Session.from_header(journal.header), journal.entries)


def drawn(name: str, theme: str) -> np.ndarray:
    session = replayed(name)
    assert session.timeline is not None and session.timeline.events, f"{name}: no demonstration"
    duration = max(ev.t1 for ev in session.timeline.events)
    frame = demonstration_frame(session.scene, session.timeline, session.canvas, duration / 2)
    return Renderer(*SIZE, session.canvas, theme).render(frame).copy()


def difference(a: np.ndarray, b: np.ndarray) -> tuple[float, float]:
    """Mean absolute difference over channels, and the share of pixels off by more than `LEVEL` somewhere."""
    diff = np.abs(a.astype(np.int16) - b.astype(np.int16))
    return float(diff.mean()), float((diff.max(axis=2) > LEVEL).mean())


@pytest.mark.parametrize("theme", THEMES)
@pytest.mark.parametrize("name", SCENES)
def test_scene_matches_its_golden_image(name: str, theme: str, tmp_path: Path) -> None:
    pixels = drawn(name, theme)
    golden = GOLDEN / f"{name}_{theme}.png"
    if UPDATE:
        write_png(golden, pixels)
        return
    assert golden.exists(), f"{golden} is missing; PHYSINK_UPDATE_GOLDEN=1 makes it (look at it before committing)"
    expected = decode_png(golden.read_bytes())
    assert expected.shape == pixels.shape, f"{golden}: {expected.shape} golden, {pixels.shape} drawn"
    mean, share = difference(pixels, expected)
    if mean >= MEAN_LIMIT or share >= SHARE_LIMIT:
        actual = tmp_path / f"{name}_{theme}.actual.png"
        write_png(actual, pixels)
        pytest.fail(f"{name} ({theme}) differs from {golden}: mean difference {mean:.3f} (limit {MEAN_LIMIT}), "
                    f"{share:.2%} of pixels off by more than {LEVEL} (limit {SHARE_LIMIT:.1%}); drawn: {actual}")


def test_the_tolerance_catches_a_body_drawn_elsewhere() -> None:
    """A golden compared with a frame whose ball is elsewhere fails, so the tolerance is not too loose."""
    session = replayed("pinball")
    timeline = session.timeline
    assert timeline is not None
    duration = max(ev.t1 for ev in timeline.events)
    renderer = Renderer(*SIZE, session.canvas)
    early = renderer.render(demonstration_frame(session.scene, timeline, session.canvas, duration * 0.3)).copy()
    late = renderer.render(demonstration_frame(session.scene, timeline, session.canvas, duration * 0.35)).copy()
    mean, share = difference(early, late)
    assert mean >= MEAN_LIMIT or share >= SHARE_LIMIT
