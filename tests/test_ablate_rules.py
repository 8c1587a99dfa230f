"""The rule ablation benchmark (benchmarks/ablate_rules.py) switches one hand rule off in its own process, reads
hand-made strokes with and without it, and reports what the rule fixes per group; the rule is back on afterwards."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from ablate_rules import FIRST, RULES, SECOND, ablate, effects, report, switched_off
from bench_generalisation import in_second_group

from physink_tui.scene.recognition import open_marks, ranker
from physink_tui.scene.recognition.recognize import recognize_stroke


def _line_begun_backwards(lead: float = 18.0) -> list[list[float]]:
    """A line whose pen lands, slides back along it for ``lead`` units, then draws it 100 units long
    (`open_marks.retraced_ends` reads it as the line)."""
    back = [[float(lead - x), 0.6] for x in np.linspace(0.0, lead, 8)]
    on = [[float(x), float(0.3 * np.sin(x / 7))] for x in np.linspace(0.0, 100.0, 60)]
    return back + on[1:]


def _plain_line() -> list[list[float]]:
    return [[float(x), float(0.2 * x)] for x in np.linspace(0.0, 80.0, 40)]


def _second_group_person() -> str:
    """A made-up person whose source falls in the second group (by the group's own hash of the name)."""
    return next(f"p{k}" for k in range(200) if in_second_group(f"handmade:p{k}"))


def _rows() -> list[dict]:
    second = _second_group_person()
    first = next(f"p{k}" for k in range(200) if not in_second_group(f"handmade:p{k}"))
    accepts = frozenset({"line"})
    return [
        {"source": "handmade", "subject": second, "label": "line", "file": "a/backwards.xml",
         "strokes": [[[x, y, None] for x, y in _line_begun_backwards()]], "accepts": accepts},
        {"source": "handmade", "subject": first, "label": "line", "file": "b/plain.xml",
         "strokes": [[[x, y, None] for x, y in _plain_line()]], "accepts": accepts},
    ]


def test_a_rule_switched_off_loses_the_stroke_it_fixes_in_its_group() -> None:
    rows = _rows()
    rule = next(r for r in RULES if r.name == "retraced_ends")
    base, off = ablate(rows, [rule])
    assert base[0].tolist() == [True, True] and base[1].tolist() == [True, True]  # every rule on: both lines
    rules_off, shipped_off = off["retraced_ends"]
    assert rules_off.tolist() == [False, True] and shipped_off.tolist() == [False, True]
    counts, _ = effects(rows, base[0], rules_off)
    assert counts[SECOND].gains == 1 and counts[SECOND].losses == 0 and counts[SECOND].net == 1
    assert FIRST not in counts  # the plain line is read alike either way
    assert counts[f"{SECOND}|class|line"].net == 1 and counts[f"{SECOND}|set|handmade"].net == 1
    text, saved = report(rows, [rule], base, off)
    row = next(line for line in text.splitlines() if line.startswith("| retraced_ends |"))
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert cells[3:] == ["0", "+1 -0 = +1", "0", "+1 -0 = +1"]  # rules alone and shipped, first then second group
    assert saved["retraced_ends"]["rules alone"][SECOND] == [f"+ handmade:{rows[0]['subject']} line backwards.xml"]


def test_the_rule_is_back_on_after_and_the_ranker_reads_unpatched_rules_within() -> None:
    rule = next(r for r in RULES if r.name == "retraced_ends")
    before_fn, before_mod = open_marks.retraced_ends, ranker.open_shapes
    stroke = _line_begun_backwards()
    with switched_off(rule):
        assert recognize_stroke(stroke, learned=False).kind != "line"
        assert ranker.open_shapes is not before_mod  # the ranker's features see the rules unpatched
    assert open_marks.retraced_ends is before_fn and ranker.open_shapes is before_mod
    assert recognize_stroke(stroke, learned=False).kind == "line"


def test_every_rule_can_be_switched_off_and_back_on() -> None:
    stroke = _plain_line()
    names = [r.name for r in RULES]
    assert len(names) == len(set(names))
    for rule in RULES:
        patches = rule.off()
        saved = [getattr(target, name) for target, name, _ in patches]
        with switched_off(rule):
            assert all(getattr(target, name) is not was for (target, name, _), was in zip(patches, saved, strict=True))
            assert recognize_stroke(stroke).kind == "line"
        assert [getattr(target, name) for target, name, _ in patches] == saved
