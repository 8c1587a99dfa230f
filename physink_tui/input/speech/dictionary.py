"""Whether a typed label can be said: its words looked up in the embedded recogniser's pronouncing dictionary
(pocketsphinx's CMUdict), read once without loading a model; recognising speech is left to the backends."""

from __future__ import annotations

from functools import cache
from pathlib import Path

from physink_tui.input.speech.grammar import normalise


@cache
def _dictionary() -> frozenset[str] | None:
    """The dictionary's words, or None when pocketsphinx is not installed."""
    try:
        import pocketsphinx
    except ImportError:
        return None
    path = Path(pocketsphinx.get_model_path("en-us/cmudict-en-us.dict"))
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return None
    return frozenset(line.split(" ", 1)[0] for line in lines if line and "(" not in line.split(" ", 1)[0])


def unspeakable_words(label: str) -> list[str]:
    """The words of ``label`` the recogniser cannot say (none when that cannot be told).

    >>> unspeakable_words("Frying pan"), unspeakable_words("zorblax pan")
    ([], ['zorblax'])
    """
    words = _dictionary()
    if words is None:
        return []
    return [w for w in normalise(label).split() if w not in words]
