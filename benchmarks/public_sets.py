"""Gathers every public stroke set the benchmarks score into JSON Lines under ``~/.cache/physink/``, each read from a
public repository at the commit measured: one command regenerates them all.

Usage: .venv/bin/python benchmarks/public_sets.py [--mirrors DIR] [--out DIR] [--only SET ...]

Writes ``DIR/student-sets/itt.jsonl`` (the first 16 students, `student_sets.REPOS`) and, from `ENTRIES` (issue 25's
second search, `benchmarks/SOURCES.md`), ``DIR/public-sets/<set>.jsonl`` (``itt-more.jsonl`` for the ITT
students): more students of the ITT course (set
``itt``), the people whom students of a course on input recognition (University of Florida, CIS6930 "Human-Centered
Input Recognition Algorithms", set ``hcira``) recorded drawing the $1 gestures, and the Mixed Multistroke Gestures
set (Anthony & Wobbrock 2012, set ``mmg``: 20 people, stylus or finger on a Tablet PC) as a student's repository
holds it; and the sets of the third search (`THIRD_ENTRIES`: set ``hcira3``, two more HCIRA teams' people, on a
trackpad, a mouse, a stylus on an iPad and a finger on a touch screen; set ``fc``, the online handwritten flowchart
database FC, a writer a source, read from InkML), which are the third held-back group
(`bench_generalisation.THIRD_SETS`: scored only by ``bench_generalisation.py --third``, by the lead, once); and the
sets of the fourth search (`FOURTH_ENTRIES`, read by `fourth_sets`: set ``quickdraw``, single drawings of Quick, Draw!
players, a country a source; set ``tutorboard``, one person's pen strokes), the fourth held-back group
(`bench_generalisation.FOURTH_SETS`: scored only by ``--fourth``); and the sets of the fifth search (`FIFTH_ENTRIES`,
read by `fifth_sets`: sets ``sign``, ``lowvision``, ``eds``, ``mmgplus``, ``homus``, ``laviola``, ``nicicon``, public
2D gesture sets as the Gester tool republishes them), the fifth held-back group (`bench_generalisation.FIFTH_SETS`:
scored only by ``--fifth``) but for ``sign``, opened as design material on 2026-12-07 (`SIGN_SETS`, ``--sign``).
Only Quick, Draw! (CC BY 4.0) carries a licence that allows copying it, and nothing is
committed; a repository is read from
``DIR/<owner>+<name>/repo`` (as the fetch tool leaves them) or cloned bare into the cache (`student_sets.git_dir`).

Each entry names the folder holding one person's recordings (``ONE``) or a folder of per-person subfolders
(``PER_FOLDER``, the person being ``owner/subfolder``); only files directly in those folders are read, never deeper
(several repositories keep the reserved $1 logs in subfolders beside their own). As in `student_sets`, a file dated
before 2010 or whose points equal a stroke of the $1 logs' development people stops the script with its name; so
does a label the spellings do not know, or a source of which more than `MAX_COPIES` gestures repeat strokes gathered
for another source (fewer are skipped and named: a file copied by hand).
"""

from __future__ import annotations

import argparse
import json
import re
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path

import fifth_sets
import fourth_sets
import student_sets

# the forms and Entry are re-exported: the tests and other scripts import them from here
from set_entries import ACCORD, GESTER, INKML, JAVA, ONE, PER_FOLDER, QUICKDRAW, SMARTINK, XML, Entry  # noqa: F401
from student_sets import _git, git_dir, reserved_points, times_ms

CACHE = Path.home() / ".cache" / "physink"
INK = "{http://www.w3.org/2003/InkML}"

