"""Trains and measures the learned ranker (`recognition.ranker`) leave one source out, beside today's rules.

Usage: .venv/bin/python benchmarks/train_ranker.py SET [SET ...] [--heldback] [--write PATH] [--lam L] [--no-gate]
       [--inner K] [--weigh W]

For every scored stroke (`bench_generalisation.scored_rows`) the rules give a kind; when it is a polyline or a curve, or
a polygon left open (`ranker.family`), the ranker scores the family's kinds by ``w_kind . phi + a * [the rules'
answer]`` over standardised features (`ranker.features`). The weights are fitted by conditional-logit maximum likelihood
(Newton steps on the likelihood's Fisher matrix, L2 penalty `LAMBDA`, fixed beforehand, not tuned). The model's kind
replaces the rules' only when its chance is over a margin (`MARGINS`) chosen by leave-one-source-out inside the sources
the model is fitted on. Design folds: each source not held back is scored by a model (and margin) fitted on the other
design sources only. The first held-back group (`bench_generalisation.held_back`) is not read unless ``--heldback`` or
``--write`` is given; the second (sources found later, `bench_generalisation.held_back_new`) was read only with
``--heldback`` until it was opened as design material (`bench_generalisation.SECOND_GROUP_OPEN`): now it is read always;
the third and fourth (the sets of the third and fourth searches, `bench_generalisation.THIRD_SETS`, `FOURTH_SETS`)
never: they are neither fitted on nor scored here; each group is then scored per source and per class, apart, by a model
fitted on the design sources. ``--write`` fits on every source given but the second held-back group (the margin chosen
by leave-one-source-out over them) and writes the model as the Python data module the recogniser imports (PATH:
physink_tui/scene/recognition/ranker_model.py). Features are kept in ~/.cache/physink/ under a key of the rows and the
recognition package's source.
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # a shared machine; and the same sums in the same order
import hashlib
import json
import pprint
from collections import Counter
from pathlib import Path

import numpy as np
from bench_generalisation import held_back, held_back_new, scored_rows
from bench_recognition import machine, table
from stroke_sets import Row, read_set, source_of

from physink_tui.scene.recognition import ranker
from physink_tui.scene.recognition.recognize import recognize_stroke

MARGINS = (0.5, 0.7, 0.9)
LAMBDA = 1e-2
"""The L2 penalty, fixed before any fit was scored (not tuned)."""
WIDTH = 4  # the largest family


def stroke_times(stroke: list) -> list[float] | None:
    if all(len(p) > 2 and p[2] is not None for p in stroke):
        return [p[2] / 1000 for p in stroke]
    return None


def device_of(row: Row) -> str:
    """The kind of pen a row was drawn with, for ``--weigh device``: a stylus (the $1 people of ../shared, the MMG
    set's stylus people), touch (a finger, a touch screen or a touchpad) or a mouse (the rest)."""
    device = str(row.get("device") or "")
    if row["source"] == "dollar1" or device == "stylus" or device.startswith("stylus on"):
        return "stylus"
    return "touch" if device in ("finger", "touchpad") or device.startswith("finger on") else "mouse"


def describe(rows: list[Row]) -> dict:
    """Per stroke: the rules' kind (without the learned ranker), the features, which family kinds are right;
    kept in ~/.cache/physink/ under a key of the rows and the recognition package's source."""
    key = hashlib.sha256(json.dumps([r["file"] + r["label"] for r in rows]).encode())
    for f in sorted(Path(ranker.__file__).parent.glob("*.py")):
        key.update(f.read_bytes())
    cache = Path.home() / ".cache" / "physink" / f"ranker-{key.hexdigest()[:16]}.npz"
    if cache.exists():
        z = np.load(cache)
        return {"rules": [str(k) if k else None for k in z["rules"]], "phi": z["phi"], "right": z["right"],
                "rules_right": z["rules_right"]}
    d = _describe(rows)
    cache.parent.mkdir(parents=True, exist_ok=True)
    np.savez(cache, rules=np.array([k or "" for k in d["rules"]]), phi=d["phi"], right=d["right"],
             rules_right=d["rules_right"])
    return d


def _describe(rows: list[Row]) -> dict:
    rules, phi, right = [], [], []
    for row in rows:
        stroke = row["strokes"][0]
        times = stroke_times(stroke)
        kind = recognize_stroke([p[:2] for p in stroke], times, learned=False).kind
        rules.append(kind)
        phi.append(ranker.features(stroke, times))
        kinds = ranker.family(kind, phi[-1])
        right.append(np.array([k in row["accepts"] for k in kinds] + [False] * (WIDTH - len(kinds)), dtype=bool))
    return {"rules": rules, "phi": np.array(phi), "right": np.array(right),
            "rules_right": np.array([k in r["accepts"] for k, r in zip(rules, rows, strict=True)])}


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
        weight: np.ndarray | None = None) -> np.ndarray:
    """Conditional-logit weights maximising the mean log chance of a right kind (weighted by ``weight`` when given),
    minus ``lam / 2 |theta|^2``."""
    theta = np.zeros(x.shape[2])
    theta[-1] = 1.0
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


