"""Experiment: does a learned re-ranker over the recogniser's answer and alternatives generalise to a held-out source?

Usage: .venv/bin/python benchmarks/bench_reranker.py SET [SET ...] [--by person|device|set]

Not shipped: this measures whether the design the issue suggests (a logistic ranker over candidates, trained offline
in numpy) would beat today's ranking on a source it never saw. For each scored stroke (`bench_generalisation`'s
rows) the recogniser gives its kind and up to three alternative kinds with their shares; each of those kinds is a
candidate. A candidate's score is ``a * log(share) + w[kind] . phi(stroke)``, where ``phi`` holds stroke features
(closure gap, ink over extent, net and absolute turning, corners found, a constant). For each held-out source,
``a`` and ``w`` are fitted by conditional-logit maximum likelihood (gradient descent, L2 penalty 1e-2) on the
other sources' strokes whose right kind is among their candidates, then the held-out source is scored: the
candidate with the best score is the answer. Prints one row per source: today's ranking against the re-ranker.
"""

from __future__ import annotations

import argparse
import math

import numpy as np
from bench_generalisation import scored_rows
from bench_recognition import table
from stroke_sets import Row, read_set, source_of

from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import KINDS
from physink_tui.scene.recognition.recognize import recognize_stroke

KIND_INDEX = {k: i for i, k in enumerate(KINDS)}
FEATURES = 6


def candidates(row: Row) -> tuple[list[str], list[float], np.ndarray]:
    """The candidate kinds of a stroke, their shares, and the stroke's features."""
    pts = np.asarray([p[:2] for p in row["strokes"][0]], dtype=float)
    result = recognize_stroke(pts.tolist())
    kinds = [result.kind or "none"] + [k for k, _ in result.alternatives]
    shares = [max(result.confidence, 1e-3)] + [max(s, 1e-3) for _, s in result.alternatives]
    pts = sg.drop_duplicates(pts)
    diag = max(sg.bbox_diagonal(pts), 1e-9)
    work = sg.resample(pts, 64) if len(pts) >= 2 else np.repeat(pts[:1], 2, axis=0)
    th = sg.turning(work)
    phi = np.array([float(np.hypot(*(pts[-1] - pts[0]))) / diag, sg.path_length(pts) / diag,
                    abs(float(th.sum())) / (2 * math.pi), float(np.abs(th).sum()) / (2 * math.pi),
                    len(sg.find_corners(work)) / 10.0, 1.0])
    return kinds, shares, phi


def fit(data: list[tuple[list[str], list[float], np.ndarray, list[bool]]], steps: int = 800) -> np.ndarray:
    """``[a, w...]`` maximising the conditional likelihood of the right candidates."""
    theta = np.zeros(1 + (len(KINDS) + 1) * FEATURES)
    theta[0] = 1.0
    for _ in range(steps):
        grad = np.zeros_like(theta)
        for kinds, shares, phi, right in data:
            x = np.stack([_x(k, s, phi) for k, s in zip(kinds, shares, strict=True)])
            score = x @ theta
            p = np.exp(score - score.max())
            p /= p.sum()
            target = np.array(right, dtype=float) / sum(right)
            grad += x.T @ (target - p)
        theta += 0.5 * (grad / len(data) - 1e-2 * theta)
    return theta


def _x(kind: str, share: float, phi: np.ndarray) -> np.ndarray:
    x = np.zeros(1 + (len(KINDS) + 1) * FEATURES)
    x[0] = math.log(share)
    k = KIND_INDEX.get(kind, len(KINDS))
    x[1 + k * FEATURES: 1 + (k + 1) * FEATURES] = phi
    return x


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", nargs="+")
    ap.add_argument("--by", choices=("person", "device", "set"), default="person")
    args = ap.parse_args()
    rows: list[Row] = []
    for path in args.sets:
        rows += read_set(__import__("pathlib").Path(path))
    kept, _ = scored_rows(rows)
    data = []
    for row in kept:
        kinds, shares, phi = candidates(row)
        data.append((source_of(row, args.by), kinds, shares, phi, [k in row["accepts"] for k in kinds]))
    out, pooled = [], [0, 0, 0]
    for held in sorted({d[0] for d in data}):
        train = [d[1:] for d in data if d[0] != held and any(d[4])]
        theta = fit(train)
        test = [d for d in data if d[0] == held]
        today = sum(d[4][0] for d in test)
        learned = 0
        for _, kinds, shares, phi, right in test:
            scores = [float(_x(k, s, phi) @ theta) for k, s in zip(kinds, shares, strict=True)]
            learned += right[int(np.argmax(scores))]
        pooled = [pooled[0] + len(test), pooled[1] + today, pooled[2] + learned]
        out.append([held, len(test), f"{100 * today / len(test):.2f}", f"{100 * learned / len(test):.2f}",
                    f"{theta[0]:.2f}"])
    print(table(["held-out source", "strokes", "today's ranking %", "learned re-ranker %", "weight on log share"],
                out))
    print(f"\nPooled: today {100 * pooled[1] / pooled[0]:.2f} %, re-ranker {100 * pooled[2] / pooled[0]:.2f} %.")


if __name__ == "__main__":
    main()
