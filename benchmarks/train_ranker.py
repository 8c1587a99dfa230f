"""Trains and measures the learned ranker (`recognition.ranker`) on sets, devices and sources it was not fitted on.

Usage: .venv/bin/python benchmarks/train_ranker.py SET [SET ...] [--folds set,device,source,in,shipped] [--brief]
       [--lam L[,L...]] [--weigh W] [--drop F[,F...]] [--margins M[,M...]] [--inner K] [--inner-by source|set]
       [--augment K] [--augment-seed S] [--events-share E] [--copies-weight A] [--no-gate] [--skip-guarded]
       [--guarded-weight G] [--drop-leaning] [--heldback] [--write PATH]
       [--sign SIGN_JSONL [--sign-weigh source|set] [--fourth Q.jsonl T.jsonl] [--hide-x61]]

For every scored stroke (`bench_generalisation.scored_rows`) the rules give a kind; when it is a polyline or a curve, or
a polygon left open (`ranker.family`), the ranker scores the family's kinds by ``w_kind . phi + a * [the rules'
answer]`` over standardised features (`ranker.features`), fitted by conditional-logit maximum likelihood (`ranker_fit`:
Newton steps, L2 penalty ``--lam``). The model's kind replaces the rules' only when its chance is over a margin
(``--margins``) chosen inside the strokes the model is fitted on, on folds of whole sources (``--inner``) or sets
(``--inner-by set``). A recipe (`ranker_fit.Recipe`) is judged on strokes of whole groups it was not fitted on
(``--folds``): **set** (the headline: each set — dollar1, itt, hcira, mmg, ahmadosama, gtiwari — read by a model
fitted without the whole set), **device** (each pen kind where it is known, `device_known`: stylus, touch or mouse,
read by a model fitted without that device; strokes of an unknown device are neither fitted on nor scored there),
**source** (each person read by a model fitted without them) and **in** (in-sample: the model fitted on every design
source reads them). ``--augment K`` adds K training-only copies of each training stroke (`augment_strokes`; never
scored). Each stroke is described by what the recogniser itself asks the model (`Asked`: its features as
`ranker.question` computes them at the one place the recogniser asks); strokes it never asks about (a wave, a chain of
steps, a straight-armed mark, a kept bracket or brace, a zig-zag's teeth, a curve between sparse events, a hurried
check, ...) keep the rules' kind in every fold, as in the app; they are fitted on (with the features `ranker.features`
gives the whole stroke) unless ``--skip-guarded``, at ``--guarded-weight`` each where given: docs/BENCHMARKS.md, "Why
a refit of the ranker loses people's readings". ``--drop-leaning`` leaves out of the fit the features that move when
a stroke is drawn from its other end (`ranker_leaning.LEANING`).
Tables per set and device (``--brief``: only these), per source and class; a ``RESULT`` line per run.
``--sign`` fits every fold twice, without and with the opened sign set's ST5022 writers weighed as design people
(``--sign-weigh``), and scores both side by side on the set and device folds, the X61 writers (fitted on by neither),
the ST writers held out and the fourth group (``--fourth``): `ranker_sign`; with ``--write`` it fits on every design
source and the ST writers (measured, not shipped: docs/BENCHMARKS.md, "The sign set as the ranker's training
material").

The first held-back group (`bench_generalisation.held_back`) is not read unless ``--heldback`` or ``--write`` is given;
the second (`bench_generalisation.held_back_new`) has been design material since it was opened
(`bench_generalisation.SECOND_GROUP_OPEN`); the third to fifth (the sets of the third to fifth searches,
`bench_generalisation.THIRD_SETS`, `FOURTH_SETS`, `FIFTH_SETS`) never: they are neither fitted on nor scored here.
``--write`` fits on every source read, the margin chosen as the recipe says, and writes the model as the Python data
module the recogniser imports (PATH: physink_tui/scene/recognition/ranker_model.py). Features are kept in
~/.cache/physink/ under a key of the rows and the recognition package's source (not the written model's).

The shipped model's recipe (`ranker_model.py`, refitted 2026-12-04 on the rules of f0d407d, the 92 design sources):
``--augment 2 --copies-weight 0.5 --margins 0.5 --drop has_times,corner_slowdown --events-share 1.0 --lam 0.003
--write physink_tui/scene/recognition/ranker_model.py``: the sixth pass's recipe with `sparse` kept, half the copies
sampled by 8-25 events, and L2 0.003, the one setting tried that kept every test floor (`test_bracket_marks`' 35 of 40
hurried rounded-corner brackets, `test_device_sampling`'s sparse braces) while beating the fourth pass's recipe (whose
model, b42c003, it replaces) on the set and device folds (docs/BENCHMARKS.md, "A ranker refit that keeps a sparse
brace a curve"). ``--folds shipped`` scores the shipped model as it is beside the folds (not held out: it was fitted on
every design source). That recipe on ef6e8be's tree (`git archive`) writes the shipped module byte for byte; on later
rules it writes other weights, none reading people's strokes as well so far (docs/BENCHMARKS.md, "Why a refit of the
ranker loses people's readings").
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # a shared machine; and the same sums in the same order
import hashlib
import json
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

import numpy as np
from augment_strokes import EVENTS_SHARE, augmented_rows
from bench_generalisation import held_back, held_back_new, scored_rows
from bench_recognition import machine
from ranker_fit import Recipe, answers, gated_model, inner_folds, model
from ranker_tables import model_module_text, report, summary
from stroke_sets import Row, read_set, source_of

from physink_tui.scene.recognition import ranker, ranker_model
from physink_tui.scene.recognition.primitives import Recognition
from physink_tui.scene.recognition.recognize import recognize_stroke

__all__ = ["inner_folds", "model_module_text"]  # the folds' dealing, tested from here; the module text, as before

LAMBDA = 1e-2
"""The L2 penalty, fixed before any fit was scored (the sixth pass's sensitivity grid: docs/BENCHMARKS.md)."""
WIDTH = 4  # the largest family
SETS = ("ahmadosama", "dollar1", "gtiwari", "hcira", "itt", "mmg")
"""The design sets, each held out whole by the set folds."""
CACHE_FORMAT = b"asked as the recogniser asks"
"""Bumped when `describe` keeps more per stroke (a key of an older cache would lack it)."""
DEVICES_UNKNOWN = ("mouse or touch screen",)
"""Devices a set names without saying which (hcira's sinarest1608: a mouse or a touch screen)."""


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


def device_known(row: Row) -> str:
    """`device_of` where the set says which pen it was; "" where it does not (`DEVICES_UNKNOWN`)."""
    return "" if str(row.get("device") or "") in DEVICES_UNKNOWN else device_of(row)


def describe(rows: list[Row], salt: bytes = b"") -> dict:
    """Per stroke: the rules' kind (without the learned ranker), the features, which family kinds are right, and
    whether the recogniser keeps the rules' kind without asking the model or keeping its answer (``guarded``:
    `Asked`); kept in ~/.cache/physink/ under a key of the rows, ``salt`` and the recognition package's source (but
    the written model, `ranker_model`, which neither the rules without it nor the features read)."""
    key = hashlib.sha256(json.dumps([r["file"] + r["label"] for r in rows]).encode() + salt + CACHE_FORMAT)
    for f in sorted(Path(ranker.__file__).parent.glob("*.py")):
        if f.name != "ranker_model.py":
            key.update(f.read_bytes())
    cache = Path.home() / ".cache" / "physink" / f"ranker-{key.hexdigest()[:16]}.npz"
    if cache.exists():
        z = np.load(cache)
        return {"rules": [str(k) if k else None for k in z["rules"]], "phi": z["phi"], "right": z["right"],
                "rules_right": z["rules_right"], "guarded": z["guarded"]}
    d = _describe(rows)
    cache.parent.mkdir(parents=True, exist_ok=True)
    np.savez(cache, rules=np.array([k or "" for k in d["rules"]]), phi=d["phi"], right=d["right"],
             rules_right=d["rules_right"], guarded=d["guarded"])
    return d


ASKED = -1.0
"""The confidence `Asked` answers with (no reading has it): the recogniser's reading has it when it kept the answer."""


class Asked:
    """Stands in for the learned ranker while the recogniser reads a stroke (`ranker.Asker`): keeps the rules' reading
    it is handed (``found``) and the features the model would be asked (`ranker.question`; None where it is not
    asked), and answers with a reading of its own (`ASKED`), so that the recogniser's reading tells whether the
    model's answer would be kept (a wave the rules read is kept from it, `waves.kept_curve`). The model is fitted on
    and scored by what the recogniser asks it, computed as the recogniser computes it (the stroke settled,
    `landing`; its last attempt, `pen_lifts`; the pen's noise as the recogniser measures it)."""

    def __init__(self) -> None:
        self.found: Recognition | None = None
        self.phi: np.ndarray | None = None

    def __call__(self, points: Sequence[Sequence[float]], times: Sequence[float] | None, noise: float,
                 found: Recognition, drawn: ranker.Drawn | None, sparse: bool) -> Recognition:
        self.found = found
        asked = ranker.question(points, times, noise, found, drawn, sparse)
        self.phi = None if asked is None else asked[0]
        return replace(found, confidence=ASKED)


def _describe(rows: list[Row]) -> dict:
    rules, phi, right, guarded = [], [], [], []
    for row in rows:
        stroke = row["strokes"][0]
        times = stroke_times(stroke)
        ask = Asked()
        read = recognize_stroke([p[:2] for p in stroke], times, learned=ask)
        found = ask.found or read  # the rules' reading, the model asked or not
        rules.append(found.kind)
        guarded.append(ask.phi is None or read.confidence != ASKED)
        # a stroke not asked: its features as `ranker.features` gives the whole stroke (not fitted on: --skip-guarded)
        phi.append(ranker.features(stroke, times) if ask.phi is None else ask.phi)
        kinds = ranker.family(found.kind, phi[-1])
        right.append(np.array([k in row["accepts"] for k in kinds] + [False] * (WIDTH - len(kinds)), dtype=bool))
    return {"rules": rules, "phi": np.array(phi).reshape(len(rows), len(ranker.FEATURES)),
            "right": np.array(right).reshape(len(rows), WIDTH),
            "rules_right": np.array([k in r["accepts"] for k, r in zip(rules, rows, strict=True)], dtype=bool),
            "guarded": np.array(guarded, dtype=bool)}


def with_copies(rows: list[Row], d: dict, copies: int, seed: int, events_share: float = EVENTS_SHARE,
                ) -> tuple[list[Row], dict, np.ndarray]:
    """The rows and their description with ``copies`` training-only copies of each stroke the family can read right
    appended (`augment_strokes`; ``events_share`` of those a device draws again sampled by a few events), and for
    every row the index of the people's row it is or was copied from."""
    n = len(rows)
    d = {**d, "real": np.ones(n, dtype=bool), "copies": copies}
    if not copies:
        return rows, d, np.arange(n)
    extra, origin = augmented_rows(rows, copies, seed, ranker.KINDS, events_share)
    salt = Path(__file__).with_name("augment_strokes.py").read_bytes() + f"events {events_share!r}".encode()
    e = describe(extra, salt)
    d = {"rules": d["rules"] + e["rules"], "phi": np.vstack([d["phi"], e["phi"]]),
         "right": np.vstack([d["right"], e["right"]]),
         "rules_right": np.concatenate([d["rules_right"], e["rules_right"]]),
         "guarded": np.concatenate([d["guarded"], e["guarded"]]),
         "real": np.concatenate([np.ones(n, dtype=bool), np.zeros(len(extra), dtype=bool)]), "copies": copies}
    return rows + extra, d, np.concatenate([np.arange(n), np.array(origin, dtype=int)])


def held_out(d: dict, rows: list[Row], design: np.ndarray, keys: np.ndarray, fitted, origin: np.ndarray,
             ) -> tuple[np.ndarray, dict[str, str]]:
    """Each design stroke read by a model fitted without every stroke (and copy) of its key (a set, a device or a
    source; "" is never held out, never fitted on, never scored): right or not, one a people's row; the margins."""
    got = np.zeros(len(origin), dtype=bool)
    margins = {}
    train = design[keys[origin[design]] != ""]
    for k in sorted(set(keys[origin[train]].tolist())):
        m = fitted(train[keys[origin[train]] != k])
        test = design[(keys[origin[design]] == k) & d["real"][design]]
        got[test] = answers(d, test, m, rows)
        margins[k] = f"{m['margin']:g}"
    return got, margins


def rows_read(rows: list[Row], heldback: bool, write: bool) -> tuple[list[Row], set[str], set[str]]:
    """The scored rows the ranker may read, and the first and second held-back groups among them. The third to
    fifth held-back groups (`bench_generalisation.THIRD_SETS`, `FOURTH_SETS`, `FIFTH_SETS`) are never read, not even
    with ``heldback`` or ``write`` (`scored_rows` leaves them out); the second only with ``heldback``; the first only
    with ``heldback`` or ``write``."""
    rows, _ = scored_rows(rows)
    first, new = held_back(rows), held_back_new(rows)
    if not heldback:  # the second group is never read without --heldback, not even to write a model
        rows = [r for r in rows if source_of(r, "person") not in new]
        new = set()
    if not (heldback or write):
        rows = [r for r in rows if source_of(r, "person") not in first]
    return rows, first, new


def recipe_from(args: argparse.Namespace, lam: float) -> Recipe:
    drop = tuple(f for f in args.drop.split(",") if f)
    if args.drop_leaning:
        from ranker_leaning import LEANING
        drop += tuple(f for f in LEANING if f not in drop)
    unknown = sorted(set(drop) - set(ranker.FEATURES))
    if unknown:
        raise SystemExit(f"--drop: {', '.join(unknown)} not among the ranker's features {ranker.FEATURES}")
    margins = (0.5,) if args.no_gate else tuple(float(v) for v in args.margins.split(","))
    if not margins or not all(0.0 <= v < 1.0 for v in margins):
        raise SystemExit(f"--margins: {args.margins!r} must be numbers in [0, 1)")
    if not 0.0 < args.guarded_weight <= 1.0 or (args.skip_guarded and args.guarded_weight != 1.0):
        raise SystemExit(f"--guarded-weight: {args.guarded_weight!r} must be in (0, 1], not with --skip-guarded")
    return Recipe(lam, args.weigh, drop, margins, args.inner, args.inner_by, args.copies_weight, args.skip_guarded,
                  args.guarded_weight)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", type=Path, nargs="+")
    ap.add_argument("--folds", default="set,device,source", help="what is held out whole, comma list of set, device, "
                    "source, in (in-sample) and shipped (the shipped model as it is, beside them: not held out); the "
                    "first is the figure a recipe is chosen on")
    ap.add_argument("--brief", action="store_true", help="print the tables per set and device only")
    ap.add_argument("--heldback", action="store_true", help="score both held-back groups (once, at the end)")
    ap.add_argument("--lam", default=str(LAMBDA), help="L2 penalty; a comma list reports the folds with each "
                    "(sensitivity), the first is used for the rest")
    ap.add_argument("--weigh", choices=("stroke", "source", "set", "device"), default="stroke", help="what weighs the "
                    "same in the likelihood: every stroke, every source, every set or every device (`device_of`)")
    ap.add_argument("--drop", default="", help="features left out of the fit (comma list; their weights stay 0)")
    ap.add_argument("--margins", default="0.5,0.7,0.9", help="the margins the model's chance may have to pass to "
                    "overrule the rules, one chosen inside each fit")
    ap.add_argument("--no-gate", action="store_true", help="overrule the rules at any margin (0.5)")
    ap.add_argument("--inner", type=int, help="choose the margin by this many folds of whole sources instead of "
                    "leave-one-source-out (many sources: the fits grow with their square)")
    ap.add_argument("--inner-by", choices=("source", "set"), default="source", help="choose the margin on folds of "
                    "whole sources (--inner) or one fold a set")
    ap.add_argument("--source-folds", type=int, help="the source folds hold out this many groups of whole sources "
                    "(dealt by the sha256 of their names) instead of one source at a time (cheaper; fitted on fewer)")
    ap.add_argument("--augment", type=int, default=0, help="training-only copies of each training stroke "
                    "(`augment_strokes`; never scored)")
    ap.add_argument("--augment-seed", type=int, default=0)
    ap.add_argument("--events-share", type=float, default=EVENTS_SHARE, help="the share of the copies a device draws "
                    "again that are sampled by 8-25 events evenly in time (`augment_strokes.SPARSE_EVENTS`)")
    ap.add_argument("--copies-weight", type=float, default=1.0, help="the copies of a stroke weigh this in all")
    ap.add_argument("--skip-guarded", action="store_true", help="fit on no stroke the recogniser never asks the "
                    "model about (`Asked`: a wave, a kept bracket or brace, a zig-zag's teeth, a sparse curve, ...)")
    ap.add_argument("--guarded-weight", type=float, default=1.0, help="each stroke the recogniser never asks the "
                    "model about weighs this in the fit (1: as any stroke; --skip-guarded: none)")
    ap.add_argument("--drop-leaning", action="store_true", help="leave out of the fit the features that move when a "
                    "stroke is drawn from its other end (`ranker_leaning.LEANING`)")
    ap.add_argument("--write", type=Path, help="fit on every source and write the model here")
    ap.add_argument("--sign", type=Path, help="the sign set: fit each fold without and with its ST5022 writers and "
                    "score both side by side (`ranker_sign`); with --write, fit on it all")
    ap.add_argument("--sign-weigh", choices=("source", "set"), default="source", help="each sign writer weighs as "
                    "the mean design person, or the set as the mean design set")
    ap.add_argument("--fourth", type=Path, nargs="*", default=[], help="with --sign: the fourth group's sets, read "
                    "by each model fitted on every design source")
    ap.add_argument("--hide-x61", action="store_true", help="with --sign: print no X61 figure (tuning)")
    args = ap.parse_args()
    if args.sign:  # the design rows as --write reads them; the first group is neither fitted on nor scored by folds
        if args.heldback:
            raise SystemExit("--sign: not with --heldback")
        import ranker_sign
        rows = []
        for path in args.sets:
            rows += read_set(path)
        rows, first, new = rows_read(rows, False, True)
        ranker_sign.run(args, rows, first | new, recipe_from(args, float(args.lam.split(",")[0])))
        return
    schemes = [f for f in args.folds.split(",") if f]
    if not set(schemes) <= {"set", "device", "source", "in", "shipped"}:
        raise SystemExit(f"--folds: {args.folds!r}: each of set, device, source, in, shipped")
    rows: list[Row] = []
    for path in args.sets:
        rows += read_set(path)
    rows, first, new = rows_read(rows, args.heldback, bool(args.write))
    group = first | new
    n = len(rows)
    rows, d, origin = with_copies(rows, describe(rows), args.augment, args.augment_seed, args.events_share)
    sources = np.array([source_of(r, "person") for r in rows])
    sets = np.array([r["source"] for r in rows])
    devices = np.array([device_known(r) for r in rows])
    weigh = {"stroke": None, "source": sources, "set": sets, "device": np.array([device_of(r) for r in rows])}
    groups = weigh[args.weigh]
    design = np.flatnonzero(~np.isin(sources, sorted(group)))
    design_real = design[design < n]
    scored = np.zeros(n, dtype=bool)
    scored[design_real] = True
    rd = {k: (v[:n] if k in ("rules_right",) else v) for k, v in d.items()}

    def fitted_by(recipe: Recipe):
        def fitted(idx: np.ndarray) -> dict:
            if len(recipe.margins) == 1:
                return {**model(d, idx, recipe, groups), "margin": recipe.margins[0]}
            inner_keys = sets if recipe.inner_by == "set" else sources
            return gated_model(d, idx, inner_keys, rows, recipe, groups)
        return fitted

    print(f"## Learned ranker ({machine()})\n")
    print(f"{len(design_real)} strokes of {len(set(sources[design_real]))} design sources"
          + (f", {len(rows) - n} training-only copies (`--augment {args.augment}`, seed {args.augment_seed})"
             if args.augment else "") + ".\n")
    keys_of = {"set": sets, "device": devices, "source": sources}
    if args.source_folds:  # K groups of whole sources dealt by the sha256 of their names, not one fold a source
        dealt = {s: f"sources {k}" for k, names in enumerate(inner_folds(sorted(set(sources[design_real].tolist())),
                                                                          args.source_folds)) for s in names}
        keys_of["source"] = np.array([dealt.get(s, "") for s in sources.tolist()])
    recipe = recipe_from(args, float(args.lam.split(",")[0]))
    copies_note = (f"; augment {args.augment} x{args.copies_weight:g}, events {args.events_share:g}" if args.augment
                   else "")
    for lam in (float(v) for v in args.lam.split(",")):
        recipe = recipe_from(args, lam)
        fitted = fitted_by(recipe)
        results: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        for scheme in schemes:
            if scheme == "shipped":  # the model the recogniser ships, as it is: fitted on sources read here
                shipped = {k: np.asarray(ranker_model.MODEL[k], dtype=float) for k in ("theta", "mean", "std")}
                got = np.zeros(n, dtype=bool)
                got[design_real] = answers(d, design_real, {**shipped, "margin": ranker_model.MODEL["margin"]}, rows)
                margins = {"all": f"{ranker_model.MODEL['margin']:g}"}
            elif scheme == "in":
                m = fitted(design)
                got = np.zeros(n, dtype=bool)
                got[design_real] = answers(d, design_real, m, rows)
                margins = {"all": f"{m['margin']:g}"}
            else:
                got, margins = held_out(d, rows, design, keys_of[scheme], fitted, origin)
                got = got[:n]
            results[scheme] = (got, scored & (devices[:n] != "") if scheme == "device" else scored)
            if scheme != "device" and not args.brief:
                folds = {s: got[np.flatnonzero(sources[:n] == s)] for s in sorted(set(sources[design_real]))}
                report(f"{scheme} folds: each source read by a model fitted without its {scheme} ({recipe.name()}; "
                       "margins " + ", ".join(f"{k} {v}" for k, v in margins.items()) + ")", rd, rows[:n],
                       sources[:n], folds)
            elif scheme == "device":
                print("Device folds' margins: " + ", ".join(f"{k} {v}" for k, v in margins.items()) + ".\n")
        summary(f"Per set ({recipe.name()}" + (f"; --augment {args.augment}" if args.augment else "") + ")", rd,
                scored, sets[:n], results)
        known = scored & (devices[:n] != "")
        summary(f"Per device where known ({recipe.name()})", rd, known, devices[:n], results)
        print("RESULT " + recipe.name() + copies_note + " | " + " | ".join(
            f"{k} {int(v[mask].sum())}/{int(mask.sum())} " + " ".join(
                f"{s}:{int(v[mask & (sets[:n] == s)].sum())}" for s in SETS) for k, (v, mask) in results.items())
            + "\n")
    if args.heldback or args.write:
        m_design = fitted_by(recipe)(design)
        n_design = len(set(sources[design_real]))
        for title, members in (("Held-back students (the first group)", first), ("Held-back sources found after the "
                               "first 19 (the second group)", new)):
            if members:
                held = {s: answers(d, np.flatnonzero(sources[:n] == s), m_design, rows) for s in sorted(members)}
                report(f"{title}, scored by a model fitted on the {n_design} design sources ({recipe.name()}, "
                       f"margin {m_design['margin']:g})", rd, rows[:n], sources[:n], held)
    if args.write:
        keep = np.flatnonzero(~np.isin(sources, sorted(new)))  # the second group is never fitted on
        m = fitted_by(recipe)(keep)
        args.write.write_text(model_module_text({
            "features": list(ranker.FEATURES), "kinds": list(ranker.KINDS), "lam": m["lam"], "margin": m["margin"],
            "theta": [round(float(v), 9) for v in m["theta"]], "mean": [round(float(v), 9) for v in m["mean"]],
            "std": [round(float(v), 9) for v in m["std"]]}))
        print(f"wrote {args.write} ({recipe.name()}" + copies_note + f"; margin {m['margin']:g})")


if __name__ == "__main__":
    main()
