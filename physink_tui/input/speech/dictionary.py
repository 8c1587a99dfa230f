"""Whether a typed label can be said: its words looked up in the embedded recogniser's pronouncing dictionary
(pocketsphinx's CMUdict), read once without loading a model, else guessed from their spelling
(`letter_to_sound`); recognising speech is left to the backends."""

from __future__ import annotations

from functools import cache
from pathlib import Path

from physink_tui.input.speech.grammar import normalise
from physink_tui.input.speech.letter_to_sound import pronounce


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
    """The words of ``label`` the recogniser cannot say: in no dictionary, and not spelled so that a pronunciation
    can be guessed (none when that cannot be told).

    >>> unspeakable_words("Frying pan"), unspeakable_words("zorblax pan"), unspeakable_words("r2d2 pan")
    ([], [], ['r2d2'])
    """
    words = _dictionary()
    if words is None:
        return []
    return [w for w in normalise(label).split() if w not in words and pronounce(w) is None]


def guessed_words(label: str) -> dict[str, str]:
    """The words of ``label`` the dictionary lacks whose pronunciation is guessed from their spelling, with it.

    >>> guessed_words("zorblax pan")
    {'zorblax': 'Z AO R B L AH K S'}
    """
    words = _dictionary()
    if words is None:
        return {}
    guesses = {w: pronounce(w) for w in normalise(label).split() if w not in words}
    return {w: p for w, p in guesses.items() if p is not None}
