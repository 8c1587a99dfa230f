"""`physink recognize STROKES.jsonl`: one recognition per input line, as JSON Lines; the only place
that turns primitives into JSON.

Input lines are ``{"strokes": [[[x, y, t?], ...], ...]}`` (one stroke, or two for an X-symbol);
output lines are ``{"kind", "confidence", "geometry", "alternatives"}`` plus ``"reason"`` when
nothing was recognised. A malformed input line stops with its line number.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import fields
from typing import Any

from physink_tui.errors import PhysinkError
from physink_tui.scene.recognition.primitives import Geometry, Line, Recognition
from physink_tui.scene.recognition.recognize import recognize_strokes


def _num(v: float) -> float | None:
    return round(float(v), 6) if math.isfinite(v) else None


def geometry_json(g: Geometry | None) -> dict[str, Any] | None:
    """The geometry as a JSON object: points as [x, y], lines as {"start", "end"}, numbers rounded."""
    if g is None:
        return None
    out: dict[str, Any] = {}
    for f in fields(g):
        v = getattr(g, f.name)
        if isinstance(v, Line):
            out[f.name] = {"start": [_num(c) for c in v.start], "end": [_num(c) for c in v.end]}
        elif isinstance(v, tuple) and v and isinstance(v[0], tuple):
            out[f.name] = [[_num(c) for c in p] for p in v]
        elif isinstance(v, tuple):
            out[f.name] = [_num(c) for c in v]
        else:
            out[f.name] = _num(v)
    return out


def recognition_json(r: Recognition) -> str:
    obj: dict[str, Any] = {
        "kind": r.kind,
        "confidence": round(r.confidence, 4),
        "geometry": geometry_json(r.geometry),
        "alternatives": [{"kind": k, "confidence": round(c, 4)} for k, c in r.alternatives],
    }
    if r.reason is not None:
        obj["reason"] = r.reason
    return json.dumps(obj, separators=(",", ":"))


def parse_line(text: str, path: str, lineno: int) -> list[list[list[float]]]:
    """The strokes of one input line; PhysinkError naming the line and what was expected."""
    where = f"{path}:{lineno}"
    try:
        obj = json.loads(text)
    except json.JSONDecodeError as exc:
        raise PhysinkError(f"{where}: not JSON ({exc.msg} at column {exc.colno})") from None
    strokes = obj.get("strokes") if isinstance(obj, dict) else None
    if not isinstance(strokes, list):
        raise PhysinkError(f'{where}: expected an object with "strokes": [[[x, y, t?], ...], ...]')
    for i, stroke in enumerate(strokes):
        if not isinstance(stroke, list):
            raise PhysinkError(f"{where}: stroke {i} must be a list of points")
        for j, point in enumerate(stroke):
            if (not isinstance(point, list) or len(point) < 2
                    or not all(isinstance(c, int | float) and not isinstance(c, bool) for c in point)):
                raise PhysinkError(f"{where}: stroke {i} point {j} must be [x, y] or [x, y, t] numbers, got {point!r}")
    return strokes


def run(args: argparse.Namespace) -> int:
    path = args.strokes
    noise = getattr(args, "noise", 1.0)
    if not (noise > 0 and noise < float("inf")):
        raise PhysinkError(f"--noise: expected a positive number of units, got {noise!r}")
    try:
        stream = sys.stdin if path == "-" else open(path, encoding="utf-8")
    except OSError as exc:
        raise PhysinkError(f"{path}: cannot read: {exc.strerror or exc}") from None
    with stream:
        for lineno, text in enumerate(stream, 1):
            if not text.strip():
                continue
            strokes = parse_line(text, path, lineno)
            points = [[p[:2] for p in s] for s in strokes]
            result = (recognize_strokes(points, noise=noise) if points
                      else Recognition(None, 0.0, None, (), "no strokes"))
            print(recognition_json(result))
    return 0
