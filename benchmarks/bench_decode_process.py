"""Benchmark: `physink decode` as a whole process beside a hid-tools script doing the same job, and its peak memory.

hid-tools is GPL and never a dependency: `benchmarks/hidtools_decode.py` uses its public API from a scratch venv
(it is frozen: a better ratio must come from our side).

    python3 -m venv /tmp/htvenv && /tmp/htvenv/bin/pip install hid-tools
    .venv/bin/python benchmarks/bench_decode_process.py [--runs 5] [--hidtools-python /tmp/htvenv/bin/python]

Both commands run as subprocesses (interpreter start-up included) writing their JSON lines to a file in /tmp,
alternating (wall medians, and the children's CPU time medians, which a loaded machine moves less), on three
captures: the largest shared one (48,182 reports of one layout); a mixed one made in /tmp from the KYE MousePen
i608X v2 capture's events repeated with increasing times to 71,000 reports (two pen report layouts in use, reports
that are not the pen's, and an x range that widens past the declared one); and a big one made the same way from the
largest (about 41 MB; ``--big-runs 0`` leaves it out). Nothing made is committed. Peak RSS is the child's
``ru_maxrss``. Our package's bytecode is compiled first, as an install would have it (hid-tools' is, by pip).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data" / "hid"
LARGEST = SHARED / "digimend__KYE_EasyPen_M506__if0.hid"
MIXED = SHARED / "digimend__KYE_MousePen_i608X_v2__if0.hid"
"""Reports 0x09 (mouse mode) and 0x10 (its descriptor's pen) in use, 0x07, 0x08 and 0x11 not the pen's, and x past
the declared range in 0x10."""
MIXED_REPORTS = 71_000


def make_big(source: Path, target: Path, megabytes: float | None = None, reports: int | None = None) -> Path:
    """``source``'s header and its events repeated, each copy 1 s after the last, until ``megabytes`` (whole
    copies) or exactly ``reports`` events."""
    lines = source.read_text(encoding="utf-8").splitlines()
    header = [x for x in lines if not x.startswith("E:")]
    events = [x.split(" ", 2) for x in lines if x.startswith("E:")]
    span = max(float(e[1]) for e in events) + 1.0
    with target.open("w", encoding="utf-8") as f:
        f.write("\n".join(header) + "\n")
        copy = written = 0
        while (f.tell() < megabytes * 1e6) if megabytes is not None else (written < (reports or 0)):
            chunk = events if reports is None else events[:reports - written]
            f.write("".join(f"E: {float(e[1]) + copy * span:013.6f} {e[2]}\n" for e in chunk))
            copy, written = copy + 1, written + len(chunk)
    return target


def run(cmd: list[str], out: Path) -> tuple[float, float]:
    """Wall seconds and CPU seconds (user + system) of one child process writing its output to the file ``out``."""
    with out.open("wb") as f:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run(cmd, stdout=f, stderr=subprocess.DEVNULL, check=True,
                       env={**os.environ, "PYTHONPATH": str(ROOT)})
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        return wall, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def peak_rss(cmd: list[str]) -> float:
    """Peak RSS (MB) of one child, measured in a fresh process so earlier children do not count."""
    probe = ("import resource, subprocess, sys; subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, "
             "stderr=subprocess.DEVNULL, check=True); print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    out = subprocess.run([sys.executable, "-c", probe, *cmd], capture_output=True, text=True, check=True,
                         env={**os.environ, "PYTHONPATH": str(ROOT)})
    return int(out.stdout) / 1024


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--big-runs", type=int, default=3, help="runs on the big capture (hid-tools takes ~40 s each)")
    ap.add_argument("--hidtools-python", default="/tmp/htvenv/bin/python")
    ap.add_argument("--big-mb", type=float, default=41.0)
    args = ap.parse_args()
    # An installed package has its bytecode compiled (pip does it, as it did for hid-tools); a checkout run with
    # PYTHONDONTWRITEBYTECODE would compile every module on every run, so compile once first.
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "physink_tui")], check=True,
                   stdout=subprocess.DEVNULL)
    mixed = make_big(MIXED, Path("/tmp/physink-bench-mixed.hid"), reports=MIXED_REPORTS)
    captures = [(LARGEST, args.runs), (mixed, args.runs)]
    if args.big_runs:
        captures.append((make_big(LARGEST, Path("/tmp/physink-bench-big.hid"), args.big_mb), args.big_runs))
    ours = [sys.executable, "-m", "physink_tui", "decode"]
    theirs = [args.hidtools_python, str(ROOT / "benchmarks" / "hidtools_decode.py")]
    out = Path("/tmp/physink-bench-decoded.jsonl")
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} at the "
          "start; medians of alternating runs, output to a file\n")
    print("| capture | size | reports | runs | physink decode | hid-tools script | ratio | CPU physink / hid-tools "
          "| CPU ratio | physink peak RSS |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for path, runs in captures:
        a, b = [], []
        for _ in range(runs):
            a.append(run([*ours, str(path)], out))
            b.append(run([*theirs, str(path)], out))
        rss = peak_rss([*ours, str(path)])
        ma, mb = statistics.median(w for w, _ in a), statistics.median(w for w, _ in b)
        ca, cb = statistics.median(c for _, c in a), statistics.median(c for _, c in b)
        reports = sum(1 for line in path.open(encoding="utf-8") if line.startswith("E:"))
        print(f"| {path.name} | {path.stat().st_size / 1e6:.1f} MB | {reports:,} | {runs} | {ma:.3f} s | {mb:.3f} s "
              f"| {mb / ma:.1f}x | {ca:.3f} s / {cb:.3f} s | {cb / ca:.1f}x | {rss:.0f} MB |", flush=True)
    out.unlink(missing_ok=True)


if __name__ == "__main__":
    main()
