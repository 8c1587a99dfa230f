"""One utterance from samples to a checked command: voice activity, decoding, parsing and rejection; acting on the
command is the session's, capturing audio the microphone's or the caller's.

`Listener.hear` is the one path both `physink listen FILE.wav` and the microphone take. An utterance is accepted
only when the recogniser's best path is a whole sentence of the grammar, every word of it but the articles scores
at least the recogniser's threshold
and is likely enough (articles are short and run into the next word, so their fit says little), and no rival
sentence (another name or verb) comes close (`Decoded.margin`: then both are named, "heard 'label marble' or 'label
ball'? say it again"); anything else is `Utterance.rejected`, with the reason (DESIGN.md "Speech conventions").
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from physink_tui.input.speech.audio import RATE
from physink_tui.input.speech.grammar import DEFAULT_VOCABULARY, Command, SpeechGrammar
from physink_tui.input.speech.recogniser import Decoded, Recogniser
from physink_tui.input.speech.vad import VadConfig, speech_bounds
from physink_tui.timeline.phrases import ARTICLES, Vocabulary

MAX_SECONDS = 8.0
"""Longer speech is no command of this grammar: rejected without decoding."""


@dataclass(frozen=True, slots=True)
class Utterance:
    """What was heard.

    Attributes:
        text: the recogniser's words ("" when nothing was decoded).
        command: the command, or None when rejected.
        rejected: why the utterance changes nothing, or None when accepted.
        began: when the speech began, in the caller's seconds (the stream's start plus the offset found).
        seconds: how long the decoded speech lasted.
        decoded: the recogniser's result, None when nothing was decoded.
    """

    text: str
    command: Command | None
    rejected: str | None
    began: float
    seconds: float = 0.0
    decoded: Decoded | None = None

    def as_json(self) -> dict[str, Any]:
        """``{"text", "command", "rejected"}`` as `physink listen` prints it."""
        return {"text": self.text, "command": None if self.command is None else self.command.as_json(),
                "rejected": self.rejected}


class Listener:
    """A recogniser kept on the grammar of the current labels and words."""

    def __init__(self, recogniser: Recogniser, labels: Iterable[str] = (),
                 vocabulary: Vocabulary = DEFAULT_VOCABULARY, vad: VadConfig | None = None) -> None:
        self.recogniser = recogniser
        self.vad = vad or VadConfig()
        self._key: tuple[frozenset[str], Vocabulary] | None = None
        self.grammar = SpeechGrammar((), (), ())
        self.set_words(labels, vocabulary)

    def set_words(self, labels: Iterable[str], vocabulary: Vocabulary = DEFAULT_VOCABULARY) -> None:
        """Listen for these labels and words from now on (the grammar is rebuilt only when they changed)."""
        key = (frozenset(labels), vocabulary)
        if key == self._key:
            return
        self.grammar = SpeechGrammar.build(key[0], vocabulary, speakable=self.recogniser.speakable)
        self.recogniser.set_grammar(self.grammar)
        self._key = key

    @property
    def unspeakable(self) -> tuple[str, ...]:
        """Names and words left out of the grammar because the recogniser's dictionary lacks one of their words."""
        return self.grammar.unspeakable

    def guessed(self, names: Iterable[str]) -> dict[str, str]:
        """The words of ``names`` the recogniser says with a pronunciation guessed from their spelling, with it."""
        words = {w for name in names for w in name.split()}
        return {w: p for w in sorted(words) if (p := self.recogniser.guessed(w)) is not None}

    def hear(self, samples: np.ndarray, began: float = 0.0) -> Utterance:
        """The utterance in 16 kHz mono int16 ``samples`` that start at time ``began`` (the caller's seconds)."""
        bounds = speech_bounds(samples, self.vad)
        if bounds is None:
            return Utterance("", None, "no speech", began)
        start, end = bounds
        if end - start > MAX_SECONDS:
            return Utterance("", None, f"{end - start:.1f} s of speech is longer than any command "
                             f"({MAX_SECONDS:g} s at most)", began + start, end - start)
        speech = np.asarray(samples[round(start * RATE):round(end * RATE)], dtype=np.int16)
        decoded = self.recogniser.decode(speech)
        words = [w for w in decoded.words]
        first = words[0].start if words else 0.0
        at = began + start + first
        if decoded.outside:
            heard = f" (the rest: {decoded.text!r})" if decoded.text else ""
            return Utterance(decoded.text, None, f"speech outside the grammar{heard}", at, end - start, decoded)
        command = self.grammar.parse(decoded.text)
        if command is None:
            why = f"not a sentence of the grammar: {decoded.text!r}" if decoded.text else "no words recognised"
            return Utterance(decoded.text, None, why, at, end - start, decoded)
        recogniser = self.recogniser
        content = [w for w in words if w.word not in ARTICLES] or words
        worst = min(content, key=lambda w: w.score)
        if worst.score < recogniser.threshold:
            return Utterance(decoded.text, None, f"poorly matched: {worst.word!r} scored {worst.score:.2f} "
                             f"(at least {recogniser.threshold:g} is needed)", at, end - start, decoded)
        unsure = min(content, key=lambda w: w.confidence)
        if unsure.confidence < recogniser.min_confidence and not _close(decoded, unsure.word):
            return Utterance(decoded.text, None, f"unsure: {unsure.word!r} is only {unsure.confidence:.0%} likely "
                             f"(at least {recogniser.min_confidence:.0%} is needed)", at, end - start, decoded)
        if unsure.confidence < recogniser.min_confidence or decoded.margin < recogniser.min_margin:
            return Utterance(decoded.text, None, f"heard {decoded.text!r} or {decoded.alternative!r}? say it again",
                             at, end - start, decoded)
        return Utterance(decoded.text, command, None, at, end - start, decoded)


CLOSE = 1.0
"""A rival within this margin a frame is what an unsure word may have been: the rejection names it."""


def _close(decoded: Decoded, word: str) -> bool:
    """Whether ``decoded``'s rival differs in ``word`` and fits nearly as well (then it is worth naming)."""
    if decoded.alternative is None or decoded.margin > CLOSE:
        return False
    return word in set(decoded.text.split()) - set(decoded.alternative.split())
