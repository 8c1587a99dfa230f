"""Reads the forms of the sets the fourth search for public sets found (issue 25; `benchmarks/SOURCES.md`, "The fourth
search"): Quick, Draw! raw NDJSON files and TutorBoard's smart-ink corpora. `public_sets` pins where they lie
(`public_sets.FOURTH_ENTRIES`) and gathers them; they are the fourth held-back group
(`bench_generalisation.FOURTH_SETS`), scored only by ``bench_generalisation.py --fourth``.

- Quick, Draw! (Google, CC BY 4.0; https://github.com/googlecreativelab/quickdraw-dataset), its raw form: a file a
  category, a drawing a line ``{"word", "countrycode", "timestamp", "recognized", "key_id", "drawing"}``, the drawing
  a list of strokes ``[[x...], [y...], [t...]]`` (t in ms from the drawing's start). Each drawing is by another
  player, who is anonymous: a drawing's source is the country it was drawn in.
- TutorBoard's smart-ink corpora (`ArtemLevin/tutorboard`, ``tests/fixtures/smart-ink-corpus``): gzipped JSON
  ``{"samples": [{"expectedKind", "metadata": {"sourceDataset", "sourceCategory", "traceOrigin", ...}, "points":
  [{"x", "y"}, ...]}, ...]}``, one stroke a sample and no times (only a duration). Its ``external*`` corpora are
  seeded samples of the Quick, Draw! raw files (one-stroke, recognised drawings, their ids hashed, their countries
  dropped) beside raster contours of another set (``hds``, not drawn strokes: never read); its
  ``captured-chromium-v1`` corpus is one person's pen strokes on a Windows laptop.
"""

from __future__ import annotations

import gzip
import json
from collections.abc import Iterator

from student_sets import times_ms

Stroke = list[list[float | None]]
QUICKDRAW_DATASET, CAPTURED = "quickdraw", "captured"


def quickdraw_drawings(where: str, data: bytes) -> Iterator[tuple[str, str, str, Stroke | list[Stroke]]]:
    """(key_id, country, word, strokes) of every drawing of a raw Quick, Draw! NDJSON file, in order; each stroke's
    points [x, y, t], t in ms from the stroke's first point (None where the clock cannot time it).

    Raises:
        ValueError: a line that is not a raw drawing (named by file and line).
    """
    for number, line in enumerate(data.decode("utf-8").splitlines(), 1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
            strokes = []
            for stroke in record["drawing"]:
                xs, ys, ts = stroke
                if not len(xs) == len(ys) == len(ts):
                    raise ValueError(f"{len(xs)} x, {len(ys)} y and {len(ts)} t")
                strokes.append([[float(x), float(y), t] for x, y, t in zip(xs, ys, times_ms(list(ts)), strict=True)])
            yield str(record["key_id"]), str(record.get("countrycode") or "unknown"), str(record["word"]), strokes
        except (json.JSONDecodeError, KeyError, TypeError, ValueError) as exc:
            raise ValueError(f"{where}:{number}: not a raw Quick, Draw! drawing ({exc})") from None


def smartink_samples(where: str, data: bytes) -> Iterator[tuple[str, str, Stroke]]:
    """(dataset, label, stroke) of every sample of a TutorBoard smart-ink corpus: dataset `QUICKDRAW_DATASET` for a
    Quick, Draw! trajectory, `CAPTURED` for a stroke captured by TutorBoard itself, else the corpus's own name (the
    raster contours, ``hds``); label the Quick, Draw! category where the corpus keeps it, else the kind it expects
    (``negative`` for a stroke drawn to be none); points [x, y, None].

    Raises:
        ValueError: a file that is not a gzipped corpus, or a sample without points (named).
    """
    try:
        samples = json.loads(gzip.decompress(data))["samples"]
    except (OSError, json.JSONDecodeError, KeyError, TypeError) as exc:
        raise ValueError(f"{where}: not a gzipped smart-ink corpus ({exc})") from None
    for k, sample in enumerate(samples):
        meta = sample.get("metadata", {})
        dataset = CAPTURED if sample.get("provenance") == "captured" else str(meta.get("sourceDataset"))
        if dataset == QUICKDRAW_DATASET and meta.get("traceOrigin") != "recorded-trajectory":
            dataset += f" ({meta.get('traceOrigin')})"  # not a drawn stroke: never read as one
        try:
            stroke: Stroke = [[float(p["x"]), float(p["y"]), None] for p in sample["points"]]
        except (KeyError, TypeError, ValueError) as exc:
            raise ValueError(f"{where}: sample {k} ({sample.get('id')}): bad points ({exc})") from None
        yield dataset, str(meta.get("sourceCategory") or sample["expectedKind"]), stroke
