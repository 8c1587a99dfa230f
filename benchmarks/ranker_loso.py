"""Leave-one-source-out refits of the learned ranker, read stroke by stroke against the shipped weights (issue 25).

Usage: .venv/bin/python benchmarks/ranker_loso.py SET [SET ...] --sign SIGN_JSONL --fourth Q.jsonl T.jsonl
       [--guarded-weights G[,G...]] [--lams L[,L...]] [--margins M[,M...]] [--augment K] [--copies-weight A]
       [--events-share E] [--drop F[,F...]] [--variants 'F,F;F;...'] [--each] [--hide-x61] [--write PATH]

Every design source (the first held-back group's students too: `misses.py design` reads them) and every sign ST5022
writer is held out once, alone, and read by a model fitted on all the others (the design strokes and their copies, the
ST writers each weighing as the mean design person, `ranker_sign.sign_scale`; the X61 writers are never fitted on).
A recipe (an unasked strokes' weight ``G``, an L2 penalty ``L``) is fitted so once per fold; each margin ``M`` reads
the same fits. The fourth group (never fitted on) is read by the model fitted on every fold's pool.

Each refit is compared with the shipped weights (`ranker_model`) **stroke by stroke**: a gain is a stroke the refit
reads right and the shipped weights wrong, a loss the reverse (the shipped weights were fitted on the design sources,
so their side is in-sample: the comparison leans towards them). A recipe is **admissible** when it loses no stroke net
on the design sources, none net on the fourth group, none net on any design source the shipped weights read under
`LOW` (the sources `misses.py design` lists under 98.6 %), and none net on the ST writers; the best admissible
recipe (most net gains on design, then ST, then fourth) is reported with its gains and losses one by one, and written
with ``--write`` (the model fitted on every design source and the ST writers; with no admissible recipe, nothing is
written). The fits follow `ranker_fit.model` exactly (the features standardised on each fold's own strokes), from
tensors built once (`Folds`) and Newton's steps started at the whole pool's weights (the optimum is unique).
``--variants`` fits every recipe once per list of features dropped besides ``--drop`` (a feature tried alone, or a
control without it, on the same description); ``--each`` lists every recipe's gains and losses stroke by stroke.
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import time
from collections import Counter
from pathlib import Path

import numpy as np
import ranker_sign
import train_ranker as tr
from ranker_fit import Recipe, dropped_columns, fit, tensors, weights
from ranker_tables import model_module_text
from stroke_sets import read_set

from physink_tui.scene.recognition import ranker, ranker_model

LOW = 0.986
"""The design sources whose share read right by the shipped weights is under this must not lose a stroke net."""
F = len(ranker.FEATURES)


class Folds:
    """The tensors of every stroke of ``pool`` whose family holds a right kind, built once on the raw features; a
    fit on a subset standardises them on its own strokes (as `ranker_fit.model` does) by each kind block's constant."""

    def __init__(self, d: dict, pool: np.ndarray) -> None:
        self.d = d
        self.rows = np.sort(pool[d["right"][pool].any(axis=1)])
        self.x, self.mask = tensors(d, self.rows, np.zeros(F), np.ones(F))

    def fit(self, idx: np.ndarray, recipe: Recipe, start: np.ndarray | None = None) -> dict:
        d = self.d
        use = np.sort(idx[d["right"][idx].any(axis=1)])
        j = np.searchsorted(self.rows, use)
        phi = d["phi"][use, :F]
        mean = phi.mean(axis=0)
        std = np.where(phi.std(axis=0) > 1e-9, phi.std(axis=0), 1.0)
        x = self.x[j]
        for k in range(len(ranker.KINDS)):
            b = k * (F + 1)
            x[:, :, b:b + F] = (x[:, :, b:b + F] - mean * x[:, :, b + F:b + F + 1]) / std
        cols = dropped_columns(recipe.drop)
        x[:, :, cols] = 0.0
        theta = fit(x, self.mask[j], d["right"][use], recipe.lam, weight=weights(d, use, recipe, None), start=start)
        theta[cols] = 0.0
        return {"theta": theta, "mean": mean, "std": std, "lam": recipe.lam}


def kinds(d: dict, idx: np.ndarray, m: dict, margin: float) -> list[str | None]:
    """The kind the recogniser reads for each stroke ``idx`` with model ``m`` at ``margin`` (`ranker_fit.answers`)."""
    model_ = ranker.Model(m["theta"], m["mean"], m["std"], margin)
    return [ranker.choose(d["rules"][i], d["phi"][i], model_)[0] if d["rules"][i] and not d["guarded"][i]
            else d["rules"][i] for i in idx]


