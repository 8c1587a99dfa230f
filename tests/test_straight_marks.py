"""Straight strokes and one-corner marks that read as curves (issue 25, session 17): a line the wrist bowed or the pen
wobbled past the line test, with no corner and no point, is a line (`open_shapes.STRAIGHT_CURVE`,
`straight_curve_as_line`); a hurried check whose short arm wobbles beside its sharp point is a polyline
(`open_shapes._roundest_corner`); a one-corner mark with both arms straight is not re-read by the learned ranker
(`open_shapes.straight_armed_mark`). Shallow arcs and braces stay what they were.

The pen models always run; dollar1's strokes are read in place from ``../shared/data`` (`shared_data`); the other
people's strokes from the caches `benchmarks/public_sets.py` writes (no licence lets the project hold them): without
them those tests skip, saying so. Floors are today's counts; at main cb69115 the bowed line was 25 of 40 lines by the
hurried hand (15 curves), and every person's stroke below but the brace was misread.
"""

from __future__ import annotations

import json
import math
import random
import sys
import zlib
from collections import Counter
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from shared_data import shared_path
from test_bracket_marks import PENS, brace_with_straight_arms
from test_open_marks import cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_device_stress import COMBINED, MORE, TRANSFORMS, as_stroke  # the benchmark's own transforms
from bench_recognition import ACCEPTS, LABEL_CLASS

SEEDS = range(40)
Point = tuple[float, float]


def _bowed(name: str, seed: int, bow: tuple[float, float], waves: int) -> list[Point]:
    """A stroke 150-400 px long at any angle, bowed off its chord by ``bow`` (a share of its length) in ``waves``
    half-waves: one for the wrist's swing, two for a wobble one way and back."""
    rng = random.Random(f"{name}:{seed}")
    length = rng.uniform(150, 400)
    off = rng.uniform(*bow) * rng.choice((-1, 1)) * length
    n = 12 * waves + 12
    pts = [(length * (k / n - 0.5), off * math.sin(waves * math.pi * k / n)) for k in range(n + 1)]
    a = rng.uniform(0, 2 * math.pi)
    c, s = math.cos(a), math.sin(a)
    return [(800 + x * c - y * s, 500 + x * s + y * c) for x, y in pts]


def bowed_line(seed: int) -> list[Point]:
    """A line the wrist bowed 6-10 % of its length (gtiwari's mouse lines bow 8-10 %)."""
    return _bowed("bowed-line", seed, (0.06, 0.10), 1)


def shallow_arc(seed: int) -> list[Point]:
    """An arc bowed 16-25 % of its chord: more than a polyline's side may (`open_shapes.STRAIGHT`)."""
    return _bowed("shallow-arc", seed, (0.16, 0.25), 1)


def _readings(shape, pen: str, learned: bool) -> Counter[str | None]:
    out: Counter[str | None] = Counter()
    for seed in SEEDS:
        drawn = PENS[pen](shape(seed), seed)
        out[recognize_stroke([p[:2] for p in drawn], [p[2] for p in drawn], learned=learned).kind] += 1
    return out


# (pen, learned) -> lines of 40 (today's counts; at main cb69115 the hurried hand's were 25: 15 read as curves). The
# careful pen draws the bow as a clean arc: 20 of its 40 pass the arc test (they are arcs), the rest are lines.
BOWED_LINE_FLOORS = {("careful", False): 20, ("careful", True): 20, ("hurried", False): 40, ("hurried", True): 40}


@pytest.mark.parametrize(("pen", "learned"), list(BOWED_LINE_FLOORS))
def test_a_line_bowed_by_the_wrist_is_a_line_never_a_curve(pen: str, learned: bool) -> None:
    read = _readings(bowed_line, pen, learned)
    assert read["curve"] == 0, read
    assert read["line"] >= BOWED_LINE_FLOORS[(pen, learned)], read


