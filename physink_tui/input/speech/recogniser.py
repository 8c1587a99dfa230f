"""The recogniser contract (decode one utterance against a grammar) and its results; choosing a backend is
`backends.make_recogniser`'s, deciding what a result means the listener's.

A backend turns 16 kHz mono int16 samples into `Decoded`: the best path through the grammar, word by word, each
with the backend's own score (higher is better) and the backend's `Recogniser.threshold` under which a word is too
poorly matched to trust. The grammar restricts the search; it cannot stop any sound from being forced into it, so
the score is what tells a sentence from noise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from physink_tui.input.speech.grammar import SpeechGrammar


@dataclass(frozen=True, slots=True)
class Word:
    """One word of a decoded utterance.

    Attributes:
        word: the word, lower-case, without a pronunciation variant's ``(2)``.
        start: seconds from the start of the audio decoded.
        end: seconds from the start of the audio decoded (> start).
        score: the backend's goodness of fit (pocketsphinx: mean log acoustic likelihood per 10 ms frame relative
            to the best senone, <= 0; vosk: its word confidence in [0, 1]).
        confidence: the word's posterior probability given the audio and the grammar, in [0, 1] (pocketsphinx:
            from its lattice, shared among a word's pronunciations; vosk: its confidence again).
    """

    word: str
    start: float
    end: float
    score: float
    confidence: float = 1.0


@dataclass(frozen=True, slots=True)
class Decoded:
    """The best path through the grammar for one utterance.

    Attributes:
        text: the words, space-separated (may be empty or stop short of a whole sentence).
        words: the words with times and scores, in order.
        seconds: the audio's length.
        decode_seconds: wall time the decoding took (for real-time factors; never used to decide anything).
        outside: whether some of the audio matched the recogniser's garbage model (sounds outside the grammar)
            better than any word; those stretches are not in ``words``.
        alternative: the best rival sentence (one name or the verb other than in ``text``), or None.
        margin: how much better ``text`` fits than ``alternative``, per frame of the words that differ (infinite
            without a rival).
    """

    text: str
    words: tuple[Word, ...]
    seconds: float
    decode_seconds: float = 0.0
    outside: bool = False
    alternative: str | None = None
    margin: float = math.inf

    @property
    def worst(self) -> float | None:
        """The lowest word score, or None without words."""
        return min((w.score for w in self.words), default=None)


class Recogniser(Protocol):
    """A grammar-restricted speech recogniser (pocketsphinx or vosk)."""

    name: str
    threshold: float
    """Words (articles aside) scoring below this are too poorly matched: the utterance is rejected."""
    min_confidence: float
    """Words (articles aside) less likely than this are too uncertain: the utterance is rejected."""
    min_margin: float
    """Commands whose `Decoded.margin` to their best rival is below this are ambiguous: rejected, naming both."""

    def speakable(self, word: str) -> bool:
        """Whether the recogniser can say ``word`` (it is in its dictionary)."""
        ...

    def guessed(self, word: str) -> str | None:
        """The pronunciation guessed from the spelling of a word the dictionary lacks, or None (a dictionary word,
        or one the recogniser cannot say)."""
        ...

    def set_grammar(self, grammar: SpeechGrammar) -> None:
        """Decode against ``grammar`` from now on."""
        ...

    def decode(self, samples: np.ndarray) -> Decoded:
        """The best path through the grammar for one whole utterance of 16 kHz mono int16 samples."""
        ...

