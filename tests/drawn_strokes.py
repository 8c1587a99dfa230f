"""A person's stroke drawn by the careful virtual pen through the thesis device and replayed (journal -> replay ->
project), for tests that follow people's strokes through a whole session; the journal helpers are xerase_drawings'."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from scenarios.thesis import DEVICE, MAPPING
from xerase_drawings import replayed_project

from physink_tui.formats.project.codec import Project
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen


def body_shapes(project: Project) -> list[str]:
    """The shapes of the project's bodies, a line's body (a polyline of two points) named "line"."""
    return ["line" if b.shape == "polyline" and len(b.outline) == 2 else b.shape for b in project.scene.bodies()]


def drawn_person_stroke(points: np.ndarray, folder: Path, across: float = 300.0) -> tuple[list[str], str]:
    """``points`` (a person's stroke, n x 2) scaled to ``across`` px at its longer side, placed at (200, 200) and
    drawn by the careful virtual pen (seed 1) through the thesis device: the replayed session's `body_shapes` and what
    it printed."""
    pts = np.asarray(points, dtype=float)
    pts = (pts - pts.min(axis=0)) / float(np.ptp(pts, axis=0).max()) * across + [200.0, 200.0]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=1).record([Stroke(tuple((x / w, y / h) for x, y in pts))])
    project, told = replayed_project(header_for_capture(capture, MAPPING), capture_entries(capture), folder)
    return body_shapes(project), told
