"""The fourth search's sets are read in the forms their sources publish (made here in miniature, no stroke of any
set): Quick, Draw! raw NDJSON, a drawing's person its country, and TutorBoard's gzipped smart-ink corpora, of which
only Quick, Draw! trajectories (set ``quickdraw``) or the strokes TutorBoard captured (set ``tutorboard``) are read;
every row belongs to the fourth held-back group, which only ``--fourth`` scores."""

from __future__ import annotations

import gzip
import json
import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_generalisation import FOURTH_SETS, scored_rows
from fourth_sets import quickdraw_drawings, smartink_samples
from mirror_repo import commit_mirror
from public_sets import FOURTH_ENTRIES, ONE, QUICKDRAW, SMARTINK, Entry, entry_rows
from stroke_sets import source_of

REPO = "someone/sketches"


def _ring(n: int = 24, r: float = 80.0) -> list[tuple[float, float]]:
    return [(200 + r * math.cos(2 * math.pi * k / n), 150 + r * math.sin(2 * math.pi * k / n)) for k in range(n + 1)]


def _drawing(word: str, country: str, key: str, strokes: list[list[tuple[float, float]]], start: int = 0) -> str:
    drawn = [[[x for x, _ in s], [y for _, y in s], [start + 1000 * j + 17 * i for i in range(len(s))]]
             for j, s in enumerate(strokes)]
    return json.dumps({"word": word, "countrycode": country, "timestamp": "2017-03-01 20:41:36.70725 UTC",
                       "recognized": True, "key_id": key, "drawing": drawn})


def _corpus(samples: list[dict]) -> bytes:
    return gzip.compress(json.dumps({"schemaVersion": "tutorboard.smart-ink-corpus/0.1", "samples": samples}).encode())


def _sample(kind: str, points, dataset: str | None = "quickdraw", category: str | None = None,
            origin: str = "recorded-trajectory", captured: bool = False) -> dict:
    meta = {"durationMs": 900, **({"sourceDataset": dataset} if dataset else {}), "traceOrigin": origin,
            **({"sourceCategory": category} if category else {})}
    return {"expectedKind": kind, "id": f"{kind}-{len(points)}", "metadata": meta,
            "points": [{"x": x, "y": y} for x, y in points], "provenance": "captured" if captured else
            "external-human", "shouldPropose": kind != "negative"}


def test_quickdraw_raw_drawings_are_one_row_each_their_country_the_source_their_times_from_zero(tmp_path) -> None:
    line, small = [(10.0 + 12 * i, 40.0 + i) for i in range(10)], _ring(r=60)
    mirrors, head = commit_mirror(tmp_path, REPO, {
        "sketches/circle.ndjson": "\n".join([_drawing("circle", "US", "1", [_ring()], start=250),
                                             _drawing("circle", "FI", "2", [small[:13], small[12:]])]) + "\n",
        "sketches/line.ndjson": _drawing("line", "US", "3", [line]) + "\n",
        "sketches/cat.ndjson": _drawing("cat", "US", "4", [line]) + "\n",  # a category not named: never read
    })
    entry = Entry("quickdraw", REPO, head, "sketches", "mouse or touch", ONE, form=QUICKDRAW, only=("circle", "line"))
    rows = entry_rows(entry, mirrors, set(), {}, [])
    assert [(source_of(r, "person"), r["label"], len(r["strokes"])) for r in rows] == [
        ("quickdraw:US", "circle", 1), ("quickdraw:FI", "circle", 2), ("quickdraw:US", "line", 1)]
    near = pytest.approx  # a point of the ring, and the times from its first point (drawn from 250 ms)
    assert rows[0]["strokes"][0][:2] == [[280.0, 150.0, 0.0], [near(277.274, abs=1e-3), near(170.706, abs=1e-3), 17.0]]
    assert rows[0]["file"] == f"{REPO}@{head[:7]}:sketches/circle.ndjson#1"
    assert scored_rows(rows)[0] == []  # the fourth held-back group: out of every run but --fourth
    kept, left = scored_rows(rows, fourth=True)
    assert [(r["label"], sorted(r["accepts"])) for r in kept] == [("circle", ["circle", "ellipse"]), ("line", ["line"])]
    assert left == {"quickdraw circle: drawn in 2 strokes": 1}


