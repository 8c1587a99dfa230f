"""The ranker's training weighs the opened sign set's writers as design people and tunes on its ST5022 writers only."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from ranker_fit import Recipe, weights
from ranker_sign import sign_scale, split_of


def test_sign_writers_split_by_their_tablet() -> None:
    st = {"source": "sign", "device": "pen on a Fujitsu-Siemens Stylistic ST5022 Tablet PC"}
    x61 = {"source": "sign", "device": "pen on a Fujitsu-Siemens Lenovo X61 Tablet PC"}
    assert (split_of(st), split_of(x61), split_of({"source": "hcira", "device": "ST5022"})) == ("st", "x61", "")


def test_each_sign_writer_weighs_as_the_mean_design_person_or_the_set_as_a_design_set() -> None:
    # three design people (2, 4 and 6 strokes; a copy each at half weight in all), two writers of 10 and 30 strokes
    sources = np.array(["a:p"] * 2 + ["a:q"] * 4 + ["b:r"] * 6 + ["sign:w1"] * 10 + ["sign:w2"] * 30 + ["a:p"] * 2)
    real = np.array([True] * 52 + [False] * 2)
    d = {"real": real, "copies": 1}
    design = np.concatenate([np.arange(12), np.arange(52, 54)])
    signs = np.arange(12, 52)
    scale = sign_scale(d, design, signs, sources, "source", 0.5)
    w = weights({**d, "scale": scale}, np.arange(54), Recipe(copies_weight=0.5), None)
    per_person = 12 * 1.5 / 3
    assert np.isclose(w[12:22].sum(), per_person) and np.isclose(w[22:52].sum(), per_person)
    assert np.allclose(w[:12], 1.0) and np.allclose(w[52:], 0.5)
    by_set = sign_scale(d, design, signs, sources, "set", 0.5)
    assert np.isclose(by_set[signs].sum(), 12 * 1.5 / 6)  # the mean of the six design sets (`train_ranker.SETS`)
    assert weights({"real": np.ones(5, dtype=bool), "copies": 0}, np.arange(5), Recipe(), None) is None
