"""The opened `sign` set as the learned ranker's training material: fits without and with it, side by side.

`train_ranker.py --sign SIGN_JSONL [--fourth Q.jsonl T.jsonl] [--sign-weigh source|set]` (the recipe flags as usual)
reads the sign set (`bench_generalisation.SIGN_SETS`, its scored rows) beside the design sets and fits every fold
twice: on the design sources alone (**design**) and on them plus the ST5022 writers (writer001-008, 1010, 1011;
**+ST sign**). The sign strokes weigh as ``--sign-weigh`` says, so that the set (9,500 ST strokes, more than any
design set) does not swamp the rest: **source**, each writer as much as the mean design person (its strokes and
copies, as the recipe weighs them), or **set**, all of them as much as the mean design set. Both fits are scored on
the design sets held out whole (set folds), the devices held out whole (device folds; a sign stroke is a stylus's),
the X61 writers (writer1000-1009: fitted on by neither, scored pooled, never listed), with ``--source-folds K`` the
design sources held out in K groups of whole sources (`ranker_fit.inner_folds`), the ST writers held out one at
a time (for the design fit, the model fitted on every design source) and the fourth group (quickdraw, tutorboard) read
by the model fitted on every design source (and the ST writers). Sign strokes are not copied (``--augment`` copies
the design strokes alone). The first held-back group is described but never fitted on nor scored here, as in the
folds of ``--write``. With ``--write``, the model is fitted on every design source and the ST writers, weighed so
(since session 38 the X61 writers are never fitted on: they are the validation).
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np
import train_ranker as tr
from bench_generalisation import scored_rows
from bench_recognition import table
from ranker_fit import Recipe, answers, gated_model, inner_folds, model
from ranker_tables import model_module_text
from stroke_sets import Row, read_set, source_of

from physink_tui.scene.recognition import ranker, ranker_model

TUNE_DEVICE = "ST5022"
"""The sign writers tuned on: those whose device names the Stylistic ST5022 (the X61 writers are the validation)."""


def split_of(row: Row) -> str:
    """``st`` (tuned on) or ``x61`` (validation) for a sign row; "" for any other."""
    if row["source"] != "sign":
        return ""
    return "st" if TUNE_DEVICE in str(row.get("device") or "") else "x61"


def group_rows(paths: list[Path], group: str) -> list[Row]:
    """The scored rows of an opened group of whole sets (``sign`` or ``fourth``), read alone as `scored_rows` does."""
    rows: list[Row] = []
    for path in paths:
        rows += read_set(path)
    return scored_rows(rows, **{group: True})[0]


def joined(parts: list[dict]) -> dict:
    """Descriptions (`train_ranker.describe`) of row lists, one after the other."""
    return {"rules": [k for p in parts for k in p["rules"]], "phi": np.vstack([p["phi"] for p in parts]),
            "right": np.vstack([p["right"] for p in parts]),
            "rules_right": np.concatenate([p["rules_right"] for p in parts]),
            "guarded": np.concatenate([p["guarded"] for p in parts]),
            "real": np.concatenate([p.get("real", np.ones(len(p["rules"]), dtype=bool)) for p in parts])}


def sign_scale(d: dict, pool: np.ndarray, signs: np.ndarray, sources: np.ndarray, weigh: str,
               copies_weight: float) -> np.ndarray:
    """Each row's weight factor: 1 but for the sign rows ``signs``, scaled so that each writer (``weigh`` source)
    or all of them (set) weigh as the mean design person or set of ``pool`` (its people's strokes 1 each, a stroke's
    copies ``copies_weight`` in all)."""
    real = pool[d["real"][pool]]
    total = len(real) * (1.0 + (copies_weight if d["copies"] else 0.0))
    scale = np.ones(len(d["real"]))
    if weigh == "set":
        scale[signs] = total / len(tr.SETS) / len(signs)
        return scale
    per_person = total / len(set(sources[real].tolist()))
    counts = Counter(sources[signs].tolist())
    scale[signs] = [per_person / counts[s] for s in sources[signs].tolist()]
    return scale


def describe_asked(d: dict, rows: list[Row], idx: np.ndarray) -> None:
    """How many sign strokes the recogniser asks the model about, by label and the rules' kind (counts only)."""
    asked = Counter((rows[i]["label"], d["rules"][i], split_of(rows[i])) for i in idx if not d["guarded"][i])
    labels = sorted({r["label"] for r in (rows[i] for i in idx)})
    out = []
    for label in labels:
        n = sum(1 for i in idx if rows[i]["label"] == label)
        cells = {k: sum(v for (lab, kind, _), v in asked.items() if lab == label and kind == k) for k in ranker.KINDS}
        out.append([label, n, *(cells[k] for k in ranker.KINDS),
                    sum(v for (lab, _, sp), v in asked.items() if lab == label and sp == "st"),
                    sum(v for (lab, _, sp), v in asked.items() if lab == label and sp == "x61")])
    print("### Sign strokes the recogniser asks the model about (not guarded), by the rules' kind\n")
    print(table(["label", "strokes", *(f"asked, read {k}" for k in ranker.KINDS), "asked ST", "asked X61"], out) + "\n")