def model(d: dict, idx: np.ndarray, lam: float, groups: np.ndarray | None = None) -> dict:
    """A model fitted on the strokes ``idx`` whose family holds a right kind; each stroke weighs the same, or, given
    ``groups`` (one name a stroke), each group does."""
    use = idx[d["right"][idx].any(axis=1)]
    phi = d["phi"][use, :len(ranker.FEATURES)]
    mean = phi.mean(axis=0)
    std = np.where(phi.std(axis=0) > 1e-9, phi.std(axis=0), 1.0)
    x, mask = tensors(d, use, mean, std)
    weight = None if groups is None else group_weights(groups[use])
    return {"theta": fit(x, mask, d["right"][use], lam, weight=weight), "mean": mean, "std": std, "lam": lam,
            "margin": 0.5}


def group_weights(groups: np.ndarray) -> np.ndarray:
    """Each stroke's weight in the likelihood when every group (a source, or a device) weighs the same."""
    count = Counter(groups.tolist())
    return np.array([1.0 / count[g] for g in groups.tolist()])


def gated_model(d: dict, idx: np.ndarray, sources: np.ndarray, rows: list[Row], lam: float,
                inner: int | None = None, groups: np.ndarray | None = None) -> dict:
    """A model fitted on ``idx`` whose margin (`MARGINS`: how sure it must be to overrule the rules) is chosen by
    leave-one-source-out within ``idx`` only (most right answers pooled; ties to the larger margin), or, with
    ``inner`` K, by K folds of whole sources (`inner_folds`) when the sources are many."""
    got = Counter()
    for held in inner_folds(sorted(set(sources[idx])), inner):
        out = np.isin(sources[idx], held)
        fold = model(d, idx[~out], lam, groups)
        for margin in MARGINS:
            got[margin] += int(answers(d, idx[out], fold, rows, margin).sum())
    m = model(d, idx, lam, groups)
    m["margin"] = max(MARGINS, key=lambda v: (got[v], v))
    return m


def inner_folds(names: list[str], k: int | None) -> list[list[str]]:
    """The sources held out together when a margin is chosen: one at a time (``k`` None), or ``k`` groups dealt in
    the order of their names' sha256 (fixed by the names alone)."""
    if k is None or k >= len(names):
        return [[n] for n in names]
    order = sorted(names, key=lambda n: hashlib.sha256(n.encode()).hexdigest())
    return [order[i::k] for i in range(k)]


def answers(d: dict, idx: np.ndarray, m: dict, rows: list[Row], margin: float | None = None) -> np.ndarray:
    out = np.zeros(len(idx), dtype=bool)
    margin = m["margin"] if margin is None else margin
    for j, i in enumerate(idx):
        kind = (ranker.choose(d["rules"][i], d["phi"][i], ranker.Model(m["theta"], m["mean"], m["std"], margin))[0]
                if d["rules"][i] else None)
        out[j] = kind in rows[i]["accepts"]
    return out


def report(title: str, d: dict, rows: list[Row], sources: np.ndarray, folds: dict[str, np.ndarray]) -> None:
    labels = sorted({r["label"] for r in rows})
    label_of = np.array([r["label"] for r in rows])
    out, pooled = [], Counter()
    for s, got in folds.items():
        mine = np.flatnonzero(sources == s)
        before = d["rules_right"][mine]
        pooled.update(n=len(mine), before=int(before.sum()), after=int(got.sum()))
        cells = []
        for label in labels:
            sel = label_of[mine] == label
            cells.append(f"{100 * before[sel].mean():.1f} → {100 * got[sel].mean():.1f} ({int(sel.sum())})"
                         if sel.any() else "")
        out.append([s, len(mine), f"{100 * before.mean():.2f}", f"{100 * got.mean():.2f}", *cells])
    print(f"### {title}\n")
    print(table(["source", "strokes", "rules %", "ranker %", *labels], out) + "\n")
    print(f"Pooled: rules {pooled['before']}/{pooled['n']} = {100 * pooled['before'] / pooled['n']:.2f} %, ranker "
          f"{pooled['after']}/{pooled['n']} = {100 * pooled['after'] / pooled['n']:.2f} %. Cells: rules → ranker "
          "% right (strokes).\n")


