"""The learned ranker's training tables (per source and class, per set or device) and its written model module."""

from __future__ import annotations

import pprint
from collections import Counter

import numpy as np
from bench_recognition import table
from stroke_sets import Row


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


def summary(title: str, d: dict, scored: np.ndarray, by: np.ndarray,
            results: dict[str, tuple[np.ndarray, np.ndarray]]) -> None:
    """Per group of ``by`` (a set or a device) and pooled: the rules and each fold scheme's % right (right), and the
    strokes each scheme gains and loses against the rules; a scheme's cell counts the strokes it scores (its mask:
    the device folds score no stroke of an unknown device), the rules' all of them."""
    out = []
    rules = d["rules_right"]
    for g in [*sorted(set(by[scored].tolist())), "all"]:
        sel = scored & ((by == g) if g != "all" else True)
        n = int(sel.sum())
        cells = [f"{100 * rules[sel].mean():.2f} ({int(rules[sel].sum())})"]
        for got, mask in results.values():
            s = sel & mask
            cells.append(f"{100 * got[s].mean():.2f} ({int(got[s].sum())}"
                         + (f" of {int(s.sum())}" if s.sum() != n else "")
                         + f"; +{int((got & ~rules)[s].sum())} -{int((rules & ~got)[s].sum())})" if s.any() else "")
        out.append([f"**{g}**" if g == "all" else g, n, *cells])
    print(f"### {title}\n")
    print(table(["group", "strokes", "rules % (right)", *(f"{k} % (right; gained -lost)" for k in results)], out)
          + "\n")


def model_module_text(doc: dict) -> str:
    """The fitted model as the Python module the recogniser imports (`ranker_model`): a literal, so that reading
    the shipped weights is an import, not file I/O in the core."""
    return ('"""The learned ranker\'s fitted weights (issue 25), written by `benchmarks/train_ranker.py --write`; '
            'data only, not\nedited by hand: `ranker.shipped_model` checks them against the features the code '
            'computes."""\n\n'
            f"MODEL = {pprint.pformat(doc, width=116, compact=True, sort_dicts=False)}\n")


