"""Least-squares fits of primitives to points, with normalised errors; no classification.

Errors are dimensionless (a distance over the shape's size), so thresholds hold at any scale.
Circle: Kasa's algebraic fit; ellipse: Fitzgibbon, Pilu and Fisher's direct least squares
(always an ellipse); lines: total least squares through the centroid; curves: one cubic Bézier
per run of points with chord-length parameters.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import linalg_cores

EllipseFit = tuple[np.ndarray, float, float, float, float]
"""An ellipse fitted to points (`fit_ellipse`): its centre, radii rx >= ry, the angle of rx and the RMS error."""


def fit_line(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Total least squares line: ``(point, unit direction, max distance / length)``."""
    c = np.add.reduce(pts, axis=0) / len(pts)  # `pts.mean(axis=0)` to the bit, without its per-call overhead
    rel = pts - c
    d = linalg_cores.svd_vt(rel)[0]
    along = rel @ d
    length = float(np.maximum.reduce(along) - np.minimum.reduce(along)) or 1e-12
    dist = np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0])
    return c, d, float(np.maximum.reduce(dist)) / length


def fit_circle(pts: np.ndarray) -> tuple[np.ndarray, float, float]:
    """Kasa fit: ``(centre, radius, RMS radial error / radius)``; radius inf for collinear points."""
    x, y = pts[:, 0], pts[:, 1]
    a = np.empty((len(pts), 3))  # as `np.column_stack` lays it out
    a[:, 0], a[:, 1], a[:, 2] = x, y, 1.0
    b = x * x + y * y
    try:
        sol = linalg_cores.lstsq_solution(a, b)
    except np.linalg.LinAlgError:
        return pts.mean(axis=0), math.inf, math.inf
    cx, cy = sol[0] / 2, sol[1] / 2
    r2 = sol[2] + cx * cx + cy * cy
    if not np.isfinite(r2) or r2 <= 0:
        return pts.mean(axis=0), math.inf, math.inf
    r = math.sqrt(r2)
    d = np.hypot(x - cx, y - cy)
    return np.array([cx, cy]), r, float(np.sqrt(np.add.reduce((d - r) ** 2) / len(d))) / r  # `np.mean` to the bit


def fit_ellipse(pts: np.ndarray) -> EllipseFit | None:
    """Direct ellipse fit: ``(centre, rx, ry, angle of rx, RMS normalised radial error)``, rx >= ry.

    None when the points do not determine an ellipse (collinear, too few).
    """
    n = len(pts)
    if n < 6:
        return None
    mean = np.add.reduce(pts, axis=0) / n  # `pts.mean(axis=0)` to the bit, without its per-call overhead
    rel = pts - mean
    scale = float(np.maximum.reduce(np.abs(rel), axis=None)) or 1.0
    p = rel / scale
    x, y = p[:, 0], p[:, 1]
    d1, d2 = np.empty((n, 3)), np.empty((n, 3))  # as `np.column_stack` lays them out
    np.multiply(x, x, out=d1[:, 0])
    np.multiply(x, y, out=d1[:, 1])
    np.multiply(y, y, out=d1[:, 2])
    d2[:, 0], d2[:, 1], d2[:, 2] = x, y, 1.0
    s1, s2, s3 = d1.T @ d1, d1.T @ d2, d2.T @ d2
    try:
        t = -linalg_cores.solve(s3, s2.T)
    except np.linalg.LinAlgError:
        return None
    m = s1 + s2 @ t
    m = np.array([m[2] / 2, -m[1], m[0] / 2])
    try:
        evecs = linalg_cores.eig_vectors(m)  # (their real parts)
    except np.linalg.LinAlgError:
        return None
    cond = 4 * evecs[0] * evecs[2] - evecs[1] ** 2
    good = np.flatnonzero(cond > 0)
    if not len(good):
        return None
    a1 = evecs[:, good[0]]
    if a1[0] + a1[2] < 0:  # an eigenvector's sign is arbitrary: make the quadratic part positive
        a1 = -a1
    # as plain floats (the same numbers and the same arithmetic, without numpy scalars' overhead)
    a, b, c = a1.tolist()
    dd, e, f = (t @ a1).tolist()
    den = b * b - 4 * a * c
    if den >= 0:
        return None
    cx = (2 * c * dd - b * e) / den
    cy = (2 * a * e - b * dd) / den
    g = a * cx * cx + b * cx * cy + c * cy * cy - f
    root = math.sqrt((a - c) ** 2 + b * b)
    l1, l2 = (a + c + root) / 2, (a + c - root) / 2
    if l1 <= 0 or l2 <= 0 or g <= 0:
        return None
    r_small, r_big = math.sqrt(g / l1), math.sqrt(g / l2)
    angle = 0.5 * math.atan2(b, a - c) + math.pi / 2  # direction of the major axis
    centre = np.array([cx, cy]) * scale + mean
    rx, ry = r_big * scale, r_small * scale
    err = ellipse_error(pts, centre, rx, ry, angle)
    return centre, rx, ry, angle, err


def ellipse_error(pts: np.ndarray, centre: np.ndarray, rx: float, ry: float, angle: float) -> float:
    """RMS of (normalised radius - 1) of the points in the ellipse's frame."""
    c, s = math.cos(angle), math.sin(angle)
    rel = pts - centre
    u = rel[:, 0] * c + rel[:, 1] * s
    v = -rel[:, 0] * s + rel[:, 1] * c
    r = np.sqrt((u / rx) ** 2 + (v / ry) ** 2)
    return float(np.sqrt(np.add.reduce((r - 1.0) ** 2) / len(r)))  # `np.mean` to the bit


def fit_cubic(pts: np.ndarray) -> tuple[np.ndarray, float]:
    """One cubic Bézier through the run's ends: ``(4 control points, max error / chord)``."""
    n = len(pts)
    p0, p3 = pts[0], pts[-1]
    if n < 4:
        ctrl = np.array([p0, p0 + (p3 - p0) / 3, p0 + 2 * (p3 - p0) / 3, p3])
        return ctrl, 0.0
    d = pts[1:] - pts[:-1]  # as np.diff, without its per-call overhead
    seg = np.hypot(d[:, 0], d[:, 1])
    u = np.empty(n)
    u[0] = 0.0
    np.add.accumulate(seg, out=u[1:])
    u = u / u[-1] if u[-1] else np.linspace(0, 1, n)
    b0, b1, b2, b3 = (1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u ** 3
    start, end = b0[:, None] * p0, b3[:, None] * p3  # np.outer(b0, p0), np.outer(b3, p3): made once, used twice
    rhs = pts - start - end
    a = np.empty((n, 2))  # as `np.column_stack` lays it out
    a[:, 0], a[:, 1] = b1, b2
    sol = linalg_cores.lstsq_solution(a, rhs)
    ctrl = np.array([p0, sol[0], sol[1], p3])
    fitted = start + b1[:, None] * sol[0] + b2[:, None] * sol[1] + end
    chord = float(np.hypot(*(p3 - p0))) or float(seg.sum()) or 1.0
    return ctrl, float(np.maximum.reduce(np.hypot(*(fitted - pts).T))) / chord
