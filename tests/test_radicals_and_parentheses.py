"""Issue 25, session 20: radical signs read as polylines and parentheses as arcs or curves, as people's labels say
(benchmarks/label_kinds.tsv, laviola). The fifth held-back group's radicals lost readings in session 19 to the
two-bend wave (`recognition.waves`, `MIN_BENDS` 2): a radical drawn without its bar (a serif, a rounded point, a long
rise) or with a rounded point bends twice, each way in turn, round enough to pass for an S; an S curves along its
longest piece, a radical's rise runs straight (`waves._long_straight_piece`). The pen-model families
(`tests/penmodels/math_marks`, `benchmarks/bench_math_marks.py`) are read by the four pens of `bench_open_marks`,
with and without times, on the held seeds (1000-1029, not looked at while designing); each floor is the figure
measured on this branch. A parenthesis whose end the pen flicks off straight is still taken for a tick now and then
(`recognition.hooked_ticks`, session 19): kept as a strict xfail naming its cause."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import pytest
from penmodels.hurried import HurriedPen
from penmodels.journal import header as hurried_header
from penmodels.math_marks import EXPECTED, barless_radical
from penmodels.shapes import Curve
from penmodels.shapes import Path as PenPath
from xerase_drawings import _pen_entry, replayed_project

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_math_marks import read
from bench_open_marks import HELD_SEEDS, PENS

from physink_tui.scene.components import Rope
from physink_tui.scene.recognition import hooked_ticks

HELD_FLOORS = {
    "radical": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60},
    "round-radical": {"careful": 60, "hurried": 56, "hurried-coarse": 54, "hurried-mouse": 58},
    "barless-radical": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60},
    "parenthesis": {"careful": 60, "hurried": 54, "hurried-coarse": 54, "hurried-mouse": 52},
    "hooked-parenthesis": {"careful": 54, "hurried": 56, "hurried-coarse": 56, "hurried-mouse": 52},
    "flicked-parenthesis": {"careful": 46, "hurried": 40, "hurried-coarse": 44, "hurried-mouse": 50},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are of the
family's kinds (`math_marks.EXPECTED`), measured on this branch (a22bdc4); main 2996772 read round-radical 60, 54, 54,
58 and barless-radical 58, 58, 58, 60 (the rest curves: two-bend waves), every other row the same."""


def _right(family: str, pen: str) -> tuple[int, list[str | None]]:
    got = [read(family, pen, seed, timed) for seed in HELD_SEEDS for timed in (True, False)]
    return sum(k in EXPECTED[family] for k in got), got


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_radicals_are_polylines_and_parentheses_bows(family: str, pen: str) -> None:
    right, got = _right(family, pen)
    assert right >= HELD_FLOORS[family][pen], got


@pytest.mark.xfail(strict=True, reason=(
    "hooked_ticks (session 19) takes a thin parenthesis whose end the pen flicks off straight (a bow within "
    "open_shapes.STRAIGHT, a straight end piece of 12 noise widths or more within a tenth of the path, turned 45 "
    "degrees or more) for a tick with a bowed long arm: the pen-model ticks it was made for "
    "(hurried_marks.hooked_tick, bowed 7-11 %) are the same stroke, and their floors (test_hooked_ticks) leave no "
    "room to tell them apart"))
def test_flicked_parentheses_read_as_before_hooked_ticks(monkeypatch: pytest.MonkeyPatch) -> None:
    """The held flicked parentheses read as many bows (arc or curve) with `hooked_ticks` as without it. Session 20:
    186 of 240 without it, 180 with it; main 40b8114: 190 and 184; session 24's wt-parens (fewer small bows taken for
    swung lines) 192 and 186, which passed the fixed 186 this test asked for: it now asks for the figure without the
    rule, read on the same tree."""
    with_rule = sum(_right("flicked-parenthesis", pen)[0] for pen in PENS)
    monkeypatch.setattr(hooked_ticks, "hooked_tick", lambda unit, noise: None)
    without_rule = sum(_right("flicked-parenthesis", pen)[0] for pen in PENS)
    assert with_rule >= without_rule


@pytest.mark.parametrize("seed", (6, 19))
def test_a_radical_without_its_bar_drawn_in_a_session_is_no_rope(seed: int, tmp_path) -> None:
    """A radical sign without its bar (a serif, a rounded point, a long rise: `math_marks.barless_radical` of the
    tuning seed), drawn by the hurried hand through a whole session (journal -> replay -> project), becomes a
    polyline body, not the rope a wave makes (main 2996772 made a rope of both)."""
    mark = barless_radical(seed)
    shape = Curve(mark.points) if mark.smooth else PenPath(mark.points)
    reports = HurriedPen(random.Random(seed)).draw(shape, 0.3)[0]
    project, told = replayed_project(hurried_header(), [_pen_entry(r) for r in reports], tmp_path)
    ropes = [c for c in project.scene.components.values() if isinstance(c, Rope)]
    bodies = project.scene.bodies()
    assert not ropes and len(bodies) == 1 and bodies[0].shape == "polyline", f"seed {seed}: {bodies}\n{told}"