def test_a_line_that_is_not_a_raw_drawing_is_named_by_file_and_line() -> None:
    good = _drawing("line", "US", "1", [[(0, 0), (5, 5)]])
    with pytest.raises(ValueError, match=r"line\.ndjson:2: not a raw Quick, Draw! drawing"):
        list(quickdraw_drawings("line.ndjson", (good + '\n{"word": "line", "key_id": "2"}\n').encode()))
    simplified = json.dumps({"word": "line", "countrycode": "US", "key_id": "3", "drawing": [[[0, 9], [0, 9]]]})
    with pytest.raises(ValueError, match=r"line\.ndjson:1: not a raw"):  # the simplified form: no times
        list(quickdraw_drawings("line.ndjson", simplified.encode()))


def test_tutorboard_corpora_give_quickdraw_trajectories_or_captured_strokes_never_raster_contours(tmp_path) -> None:
    ring, line = _ring(), [(0.0, 0.0), (40.0, 1.0), (80.0, 2.0), (120.0, 3.0)]
    external = _corpus([_sample("circle", ring), _sample("negative", line),
                        _sample("negative", ring, category="squiggle"),
                        _sample("rectangle", ring[:5], dataset="hds", origin="raster-contour")])
    captured = _corpus([_sample("ellipse", ring, dataset=None, captured=True),
                        _sample("negative", line, dataset=None, captured=True)])
    assert [(d, label) for d, label, _ in smartink_samples("e.json.gz", external)] == [
        ("quickdraw", "circle"), ("quickdraw", "negative"), ("quickdraw", "squiggle"), ("hds", "rectangle")]
    with pytest.raises(ValueError, match=r"bad\.json\.gz: not a gzipped smart-ink corpus"):
        list(smartink_samples("bad.json.gz", b"{}"))
    mirrors, head = commit_mirror(tmp_path, REPO, {"fixtures/external/sample.json.gz": external,
                                                   "fixtures/captured/corpus.json.gz": captured})
    rows = entry_rows(Entry("quickdraw", REPO, head, "fixtures/external", "mouse or touch", ONE, "tutorboard/seed1",
                            ("sample.json.gz",), SMARTINK), mirrors, set(), {}, [])
    rows += entry_rows(Entry("tutorboard", REPO, head, "fixtures/captured", "pen", ONE, "captured-v1",
                             ("corpus.json.gz",), SMARTINK), mirrors, set(), {}, [])
    assert [(source_of(r, "person"), r["label"]) for r in rows] == [
        ("quickdraw:tutorboard/seed1", "circle"), ("quickdraw:tutorboard/seed1", "negative"),
        ("quickdraw:tutorboard/seed1", "squiggle"), ("tutorboard:captured-v1", "ellipse"),
        ("tutorboard:captured-v1", "negative")]
    assert rows[0]["strokes"][0][0] == [280.0, 150.0, None]  # no times: only the stroke's duration is kept
    kept, left = scored_rows(rows, fourth=True)
    assert [(r["source"], r["label"]) for r in kept] == [("quickdraw", "circle"), ("quickdraw", "squiggle"),
                                                         ("tutorboard", "ellipse")]
    assert sum(left.values()) == 2 and scored_rows(rows)[0] == []


def test_a_drawing_two_repositories_both_hold_is_read_once(tmp_path) -> None:
    """TutorBoard's samples keep Quick, Draw!'s raw points: one that a repository of raw files also holds is the same
    drawing, skipped the second time and named."""
    ring = _ring()
    mirrors, head = commit_mirror(tmp_path, REPO, {"raw/circle.ndjson": _drawing("circle", "US", "1", [ring]) + "\n",
                                                   "fixtures/s.json.gz": _corpus([_sample("circle", ring)])})
    seen: dict = {}
    skipped: list[str] = []
    rows = entry_rows(Entry("quickdraw", REPO, head, "raw", "", ONE, form=QUICKDRAW, only=("circle",)), mirrors,
                      set(), seen, skipped)
    rows += entry_rows(Entry("quickdraw", REPO, head, "fixtures", "", ONE, "tutorboard/seed1", ("s.json.gz",),
                             SMARTINK), mirrors, set(), seen, skipped)
    assert [source_of(r, "person") for r in rows] == ["quickdraw:US"]
    assert skipped == [f"{REPO}@{head[:7]}:fixtures/s.json.gz#0 (a stroke of quickdraw:US again)"]


def test_the_pinned_fourth_entries_are_all_of_the_fourth_group() -> None:
    assert {e.set_name for e in FOURTH_ENTRIES} == FOURTH_SETS
    assert all(e.form in (QUICKDRAW, SMARTINK) and len(e.commit) == 40 for e in FOURTH_ENTRIES)
