"""Upgrades a format's document written by an earlier version to the current one, one version at a time; no I/O.

Every format carries its version. A version bump comes with a step here-registered by its codec: a function
taking the parsed document of version N-1 and returning the same document as version N would write it. Steps
work on plain JSON values (dicts and lists), before any field is checked, so the checks see only the current
version. A document from a newer program is refused, naming where it came from and both versions.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from physink_tui.formats.json_checks import Place

Step = Callable[[dict[str, Any]], dict[str, Any]]
"""Turns a document of version N-1 into version N (a new dict; the one given is left as it was)."""


def upgrade(doc: dict[str, Any], version: int, steps: Mapping[int, Step], current: int, *, what: str,
            where: Place) -> dict[str, Any]:
    """The document of ``version`` upgraded step by step to ``current``.

    Args:
        doc: the parsed document.
        version: the version it says it is (already checked to be an integer >= its format's first).
        steps: ``steps[n]`` upgrades version n-1 to n, for every n in (first, current].
        current: the version this program writes and the newest it reads.
        what: the format's name in messages, e.g. ``"timeline format"``.
        where: where the document comes from, for the error.

    Raises:
        PhysinkError (``where.error``): the document is newer than ``current``.

    >>> from physink_tui.errors import SceneError
    >>> upgrade({"version": 3}, 3, {}, 2, what="format", where=Place("p.json", SceneError))
    Traceback (most recent call last):
    ...
    physink_tui.errors.SceneError: p.json was written by format version 3; this program reads version 2 \
(upgrade physink-tui)
    >>> upgrade({"v": 0}, 0, {1: lambda d: {**d, "v": 1}}, 1, what="format", where=Place("p.json"))
    {'v': 1}
    """
    if version > current:
        raise where.error(f"{where} was written by {what} version {version}; this program reads version "
                          f"{current} (upgrade physink-tui)")
    for target in range(version + 1, current + 1):
        doc = steps[target](doc)
    return doc
