"""The learned ranker's fit: a recipe (`Recipe`), the conditional logit's Newton steps, the margin chosen on folds.

`train_ranker.py` describes the strokes (``d``: the rules' kind, the features, which family kinds are right) and calls
`gated_model` on the strokes a fold may be fitted on; this module knows nothing of files. ``d`` may hold training-only
copies of strokes (`augment_strokes`): ``d["real"]`` is false for them, and they are never scored.
"""

from __future__ import annotations

import hashlib
from collections import Counter
from dataclasses import dataclass

import numpy as np
from stroke_sets import Row

from physink_tui.scene.recognition import ranker

WIDTH = 4  # the largest family, with room to spare (the tensors' shape; empty slots are masked)


@dataclass(frozen=True)
class Recipe:
    """How a model is fitted: the L2 penalty ``lam``; what weighs the same in the likelihood (``weigh``: every
    stroke, source, set or device); the features left out (``drop``: their weights stay 0); the margins the
    model's chance may have to pass (``margins``), chosen on ``inner`` folds of whole sources (None: one a source)
    or, with ``inner_by`` "set", one fold a set; the training-only copies' total weight against the people's
    strokes (``copies_weight``, when ``d`` holds copies); ``skip_guarded``: fit on no stroke the recogniser never asks
    the model about (``d["guarded"]``; fitted on, they pull the model towards the rules' answer: docs/BENCHMARKS.md,
    "Why a refit of the ranker loses people's readings"), or, with ``guarded_weight`` under 1, fit on them at that
    weight each (a smaller pull, not none)."""

    lam: float = 1e-2
    weigh: str = "stroke"
    drop: tuple[str, ...] = ()
    margins: tuple[float, ...] = (0.5, 0.7, 0.9)
    inner: int | None = None
    inner_by: str = "source"
    copies_weight: float = 1.0
    skip_guarded: bool = False
    guarded_weight: float = 1.0

    def name(self) -> str:
        parts = [f"lam {self.lam:g}", f"weigh {self.weigh}", "margins " + "/".join(f"{m:g}" for m in self.margins),
                 f"inner {self.inner_by}" + (f" {self.inner}" if self.inner and self.inner_by == "source" else "")]
        if self.drop:
            parts.append("drop " + ",".join(self.drop))
        if self.skip_guarded:
            parts.append("unasked strokes not fitted on")
        elif self.guarded_weight != 1.0:
            parts.append(f"unasked strokes weigh {self.guarded_weight:g}")
        return "; ".join(parts)


