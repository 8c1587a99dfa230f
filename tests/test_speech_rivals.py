"""Names that cannot be confused silently (issue 29): the user's names are preferred over the default ones, and a
command whose rival sentence (another name or verb) fits nearly as well is rejected naming both."""

from __future__ import annotations

import math

import numpy as np
import pytest

from physink_tui.input.speech.grammar import SpeechGrammar
from physink_tui.input.speech.listener import Listener
from physink_tui.input.speech.recogniser import Decoded, Word
from physink_tui.input.speech.rivals import differing, rival_jsgf
from physink_tui.timeline.phrases import DEFAULT_VOCABULARY, Vocabulary


class Heard:
    """A recogniser that hears what it is told, with the rival and margin it is told (the listener's side only)."""

    name = "stub"
    threshold = -3.0
    min_confidence = 0.0
    min_margin = 1.0

    def __init__(self, text: str, alternative: str | None, margin: float) -> None:
        self.decoded = Decoded(text, tuple(Word(w, 0.3 + i * 0.3, 0.6 + i * 0.3, -1.0) for i, w in
                                           enumerate(text.split())), 1.5, alternative=alternative,
                               margin=margin)

    def speakable(self, word: str) -> bool:
        return True

    def guessed(self, word: str) -> str | None:
        return None

    def set_grammar(self, grammar: SpeechGrammar) -> None:
        pass

    def decode(self, samples: np.ndarray) -> Decoded:
        return self.decoded


def _speech() -> np.ndarray:
    rng = np.random.default_rng(0)
    quiet = rng.normal(0, 8, 8000)
    loud = np.sin(np.arange(16000) * 0.2) * 8000 * (1 + rng.normal(0, 0.05, 16000))
    return np.concatenate([quiet, loud, quiet]).astype(np.int16)


def test_a_close_rival_rejects_the_command_naming_both() -> None:
    listener = Listener(Heard("label marble", "label ball", 0.4), ["ball"])
    utterance = listener.hear(_speech())
    assert utterance.command is None
    assert utterance.rejected == "heard 'label marble' or 'label ball'? say it again"


def test_a_clear_margin_keeps_the_command() -> None:
    listener = Listener(Heard("the egg lands in the frying pan", "the egg glides in the frying pan", 2.5), ["egg"])
    utterance = listener.hear(_speech())
    assert utterance.rejected is None and utterance.command is not None
    assert utterance.command.as_json()["verb"] == "lands"


def test_a_command_without_any_rival_is_judged_by_its_fit_alone() -> None:
    utterance = Listener(Heard("label ball", None, math.inf), ["ball"]).hear(_speech())
    assert utterance.command is not None and utterance.rejected is None


def test_labels_and_vocabulary_names_are_the_preferred_names() -> None:
    vocabulary = Vocabulary(DEFAULT_VOCABULARY.verbs, DEFAULT_VOCABULARY.prepositions, frozenset({"bowl"}))
    grammar = SpeechGrammar.build(["Ball", "crate"], vocabulary)
    assert grammar.preferred == {"ball", "crate", "bowl"}
    assert "marble" in grammar.components and "marble" not in grammar.preferred


def test_rivals_differ_in_exactly_one_name_or_the_verb() -> None:
    grammar = SpeechGrammar.build(["paddle a"], DEFAULT_VOCABULARY, defaults=["ball", "egg", "pan"])
    jsgf = rival_jsgf(grammar, grammar.parse("the ball hits paddle a"))
    assert jsgf is not None
    body = jsgf.splitlines()[-1]
    assert body.startswith("public <rival> = ( the ( egg | paddle a | pan ) hits paddle a ) | ( the ball ( ")
    assert body.endswith(" ) paddle a ) | ( the ball hits ( ball | egg | pan ) );")
    assert rival_jsgf(SpeechGrammar.build([], defaults=["ball"]), SpeechGrammar.build([], defaults=["ball"])
                      .parse("label ball")) is None
    assert differing("the ball hits paddle a".split(), "the egg hits paddle a".split()) == [1]


@pytest.mark.slow
@pytest.mark.parametrize("voice", [("flite", "slt"), ("festival", "cmu_us_slt_arctic_hts")])
def test_two_labels_that_sound_the_same_are_never_chosen_between_silently(voice: tuple[str, str]) -> None:
    from speechgen import conditions, voices

    from physink_tui.input.speech.audio import to_int16
    from physink_tui.input.speech.backends import make_recogniser

    if not voices.available(voice[0]):
        pytest.fail(f"{voice[0]} cannot synthesise here: run scripts/setup.sh")
    said = conditions.trimmed(voices.synthesise("label pear", voices.Voice(voice[0], voice[1], 1.0, None)))
    audio = to_int16(conditions.in_room(said, np.random.default_rng(0)))
    utterance = Listener(make_recogniser(), ["pear", "pair"]).hear(audio)
    assert utterance.command is None
    assert utterance.rejected in ("heard 'label pear' or 'label pair'? say it again",
                                  "heard 'label pair' or 'label pear'? say it again")