def model_module_text(doc: dict) -> str:
    """The fitted model as the Python module the recogniser imports (`ranker_model`): a literal, so that reading
    the shipped weights is an import, not file I/O in the core."""
    return ('"""The learned ranker\'s fitted weights (issue 25), written by `benchmarks/train_ranker.py --write`; '
            'data only, not\nedited by hand: `ranker.shipped_model` checks them against the features the code '
            'computes."""\n\n'
            f"MODEL = {pprint.pformat(doc, width=116, compact=True, sort_dicts=False)}\n")


def rows_read(rows: list[Row], heldback: bool, write: bool) -> tuple[list[Row], set[str], set[str]]:
    """The scored rows the ranker may read, and the first and second held-back groups among them. The third and
    fourth held-back groups (`bench_generalisation.THIRD_SETS`, `FOURTH_SETS`) are never read, not even with
    ``heldback`` or ``write`` (`scored_rows` leaves them out); the second only with ``heldback``; the first only with
    ``heldback`` or ``write``."""
    rows, _ = scored_rows(rows)
    first, new = held_back(rows), held_back_new(rows)
    if not heldback:  # the second group is never read without --heldback, not even to write a model
        rows = [r for r in rows if source_of(r, "person") not in new]
        new = set()
    if not (heldback or write):
        rows = [r for r in rows if source_of(r, "person") not in first]
    return rows, first, new


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--heldback", action="store_true", help="score both held-back groups (once, at the end)")
    ap.add_argument("--lam", default=str(LAMBDA), help="L2 penalty; a comma list reports the design folds with each "
                    "(sensitivity), the first is used for the rest")
    ap.add_argument("--no-gate", action="store_true", help="overrule the rules at any margin (0.5)")
    ap.add_argument("--inner", type=int, help="choose the margin by this many folds of whole sources instead of "
                    "leave-one-source-out (many sources: the fits grow with their square)")
    ap.add_argument("--weigh", choices=("stroke", "source", "device"), default="stroke", help="what weighs the same "
                    "in the likelihood: every stroke (the shipped recipe), every source or every device (`device_of`)")
    ap.add_argument("--write", type=Path, help="fit on every source and write the model here")
    args = ap.parse_args()
    rows: list[Row] = []
    for path in args.sets:
        rows += read_set(path)
    rows, first, new = rows_read(rows, args.heldback, bool(args.write))
    group = first | new
    sources = np.array([source_of(r, "person") for r in rows])
    d = describe(rows)
    groups = {"stroke": None, "source": sources, "device": np.array([device_of(r) for r in rows])}[args.weigh]
    design_idx = np.flatnonzero(~np.isin(sources, sorted(group)))
    lams = [float(v) for v in args.lam.split(",")]

    def fitted(idx: np.ndarray, lam: float) -> dict:
        return (model(d, idx, lam, groups) if args.no_gate
                else gated_model(d, idx, sources, rows, lam, args.inner, groups))

    print(f"## Learned ranker ({machine()})\n")
    for lam in lams:
        folds, margins = {}, {}
        for s in sorted(set(sources[design_idx])):
            m = fitted(design_idx[sources[design_idx] != s], lam)
            folds[s] = answers(d, np.flatnonzero(sources == s), m, rows)
            margins[s] = m["margin"]
        report(f"Design sources, each scored by a model fitted without it (lam {lam:g}; margins "
               + ", ".join(f"{v:g}" for v in margins.values()) + ")", d, rows, sources, folds)
    if args.heldback or args.write:
        m_design = fitted(design_idx, lams[0])
        n_design = len(set(sources[design_idx]))
        for title, members in (("Held-back students (the first group)", first), ("Held-back sources found after the "
                               "first 19 (the second group)", new)):
            if members:
                held = {s: answers(d, np.flatnonzero(sources == s), m_design, rows) for s in sorted(members)}
                report(f"{title}, scored by a model fitted on the {n_design} design sources (lam "
                       f"{m_design['lam']:g}, margin {m_design['margin']:g})", d, rows, sources, held)
    if args.write:
        keep = np.flatnonzero(~np.isin(sources, sorted(new)))  # the second group is never fitted on
        m = fitted(keep, lams[0])
        args.write.write_text(model_module_text({
            "features": list(ranker.FEATURES), "kinds": list(ranker.KINDS), "lam": m["lam"], "margin": m["margin"],
            "theta": [round(float(v), 9) for v in m["theta"]], "mean": [round(float(v), 9) for v in m["mean"]],
            "std": [round(float(v), 9) for v in m["std"]]}))
        print(f"wrote {args.write} (margin {m['margin']:g})")


if __name__ == "__main__":
    main()
