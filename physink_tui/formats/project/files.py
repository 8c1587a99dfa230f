"""Project files on disk: saved atomically, loaded and checked; the JSON itself is `codec`'s.

Every failure is one `SceneError` line naming the file: a save that fails leaves the file it would have
replaced untouched and no temporary file behind (`physink_tui.formats.atomic_write`).
"""

from __future__ import annotations

import os

from physink_tui.errors import SceneError
from physink_tui.formats.atomic_write import write_text_atomic
from physink_tui.formats.project.codec import Project, decode_project, encode_project
from physink_tui.formats.project.sanity import check_project


def save_project(project: Project, path: str | os.PathLike[str]) -> None:
    """Writes the project to ``path``: the whole new file or, on any failure, the old one unchanged.

    Raises:
        SceneError: a field of the project is bad (named as in `encode_project`), or the file cannot be written.
    """
    target = os.fspath(path)
    text = encode_project(project, where=target)
    try:
        write_text_atomic(target, text)
    except OSError as e:
        raise SceneError(f"cannot save project {target}: {e.strerror or e}") from None


def load_project(path: str | os.PathLike[str], *, warnings: list[str] | None = None) -> Project:
    """The project in the file at ``path``.

    Args:
        path: the file.
        warnings: when given, one message per unknown key (which is ignored) is appended.

    Raises:
        SceneError: the file cannot be read, is not UTF-8, or is no valid project (the first bad field named),
            or holds a value no command can use (`sanity.check_project`).
    """
    target = os.fspath(path)
    try:
        with open(target, "rb") as f:
            data = f.read()
    except OSError as e:
        raise SceneError(f"cannot read project {target}: {e.strerror or e}") from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise SceneError(f"{target}: not UTF-8 text (byte {e.start} is {data[e.start]:#04x})") from None
    return check_project(decode_project(text, target, warnings=warnings), target)