@pytest.mark.parametrize("pen", list(PENS))
def test_a_shallow_arc_or_a_brace_is_never_a_line(pen: str) -> None:
    arcs = _readings(shallow_arc, pen, True)
    assert arcs["line"] == 0, arcs
    braces = _readings(brace_with_straight_arms, pen, True)
    assert braces["line"] <= 1, braces  # one seed's brace reads as a line at main cb69115 too: not this rule's


@cache
def dollar1_rows() -> dict[str, dict]:
    path = shared_path("strokes", "dollar1-dev.jsonl")
    rows = (json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip())
    return {r["file"]: r for r in rows}


def _read(row: dict, learned: bool = True) -> str | None:
    stroke = row["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    return recognize_stroke([p[:2] for p in stroke], times, learned=learned).kind


def test_a_check_whose_short_arm_wobbles_is_a_polyline() -> None:
    """dollar1 s04's fast check: its short arm waves (a 59 degree bend, round) on the way down to a 148 degree point;
    a curve at main cb69115."""
    row = dollar1_rows()["s04/fast/check09.xml"]
    assert _read(row, learned=False) == "polyline"
    assert _read(row) == "polyline"


GTIWARI = ("gtiwari333/mouse-gesture-recognition-java-hidden-markov-model@06d9351:trainData/StrtLine_{0}/"
           "StrtLine_{0}{1}.TRAINDATA")
PEOPLE = {
    # mouse lines bowed 8-10 % of their length with a landing hook: curves at main cb69115
    GTIWARI.format("LeftDown_To_RightUp", "1308483841226"): "line",
    GTIWARI.format("LeftDown_To_RightUp", "1308483909370"): "line",
    GTIWARI.format("LeftUp_To_RightDown", "1308483743755"): "line",
    GTIWARI.format("LeftUp_To_RightDown", "1308483749771"): "line",
    # a tick with two straight arms turning 94 degrees: the rules' polyline, re-read as a curve by the model at main
    "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TestData/Tick.xml#3": "polyline",
    # a thin brace whose straight-looking spine has its tip: a curve, as at main (the arms' no-point test keeps it)
    "klarubbio/hcira_p1@e8eb332:xml/s03/right_curly_brace04.xml": "curve",
}
SETS = {"gtiwari": "public-sets/gtiwari.jsonl", "AhmadOsama4": "public-sets/ahmadosama.jsonl",
        "klarubbio": "public-sets/hcira.jsonl"}


@pytest.mark.parametrize("file", list(PEOPLE), ids=[f.rsplit("/", 1)[-1] for f in PEOPLE])
def test_a_persons_straight_stroke_or_one_corner_mark_is_read_as_what_it_is(file: str) -> None:
    name = next(path for owner, path in SETS.items() if file.startswith(owner))
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    assert _read(row) == PEOPLE[file]


ONE_CORNER_UNDER_DEVICES_FLOOR = 6949
"""dollar1's checks, v's and carets (270 strokes), each under every device transform of `bench_device_stress`
(`TRANSFORMS`, `COMBINED`, `MORE`: 26), read right: 6,949 of 7,020 today, 6,934 at main cb69115 (none fewer in any
transform; transformed strokes, not people)."""


def test_peoples_one_corner_marks_under_device_transforms() -> None:
    rows = [r for r in dollar1_rows().values() if r["label"] in ("check", "v", "caret")]
    assert len(rows) == 270
    right = 0
    for name, change in {**TRANSFORMS, **COMBINED, **MORE}.items():
        for row in rows:
            rng = np.random.default_rng(zlib.crc32(f"{row['file']}|{row['label']}|{name}".encode()))
            pts, times = change(as_stroke(row), rng)
            found = recognize_stroke(pts.tolist(), None if times is None else times.tolist())
            right += found.kind in ACCEPTS[LABEL_CLASS[row["label"]]]
    assert right >= ONE_CORNER_UNDER_DEVICES_FLOOR, right
