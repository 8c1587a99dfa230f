"""Gathers the strokes students of an HCI course recorded of themselves for the $1 recogniser into one JSON Lines set
(``itt``), pinned to the commits measured, for `bench_generalisation` to score person by person.

Usage: .venv/bin/python benchmarks/student_sets.py [--mirrors DIR] [--out FILE]

The course (Interaction Techniques and Technologies, University of Regensburg, GitHub organisations ITT23, ITT-24,
ITT-25, ITT-26) asks each student to implement the $1 unistroke recogniser and to record a gesture set of their own,
drawn with the mouse; many publish it in their assignment repository. Each repository below is one person. The
repositories carry no licence, so nothing is copied into the project: the script reads each one at the pinned
commit from ``DIR/<owner>+<name>/repo`` (a git directory, as the fetch tool leaves them) or, failing that, clones it
bare from GitHub into ``~/.cache/physink/student-sets``, and writes the rows to ``--out`` (by default
``~/.cache/physink/student-sets/itt.jsonl``). Row form as in `stroke_sets`: source ``itt``, subject the GitHub
account, device ``mouse``, label from the file name (spellings unified, see `LABEL_SPELLINGS`), t in ms or None.

Copies of the original $1 logs (Wobbrock et al. 2007), reserved for independent measurement, are refused: a file
dated before 2010, or whose points equal a stroke of ../shared/data/strokes/dollar1-dev.jsonl, stops the script
with its name. Repositories found to hold such copies were left out of `REPOS` (SOURCES.md names them).
"""

from __future__ import annotations

import argparse
import csv
import io
import itertools
import json
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

CACHE = Path.home() / ".cache" / "physink" / "student-sets"
DEV = Path(__file__).resolve().parents[2] / "shared" / "data" / "strokes" / "dollar1-dev.jsonl"

REPOS: tuple[tuple[str, str, str], ...] = (
    # (owner/name, commit, folder of the student's own recordings)
    ("ITT-24/assignment-6-gesture-recognition-LucaEscher", "4cefb6a7187effdb666ed0354a7021e6005a83de",
     "dataset/my_data"),
    ("ITT-24/assignment-6-gesture-recognition-michaelpickl", "be2ef8802baacf80cc59d434ade91fd5f79e0eb8",
     "dataset/michael_dataset"),
    ("ITT-24/assignment-6-gesture-recognition-JonasBachmeier-UNI", "ff51f08946f09b3d746d1b56c28f745b158f5d17",
     "dataset"),
    ("ITT-24/assignment-6-gesture-recognition-LeS-crypto", "6c07a6001134a6311219326ac1b725e880adcdc0",
     "dataset/test-own"),
    ("ITT-24/assignment-6-gesture-recognition-MaximilianKilger", "0cb00113b9f49d249dffe105611591d5c2ef6484", "test"),
    ("ITT-25/assignment-06-gesture-recognition-realdegrees", "f5ce23956a0d4fc28abc3578a49c9e983416330c",
     "datasets/custom"),
    ("ITT-25/assignment-06-gesture-recognition-uniUbungsAccount", "1b61d950dbfa872f90d437bcad0637a96cab0cd9",
     "datasets/own_recorded_gestures"),
    ("ITT-25/assignment-06-gesture-recognition-Coldjack007", "1fa71eb0041c1e6118b22a0f077d29b88eeaa501", "datasets"),
    ("ITT-26/assignment-06-gesture-recognition-Bam33751", "b6a1cfd75ae924030a59edf4161dd17f2d2b2dbc", "datasets"),
    ("ITT-26/assignment-06-gesture-recognition-Alphazerfall", "e406dd0263a94bd0fd0dacd791b809a4828fd998",
     "datasets/custom"),
    ("ITT-26/assignment-06-gesture-recognition-DerD4n", "1ee2c34f1e12bf8b20646375eeb1eca4a0d88450",
     "datasets/my_gestures"),
    ("ITT-26/assignment-06-gesture-recognition-Ferdi-FM", "2fa48c6c75fdd78cb813d90c71bc40fe603c7422",
     "datasets/my_logs"),
    ("ITT-26/assignment-06-gesture-recognition-GixD42", "78545e5fdc7679d706e03449029ca300aa38e5f2",
     "datasets/mylogs"),
    ("ITT-26/assignment-06-gesture-recognition-lvht1203", "925708d9837b92b51c407406bf42df5dcf5ac9eb",
     "datasets/logs_custom"),
    ("ITT-26/assignment-06-gesture-recognition-marcel-moz", "5404f893fc066030484fa9c2259a8a68562a8479",
     "02-recognizer-comparison/datasets"),
    ("ITT-26/assignment-06-gesture-recognition-martinarobyculasso", "99cd5d3b72587858c03ca2d7cea4bcc68c0602c1",
     "datasets"),
)

LABEL_SPELLINGS = {
    "delete": "delete_mark", "left_curly_bracket": "left_curly_brace", "right_curly_bracket": "right_curly_brace",
    "left_square_bracket": "left_sq_bracket", "right_square_bracket": "right_sq_bracket",
    "left_sq_brace": "left_sq_bracket", "right_sq_brace": "right_sq_bracket", "zig_zag": "zigzag",
}
"""The students' spellings of the $1 set's labels (and one label of their own, the zigzag), unified."""


def label_of(file_name: str) -> str:
    """``left-curly-bracket-3.csv`` -> ``left_curly_brace``."""
    stem = re.sub(r"[-_]?\d+$", "", Path(file_name).stem).lower().replace("-", "_")
    return LABEL_SPELLINGS.get(stem, stem)


