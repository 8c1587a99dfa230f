"""Issue 25, session 31 (wt-mouse): a mouse's bursts of events tangent to one round curve or lying on sides
(`recognition.burst_tangents`): closed whole notes through the busy mouse read round, where no outline of three or four
sides through their few bursts was clearly farther from the points than their ellipse; small boxes through it stay
boxes. Pen-model seeds are tuning seeds (0-29); the held figures are floors in the benches' own tests."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from physink_tui.scene.recognition import burst_tangents, pen_noise
from physink_tui.scene.recognition.shape_fits import fit_ellipse

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import bench_boxes
from bench_circle_gestures import EXPECTED, drawn, reading


def _bursts(points: list[tuple[float, float]], at: list[float], spread: float) -> np.ndarray:
    """Bursts of five events ``spread`` long (path units) round the closed path through ``points`` (in order), centred
    at the shares ``at`` of its length: a busy mouse's events, the path between them not sent."""
    ring = np.array([*points, points[0]], dtype=float)
    steps = np.hypot(*np.diff(ring, axis=0).T)
    along = np.concatenate([[0.0], np.cumsum(steps)])

    def at_length(s: float) -> np.ndarray:
        s %= along[-1]
        k = int(np.searchsorted(along, s, side="right")) - 1
        return ring[k] + (ring[k + 1] - ring[k]) * (s - along[k]) / steps[k]
    return np.array([at_length(a * along[-1] + d) for a in at for d in np.linspace(-spread / 2, spread / 2, 5)])


def _judged(pts: np.ndarray) -> tuple[np.ndarray, float]:
    diag = float(np.hypot(*(pts.max(0) - pts.min(0))))
    return pen_noise.burst_jumps(pts, diag)[1], diag


def test_a_circles_bursts_are_tangent_to_it_a_boxs_lie_on_its_sides() -> None:
    """Five bursts round a circle (100 across) make equal angles with the chords between them; six bursts on a
    square's sides, off their middles, do not."""
    circle = [(50 * math.cos(a), 50 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 720, endpoint=False)]
    at = [0.03, 0.22, 0.41, 0.6, 0.81]
    round_one = _bursts(circle, at, 12.0)
    jumps, _ = _judged(round_one)
    ellipse = fit_ellipse(round_one)
    assert ellipse is not None
    assert burst_tangents.tangent_to_one_curve(round_one, jumps, ellipse)
    square = _bursts([(0, 0), (100, 0), (100, 100), (0, 100)], [0.05, 0.22, 0.33, 0.55, 0.7, 0.95], 12.0)
    jumps, _ = _judged(square)
    ellipse = fit_ellipse(square)
    assert ellipse is not None
    assert not burst_tangents.tangent_to_one_curve(square, jumps, ellipse)


@pytest.mark.parametrize(("family", "seed"), [
    ("whole-note-closed", 3), ("whole-note-closed", 14), ("whole-note-closed", 17), ("whole-note-closed-hooked", 4),
    ("whole-note-over", 12), ("whole-note-over", 17), ("whole-note-over-hooked", 26)])
def test_a_closed_note_through_a_busy_mouse_reads_round_either_way_round(family: str, seed: int) -> None:
    """Polygons or boxes on main 54414db: each of the note's 4-6 bursts lies near an outline of four sides through them
    all (`pen_noise.BURST_CLOSER` could not part them), but the chords between the bursts turn as much from the burst
    before as into the burst after, as chords of one round curve do (`burst_tangents.EVEN_TANGENTS`)."""
    for mirror in (False, True):
        stroke = drawn(family, "hurried-mouse", seed, mirror)
        assert all(reading(stroke, timed) in EXPECTED for timed in (True, False))


@pytest.mark.parametrize("seed", [4, 5, 6, 7, 11, 12, 14, 15, 19, 22, 28])
def test_a_small_box_through_a_busy_mouse_stays_a_box(seed: int) -> None:
    """The small boxes (18-40 px) through the mouse whose bursts the closeness test refuses as round, as it refuses
    the notes above, read as boxes on main and here: their chords turn unequally (0.5-0.9 of the turning)."""
    assert bench_boxes.read("small", "hurried-mouse", seed) == "box"

