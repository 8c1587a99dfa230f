"""`physink recognize STROKES.jsonl`: one recognition per input line, as JSON Lines; the only place
that turns primitives into JSON.

Input lines are ``{"strokes": [[[x, y, t?], ...], ...]}`` (one stroke, or two for an X-symbol; a stroke whose every
point carries ``t``, the pen's time, is read with its times, as sketch mode reads a stroke);
output lines are ``{"kind", "confidence", "geometry", "alternatives"}`` plus ``"reason"`` when
nothing was recognised. Without ``--noise`` the pen's noise is judged from each stroke (`units.stroke_noise`), so a
drawing stored in pixels, tablet units, millimetres or fractions of a screen reads alike. A malformed input line
stops with its line number.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import fields
from typing import Any

from physink_tui.errors import PhysinkError
from physink_tui.formats.json_checks import show
from physink_tui.scene.recognition.primitives import Geometry, Line, Recognition
from physink_tui.scene.recognition.recognize import recognize_strokes

#: The largest coordinate or time accepted: squares and sums of such numbers stay far from overflow.
MAX_COORDINATE = 1e9


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


def _no_constant(name: str) -> float:
    raise ValueError(f"{name} is not a number JSON allows")


def _coordinate(c: object) -> bool:
    """A number recognition can work with: finite, and far from overflowing when squared."""
    if isinstance(c, bool) or not isinstance(c, int | float):
        return False
    try:
        return abs(float(c)) <= MAX_COORDINATE
    except OverflowError:
        return False


def parse_line(text: str, path: str, lineno: int) -> list[list[list[float]]]:
    """The strokes of one input line; PhysinkError naming the line and what was expected."""
    where = f"{path}:{lineno}"
    try:
        obj = json.loads(text, parse_constant=_no_constant)
    except json.JSONDecodeError as exc:
        raise PhysinkError(f"{where}: not JSON ({exc.msg} at column {exc.colno})") from None
    except RecursionError:
        raise PhysinkError(f"{where}: not usable JSON (nested too deeply)") from None
    except ValueError as exc:  # a number too long to convert, NaN or Infinity
        raise PhysinkError(f"{where}: not usable JSON ({exc})") from None
    strokes = obj.get("strokes") if isinstance(obj, dict) else None
    if not isinstance(strokes, list):
        raise PhysinkError(f'{where}: expected an object with "strokes": [[[x, y, t?], ...], ...]')
    for i, stroke in enumerate(strokes):
        if not isinstance(stroke, list):
            raise PhysinkError(f"{where}: stroke {i} must be a list of points")
        for j, point in enumerate(stroke):
            if (not isinstance(point, list) or len(point) < 2
                    or not all(_coordinate(c) for c in point)):
                raise PhysinkError(f"{where}: stroke {i} point {j} must be [x, y] or [x, y, t] numbers of at most "
                                   f"{MAX_COORDINATE:g} in size, got {show(point)}")
    return strokes


def run(args: argparse.Namespace) -> int:
    path = args.strokes
    noise = getattr(args, "noise", None)  # None: judged from each stroke, in whatever units it is stored
    if noise is not None and not (noise > 0 and noise < float("inf")):
        raise PhysinkError(f"--noise: expected auto or a positive number of units, got {noise!r}")
    try:
        stream = sys.stdin.buffer if path == "-" else open(path, "rb")
    except OSError as exc:
        raise PhysinkError(f"{path}: cannot read: {exc.strerror or exc}") from None
    with stream:
        for lineno, raw in enumerate(stream, 1):
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError as exc:
                raise PhysinkError(f"{path}:{lineno}: not UTF-8 text (byte {exc.start + 1} of the line)") from None
            if not text.strip():
                continue
            strokes = parse_line(text, path, lineno)
            points = [[p[:2] for p in s] for s in strokes]
            times = [[p[2] for p in s] if s and all(len(p) > 2 for p in s) else None for s in strokes]
            result = (recognize_strokes(points, noise=noise, times=times) if points
                      else Recognition(None, 0.0, None, (), "no strokes"))
            print(recognition_json(result))
    return 0