MAX_COPIES = 5
"""A gesture file whose stroke was gathered already under another source is skipped (a file copied by hand); more
than this many in one source stop the script: the source is a copy."""
HCIRA_MOUSE = "mouse"
SUBHASH = ("subhash-vadlamani/UniStrokeGestureRecognizer", "c098c374c9d7dfc121e3e33731d8b7fc531f2bd7")
THIRD_ENTRIES: tuple[Entry, ...] = (
    Entry("hcira3", *SUBHASH, "Part_4/part4_dataset/user_logs", "trackpad", PER_FOLDER, rename=("trackpad-", "")),
    *(Entry("hcira3", *SUBHASH, f"project2_sourcecode/user_logs_{folder}", device, PER_FOLDER, rename=("", suffix))
      for folder, device, suffix in (("mouse", "mouse", "mouse"), ("stylus", "stylus on an iPad", ""),
                                     ("touchscreen", "finger on a laptop's touch screen", ""))),
    Entry("hcira3", "srichaitanyanulu/Dollar1-with-Protractor-Algorithm", "d70976beca745cafbe4dec0451253316fd904e01",
          "User Gesture Dataset", "pointer on a tkinter canvas (mouse or touch: not stated)", PER_FOLDER),
    Entry("fc", "zevisert/FCinkML1.7-renders", "ec845d2f0c140b2df296c5932339c881a2bfb1b7", "sources",
          "pen (the FC database's acquisition device)", ONE, form=INKML),
)
"""The sets of the third search (issue 25, `bench_generalisation.THIRD_SETS`: the third held-back group, never
designed on; `benchmarks/SOURCES.md`, "The third search")."""
QUICKDRAW_DEVICE = "mouse or touch (the Quick, Draw! web game; not recorded)"
TUTORBOARD = ("ArtemLevin/tutorboard", "3b2766953482f1d7dc7f632f689f24efffeafa03")
FOURTH_ENTRIES: tuple[Entry, ...] = (
    Entry("quickdraw", "borismus/exupery", "5ab788cb27b61d790d9f289d2fb3944748115f85", "docs/sketches",
          QUICKDRAW_DEVICE, ONE, form=QUICKDRAW,
          only=("circle", "hexagon", "line", "octagon", "square", "squiggle", "star", "triangle", "zigzag")),
    *(Entry("quickdraw", *TUTORBOARD, f"tests/fixtures/smart-ink-corpus/{folder}", QUICKDRAW_DEVICE, ONE,
            f"tutorboard/seed{seed}", (f"{name}.seed-{seed}.json.gz",), SMARTINK)
      for folder, name, seed in (("external", "quickdraw", 90210), ("external-v2", "holdout", 170731),
                                 ("external-v3", "negative-holdout", 260730))),
    Entry("tutorboard", *TUTORBOARD, "tests/fixtures/smart-ink-corpus/captured-chromium-v1",
          "pen on a Windows laptop (Chromium)", ONE, "captured-chromium-v1", ("corpus.json.gz",), SMARTINK),
)
"""The sets of the fourth search (issue 25, `bench_generalisation.FOURTH_SETS`: the fourth held-back group, never
designed on; `benchmarks/SOURCES.md`, "The fourth search")."""
GESTER_REPO = ("nmagrofuoco/Gester", "cd24525018a3007b769f100518e9bfc6bf982e2c")
FIFTH_ENTRIES: tuple[Entry, ...] = (
    Entry("sign", *GESTER_REPO, "datasets/2D/SIGN", "pen on a {os}", ONE, "{0}", form=GESTER),
    Entry("lowvision", *GESTER_REPO, "datasets/2D/LowVision", "finger on a touch screen", ONE, "{0}/{1}",
          ("with_impairment", "without_impairment"), GESTER),
    Entry("eds", *GESTER_REPO, "datasets/2D/EDS", "pen", ONE, "{0}/{1}", ("EDS-1", "EDS-2"), GESTER),
    Entry("mmgplus", *GESTER_REPO, "datasets/2D/MMG+", "finger on a smartphone (Huawei ANE-LX1)", ONE, "{1}",
          ("Smartphone",), GESTER),
    Entry("mmgplus", *GESTER_REPO, "datasets/2D/MMG+", "finger on a tablet (Samsung SM-T580)", ONE, "{1}", ("Tablet",),
          GESTER),
    Entry("homus", *GESTER_REPO, "datasets/2D/HOMUS", "stylus on a Samsung Galaxy Note 10.1", ONE, "{0}", form=GESTER),
    Entry("laviola", *GESTER_REPO, "datasets/2D/LaViola", "pen on an HP TC1100 Tablet PC", ONE, "{1}",
          ("training1", "training2"), GESTER),
    Entry("nicicon", *GESTER_REPO, "datasets/2D/NicIcon", "pen", ONE, "{0}", form=GESTER),
)
"""The sets of the fifth search (issue 25, `bench_generalisation.FIFTH_SETS`: the fifth held-back group, never
designed on; `benchmarks/SOURCES.md`, "The fifth search"): Gester's copies of public 2D sets, each read from its own
folder only (never its ``$1`` folder, the reserved $1 logs, nor its ``MMG`` folder, the set ``mmg`` again)."""
ENTRIES: tuple[Entry, ...] = (
    Entry("itt", "ITT-24/assignment-6-gesture-recognition-EmmaSophieReichert",
          "32d2840d2a55803e49d522f51e260a494c71589e", "dataset/my-dataset", "mouse", ONE, "EmmaSophieReichert"),
    Entry("itt", "ITT23/assignment-06-gesture-recognition-sina-sch", "8c0dbdb9e1c804a414cfff602c336af6f431ee4e",
          "dataset", "mouse", ONE, "sina-sch"),
    Entry("hcira", "Nikhil-Kumar-Singh0612/HCIRA", "767a65a6bc2a688c16ff41b43fa916f3794ff65f",
          "$1 Recognizer/data_set", HCIRA_MOUSE, PER_FOLDER),
    Entry("hcira", "pixelfac/hcira-project-23", "80d4cc73e4b3aff82fc72040e61e6d61ebab9e2f", "src/dataset",
          HCIRA_MOUSE, PER_FOLDER),
    Entry("hcira", "sinarest1608/HCIRA-HK", "d91ccc6dc416467ccde769a36e91d84624afa9c2", "Project1/usersamples",
          HCIRA_MOUSE, PER_FOLDER, only=tuple(f"Subject{k}" for k in range(1, 7))),
    Entry("hcira", "jd4386/HCIRA-Project", "ff559d7cba27a72d5019ed7169ad10e3e8b26d42", "Part 4/custom_xml_logs",
          HCIRA_MOUSE, PER_FOLDER),
    Entry("hcira", "hat359/HCIRA", "69a6542ac5f0fac384587158b5ecf4c05c59194e", "xml_collected_logs",
          "mouse or touch screen", PER_FOLDER),
    Entry("hcira", "jonathanzhang53/gesture-recognizer", "8f3085122e4a72bce618afc9d97faf31ee81fc7c", "user_gestures",
          HCIRA_MOUSE, PER_FOLDER),
    Entry("hcira", "klarubbio/hcira_p1", "e8eb332ae77da0ddd630fa2c87d3423bd2f732ef", "xml", HCIRA_MOUSE, PER_FOLDER),
    *(Entry("hcira", "shriyansnidhish/Dollar-one-recognizer", "35d6736f40cc036b53ce50172c58a2c86ee3495d",
            f"Part-2/Dataset/{folder}", device, PER_FOLDER)
      for folder, device in (("MousePad", "touchpad"), ("TouchScreen_with_stylus", "stylus on a touch screen"),
                             ("TouchScreen_without_stylus", "finger on a touch screen"))),
    Entry("mmg", "pixelfac/hcira-project-23", "80d4cc73e4b3aff82fc72040e61e6d61ebab9e2f", "src/mmg", None,
          PER_FOLDER),
    *(Entry("ahmadosama", "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM",
            "4285ca64256da189a171135fd84598f4da4badd6", folder, "mouse", ONE, "AhmadOsama4", form=ACCORD)
      for folder in ("TrainingData", "TestData")),
    Entry("gtiwari", "gtiwari333/mouse-gesture-recognition-java-hidden-markov-model",
          "06d93512747fca7352b4d7e1c5417f999767ad8f", "trainData", "mouse", ONE, "gtiwari333", form=JAVA),
    *THIRD_ENTRIES,
    *FOURTH_ENTRIES,
    *FIFTH_ENTRIES,
)
"""Every set of the second to fifth searches (issue 25), pinned; `benchmarks/SOURCES.md` says who drew each and how."""