def material(args, rows: list[Row], group: set[str]) -> dict:
    """The design rows (``rows``; ``group`` the held-back sources among them), the sign set's and the fourth group's
    scored rows and the design strokes' training-only copies, described (`train_ranker.describe`) and joined: ``d``,
    the rows ``every``, the people's rows' count ``n``, each row's ``origin``, set, source, sign split and device, and
    the indices of the design (less ``group``), ST, X61 and fourth-group rows."""
    n_d = len(rows)
    srows, frows = group_rows([args.sign], "sign"), group_rows(list(args.fourth), "fourth")
    dd = tr.describe(rows)
    copied, dc, origin_c = tr.with_copies(rows, dd, args.augment, args.augment_seed, args.events_share)
    parts = [dd, tr.describe(srows)] + ([tr.describe(frows)] if frows else [])
    extra = {k: (v[n_d:] if k != "copies" else v) for k, v in dc.items()}
    every = rows + srows + frows + copied[n_d:]
    n = n_d + len(srows) + len(frows)
    d = {**joined(parts + ([extra] if len(copied) > n_d else [])), "copies": args.augment}
    origin = np.concatenate([np.arange(n), np.asarray(origin_c[n_d:], dtype=int)])
    sets = np.array([r["source"] for r in every])
    sources = np.array([source_of(r, "person") for r in every])
    split = np.array([split_of(r) for r in every])
    devices = np.array(["stylus" if r["source"] == "sign" else tr.device_known(r) if r["source"] in tr.SETS else ""
                        for r in every])
    is_design = np.isin(sets, tr.SETS)
    design = np.flatnonzero(is_design & ~np.isin(sources, sorted(group)))
    st, x61 = np.flatnonzero(split == "st"), np.flatnonzero(split == "x61")
    fourth = np.flatnonzero(np.isin(sets, ["quickdraw", "tutorboard"]))
    return {"d": d, "every": every, "n": n, "origin": origin, "sets": sets, "sources": sources, "split": split,
            "devices": devices, "is_design": is_design, "design": design, "st": st, "x61": x61, "fourth": fourth}


