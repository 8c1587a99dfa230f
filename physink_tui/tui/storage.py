"""Where the TUI keeps its journals (the XDG data folder) and which of them a crash left unfinished; no Textual.

Every TUI session journals to ``$XDG_DATA_HOME/physink/sessions/`` (default ``~/.local/share/physink/sessions/``),
one ``YYYYmmdd-HHMMSS-PID.physink.jsonl`` per session, from its first input. A journal whose last line is not
``end`` was left by a session that did not finish (a crash, a killed terminal): the TUI offers to recover it
(every line before a malformed one, saying what is dropped, as the kiosk does), then renames it
``….physink.jsonl.recovered`` so it is offered once. Reading and replaying are the journal reader's and the
session's.
"""

from __future__ import annotations

import os
import stat
import time
from pathlib import Path

from physink_tui.errors import JournalError
from physink_tui.formats.journal.entries import CommandEntry
from physink_tui.formats.journal.reader import Journal, read_journal

SUFFIX = ".physink.jsonl"
PROJECT_SUFFIX = ".physink.json"
RECOVERED = ".recovered"


def data_home() -> Path:
    """``$XDG_DATA_HOME`` or ``~/.local/share`` (the XDG Base Directory default)."""
    value = os.environ.get("XDG_DATA_HOME", "")
    return Path(value) if os.path.isabs(value) else Path.home() / ".local" / "share"


def config_home() -> Path:
    """``$XDG_CONFIG_HOME`` or ``~/.config``."""
    value = os.environ.get("XDG_CONFIG_HOME", "")
    return Path(value) if os.path.isabs(value) else Path.home() / ".config"


def sessions_dir() -> Path:
    """The folder of TUI session journals (not created here)."""
    return data_home() / "physink" / "sessions"


def exports_dir() -> Path:
    """The folder videos exported from the TUI go to (not created here)."""
    return data_home() / "physink" / "exports"


def projects_dir() -> Path:
    """The folder Save offers (``$XDG_DATA_HOME/physink/projects/``; made when a project is saved there)."""
    return data_home() / "physink" / "projects"


def new_project_path(now: float | None = None) -> Path:
    """The name Save offers: ``machine-YYYYmmdd-HHMMSS.physink.json`` in `projects_dir`, not taken yet."""
    folder = projects_dir()
    stamp = time.strftime("%Y%m%d-%H%M%S", time.localtime(now))
    path, n = folder / f"machine-{stamp}{PROJECT_SUFFIX}", 1
    while path.exists():
        n += 1
        path = folder / f"machine-{stamp}-{n}{PROJECT_SUFFIX}"
    return path


def project_target(text: str) -> Path:
    """Where Save writes for what the user typed: ``~`` expanded; a bare name (no folder) goes in `projects_dir`
    and gets the ``.physink.json`` suffix if it has none; any other path is taken as given (made absolute)."""
    path = Path(text.strip()).expanduser()
    if not path.is_absolute() and path.parent == Path("."):
        path = projects_dir() / (path.name if path.name.endswith(".json") else path.name + PROJECT_SUFFIX)
    return path.absolute()


def new_journal_path(folder: Path | None = None, now: float | None = None) -> Path:
    """A fresh journal path in ``folder`` (made if needed), named by the local time and the process id."""
    folder = folder or sessions_dir()
    folder.mkdir(parents=True, exist_ok=True)
    stamp = time.strftime("%Y%m%d-%H%M%S", time.localtime(now))
    path = folder / f"{stamp}-{os.getpid()}{SUFFIX}"
    n = 1
    while path.exists():
        n += 1
        path = folder / f"{stamp}-{os.getpid()}-{n}{SUFFIX}"
    return path


def finished(journal: Journal) -> bool:
    """Whether the journal's session ended (its last entry is ``end``)."""
    last = journal.entries[-1] if journal.entries else None
    return isinstance(last, CommandEntry) and last.name == "end"


def unfinished_journals(folder: Path | None = None, exclude: Path | None = None,
                        limit: int = 20) -> list[tuple[Path, Journal]]:
    """Journals in ``folder`` whose session did not end and that hold at least one input, newest first, among the
    ``limit`` newest (a folder of old sessions does not slow the start).

    A journal that cannot be read at all is skipped (it holds nothing to recover); ``exclude`` is the running
    session's own journal.
    """
    folder = folder or sessions_dir()
    if not folder.is_dir():
        return []
    found = []
    for path, _ in sorted(_journals(folder), key=lambda pair: pair[1], reverse=True)[:limit]:
        if exclude is not None and path.resolve() == exclude.resolve():
            continue
        try:
            journal = read_journal(path, salvage=True)  # the lines before a malformed one are still worth having
        except (JournalError, OSError):
            continue  # no header to replay it with, or gone meanwhile
        if journal.entries and not finished(journal):
            found.append((path, journal))
    return found


def _journals(folder: Path) -> list[tuple[Path, float]]:
    """The journal files in ``folder`` with their modification times; a dangling symlink or a file that vanished
    meanwhile is left out, and so is anything that is not a regular file."""
    found = []
    for path in folder.glob(f"*{SUFFIX}"):
        try:
            st = path.stat()
        except OSError:
            continue
        if stat.S_ISREG(st.st_mode):
            found.append((path, st.st_mtime))
    return found


def mark_recovered(path: Path) -> Path:
    """Renames a recovered (or declined) journal so it is not offered again; returns the new path."""
    target = path.with_name(path.name + RECOVERED)
    os.replace(path, target)
    return target


def remove_if_empty(path: Path) -> bool:
    """Removes a journal holding only its header and ``end`` (a session in which nothing happened)."""
    try:
        journal = read_journal(path)
    except JournalError:
        return False
    if all(isinstance(e, CommandEntry) and e.name == "end" for e in journal.entries):
        path.unlink(missing_ok=True)
        return True
    return False
