#!/usr/bin/env python3
"""Makes the cross-synthesiser speech corpus (issue 29) into a cache folder, never the repository: every family of
tests/speechgen (espeak-ng, flite, festival, SVOX Pico) saying commands, near-misses and other sentences at several
speeds and pitches, clean and with noise, plus degraded conditions and recordings without speech.

    nice -n 10 .venv/bin/python scripts/make_speech_corpus.py [--out DIR] [--families espeak-ng,flite,...]

The synthesisers come from scripts/setup.sh (espeak-ng, flite, festival with its festvox voices) and the test extra
(py-nanotts for Pico). benchmarks/bench_speech_corpus.py decodes the corpus and calibrates the rejection on it.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

from speechgen import corpus, voices  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=corpus.DEFAULT_DIR, help="the cache folder (default %(default)s)")
    parser.add_argument("--families", default=",".join(voices.FAMILIES), help="comma-separated families")
    args = parser.parse_args(argv)
    families = tuple(f for f in args.families.split(",") if f)
    missing = [f for f in families if not voices.available(f)]
    if missing:
        print(f"make_speech_corpus: {', '.join(missing)} cannot synthesise here (scripts/setup.sh installs "
              "espeak-ng, flite and festival; pip install py-nanotts for pico)", file=sys.stderr)
        return 1
    items = corpus.make(args.out, corpus.plan(families), progress=True)
    print(f"{len(items)} recordings in {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
