"""The learned ranker's shipped weights: the kinds and features they score, and loading them checked against this code.

`ranker` computes the features and scores; this module only says which columns a model has and loads one (the shipped
`ranker_model`, or a JSON model fitted elsewhere), with a clear error when it does not fit the code."""

from __future__ import annotations

import functools
import json
from dataclasses import dataclass

import numpy as np

from physink_tui.scene.recognition import ranker_model

KINDS = ("polyline", "curve", "polygon")
"""The kinds re-ranked (`family`): an open stroke of straight sides or of bends, the people's sets' most telling
disagreement (braces and question marks drawn with a mouse are straight runs and cusps; checks drawn fast have bowed
arms); and a polygon whose ends stay apart (`OPEN_GAP`: a caret, a v, an arrow or a brace the rules closed), which
may be re-read as either, never as a box. An arc, a box, a closed polygon or a round shape is left to the rules: the
sets label no arc, and label trapezoids and parallelograms "rectangle", against the outline kept as drawn (issue
25), so a model fitted on them would learn to turn every arc into a curve and every trapezoid into a box."""
FEATURES = ("closure", "ink", "net_turn", "abs_turn", "corners", "concentration", "max_roundness",
            "mean_roundness", "straight_share", "max_bow", "mean_bow", "max_corner_turn", "min_corner_turn",
            "lobes", "ellipse_error", "circle_error", "aspect", "line_error", "corner_share", "one_way",
            "max_bend", "sparse", "one_corner", "two_corners", "all_straight", "bent_polyline", "brace_tip",
            "bowed_between", "rounded_bracket", "has_times", "corner_slowdown", "point_balance")
MODEL_MODULE = "physink_tui/scene/recognition/ranker_model.py"
"""Where the shipped model lives (fitted on every source by `benchmarks/train_ranker.py --write`)."""


@functools.cache
def shipped_model() -> Model:
    """The shipped model, checked once against this code's features."""
    return model_from(ranker_model.MODEL, MODEL_MODULE)


@dataclass(frozen=True, slots=True)
class Model:
    """Fitted weights (`benchmarks/train_ranker.py`): ``theta`` over `design`'s columns, the features' training
    ``mean`` and ``std``, and the ``margin`` the model's chance must pass to overrule the rules."""

    theta: np.ndarray
    mean: np.ndarray
    std: np.ndarray
    margin: float


def parse_model(text: str, where: str = "ranker model") -> Model:
    """A `Model` from its JSON text (a model fitted elsewhere, for experiments); errors as `model_from`."""
    try:
        doc = json.loads(text)
    except ValueError as exc:
        raise ValueError(f"{where}: not a ranker model ({exc})") from None
    return model_from(doc, where)


def model_from(doc: object, where: str = "ranker model") -> Model:
    """A `Model` from its fields; a clear error naming ``where`` and the field when it does not fit this code."""
    if not isinstance(doc, dict):
        raise ValueError(f"{where}: not a ranker model (a {type(doc).__name__}, not a mapping)")
    try:
        names, kinds = tuple(doc["features"]), tuple(doc["kinds"])
        theta, mean, std = (np.asarray(doc[k], dtype=float) for k in ("theta", "mean", "std"))
        margin = float(doc["margin"])
    except (ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{where}: not a ranker model ({exc})") from None
    if names != FEATURES or kinds != KINDS:
        raise ValueError(f"{where}: features {names} / kinds {kinds} are not this code's {FEATURES} / {KINDS}")
    if theta.shape != (len(KINDS) * (len(FEATURES) + 1) + 1,) or mean.shape != std.shape != (len(FEATURES),):
        raise ValueError(f"{where}: theta has {theta.size} weights, mean {mean.size}, std {std.size}")
    if not (np.isfinite(theta).all() and np.isfinite(mean).all() and (std > 0).all() and 0 <= margin < 1):
        raise ValueError(f"{where}: weights must be finite, std positive and the margin in [0, 1)")
    return Model(theta, mean, std, margin)
