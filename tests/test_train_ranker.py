"""The ranker's training script chooses its margin on folds of whole sources fixed by their names alone, and never
reads the second held-back group unless asked (issue 25)."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from train_ranker import inner_folds


def test_inner_folds_hold_out_every_source_once_in_groups_fixed_by_name() -> None:
    names = [f"hcira:team/user{k}" for k in range(23)]
    folds = inner_folds(names, 5)
    assert len(folds) == 5 and sorted(n for f in folds for n in f) == sorted(names)
    assert {len(f) for f in folds} == {4, 5}
    assert inner_folds(list(reversed(names)), 5) == folds
    assert inner_folds(names, None) == [[n] for n in names] == inner_folds(names, 40)