SPELLINGS = {**student_sets.LABEL_SPELLINGS, "pig_tail": "pigtail", "zig_zag": "zigzag",
             "left_square_bracket": "left_sq_bracket", "right_square_bracket": "right_sq_bracket",
             "left_curly_braces": "left_curly_brace", "right_curly_braces": "right_curly_brace",
             "left_square_braces": "left_sq_bracket", "right_square_braces": "right_sq_bracket",
             "left_square_brace": "left_sq_bracket", "right_square_brace": "right_sq_bracket"}
DOLLAR_LABELS = frozenset({"arrow", "caret", "check", "circle", "delete_mark", "left_curly_brace", "left_sq_bracket",
                           "pigtail", "question_mark", "rectangle", "right_curly_brace", "right_sq_bracket", "star",
                           "triangle", "v", "x", "zigzag"})


def dollar_label(file_name: str) -> str:
    """``User07-left square bracket-3.xml`` -> ``left_sq_bracket``: the file's label in the $1 set's spelling.

    Raises:
        ValueError: a label none of the $1 set's (nor the zigzag) once spellings are unified.
    """
    stem = re.sub(r"^user\d+-", "", Path(file_name).stem.lower())
    stem = re.sub(r"[-_~ ]?\d+$", "", stem)
    label = re.sub(r"[- ]+", "_", stem)
    label = SPELLINGS.get(label, label)
    if label not in DOLLAR_LABELS:
        raise ValueError(f"{file_name}: label {label!r} is not one of the $1 set's")
    return label


