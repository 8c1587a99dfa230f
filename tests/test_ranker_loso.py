"""The leave-one-source-out refits (`benchmarks/ranker_loso.py`): the same fits as `ranker_fit.model`; the verdict."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from ranker_fit import Recipe, model
from ranker_loso import Folds, verdict

from physink_tui.scene.recognition import ranker


def _described(n: int, seed: int) -> dict:
    """``n`` made-up descriptions (rules' kind, features, right kinds) whose families the ranker offers."""
    rng = np.random.default_rng(seed)
    rules, phi, right = [], [], []
    while len(rules) < n:
        kind = ("curve", "polyline")[len(rules) % 2]
        p = np.abs(rng.normal(0.5, 0.4, len(ranker.FEATURES)))
        fam = ranker.family(kind, p)
        if len(fam) < 2:
            continue
        r = np.zeros(4, dtype=bool)
        r[int(rng.integers(len(fam)))] = True
        rules.append(kind)
        phi.append(p)
        right.append(r)
    real = np.ones(n, dtype=bool)
    real[::5] = False  # every fifth a training-only copy
    return {"rules": rules, "phi": np.array(phi), "right": np.array(right), "real": real, "copies": 1,
            "guarded": np.arange(n) % 3 == 0, "scale": np.where(np.arange(n) % 7 == 0, 0.5, 1.0)}


def test_folds_fit_as_the_ranker_fit_does_on_every_subset_and_from_a_warm_start() -> None:
    d = _described(240, 0)
    recipe = Recipe(0.003, drop=("has_times", "corner_slowdown"), margins=(0.5,), copies_weight=0.5,
                    guarded_weight=0.25)
    folds = Folds(d, np.arange(240))
    whole = folds.fit(np.arange(240), recipe)
    ref = model(d, np.arange(240), recipe)
    assert np.allclose(whole["theta"], ref["theta"], atol=1e-8) and np.allclose(whole["std"], ref["std"])
    part = np.arange(240)[np.arange(240) % 4 != 1]
    warm = folds.fit(part, recipe, start=whole["theta"])
    assert np.allclose(warm["theta"], model(d, part, recipe)["theta"], atol=1e-6)
    assert np.allclose(warm["mean"], model(d, part, recipe)["mean"])


def test_a_refit_is_admissible_only_if_no_group_and_no_low_source_loses_net() -> None:
    def c(source: str, sign: int) -> tuple:
        return (source, "label", "file", "curve", "polyline", sign)

    even = {"design": [c("a", 1), c("b", -1)], "st": [], "fourth": []}
    assert verdict(even, {"c"})[0]
    assert not verdict(even, {"b"})[0] and verdict(even, {"b"})[2] == ["b"]  # a low source loses what another gains
    assert not verdict({**even, "fourth": [c("q", -1)]}, set())[0]
    assert not verdict({**even, "st": [c("w", 1), c("w", -1), c("v", -1)]}, set())[0]
    assert verdict({**even, "fourth": [c("q", 1), c("q", -1)]}, set())[1] == {"design": 0, "st": 0, "fourth": 0}
