"""The ranker's refit options of session 38: unasked strokes at a smaller weight, and features alike from either end."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_reversed import reversed_stroke
from ranker_fit import Recipe, weights
from ranker_leaning import LEANING
from shared_data import shared_path
from train_ranker import recipe_from

from physink_tui.scene.recognition import ranker


def test_unasked_strokes_weigh_the_guarded_weight_and_copies_still_their_share() -> None:
    # four people's strokes (the second and fourth never asked) and two copies of the first (0.5 in all)
    d = {"real": np.array([True] * 4 + [False] * 2), "copies": 2,
         "guarded": np.array([False, True, False, True, False, True])}
    w = weights(d, np.arange(6), Recipe(copies_weight=0.5, guarded_weight=0.25), None)
    assert np.allclose(w, [1.0, 0.25, 1.0, 0.25, 0.25, 0.0625])
    plain = {"real": np.ones(3, dtype=bool), "copies": 0, "guarded": np.array([True, False, True])}
    assert weights(plain, np.arange(3), Recipe(), None) is None  # the shipped recipe's fit is unchanged
    assert np.allclose(weights(plain, np.arange(3), Recipe(guarded_weight=0.5), None), [0.5, 1.0, 0.5])
    assert "unasked strokes weigh 0.5" in Recipe(guarded_weight=0.5).name()


def _args(**kw: object) -> object:
    base = {"drop": "has_times,corner_slowdown", "drop_leaning": False, "no_gate": False, "margins": "0.5",
            "weigh": "stroke", "inner": None, "inner_by": "source", "copies_weight": 0.5, "skip_guarded": False,
            "guarded_weight": 1.0}
    return type("Args", (), {**base, **kw})()


def test_drop_leaning_adds_the_leaning_features_once_and_the_weight_is_checked() -> None:
    recipe = recipe_from(_args(drop_leaning=True, guarded_weight=0.3), 0.003)
    assert recipe.drop[:2] == ("has_times", "corner_slowdown") and set(LEANING) <= set(recipe.drop)
    assert len(recipe.drop) == len(set(recipe.drop)) and recipe.guarded_weight == 0.3
    for bad in ({"guarded_weight": 0.0}, {"guarded_weight": 1.5}, {"guarded_weight": 0.5, "skip_guarded": True}):
        with pytest.raises(SystemExit):
            recipe_from(_args(**bad), 0.003)


def test_the_features_kept_by_drop_leaning_read_people_alike_from_either_end() -> None:
    dollar1 = shared_path("strokes", "dollar1-dev.jsonl", module_level=False)
    kept = [j for j, f in enumerate(ranker.FEATURES) if f not in LEANING]
    rows = [json.loads(line) for line in dollar1.read_text().splitlines()[::40]]
    assert len(rows) > 30
    for row in rows:
        stroke = row["strokes"][0]
        points = [[float(v) for v in p[:2]] for p in stroke]
        times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 for p in stroke) else None
        ahead, back = ranker.features(points, times), ranker.features(*reversed_stroke(points, times))
        assert np.allclose(ahead[kept], back[kept], atol=0.02), row["file"]
