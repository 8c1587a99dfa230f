"""The learned ranker is trained on what the recogniser asks it (issue 25, session 32): `train_ranker`'s description
of a stroke gives the reading the recogniser gives, the model asked or not, and the same strokes fit byte-identical
weights. Before, the training scored every polyline and curve of the rules by the model, some 5,000 people's strokes
the recogniser never asks it about, with features of the whole stroke where the recogniser reads a settled stroke or
its last attempt (docs/BENCHMARKS.md, "Why a refit of the ranker loses people's readings").

People's strokes are read in place from ``../shared/data/strokes/dollar1-dev.jsonl`` (`shared_data`).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from shared_data import shared_path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_generalisation import scored_rows
from stroke_sets import read_set

from physink_tui.scene.recognition import ranker
from physink_tui.scene.recognition.recognize import recognize_stroke


def _rows(step: int) -> list[dict]:
    rows, _ = scored_rows(read_set(shared_path("strokes", "dollar1-dev.jsonl")))
    return rows[::step]


def test_the_description_reads_each_stroke_as_the_recogniser_does() -> None:
    """Scored with the shipped model as `train_ranker` scores a fold (`ranker_fit.answers`), every stroke gets the
    kind the recogniser gives it; strokes the recogniser does not ask the model about are guarded."""
    from ranker_fit import answers
    from train_ranker import _describe, stroke_times

    rows = _rows(5)
    d = _describe(rows)
    shipped = ranker.shipped_model()
    m = {"theta": shipped.theta, "mean": shipped.mean, "std": shipped.std, "margin": shipped.margin}
    asked = 0
    for i, row in enumerate(rows):
        stroke = row["strokes"][0]
        read = recognize_stroke([p[:2] for p in stroke], stroke_times(stroke)).kind
        described = (ranker.choose(d["rules"][i], d["phi"][i], shipped)[0] if not d["guarded"][i]
                     else d["rules"][i])
        assert read == described, row["file"]
        asked += not d["guarded"][i]
    assert 0 < asked < len(rows)
    got = answers(d, np.arange(len(rows)), m, rows)
    assert got.tolist() == [recognize_stroke([p[:2] for p in r["strokes"][0]], stroke_times(r["strokes"][0])).kind
                            in r["accepts"] for r in rows]


def test_the_same_strokes_fit_byte_identical_weights(monkeypatch) -> None:
    """Described, copied (`augment_strokes`) and fitted twice over, the written model's text is the same."""
    import train_ranker
    from ranker_fit import Recipe, model
    from train_ranker import _describe, model_module_text, with_copies

    monkeypatch.setattr(train_ranker, "describe", lambda rows, salt=b"": _describe(rows))  # no cache written
    texts = []
    for _ in range(2):
        rows = _rows(12)
        rows, d, _ = with_copies(rows, _describe(rows), 1, 0, 1.0)
        m = model(d, np.arange(len(rows)), Recipe(lam=0.003, drop=("has_times", "corner_slowdown"),
                                                    copies_weight=0.5, margins=(0.5,)))
        texts.append(model_module_text({
            "features": list(ranker.FEATURES), "kinds": list(ranker.KINDS), "lam": m["lam"], "margin": m["margin"],
            "theta": [round(float(v), 9) for v in m["theta"]], "mean": [round(float(v), 9) for v in m["mean"]],
            "std": [round(float(v), 9) for v in m["std"]]}))
        assert np.count_nonzero(m["theta"]) > 20
    assert texts[0] == texts[1]