def tensors(d: dict, idx: np.ndarray, mean: np.ndarray, std: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    p = (len(ranker.FEATURES) + 1) * len(ranker.KINDS) + 1
    x = np.zeros((len(idx), WIDTH, p))
    mask = np.zeros((len(idx), WIDTH), dtype=bool)
    for j, i in enumerate(idx):
        kinds = ranker.family(d["rules"][i], d["phi"][i])
        x[j, :len(kinds)] = ranker.design(kinds, (d["phi"][i, :len(ranker.FEATURES)] - mean) / std, d["rules"][i])
        mask[j, :len(kinds)] = True
    return x, mask


def fit(x: np.ndarray, mask: np.ndarray, right: np.ndarray, lam: float, steps: int = 40,
        weight: np.ndarray | None = None, start: np.ndarray | None = None) -> np.ndarray:
    """Conditional-logit weights maximising the mean log chance of a right kind (weighted by ``weight`` when given),
    minus ``lam / 2 |theta|^2``; Newton's steps from ``start`` (default: the rules' answer alone, weight 1)."""
    if start is None:
        theta = np.zeros(x.shape[2])
        theta[-1] = 1.0
    else:
        theta = np.array(start, dtype=float)
    w = np.full(len(x), 1.0 / len(x)) if weight is None else weight / weight.sum()

    def loss(t: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
        s = np.where(mask, (x.reshape(-1, x.shape[2]) @ t).reshape(mask.shape), -np.inf)
        s = s - s.max(axis=1, keepdims=True)
        e = np.exp(s)
        p = e / e.sum(axis=1, keepdims=True)
        pr = np.where(right, p, 0.0).sum(axis=1)
        nll = -float(w @ np.log(np.maximum(pr, 1e-300))) + 0.5 * lam * float(t @ t)
        return nll, p, pr

    for _ in range(steps):
        nll, p, pr = loss(theta)
        q = np.where(right, p, 0.0) / np.maximum(pr, 1e-300)[:, None]
        ex = (p[:, :, None] * x).sum(axis=1)
        grad = w @ (ex - (q[:, :, None] * x).sum(axis=1)) + lam * theta
        centred = (x - ex[:, None, :]) * np.sqrt(p * w[:, None])[:, :, None]
        flat = centred.reshape(-1, x.shape[2])
        hess = flat.T @ flat + lam * np.eye(len(theta))
        step = np.linalg.solve(hess, grad)
        rate = 1.0
        while rate > 1e-4 and loss(theta - rate * step)[0] > nll:
            rate /= 2
        theta = theta - rate * step
        if nll - loss(theta)[0] < 1e-10:
            break
    return theta


def dropped_columns(drop: tuple[str, ...]) -> list[int]:
    """The columns of `ranker.design` that hold the features ``drop``, in every kind's block."""
    width = len(ranker.FEATURES) + 1
    return [k * width + ranker.FEATURES.index(f) for k in range(len(ranker.KINDS)) for f in drop]


def model(d: dict, idx: np.ndarray, recipe: Recipe, groups: np.ndarray | None = None) -> dict:
    """A model fitted on the strokes ``idx`` whose family holds a right kind (with ``recipe.skip_guarded``, only those
    the recogniser asks the model about: not ``d["guarded"]``), each weighing as ``recipe.weigh`` says (``groups``: one
    name a stroke, for every weighing but "stroke"); a dropped feature's column is zero, so its weights stay 0."""
    fits = d["right"][idx].any(axis=1)
    if recipe.skip_guarded:
        fits &= ~d["guarded"][idx]
    use = idx[fits]
    phi = d["phi"][use, :len(ranker.FEATURES)]
    mean = phi.mean(axis=0)
    std = np.where(phi.std(axis=0) > 1e-9, phi.std(axis=0), 1.0)
    x, mask = tensors(d, use, mean, std)
    cols = dropped_columns(recipe.drop)
    x[:, :, cols] = 0.0
    theta = fit(x, mask, d["right"][use], recipe.lam, weight=weights(d, use, recipe, groups))
    theta[cols] = 0.0  # already 0 (no gradient, the penalty alone): said outright
    return {"theta": theta, "mean": mean, "std": std, "lam": recipe.lam, "margin": 0.5}


def weights(d: dict, use: np.ndarray, recipe: Recipe, groups: np.ndarray | None) -> np.ndarray | None:
    """Each stroke's weight in the likelihood: people's strokes 1, the copies of a stroke ``copies_weight`` in all,
    times ``d["scale"]`` where given, times ``recipe.guarded_weight`` for a stroke the recogniser never asks the model
    about (``d["guarded"]``); with ``groups``, scaled so that every group weighs the same."""
    real = d["real"][use]
    scale = d.get("scale")  # a factor a row (`ranker_sign`: the sign writers weighed as design people)
    if real.all() and groups is None and scale is None and recipe.guarded_weight == 1.0:
        return None
    base = np.where(real, 1.0, recipe.copies_weight / max(d.get("copies", 1), 1))
    if recipe.guarded_weight != 1.0:
        base = base * np.where(d["guarded"][use], recipe.guarded_weight, 1.0)
    if scale is not None:
        base = base * scale[use]
    if groups is None:
        return base
    g = groups[use].tolist()
    total = Counter()
    for name, b in zip(g, base.tolist(), strict=True):
        total[name] += b
    return np.array([b / total[name] for name, b in zip(g, base.tolist(), strict=True)])


def gated_model(d: dict, idx: np.ndarray, keys: np.ndarray, rows: list[Row], recipe: Recipe,
                groups: np.ndarray | None = None) -> dict:
    """A model fitted on ``idx`` whose margin (how sure it must be to overrule the rules) is chosen among
    ``recipe.margins`` on folds of whole ``keys`` within ``idx`` only — sources (one at a time, or ``recipe.inner``
    groups, `inner_folds`) or sets — most right answers on the people's strokes pooled, ties to the larger margin."""
    got = Counter()
    for held in inner_folds(sorted(set(keys[idx].tolist())), recipe.inner if recipe.inner_by == "source" else None):
        out = np.isin(keys[idx], held)
        fold = model(d, idx[~out], recipe, groups)
        test = idx[out & d["real"][idx]]
        for margin in recipe.margins:
            got[margin] += int(answers(d, test, fold, rows, margin).sum())
    m = model(d, idx, recipe, groups)
    m["margin"] = max(recipe.margins, key=lambda v: (got[v], v))
    return m


def inner_folds(names: list[str], k: int | None) -> list[list[str]]:
    """The sources held out together when a margin is chosen: one at a time (``k`` None), or ``k`` groups dealt in
    the order of their names' sha256 (fixed by the names alone)."""
    if k is None or k >= len(names):
        return [[n] for n in names]
    order = sorted(names, key=lambda n: hashlib.sha256(n.encode()).hexdigest())
    return [order[i::k] for i in range(k)]


def answers(d: dict, idx: np.ndarray, m: dict, rows: list[Row], margin: float | None = None) -> np.ndarray:
    """Whether the recogniser with model ``m`` (at ``margin``, or the model's own) reads each stroke ``idx`` right: the
    rules' kind where the recogniser does not ask the model or would not keep its answer (``d["guarded"]``), else
    `ranker.choose`'s."""
    out = np.zeros(len(idx), dtype=bool)
    margin = m["margin"] if margin is None else margin
    model_ = ranker.Model(m["theta"], m["mean"], m["std"], margin)
    for j, i in enumerate(idx):
        rules = d["rules"][i]
        kind = ranker.choose(rules, d["phi"][i], model_)[0] if rules and not d["guarded"][i] else rules
        out[j] = kind in rows[i]["accepts"]
    return out