def strokes_of(where: str, data: bytes) -> tuple[list[list[list[float | None]]], ET.Element]:
    """The pen-downs of one XML gesture file (``<Stroke>`` elements, else all its points as one), points [x, y, t]
    with t in ms from the stroke's first point where the file's clock can time it, and the root element."""
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise ValueError(f"{where}: {exc}") from None
    pen_downs = root.findall("Stroke") or [root]
    out = []
    for pen in pen_downs:
        pts = list(pen.iter("Point"))
        ts = times_ms([float(p.get("T", "nan")) if p.get("T") is not None else None for p in pts])
        out.append([[float(p.get("X", "nan")), float(p.get("Y", "nan")), t] for p, t in zip(pts, ts, strict=True)])
    return out, root


def _files(gdir: Path, commit: str, folder: str, ext: str = ".xml") -> list[str]:
    """The files ending in ``ext`` directly in ``folder`` at ``commit`` (not in its subfolders), sorted."""
    listing = _git(gdir, "ls-tree", "--name-only", commit, "--", folder.rstrip("/") + "/").decode().splitlines()
    return sorted(n for n in listing if n.endswith(ext))


def _subfolders(gdir: Path, commit: str, folder: str) -> list[str]:
    listing = _git(gdir, "ls-tree", "-d", "--name-only", commit, "--", folder.rstrip("/") + "/").decode()
    return sorted(listing.splitlines())