def person_of(repo: str) -> str:
    return repo.split("gesture-recognition-", 1)[1]


def git_dir(repo: str, mirrors: Path | None) -> Path:
    """The repository's git directory: the fetched mirror, else a bare clone in the cache (made on first use)."""
    if mirrors is not None:
        mirror = mirrors / repo.replace("/", "+") / "repo"
        if (mirror / ".git").is_dir():  # a snapshot with a work tree
            return mirror / ".git"
        if mirror.is_dir():
            return mirror
    clone = CACHE / (repo.replace("/", "+") + ".git")
    if not clone.is_dir():
        clone.parent.mkdir(parents=True, exist_ok=True)
        subprocess.run(["git", "clone", "--bare", "--quiet", f"https://github.com/{repo}", str(clone)], check=True)
    return clone


def _git(gdir: Path, *args: str) -> bytes:
    return subprocess.run(["git", "--git-dir", str(gdir), *args], check=True, capture_output=True).stdout


def times_ms(raw: list[float | None]) -> list[float | None]:
    """The stroke's times in ms from its first point, or all None where the recorder kept no usable clock: a time
    missing, going backwards, or ticking too coarsely for the stroke (whole seconds). Seconds (fractional, steps
    under 1) become ms."""
    if not raw or any(t is None for t in raw):
        return [None] * len(raw)
    ts = [float(t) for t in raw if t is not None]
    if any(b < a for a, b in itertools.pairwise(ts)) or ts[-1] - ts[0] <= 0:
        return [None] * len(raw)
    steps = [b - a for a, b in itertools.pairwise(ts) if b > a]
    scale = 1000.0 if steps and max(steps) < 1.0 else 1.0
    if (ts[-1] - ts[0]) * scale < 2.0 * len(ts):  # faster than 500 points a second: a clock in whole seconds
        return [None] * len(raw)
    return [(t - ts[0]) * scale for t in ts]


def parse(path: str, data: bytes) -> tuple[list[list[float | None]], str | None]:
    """(points as [x, y, t], the recording's Date attribute) of one XML or CSV file."""
    if path.endswith(".csv"):
        rows = list(csv.DictReader(io.StringIO(data.decode("utf-8-sig"))))
        xy = [(float(r["x"]), float(r["y"])) for r in rows]
        return [[x, y, None] for x, y in xy], None
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise ValueError(f"{path}: {exc}") from None
    pts = list(root.iter("Point"))
    raw = [float(p.get("T")) if p.get("T") is not None else None for p in pts]
    ts = times_ms(raw)
    return [[float(p.get("X", "nan")), float(p.get("Y", "nan")), t] for p, t in zip(pts, ts, strict=True)], \
        root.get("Date")


def reserved_points() -> set[tuple[tuple[float, float], ...]]:
    """The first 12 points of every stroke of the $1 logs' development people, to refuse copies of the logs."""
    if not DEV.is_file():
        return set()
    out = set()
    for line in DEV.read_text(encoding="utf-8").splitlines():
        row = json.loads(line)
        for s in row["strokes"]:
            out.add(tuple((float(p[0]), float(p[1])) for p in s[:12]))
    return out


def rows(mirrors: Path | None, skipped: list[str]) -> list[dict]:
    """Every stroke of every repository in `REPOS`, in order; files of fewer than two points go to ``skipped``.

    Raises:
        ValueError: a file that does not parse, or one that looks like a copy of the original $1 logs (named).
    """
    known = reserved_points()
    out = []
    for repo, commit, folder in REPOS:
        gdir = git_dir(repo, mirrors)
        names = _git(gdir, "ls-tree", "-r", "--name-only", commit, "--", folder).decode().splitlines()
        for name in sorted(n for n in names if n.endswith((".xml", ".csv"))):
            points, date = parse(f"{repo}@{commit[:7]}:{name}", _git(gdir, "show", f"{commit}:{name}"))
            where = f"{repo}@{commit[:7]}:{name}"
            year = re.search(r"(19|20)\d\d", date or "")
            if year and int(year.group(0)) < 2010:
                raise ValueError(f"{where}: dated {date!r}, as the original $1 logs: reserved, not a student's own")
            if tuple((p[0], p[1]) for p in points[:12]) in known:
                raise ValueError(f"{where}: its points are a stroke of the $1 logs: reserved, not a student's own")
            if len(points) < 2:  # a click the recorder saved: no stroke to recognise
                skipped.append(where)
                continue
            out.append({"source": "itt", "subject": person_of(repo), "device": "mouse", "label": label_of(name),
                        "file": where, "strokes": [points]})
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mirrors", type=Path, default=Path("/work/.mirror"),
                    help="folder of fetched repositories (<owner>+<name>/repo); cloned from GitHub when absent")
    ap.add_argument("--out", type=Path, default=CACHE / "itt.jsonl")
    args = ap.parse_args()
    skipped: list[str] = []
    try:
        got = rows(args.mirrors, skipped)
    except (ValueError, subprocess.CalledProcessError) as exc:
        raise SystemExit(f"student_sets: {exc}") from None
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("".join(json.dumps(r, separators=(",", ":")) + "\n" for r in got), encoding="utf-8")
    people = sorted({r["subject"] for r in got})
    print(f"{len(got)} strokes of {len(people)} people -> {args.out}")
    for where in skipped:
        print(f"skipped (fewer than two points): {where}")


if __name__ == "__main__":
    sys.exit(main())