def right(every: list, idx: np.ndarray, ks: list) -> np.ndarray:
    return np.array([k in every[i]["accepts"] for i, k in zip(idx, ks, strict=True)], dtype=bool)


def changes(every: list, sources: np.ndarray, idx: np.ndarray, ref: list, new: list) -> list[tuple]:
    """(source, label, file, shipped kind, refit kind, +1 gained / -1 lost) for each stroke read otherwise."""
    out = []
    for i, a, b in zip(idx, ref, new, strict=True):
        ra, rb = a in every[i]["accepts"], b in every[i]["accepts"]
        if ra != rb:
            out.append((str(sources[i]), every[i]["label"], every[i]["file"], a, b, 1 if rb else -1))
    return out


def verdict(ch: dict[str, list[tuple]], low: set[str]) -> tuple[bool, dict[str, int], list[str]]:
    """Whether a recipe's changes (per group: design, st, fourth) are admissible (module docstring), the nets, and
    the low sources that lose net."""
    net = {g: sum(c[-1] for c in v) for g, v in ch.items()}
    per = Counter()
    for c in ch["design"]:
        per[c[0]] += c[-1]
    bad = sorted(s for s in low if per[s] < 0)
    return net["design"] >= 0 and net["fourth"] >= 0 and net["st"] >= 0 and not bad, net, bad


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--sign", type=Path, required=True)
    ap.add_argument("--fourth", type=Path, nargs="*", default=[])
    ap.add_argument("--guarded-weights", default="0.25")
    ap.add_argument("--lams", default="0.003")
    ap.add_argument("--margins", default="0.5")
    ap.add_argument("--augment", type=int, default=2)
    ap.add_argument("--augment-seed", type=int, default=0)
    ap.add_argument("--copies-weight", type=float, default=0.5)
    ap.add_argument("--events-share", type=float, default=1.0)
    ap.add_argument("--drop", default="has_times,corner_slowdown")
    ap.add_argument("--variants", default="", help="';'-separated comma lists of features dropped besides --drop, "
                    "each fitted as a recipe of its own (an empty item: none more); e.g. the new features in turn")
    ap.add_argument("--each", action="store_true", help="list every recipe's gains and losses, not only the best's")
    ap.add_argument("--hide-x61", action="store_true")
    ap.add_argument("--write", type=Path)
    args = ap.parse_args()
    rows = []
    for path in args.sets:
        rows += read_set(path)
    rows, first, new = tr.rows_read(rows, False, True)
    m = ranker_sign.material(args, rows, first | new)
    d, every, origin, sources = m["d"], m["every"], m["origin"], m["sources"]
    st, x61, fourth = m["st"], m["x61"], m["fourth"]
    design_all = np.flatnonzero(m["is_design"])  # the first group's students too (fitted on by --write)
    real_design = design_all[d["real"][design_all]]
    pool = np.concatenate([design_all, st])
    dm = {**d, "scale": ranker_sign.sign_scale(d, design_all, st, sources, "source", args.copies_weight)}
    drop0 = tuple(f for f in args.drop.split(",") if f)
    variants = [tuple(f for f in v.split(",") if f) for v in args.variants.split(";")] if args.variants else [()]
    unknown = sorted(({f for v in variants for f in v} | set(drop0)) - set(ranker.FEATURES))
    if unknown:
        raise SystemExit(f"--drop/--variants: {', '.join(unknown)} not among the ranker's features")
    margins = [float(v) for v in args.margins.split(",")]
    shipped = {**{k: np.asarray(ranker_model.MODEL[k], dtype=float) for k in ("theta", "mean", "std")}}
    ref = {g: kinds(d, idx, shipped, ranker_model.MODEL["margin"])
           for g, idx in (("design", real_design), ("st", st), ("fourth", fourth), ("x61", x61))}
    share = Counter()
    for i, ok in zip(real_design, right(every, real_design, ref["design"]), strict=True):
        share[(sources[i], "n")] += 1
        share[(sources[i], "ok")] += int(ok)
    names = sorted(set(sources[real_design].tolist()))
    low = {s for s in names if share[(s, "ok")] < LOW * share[(s, "n")]}
    print(f"## Leave-one-source-out refits against the shipped weights\n\n{len(real_design)} design strokes of "
          f"{len(names)} sources ({len(low)} read under {100 * LOW:g} % by the shipped weights: "
          f"{', '.join(sorted(low))}), {len(st)} ST strokes of {len(set(sources[st].tolist()))} writers, "
          f"{len(fourth)} fourth-group strokes; {len(pool) - len(real_design) - len(st)} training-only copies.\n")
    print("Shipped weights (design in-sample): design " + f"{int(right(every, real_design, ref['design']).sum())}, "
          f"ST {int(right(every, st, ref['st']).sum())}, fourth {int(right(every, fourth, ref['fourth']).sum())}"
          + ("" if args.hide_x61 else f", X61 {int(right(every, x61, ref['x61']).sum())}") + ".\n", flush=True)
    folds = Folds(dm, pool)
    keys = sources[origin[pool]]
    held = names + sorted(set(sources[st].tolist()))
    results = []
    for gw, lam, more in ((g, la, v) for v in variants for g in (float(x) for x in args.guarded_weights.split(","))
                          for la in (float(x) for x in args.lams.split(","))):
        drop = drop0 + tuple(f for f in more if f not in drop0)
        tag = f" drop {','.join(more)}" if more else ""
        recipe = Recipe(lam, "stroke", drop, (margins[0],), None, "source", args.copies_weight, False, gw)
        t0 = time.time()
        whole = folds.fit(pool, recipe)
        got = {mg: {} for mg in margins}
        for s in held:
            fm = folds.fit(pool[keys != s], recipe, start=whole["theta"])
            test = np.flatnonzero((sources == s) & d["real"])
            test = test[np.isin(test, pool)]
            for mg in margins:
                for i, k in zip(test, kinds(d, test, fm, mg), strict=True):
                    got[mg][i] = k
        print(f"(G {gw:g}, lam {lam:g}{tag}: {len(held)} folds in {time.time() - t0:.0f} s; rules' weight "
              f"{whole['theta'][-1]:.3f})", flush=True)
        for mg in margins:
            new_k = {"design": [got[mg][i] for i in real_design], "st": [got[mg][i] for i in st],
                     "fourth": kinds(d, fourth, whole, mg), "x61": kinds(d, x61, whole, mg)}
            ch = {g: changes(every, sources, idx, ref[g], new_k[g])
                  for g, idx in (("design", real_design), ("st", st), ("fourth", fourth))}
            ok, net, bad = verdict(ch, low)
            fig = {g: int(right(every, idx, new_k[g]).sum())
                   for g, idx in (("design", real_design), ("st", st), ("fourth", fourth), ("x61", x61))}
            fig["in"] = int(right(every, real_design, kinds(d, real_design, whole, mg)).sum())
            results.append(((gw, lam, mg), ok, net, ch, whole, fig, bad, tag))
            print(f"RESULT G {gw:g} lam {lam:g} margin {mg:g}{tag} | {'admissible' if ok else 'not admissible'} | "
                  f"design held out {fig['design']} ({net['design']:+d}: +{sum(c[-1] > 0 for c in ch['design'])}"
                  f" -{sum(c[-1] < 0 for c in ch['design'])}) | ST held out {fig['st']} ({net['st']:+d}) | "
                  f"fourth {fig['fourth']} ({net['fourth']:+d}) | design in-sample {fig['in']}"
                  + ("" if args.hide_x61 else f" | X61 {fig['x61']}")
                  + (f" | low sources losing: {', '.join(bad)}" if bad else ""), flush=True)
            if args.each:
                for g in ("design", "fourth", "st"):
                    for c in sorted(ch[g]):
                        print(f"  {g} {'gained' if c[-1] > 0 else 'lost'} {c[0]} {c[1]} `{c[2]}`: shipped {c[3]}, "
                              f"refit {c[4]}", flush=True)
    admissible = [r for r in results if r[1]]
    best = max(admissible or results, key=lambda r: (r[2]["design"], r[2]["st"], r[2]["fourth"]))
    (gw, lam, mg), ok, net, ch, whole, fig, bad, tag = best
    print(f"\n### {'Best admissible' if ok else 'No admissible recipe; the best by net'}: G {gw:g}, lam {lam:g}, "
          f"margin {mg:g}{tag}\n")
    for g in ("design", "fourth", "st"):
        per = Counter()
        for c in ch[g]:
            per[c[0]] += c[-1]
        print(f"{g}: net {net[g]:+d}; per source " + ", ".join(f"{s} {v:+d}" for s, v in sorted(per.items()) if v)
              + "\n")
        for c in sorted(ch[g]):
            print(f"- {'gained' if c[-1] > 0 else 'lost'} {c[0]} {c[1]} `{c[2]}`: shipped {c[3]}, refit {c[4]}")
        print()
    if args.write and ok:
        args.write.write_text(model_module_text({
            "features": list(ranker.FEATURES), "kinds": list(ranker.KINDS), "lam": lam, "margin": mg,
            "theta": [round(float(v), 9) for v in whole["theta"]], "mean": [round(float(v), 9) for v in whole["mean"]],
            "std": [round(float(v), 9) for v in whole["std"]]}))
        print(f"wrote {args.write} (design and the ST writers; G {gw:g}, lam {lam:g}, margin {mg:g}{tag})")


if __name__ == "__main__":
    main()