def java_stroke(where: str, data: bytes) -> list[list[float | None]]:
    """The stroke of one Java-serialised ``RawFeature`` (a ``double[]`` of times in ms, a ``java.awt.Point[]``)."""
    try:
        i = data.index(b"ur\x00\x02[D")
        i = data.index(b"xp", i) + 2
        n = int.from_bytes(data[i:i + 4], "big")
        times = struct.unpack(f">{n}d", data[i + 4:i + 4 + 8 * n])
        j = data.index(b"xp", data.index(b"ur\x00\x11[Ljava.awt.Point;", i)) + 2
        m, j = int.from_bytes(data[j:j + 4], "big"), j + 4
        xy = []
        for _ in range(m):
            if data[j:j + 2] == b"sr":  # the first Point: its class description, ended by TC_ENDBLOCKDATA, TC_NULL
                j = data.index(b"yxp", j) + 3
            elif data[j:j + 3] == b"sq\x00":  # a Point by reference to that description
                j += 6
            else:
                raise ValueError(f"byte {j}: not a java.awt.Point")
            xy.append(struct.unpack(">ii", data[j:j + 8]))
            j += 8
    except (ValueError, struct.error) as exc:
        raise ValueError(f"{where}: not a serialised RawFeature ({exc})") from None
    if m != n:
        raise ValueError(f"{where}: {n} times for {m} points")
    ts = times_ms(list(times))
    return [[float(x), float(y), t] for (x, y), t in zip(xy, ts, strict=True)]


def inkml_symbols(where: str, data: bytes) -> list[tuple[str, str, list[list[list[float | None]]]]]:
    """(writer, label, pen-downs) of every symbol of an InkML diagram: each innermost ``traceGroup`` with a ``truth``
    annotation, its strokes the traces it refers to, in order (points [x, y, None]: the files keep no times).

    Raises:
        ValueError: the file does not parse, names no writer, or a group refers to a trace it does not hold.
    """
    if b"<inkml:" in data and b"xmlns:inkml" not in data:  # one FC file uses the prefix without declaring it
        data = data.replace(b'xmlns="http://www.w3.org/2003/InkML"',
                            b'xmlns="http://www.w3.org/2003/InkML" xmlns:inkml="http://www.w3.org/2003/InkML"', 1)
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise ValueError(f"{where}: {exc}") from None
    writer = next((a.text or "" for a in root.findall(f"{INK}annotation") if a.get("type") == "writer"), "").strip()
    if not writer:
        raise ValueError(f"{where}: no <annotation type=\"writer\">")
    traces = {t.get("id"): [[float(v) for v in pt.split()[:2]] + [None] for pt in (t.text or "").split(",")
                            if pt.strip()] for t in root.iter(f"{INK}trace")}
    out = []
    for group in root.iter(f"{INK}traceGroup"):
        if group.find(f"{INK}traceGroup") is not None:
            continue
        label = next((a.text or "" for a in group.findall(f"{INK}annotation") if a.get("type") == "truth"), "").strip()
        refs = [v.get("traceDataRef") for v in group.findall(f"{INK}traceView")]
        if not label or not refs:
            continue
        missing = [r for r in refs if r not in traces]
        if missing:
            raise ValueError(f"{where}: trace group {label!r} refers to traces {missing} the file does not hold")
        out.append((writer, label, [traces[r] for r in refs]))
    return out


