"""Reads the form of the sets the fifth search for public sets found (issue 25; `benchmarks/SOURCES.md`, "The fifth
search"): the unified JSON in which the Gester evaluation tool (`nmagrofuoco/Gester`, Magrofuoco, Vanderdonckt &
Roselli 2021) republishes public 2D stroke gesture sets. `public_sets` pins where they lie (`public_sets.FIFTH_ENTRIES`)
and gathers them; they are the fifth held-back group (`bench_generalisation.FIFTH_SETS`), scored only by
``bench_generalisation.py --fifth``, but for ``sign``, opened on 2026-12-07 (`SIGN_SETS`, ``--sign``).

A file is one gesture: ``{"name": label, "subject": n, "date": ..., "paths": {"Pen" | "Finger": {"strokes": [{"x",
"y", "t", "stroke_id", ...}, ...]}}, "device": {"osBrowserInfo", "pen", "finger", "mouse", ...}}``, its points in
drawing order, each naming its pen-down (``stroke_id``), ``t`` in ms.
"""

from __future__ import annotations

import json
import subprocess
from collections.abc import Iterator
from pathlib import Path

from set_entries import Entry
from student_sets import _git, times_ms

Stroke = list[list[float | None]]


def gester_gesture(where: str, data: bytes) -> tuple[str, str, list[Stroke]]:
    """(label, the device's description, pen-downs) of one Gester JSON gesture; a pen-down's points [x, y, t], t in ms
    from its first point (None where the clock cannot time it), the pen-downs in the order they were started.

    Raises:
        ValueError: a file that is not one 2D gesture in that form (named).
    """
    try:
        record = json.loads(data)
        paths = record["paths"]
        if len(paths) != 1:
            raise ValueError(f"{len(paths)} input paths ({', '.join(paths)}), not one")
        downs: dict[object, list[tuple[float, float, float | None]]] = {}
        for point in next(iter(paths.values()))["strokes"]:
            t = point.get("t")
            downs.setdefault(point["stroke_id"], []).append((float(point["x"]), float(point["y"]),
                                                             None if t is None else float(t)))
        label = str(record["name"])
        device = str((record.get("device") or {}).get("osBrowserInfo") or "")
    except (json.JSONDecodeError, KeyError, TypeError, ValueError, StopIteration, AttributeError) as exc:
        raise ValueError(f"{where}: not a Gester gesture ({exc})") from None
    strokes = []
    for points in downs.values():
        ts = times_ms([t for _, _, t in points])
        strokes.append([[x, y, t] for (x, y, _), t in zip(points, ts, strict=True)])
    return label, device, strokes


def git_blobs(gdir: Path, commit: str, paths: list[str]) -> Iterator[tuple[str, bytes]]:
    """(path, bytes) of each file at ``commit``, in order, read through one ``git cat-file --batch``."""
    with subprocess.Popen(["git", "--git-dir", str(gdir), "cat-file", "--batch"], stdin=subprocess.PIPE,
                          stdout=subprocess.PIPE) as proc:
        assert proc.stdin is not None and proc.stdout is not None
        for path in paths:
            proc.stdin.write(f"{commit}:{path}\n".encode())
            proc.stdin.flush()
            header = proc.stdout.readline().split()
            if len(header) != 3:
                raise ValueError(f"{commit[:7]}:{path}: not in the repository ({b' '.join(header).decode()})")
            data = proc.stdout.read(int(header[2]))
            proc.stdout.read(1)
            yield path, data
        proc.stdin.close()


def gester_files(gdir: Path, commit: str, folder: str, only: tuple[str, ...] = ()) -> list[str]:
    """The JSON files below ``folder`` at ``commit`` (below the subfolders ``only`` names, if any), sorted."""
    roots = [f"{folder}/{sub}/" for sub in only] or [f"{folder}/"]
    listing = _git(gdir, "ls-tree", "-r", "--name-only", commit, "--", *roots).decode().splitlines()
    return sorted(name for name in listing if name.endswith(".json"))


def gester_gestures(entry: Entry, gdir: Path) -> Iterator[tuple[str, str, str | None, str, list[Stroke], str]]:
    """(where, person, device, label, pen-downs, date) of every gesture ``entry`` names: its person ``entry.person``
    formatted with the file's folders below ``entry.folder``, its device ``entry.device`` with ``{os}`` the file's
    device description; no date (the sets' own, where they keep one, are not of the $1 logs' form).

    Raises:
        ValueError: a file not in the form, or deeper than ``entry.person`` expects (named).
    """
    at = f"{entry.repo}@{entry.commit[:7]}:"
    for path, data in git_blobs(gdir, entry.commit, gester_files(gdir, entry.commit, entry.folder, entry.only)):
        folders = path[len(entry.folder) + 1:].split("/")[:-1]
        try:
            person = entry.person.format(*folders)
        except IndexError:
            raise ValueError(f"{at}{path}: fewer folders than {entry.person!r} names") from None
        label, device, strokes = gester_gesture(at + path, data)
        yield at + path, person, (entry.device or "").format(os=device), label, strokes, ""
