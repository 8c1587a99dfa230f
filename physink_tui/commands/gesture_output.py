"""Gestures as text lines and JSON Lines for `physink replay`; the one place that formats them."""

from __future__ import annotations

import json

from physink_tui.input.pen.gestures import Dwell, Gesture, ProximityChanged, StrokeEnded, Tap


def _r(v: float) -> float:
    return round(v, 6)


def gesture_text(g: Gesture) -> str | None:
    """One line for a person, or None for gestures too frequent to list (pen moves, pen downs)."""
    if isinstance(g, StrokeEnded):
        st = g.stroke
        a, b = st.points[0], st.points[-1]
        kind = "eraser stroke" if st.eraser else ("drag" if st.dwell_t is not None else "stroke")
        extra = "" if st.ended_by == "lift" else f"  (ended: {st.ended_by})"
        return (f"{g.t:9.3f}  {kind:<13} {len(st.points):4d} points {st.t1 - st.t0:6.2f} s  "
                f"({a.x:.3f}, {a.y:.3f}) -> ({b.x:.3f}, {b.y:.3f}){extra}")
    if isinstance(g, Tap):
        return f"{g.t:9.3f}  tap           at ({g.x:.3f}, {g.y:.3f})"
    if isinstance(g, Dwell):
        return f"{g.t:9.3f}  dwell         at ({g.x:.3f}, {g.y:.3f})"
    if isinstance(g, ProximityChanged):
        return f"{g.t:9.3f}  pen {'in range' if g.in_range else 'out of range'}"
    return None


def gesture_json(g: Gesture) -> str | None:
    """One JSON object for the gestures `gesture_text` lists (strokes with every point)."""
    if isinstance(g, StrokeEnded):
        st = g.stroke
        obj = {
            "t": _r(g.t), "gesture": "stroke", "eraser": st.eraser,
            "dwell_t": None if st.dwell_t is None else _r(st.dwell_t), "ended_by": st.ended_by,
            "points": [[_r(p.x), _r(p.y), _r(p.t), _r(p.p)] for p in st.points],
        }
    elif isinstance(g, Tap | Dwell):
        obj = {"t": _r(g.t), "gesture": "tap" if isinstance(g, Tap) else "dwell", "x": _r(g.x), "y": _r(g.y)}
    elif isinstance(g, ProximityChanged):
        obj = {"t": _r(g.t), "gesture": "proximity", "in_range": g.in_range}
    else:
        return None  # pen downs and moves: too many to list
    return json.dumps(obj, separators=(",", ":"))