def _gestures(entry: Entry, gdir: Path) -> Iterator[tuple[str, str, str | None, str, list, str]]:
    """(where, person, device, label, pen-downs, date) of every gesture ``entry`` names, in order."""
    owner, c = entry.repo.split("/")[0], entry.commit
    at = f"{entry.repo}@{c[:7]}:"
    if entry.form == ACCORD:  # a file per label holding every sample: <Sequence> of <Point><X/><Y/></Point>
        for name in _files(gdir, c, entry.folder):
            try:
                root = ET.fromstring(_git(gdir, "show", f"{c}:{name}"))
            except ET.ParseError as exc:
                raise ValueError(f"{at}{name}: {exc}") from None
            for k, seq in enumerate(root.iter("Sequence"), 1):
                pts = [[float(p.findtext("X", "nan")), float(p.findtext("Y", "nan")), None] for p in seq.iter("Point")]
                yield f"{at}{name}#{k}", entry.person, entry.device, Path(name).stem, [pts], ""
        return
    if entry.form == INKML:  # a diagram per file: every labelled trace group is one symbol of the file's writer
        for name in _files(gdir, c, entry.folder, ".inkml"):
            for k, (writer, label, strokes) in enumerate(inkml_symbols(at + name, _git(gdir, "show", f"{c}:{name}")),
                                                        1):
                yield f"{at}{name}#{k}", writer, entry.device, label, strokes, ""
        return
    if entry.form == QUICKDRAW:  # a file a category, a drawing a line; its person is its country
        for category in entry.only:
            name = f"{entry.folder}/{category}.ndjson"
            for key, country, word, strokes in fourth_sets.quickdraw_drawings(at + name, _git(gdir, "show",
                                                                                              f"{c}:{name}")):
                yield f"{at}{name}#{key}", country, entry.device, word, strokes, ""
        return
    if entry.form == SMARTINK:  # TutorBoard's corpora: only the strokes drawn by people of the entry's set
        keep = fourth_sets.QUICKDRAW_DATASET if entry.set_name == "quickdraw" else fourth_sets.CAPTURED
        for name in entry.only:
            path = f"{entry.folder}/{name}"
            for k, (dataset, label, stroke) in enumerate(fourth_sets.smartink_samples(at + path, _git(
                    gdir, "show", f"{c}:{path}"))):
                if dataset == keep:
                    yield f"{at}{path}#{k}", entry.person, entry.device, label, [stroke], ""
        return
    if entry.form == GESTER:  # Gester's unified JSON, a gesture a file
        yield from fifth_sets.gester_gestures(entry, gdir)
        return
    if entry.form == JAVA:  # a folder per label, a serialised RawFeature per sample
        for sub in _subfolders(gdir, c, entry.folder):
            for name in _files(gdir, c, sub, ".TRAINDATA"):
                stroke = java_stroke(at + name, _git(gdir, "show", f"{c}:{name}"))
                yield at + name, entry.person, entry.device, Path(sub).name, [stroke], ""
        return
    if entry.layout == ONE:
        people = [(entry.person, entry.folder)]
    else:
        subs = _subfolders(gdir, c, entry.folder)
        prefix, suffix = entry.rename
        people = [(f"{owner}/{prefix}{Path(s).name.removesuffix(suffix)}", s) for s in subs
                  if not entry.only or Path(s).name in entry.only]
    for person, folder in people:
        for name in _files(gdir, c, folder):
            strokes, root = strokes_of(at + name, _git(gdir, "show", f"{c}:{name}"))
            if entry.set_name == "mmg":
                label = root.get("Name", "").split("~")[0].replace("-", "_").replace(" ", "_")
                yield at + name, f"{root.get('Subject')}", root.get("InputType"), label, strokes, root.get("Date", "")
            else:
                yield at + name, person, entry.device, dollar_label(name), strokes, root.get("Date", "")


