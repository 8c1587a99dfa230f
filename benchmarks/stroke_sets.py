"""Reads public single-stroke sets into one form for the benchmarks: rows of ``source`` (the set), ``subject`` (who
drew it, or None when the set does not say), ``device``, ``label``, ``file`` and ``strokes`` ([[x, y, t_ms], ...]
per pen-down; t None when the set has no times). Nothing here is copied from a set: the sets stay where they are.

Forms read (the folder layouts their authors publish):
- JSON Lines already in this form (``../shared/data/strokes/dollar1-dev.jsonl``);
- the $1 unistroke logs (Wobbrock et al. 2007): XML files ``<Gesture Name="arrow01" Subject="2" Speed="fast">``
  with ``<Point X Y T/>`` children, anywhere under a folder (set ``dollar1``);
- the $N multistroke set MMG (Anthony & Wobbrock 2010): XML files ``<Gesture Name="arrowhead~01" Subject="10"
  InputType="stylus" Speed="FAST">`` with ``<Stroke>`` elements of ``<Point X Y T/>`` (set ``mmg``);
- the Drawn Shapes set (Bouchal 2019): ``paths/<shape>/<name>.json``, each a list of paths of ``["x", "y"]``
  strings, no times and no person (set ``bouchal``; its source is the device, an Apple Pencil on an iPad Pro).
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path

Row = dict


def read_sets(paths: list[Path], program: str) -> list[Row]:
    """Every row of every set at ``paths``, in order; a set that cannot be read ends ``program`` with its reason."""
    rows: list[Row] = []
    for path in paths:
        try:
            rows += read_set(path)
        except (OSError, ValueError) as exc:
            raise SystemExit(f"{program}: {exc}") from None
    return rows


def read_set(path: Path) -> list[Row]:
    """Every row of the set at ``path`` (a .jsonl file, or a folder in one of the forms above).

    Raises:
        ValueError: a folder in no known form, or a file that does not parse (named).
    """
    if path.is_file():
        return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]
    if (path / "paths").is_dir():
        return list(_bouchal(path / "paths"))
    xmls = sorted(path.rglob("*.xml"))
    if not xmls:
        raise ValueError(f"{path}: no .jsonl file, no paths/ folder and no .xml files: not a set this reads")
    return [_gesture(x) for x in xmls]


def _gesture(path: Path) -> Row:
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as exc:
        raise ValueError(f"{path}: {exc}") from None
    name = root.get("Name", "")
    strokes = root.findall("Stroke")
    if strokes or "~" in name:  # MMG
        label = name.split("~")[0].replace("-", "_").replace(" ", "_")
        pen_downs = strokes or [root]
        return {"source": "mmg", "subject": root.get("Subject"), "device": root.get("InputType"),
                "speed": root.get("Speed"), "label": label, "file": str(path),
                "strokes": [[_point(p) for p in s.iter("Point")] for s in pen_downs]}
    subject = root.get("Subject")
    return {"source": "dollar1", "subject": f"s{int(subject):02d}" if subject and subject.isdigit() else subject,
            "device": "pocket pc stylus", "speed": root.get("Speed"), "label": re.sub(r"\d+$", "", name),
            "file": str(path), "strokes": [[_point(p) for p in root.iter("Point")]]}


def _point(p: ET.Element) -> list[float | None]:
    t = p.get("T")
    return [float(p.get("X", "nan")), float(p.get("Y", "nan")), float(t) if t is not None else None]


def _bouchal(paths: Path) -> Iterator[Row]:
    for shape in sorted(d for d in paths.iterdir() if d.is_dir()):
        for file in sorted(shape.glob("*.json")):
            try:
                drawn = json.loads(file.read_text(encoding="utf-8"))
            except json.JSONDecodeError as exc:
                raise ValueError(f"{file}: {exc}") from None
            yield {"source": "bouchal", "subject": None, "device": "apple pencil", "label": shape.name,
                   "file": str(file), "strokes": [[[float(x), float(y), None] for x, y in path] for path in drawn]}


def source_of(row: Row, by: str) -> str:
    """The source a row is scored as: its person (``set:subject``, the set when it names none), its device
    (``set:device``) or its whole set."""
    if by == "person" and row.get("subject"):
        return f"{row['source']}:{row['subject']}"
    if by == "device" and row.get("device"):
        return f"{row['source']}:{row['device']}"
    return str(row["source"])