def run(args, rows: list[Row], group: set[str], recipe: Recipe) -> None:
    """The side-by-side comparison (and ``--write``) of module docstring; ``rows`` the design rows as `--write`
    reads them, ``group`` the held-back sources among them (described, never fitted on nor scored but by a write)."""
    if recipe.weigh != "stroke":
        raise SystemExit("--sign: the sign writers are weighed by --sign-weigh; use --weigh stroke")
    m = material(args, rows, group)
    d, every, n, origin, sets, sources = m["d"], m["every"], m["n"], m["origin"], m["sets"], m["sources"]
    split, devices, is_design, design = m["split"], m["devices"], m["is_design"], m["design"]
    real, st, x61, fourth = d["real"], m["st"], m["x61"], m["fourth"]
    print(f"## Learned ranker with the sign set ({recipe.name()}; sign weighed by {args.sign_weigh})\n")
    print(f"{int(real[design].sum())} design strokes of {len(set(sources[design].tolist()))} sources, "
          f"{len(st)} ST and {len(x61)} X61 sign strokes, {len(fourth)} fourth-group strokes, "
          f"{len(every) - n} training-only copies of design strokes.\n")
    describe_asked(d, every, np.concatenate([st, x61]))

    shipped = {**{k: np.asarray(ranker_model.MODEL[k], dtype=float) for k in ("theta", "mean", "std")},
               "margin": ranker_model.MODEL["margin"]}

    def fit(idx: np.ndarray, dm: dict) -> dict:
        if not d["right"][idx].any():  # nothing to fit on (a run on one set): the rules alone
            return {"theta": np.zeros(len(shipped["theta"])), "mean": shipped["mean"], "std": shipped["std"],
                    "lam": recipe.lam, "margin": 1.0}
        if len(recipe.margins) == 1:
            return {**model(dm, idx, recipe), "margin": recipe.margins[0]}
        return gated_model(dm, idx, sources, every, recipe)

    def score(m: dict, idx: np.ndarray) -> np.ndarray:
        return answers(d, idx, m, every)

    real_design = design[real[design]]
    shown = x61[:0] if args.hide_x61 else x61  # the validation writers' cells, hidden while tuning
    columns = ["set folds", *tr.SETS, "device folds", "source folds", "X61 (held)", "ST (held)", "quickdraw",
               "tutorboard", "design in-sample"]
    out = [["rules alone", *(_cells(d["rules_right"], real_design, sets, devices, shown, st, fourth, every))]]
    shipped_got = np.zeros(n, dtype=bool)
    for idx in (real_design, x61, st, fourth):
        shipped_got[idx] = score(shipped, idx)
    out.append(["shipped model (fitted on design, not held out)",
                *(_cells(shipped_got, real_design, sets, devices, shown, st, fourth, every))])
    for name, pool, dm in (("design", design, d),
                           ("design + ST sign", np.concatenate([design, st]),
                            {**d, "scale": sign_scale(d, design, st, sources, args.sign_weigh, recipe.copies_weight)})):
        got = np.zeros(n, dtype=bool)
        for s in tr.SETS:  # set folds
            test = real_design[sets[real_design] == s]
            got[test] = score(fit(pool[sets[origin[pool]] != s], dm), test)
        set_got = got.copy()
        dev = np.zeros(n, dtype=bool)
        known = pool[devices[origin[pool]] != ""]
        for k in sorted(set(devices[real_design].tolist()) - {""}):
            test = real_design[devices[real_design] == k]
            dev[test] = score(fit(known[devices[origin[known]] != k], dm), test)
        src = None
        if args.source_folds:  # K groups of whole design sources; the ST writers stay in the +ST fits' pool
            src = np.zeros(n, dtype=bool)
            for held in inner_folds(sorted(set(sources[real_design].tolist())), args.source_folds):
                test = real_design[np.isin(sources[real_design], held)]
                src[test] = score(fit(pool[~np.isin(sources[origin[pool]], held)], dm), test)
        whole = fit(pool, dm)
        got[x61], got[fourth] = score(whole, x61), score(whole, fourth)
        if name == "design":
            got[st] = score(whole, st)
        else:
            for w in sorted(set(sources[st].tolist())):
                test = st[sources[st] == w]
                got[test] = score(fit(pool[sources[origin[pool]] != w], dm), test)
        insample = score(whole, real_design)
        row = _cells(set_got, real_design, sets, devices, shown, st, fourth, every, dev, got, src)
        row[-1] = f"{int(insample.sum())}"
        out.append([f"refit on {name}", *row])
        print(f"RESULT {name} | margin {whole['margin']:g} | rules' weight {whole['theta'][-1]:.3f} | "
              + " | ".join(f"{c} {v}" for c, v in zip(columns, row, strict=True)), flush=True)
        flips = [f"{every[i]['file']} {every[i]['label']}: rules {d['rules'][i]} "
                 f"{'right' if got[i] else 'wrong'}" for i in fourth if got[i] != d["rules_right"][i]]
        print(f"Fourth group strokes the {name} refit reads otherwise than the rules ({len(flips)}):\n"
              + "".join(f"- {f}\n" for f in flips))
    print("### Side by side (strokes read right)\n")
    print(table(["model", *columns], out) + "\n")
    if args.write:
        keep = np.flatnonzero(is_design | (split == "st"))  # the first group too, as `train_ranker --write` fits it
        signs = np.flatnonzero(split == "st")  # the X61 writers stay the validation (session 38)
        dm = {**d, "scale": sign_scale(d, keep[is_design[keep]], signs, sources, args.sign_weigh, recipe.copies_weight)}
        m = fit(keep, dm)
        args.write.write_text(model_module_text({
            "features": list(ranker.FEATURES), "kinds": list(ranker.KINDS), "lam": m["lam"], "margin": m["margin"],
            "theta": [round(float(v), 9) for v in m["theta"]], "mean": [round(float(v), 9) for v in m["mean"]],
            "std": [round(float(v), 9) for v in m["std"]]}))
        print(f"wrote {args.write} (design and the ST writers, weighed by {args.sign_weigh}; {recipe.name()})")


def _cells(got: np.ndarray, real_design: np.ndarray, sets: np.ndarray, devices: np.ndarray, x61: np.ndarray,
           st: np.ndarray, fourth: np.ndarray, rows: list[Row], dev: np.ndarray | None = None,
           other: np.ndarray | None = None, src: np.ndarray | None = None) -> list[str]:
    """The side-by-side row: set folds (pooled, per set), device folds, source folds ("-" when not run), X61, ST,
    quickdraw, tutorboard, in-sample."""
    src_cell = "-" if src is None and dev is not None else f"{int((got if src is None else src)[real_design].sum())}"
    other = got if other is None else other
    dev = got if dev is None else dev
    known = real_design[devices[real_design] != ""]
    q = fourth[sets[fourth] == "quickdraw"]
    t = fourth[sets[fourth] == "tutorboard"]
    return [f"{int(got[real_design].sum())}/{len(real_design)}",
            *(f"{int(got[real_design][sets[real_design] == s].sum())}" for s in tr.SETS),
            f"{int(dev[known].sum())}/{len(known)}", src_cell,
            f"{int(other[x61].sum())}/{len(x61)}" if len(x61) else "hidden",
            f"{int(other[st].sum())}/{len(st)}", f"{int(other[q].sum())}/{len(q)}",
            f"{int(other[t].sum())}/{len(t)}", f"{int(got[real_design].sum())}"]