def entry_rows(entry: Entry, mirrors: Path | None, known: set, seen: dict, skipped: list[str]) -> list[dict]:
    """The rows of one entry. ``known``: the $1 development people's strokes (refused); ``seen``: stroke -> source
    of every stroke gathered so far (a stroke seen under another source is refused), and (source, gesture) -> file
    (a `GESTER` gesture whose every point repeats one of the same source is skipped)."""
    out: list[dict] = []
    copies: dict[str, int] = {}
    for where, subject, device, label, strokes, date in _gestures(entry, git_dir(entry.repo, mirrors)):
        year = re.search(r"(19|20)\d\d", date)
        if year and int(year.group(0)) < 2010:
            raise ValueError(f"{where}: dated {date!r}, as the original $1 logs: reserved")
        source = f"{entry.set_name}:{subject}"
        keys = [tuple((p[0], p[1]) for p in stroke[:12]) for stroke in strokes]
        if any(key in known for key in keys):
            raise ValueError(f"{where}: its points are a stroke of the $1 logs: reserved")
        if sum(len(s) for s in strokes) < 2:
            skipped.append(f"{where} (fewer than two points)")
            continue
        first = next((seen[k] for k, s in zip(keys, strokes, strict=True) if len(s) >= 8 and seen.get(k, source)
                      != source), None)
        if first is not None:
            copies[source] = copies.get(source, 0) + 1
            if copies[source] > MAX_COPIES:
                raise ValueError(f"{where}: more than {MAX_COPIES} gestures of {source} are strokes of {first}: "
                                 "a copy of another source")
            skipped.append(f"{where} (a stroke of {first} again)")
            continue
        if entry.form == GESTER:  # Gester's copies keep a few files twice under one person: read once
            whole = (source, tuple(tuple((p[0], p[1]) for p in s) for s in strokes))
            if whole in seen:
                skipped.append(f"{where} (the same gesture as {seen[whole]})")
                continue
            seen[whole] = where
        for k, s in zip(keys, strokes, strict=True):
            if len(s) >= 8:
                seen.setdefault(k, source)
        out.append({"source": entry.set_name, "subject": subject, "device": device, "label": label, "file": where,
                    "strokes": strokes})
    return out


def gather(mirrors: Path | None, first: list[dict], skipped: list[str]) -> dict[str, list[dict]]:
    """set name -> rows, for every entry of `ENTRIES` in order (the strokes of ``first``, the first 16 students,
    count as seen)."""
    known = reserved_points()
    seen: dict = {}
    for row in first:
        for stroke in row["strokes"]:
            seen.setdefault(tuple((p[0], p[1]) for p in stroke[:12]), f"itt:{row['subject']}")
    sets: dict[str, list[dict]] = {}
    for entry in ENTRIES:
        sets.setdefault(entry.set_name, []).extend(entry_rows(entry, mirrors, known, seen, skipped))
    return sets


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mirrors", type=Path, default=Path("/work/.mirror"),
                    help="folder of fetched repositories (<owner>+<name>/repo); cloned from GitHub when absent")
    ap.add_argument("--out", type=Path, default=CACHE)
    ap.add_argument("--only", nargs="+", metavar="SET", help="write only these sets' files (every set is still read, "
                    "so a stroke copied from an earlier set is still caught)")
    args = ap.parse_args()
    skipped: list[str] = []
    try:
        first = student_sets.rows(args.mirrors, skipped)
        sets = gather(args.mirrors, first, skipped)
    except (ValueError, subprocess.CalledProcessError) as exc:
        raise SystemExit(f"public_sets: {exc}") from None
    outputs = {args.out / "student-sets" / "itt.jsonl": first}
    outputs.update({args.out / "public-sets" / f"{'itt-more' if name == 'itt' else name}.jsonl": rows
                    for name, rows in sets.items()})
    if args.only:
        unknown = set(args.only) - set(sets) - {"itt-more"}
        if unknown:
            raise SystemExit(f"public_sets: --only {sorted(unknown)}: no such set (sets: {sorted(sets)})")
        outputs = {p: rows for p, rows in outputs.items() if p.parent.name == "public-sets" and p.stem in args.only}
    for path, rows in outputs.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        partial = path.with_suffix(".partial")  # written whole, then renamed: a run reading it never sees half
        partial.write_text("".join(json.dumps(r, separators=(",", ":")) + "\n" for r in rows), encoding="utf-8")
        partial.replace(path)
        people = {r["subject"] for r in rows}
        print(f"{len(rows)} gestures of {len(people)} people -> {path}")
    for where in sorted(set(skipped)):
        print(f"skipped: {where}")


if __name__ == "__main__":
    sys.exit(main())
