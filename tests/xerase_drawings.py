"""Journals of a platform and then an X or a lone stroke across it, drawn by either pen model (the virtual pen's
HID reports, the hurried hand's pen lines), for tests/test_x_or_erase.py; canvas pixels, seconds."""

from __future__ import annotations

import contextlib
import io
import math
import random
from pathlib import Path

from penmodels.hurried import HurriedPen, PenPoint
from penmodels.journal import header as hurried_header
from penmodels.shapes import CANVAS, box
from scenarios.thesis import DEVICE, MAPPING

from physink_tui import cli
from physink_tui.formats.journal.entries import JournalEntry, JournalHeader, PenEntry
from physink_tui.formats.project.codec import Project
from physink_tui.formats.project.files import load_project
from physink_tui.input.journal_compose import capture_entries, header_for_capture, write_journal
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen

Point = tuple[float, float]
Segment = tuple[Point, Point]
DIAGONAL = math.hypot(*CANVAS)
PLATFORM_CENTRE = (800.0, 520.0)
PENS = ("virtual", "hurried")


def platform_length(arm: float) -> float:
    """A platform at least twice as long as an X of arms ``arm`` long is wide (an X is never wider than its arm)."""
    return max(2.2 * arm, 120.0)


def x_segments(rng: random.Random, centre: Point, arm: float) -> tuple[Segment, Segment]:
    """Two arms of about ``arm`` crossing at ``centre`` at 70-110 degrees, the first leaning 30-60 degrees."""
    first = math.radians(rng.uniform(30.0, 60.0)) * rng.choice((-1, 1))
    second = first + math.radians(rng.uniform(70.0, 110.0))
    out = []
    for heading, length in ((first, arm), (second, arm * rng.uniform(0.85, 1.15))):
        d = (math.cos(heading) * length / 2, math.sin(heading) * length / 2)
        slide = rng.uniform(-0.15, 0.15)  # the crossing off the arm's middle
        c = (centre[0] + 2 * d[0] * slide, centre[1] + 2 * d[1] * slide)
        out.append(((c[0] - d[0], c[1] - d[1]), (c[0] + d[0], c[1] + d[1])))
    return out[0], out[1]


def _pen_entry(r: PenPoint) -> PenEntry:
    x = min(max(r.x / CANVAS[0], 0.0), 1.0)
    y = min(max(r.y / CANVAS[1], 0.0), 1.0)
    return PenEntry(round(r.t, 6), round(x, 7), round(y, 7), round(r.p, 4), r.tip, r.in_range, False, False, False)


def hurried_journal(seed: int, thickness: float, length: float, strokes: list[Segment],
                    gap: float) -> tuple[JournalHeader, list[JournalEntry]]:
    """The hurried hand draws the platform, then each segment as one stroke, ``gap`` seconds from one lifting to
    the next landing; the journal's pen leaves range and the session goes on 3 s after the last."""
    pen = HurriedPen(random.Random(seed))
    reports = pen.draw(box(PLATFORM_CENTRE, length, thickness), 0.3)[0]
    entries = [_pen_entry(r) for r in reports]
    land = reports[-1].t + 0.8
    for a, b in strokes:
        played = pen.play([a, b], land)
        entries += [_pen_entry(r) for r in played]
        lifted = max(r.t for r in played if r.tip)
        land = lifted + gap
    end = entries[-1].t + 3.0
    entries.append(PenEntry(round(end, 6), 0.95, 0.95, 0.0, False, False, False, False, False))
    return hurried_header(), entries


def virtual_journal(seed: int, thickness: float, length: float, strokes: list[Segment],
                    gap: float) -> tuple[JournalHeader, list[JournalEntry]]:
    """The virtual pen (a UC-Logic tablet's HID reports) draws the same: the platform, then the segments with
    ``gap`` seconds between the tip leaving and the tip landing."""
    pen = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed)
    w, h = CANVAS
    (cx, cy), hw, hh = PLATFORM_CENTRE, length / 2, thickness / 2
    outline = Stroke.box((cx - hw) / w, (cy - hh) / h, (cx + hw) / w, (cy + hh) / h)
    lines = [Stroke.line((a[0] / w, a[1] / h), (b[0] / w, b[1] / h)) for a, b in strokes]
    overhead = _overhead(pen, lines)  # from one tip lifting to the next landing, with no time out of range
    platform = pen.record([outline])
    start = platform.events[-1].t + 0.8
    marks = pen.record(lines, start_t=start, gap_s=max(gap - overhead, 0.0))
    capture_header = header_for_capture(platform, MAPPING)
    entries = [*capture_entries(platform), *capture_entries(marks)]
    end = entries[-1].t + 3.0
    entries.append(PenEntry(round(end, 6), 0.95, 0.95, 0.0, False, False, False, False, False))
    return capture_header, entries


def _overhead(pen: VirtualPen, lines: list[Stroke]) -> float:
    if len(lines) < 2:
        return 0.0
    samples = pen.samples(lines[:2], gap_s=0.0)
    lifted = max(s.t for s in samples if s.stroke == 0 and s.phase == "touch")
    landed = min(s.t for s in samples if s.stroke == 1 and s.phase == "touch")
    return landed - lifted


def journal(pen: str, seed: int, thickness: float, length: float, strokes: list[Segment],
            gap: float) -> tuple[JournalHeader, list[JournalEntry]]:
    make = {"virtual": virtual_journal, "hurried": hurried_journal}[pen]
    return make(seed, thickness, length, strokes, gap)


def replayed_project(header: JournalHeader, entries: list[JournalEntry], folder: Path) -> tuple[Project, str]:
    """Writes the journal into ``folder``, replays it with ``physink replay`` and reads back the project and what
    the replay printed (the session's messages)."""
    path = folder / "drawn.physink.jsonl"
    write_journal(path, header, entries)
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()) as err:
        status = cli.main(["replay", str(path), "--out", str(folder / "out")])
    assert status == 0, err.getvalue()
    return load_project(folder / "out" / "project.json"), out.getvalue()
