"""The letter-to-sound fallback (input/speech/letter_to_sound.py): its guesses against the bundled CMUdict, its phone
set, and a guessed word decoded by the embedded recogniser from a fixture."""

from __future__ import annotations

import random
import re
from functools import cache
from pathlib import Path

import pytest

from physink_tui.input.speech.audio import RATE, read_wav
from physink_tui.input.speech.grammar import SpeechGrammar
from physink_tui.input.speech.letter_to_sound import LETTER_NAMES, pronounce
from physink_tui.input.speech.vad import speech_bounds

pocketsphinx = pytest.importorskip("pocketsphinx")
SPEECH = Path(__file__).parent / "speech"
PHONES = set("""AA AE AH AO AW AY B CH D DH EH ER EY F G HH IH IY JH K L M N NG OW OY P R S SH T TH UH UW V W Y Z
    ZH""".split())


@cache
def cmudict() -> dict[str, list[str]]:
    entries: dict[str, list[str]] = {}
    for line in Path(pocketsphinx.get_model_path("en-us/cmudict-en-us.dict")).read_text().splitlines():
        word, phones = line.split(" ", 1)
        entries.setdefault(re.sub(r"\(\d+\)$", "", word), []).append(phones.strip())
    return entries


def _distance(a: list[str], b: list[str]) -> int:
    row = list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        diagonal, row[0] = row[0], i
        for j in range(1, len(b) + 1):
            diagonal, row[j] = row[j], min(row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1]))
    return row[-1]


def _phone_error_rate(words: list[str]) -> float:
    """Phones wrong (edits to the nearest dictionary pronunciation) over the dictionary's phones."""
    errors = total = 0
    for word in words:
        guess = (pronounce(word) or "").split()
        best = min(cmudict()[word], key=lambda p: _distance(guess, p.split()))
        errors += _distance(guess, best.split())
        total += len(best.split())
    return errors / total


def test_the_grammar_vocabulary_is_mostly_guessed_as_the_dictionary_says_it() -> None:
    words = [w for w in SpeechGrammar.build([]).words() if w in cmudict()]
    assert len(words) > 100
    assert _phone_error_rate(words) < 0.12


def test_dictionary_words_at_large_are_guessed_within_a_quarter_of_their_phones() -> None:
    pool = sorted(w for w in cmudict() if w.isalpha() and 4 <= len(w) <= 9)
    assert _phone_error_rate(random.Random(16).sample(pool, 400)) < 0.25


def test_every_guess_uses_the_models_phones_only() -> None:
    for word in ["zorblax", "grabber", "whizzing", "quetzal", "xylophone", "jiggle", "thwack", "o'brien", "t-bar",
                 *LETTER_NAMES]:
        guess = pronounce(word)
        assert guess and set(guess.split()) <= PHONES, (word, guess)


def test_words_that_are_not_spelled_with_letters_get_no_guess() -> None:
    assert [pronounce(w) for w in ("r2d2", "", "-", "x_y", "café")] == [None] * 5


def test_a_guessed_word_is_decoded_from_speech() -> None:
    from physink_tui.input.speech.pocketsphinx_backend import PocketsphinxRecogniser

    recogniser = PocketsphinxRecogniser()
    assert recogniser.guessed("kup") == "K AH P" and recogniser.guessed("cup") is None
    recogniser.set_grammar(SpeechGrammar(("ball", "basket", "kup", "peg"), ("falls", "hits"), ("off", "on")))
    for name in ("cmd08_0.wav", "cmd08_1.wav"):  # "label cup" said, in espeak-ng's and flite's voices
        samples = read_wav(SPEECH / name)
        start, end = speech_bounds(samples) or (0.0, 0.0)
        assert recogniser.decode(samples[round(start * RATE):round(end * RATE)]).text == "label kup", name
