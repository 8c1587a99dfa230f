"""SIMULATE on the thesis's portfolio (issue 14): each machine whose demonstration a gravity simulation can follow is
found equivalent (qualitative distance 0) by the default search with seed 0 and the default budget, through the
command a user runs. The ones still unsolved and why are in docs/BENCHMARKS.md ("SIMULATE")."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physink_tui.cli import main
from physink_tui.sim.defaults import DEFAULT_BUDGET

JOURNALS = Path(__file__).parent / "journals"
SOLVED = ("pinball", "basketball", "golf_ball_helper", "egg_cracker", "cup_dispenser", "bouncing_hits_b_once",
          "bouncing_above_b", "bouncing_below_b", "bouncing_a_then_b_bottom", "bouncing_a_then_b_bottom_again")
"""Every machine issue 14 lists: figures 3-21 (hits B once), 2-14 (above B), 3-22 (below B), 2-15 (both paths), and
the portfolio of chapter 4."""


@pytest.mark.parametrize("name", SOLVED)
def test_the_default_search_finds_an_equivalent_simulation(name: str, tmp_path: Path,
                                                           capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["replay", str(JOURNALS / f"{name}.physink.jsonl"), "--out", str(tmp_path / "demo")]) == 0
    out = tmp_path / "sim"
    assert main(["simulate", str(tmp_path / "demo" / "project.json"), "--out", str(out), "--seed", "0",
                 "--workers", "2"]) == 0
    result = json.loads((out / "result.json").read_text(encoding="utf-8"))
    assert result["found"] and result["qualitative_distance"] == 0, result["verdict"]
    assert result["rollouts"] <= DEFAULT_BUDGET and result["differences"] == []
    assert "found: qualitative distance 0" in capsys.readouterr().out
