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


def _rows() -> list[dict]:
    """Small rows of three sets and two devices: v shapes (polyline) and arcs of a brace (curve), times kept."""
    import math

    rows = []
    for k, (set_name, device) in enumerate([("aa", "mouse"), ("aa", "stylus"), ("bb", "mouse"), ("cc", "finger"),
                                            ("cc", "mouse or touch screen")]):
        for j in range(6):
            v = [[float(i), float(abs(i - 20) * (1 + 0.1 * j)), 10.0 * i] for i in range(41)]
            brace = [[30 * math.sin(t / 12) + 3 * j, 4.0 * t, 10.0 * t] for t in range(40)]
            for label, stroke, kinds in (("v", v, ["polyline"]), ("brace", brace, ["curve"])):
                rows.append({"source": set_name, "subject": f"p{k}", "device": device, "label": label,
                             "file": f"{set_name}/p{k}/{label}{j}", "strokes": [stroke], "accepts": kinds})
    return rows


def test_training_copies_are_the_same_for_the_same_seed_and_keep_their_label() -> None:
    from augment_strokes import augmented_rows

    rows = _rows()
    copies, origin = augmented_rows(rows, 2, 7, ("polyline", "curve"))
    again, _ = augmented_rows(rows, 2, 7, ("polyline", "curve"))
    other, _ = augmented_rows(rows, 2, 8, ("polyline", "curve"))
    assert len(copies) == 2 * len(rows) and copies == again and copies != other
    for copy, i in zip(copies, origin, strict=True):
        assert copy["label"] == rows[i]["label"] and copy["accepts"] == rows[i]["accepts"]
        assert copy["file"] != rows[i]["file"] and copy["strokes"] != rows[i]["strokes"]
        assert all(len(p) == 3 for p in copy["strokes"][0])  # times kept where the stroke had them


def test_a_held_out_group_is_never_fitted_on_and_copies_are_never_scored(monkeypatch) -> None:
    """The set and device folds fit without every stroke (and every training copy) of the group they score, never on
    a stroke of an unknown device, and score people's strokes only."""
    import numpy as np
    import train_ranker
    from train_ranker import _describe, device_known, held_out, with_copies

    monkeypatch.setattr(train_ranker, "describe", lambda rows, salt=b"": _describe(rows))  # no cache written
    rows = _rows()
    n = len(rows)
    rows2, d2, origin = with_copies(rows, _describe(rows), 1, 0)
    sets = np.array([r["source"] for r in rows2])
    devices = np.array([device_known(r) for r in rows2])
    assert set(devices[:n]) == {"mouse", "stylus", "touch", ""} and len(rows2) == 2 * n
    seen = []

    def fitted(idx: np.ndarray) -> dict:
        seen.append(idx)
        return {"theta": np.zeros(3 * 33 + 1), "mean": np.zeros(32), "std": np.ones(32), "margin": 0.5}

    for keys in (sets, devices):
        seen.clear()
        got, margins = held_out(d2, rows2, np.arange(len(rows2)), keys, fitted, origin)
        held = sorted(k for k in set(keys.tolist()) if k)
        assert sorted(margins) == held and len(seen) == len(held)
        for k, idx in zip(held, seen, strict=True):
            assert k not in set(keys[idx].tolist()) and "" not in set(keys[idx].tolist())
            assert (idx >= n).any()  # copies of the other groups are fitted on
        assert got.shape == (len(rows2),) and not got[n:].any()
        assert got[:n][keys[:n] != ""].any()  # people's strokes are scored


def test_a_dropped_feature_weighs_nothing_and_the_others_are_fitted() -> None:
    import numpy as np
    from ranker_fit import Recipe, dropped_columns, model
    from train_ranker import _describe

    rows = _rows()
    d = {**_describe(rows), "real": np.ones(len(rows), dtype=bool)}
    m = model(d, np.arange(len(rows)), Recipe(drop=("sparse", "ink")))
    cols = dropped_columns(("sparse", "ink"))
    assert len(cols) == 6 and (m["theta"][cols] == 0.0).all()
    assert np.count_nonzero(m["theta"]) > 20
