"""A git repository made in a temporary folder and laid out as the fetch tool leaves a snapshot, for the stroke-set
readers' tests; the readers themselves are in benchmarks/."""

from __future__ import annotations

import subprocess
from pathlib import Path


def commit_mirror(tmp_path: Path, repo: str, files: dict[str, str | bytes]) -> tuple[Path, str]:
    """Commits ``files`` (path → text, or bytes as they are); returns the mirrors folder (``<owner>+<name>/repo``
    inside) and the commit."""
    work = tmp_path / "work"
    for name, text in files.items():
        (work / name).parent.mkdir(parents=True, exist_ok=True)
        if isinstance(text, bytes):
            (work / name).write_bytes(text)
        else:
            (work / name).write_text(text, encoding="utf-8")
    git = ["git", "-C", str(work), "-c", "user.name=t", "-c", "user.email=t@t"]
    subprocess.run([*git[:3], "init", "-q"], check=True)
    subprocess.run([*git, "add", "-A"], check=True)
    subprocess.run([*git, "commit", "-qm", "gestures"], check=True)
    mirror = tmp_path / "mirrors" / repo.replace("/", "+")
    mirror.mkdir(parents=True)
    (work / ".git").rename(mirror / "repo")
    head = subprocess.run(["git", "--git-dir", str(mirror / "repo"), "rev-parse", "HEAD"], check=True,
                          capture_output=True, text=True).stdout.strip()
    return tmp_path / "mirrors", head
