"""The thesis journals (tests/journals) as projects, for the benchmarks: each replayed with ``physink replay`` (its
output silenced) and read back, as ``physink simulate DIR/project.json`` would see it; timing is the callers'."""

from __future__ import annotations

import contextlib
import io
import tempfile
from collections.abc import Sequence
from pathlib import Path

from physink_tui import cli
from physink_tui.formats.project.codec import Project
from physink_tui.formats.project.files import load_project

JOURNALS = Path(__file__).resolve().parent.parent / "tests" / "journals"
SUFFIX = ".physink.jsonl"


def journal_names(folder: Path = JOURNALS) -> list[str]:
    """Every journal's name in ``folder`` (without ``.physink.jsonl``), sorted."""
    return sorted(p.name[: -len(SUFFIX)] for p in folder.glob(f"*{SUFFIX}"))


def replayed_projects(names: Sequence[str], program: str, folder: Path = JOURNALS) -> dict[str, Project]:
    """Each named journal of ``folder`` replayed into a project; a failed replay stops ``program`` with the replay's
    message."""
    out = {}
    journals = folder
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            folder = Path(tmp) / name
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()) as err:
                status = cli.main(["replay", str(journals / f"{name}{SUFFIX}"), "--out", str(folder)])
            if status != 0:
                raise SystemExit(f"{program}: replaying {name} failed: {err.getvalue().strip()}")
            out[name] = load_project(folder / "project.json")
    return out
