"""The default recogniser: pocketsphinx 5 with its bundled US English model and a JSGF grammar; parsing is not here.

British pronunciations are added for every grammar word the US dictionary has in one accent only (non-rhotic
"platform" P L AE T F AO M, the broad A of "basket" B AA S K IH T; DESIGN.md "Speech conventions"). Each word is
scored by its mean log acoustic likelihood per 10 ms frame (pocketsphinx normalises a frame's senone scores to its
best one, so 0 is a perfect fit) and by its posterior probability in the decoder's lattice; `THRESHOLD` and
`MIN_CONFIDENCE` were calibrated on a synthetic development set and checked on the fixtures (tests/speech/,
docs/BENCHMARKS.md). A grammar forces any sound into a sentence, so the grammar given to pocketsphinx also has a loop
of single phones (`GARBAGE`, at weight `GARBAGE_WEIGHT`): speech outside the grammar fits the loop better and comes
out as `Decoded.outside`. A word the dictionary lacks is given the pronunciation `letter_to_sound.pronounce` guesses
from its spelling.
"""

from __future__ import annotations

import math
import re
import time
from typing import Any

import numpy as np

from physink_tui.errors import SpeechError
from physink_tui.input.speech.audio import RATE
from physink_tui.input.speech.grammar import SpeechGrammar
from physink_tui.input.speech.letter_to_sound import pronounce
from physink_tui.input.speech.recogniser import Decoded, Word

THRESHOLD = -4.2
"""Words other than articles whose mean log likelihood per frame is below this are rejected. Calibrated with
`MIN_CONFIDENCE` on the development set (``scripts/make_speech_fixtures.py --development DIR``: 208 synthetic
utterances, none of them committed fixtures) by maximising right - 5 x wrong over a grid, then checked on the
committed fixtures (benchmarks/bench_speech.py --development DIR, docs/BENCHMARKS.md)."""
MIN_CONFIDENCE = 0.4
"""Words other than articles with a lattice posterior below this are rejected (calibrated with `THRESHOLD`)."""
GARBAGE = tuple(f"gb{p.lower()}" for p in """AA AE AH AO AW AY B CH D DH EH ER EY F G HH IH IY JH K L M N NG OW OY P R S
    SH T TH UH UW V W Y Z ZH""".split())
"""One pseudo-word per phone of the en-us model, spelled ``gb`` + the phone (``gbaa`` is AA)."""
GARBAGE_WEIGHT = 0.01
"""The phone loop's weight against each sentence shape's 1 (calibrated on the out-of-grammar fixtures)."""
FRAME_SECONDS = 0.01
_GARBAGE = frozenset(GARBAGE)
_VARIANT = re.compile(r"\(\d+\)$")
_VOWELS = {"AA", "AE", "AH", "AO", "AW", "AY", "EH", "ER", "EY", "IH", "IY", "OW", "OY", "UH", "UW"}
_BROAD_A = {"S", "F", "TH", "N"}  # "basket", "after", "path", "dance": AE before these is AA in the south of England


def british(phones: str) -> str | None:
    """A non-rhotic, broad-A variant of a US pronunciation, or None when it would be the same.

    >>> british("P L AE T F AO R M"), british("B AE S K AH T"), british("B AO L")
    ('P L AE T F AO M', 'B AA S K AH T', None)
    >>> british("L IY V ER")
    'L IY V AH'
    """
    ph = phones.split()
    out: list[str] = []
    for i, p in enumerate(ph):
        after = ph[i + 1] if i + 1 < len(ph) else None
        if p == "R" and out and out[-1] in _VOWELS and (after is None or after not in _VOWELS):
            continue  # r after a vowel and not before one is silent
        if p == "ER" and after is None:
            out.append("AH")
        elif p == "AE" and after in _BROAD_A and i + 2 < len(ph):
            out.append("AA")
        else:
            out.append(p)
    variant = " ".join(out)
    return None if variant == phones else variant


def dithered(samples: np.ndarray) -> np.ndarray:
    """``samples`` with one least significant bit of seeded noise: a recording's digital silence (exact zeros)
    otherwise throws the cepstral normalisation off. Seeded by the length, so a decode depends on its input only."""
    noise = np.random.default_rng(len(samples)).integers(-1, 2, len(samples))
    return np.clip(np.asarray(samples, dtype=np.int32) + noise, -32768, 32767).astype("<i2")


class PocketsphinxRecogniser:
    """pocketsphinx 5's `Decoder` with the bundled en-us model, restricted by a JSGF grammar."""

    name = "pocketsphinx"
    threshold = THRESHOLD
    min_confidence = MIN_CONFIDENCE

    def __init__(self, **options: object) -> None:
        """``options`` are pocketsphinx configuration parameters over the defaults (benchmarks tune with them)."""
        try:
            import pocketsphinx
        except ImportError as exc:
            raise SpeechError(f"pocketsphinx is not installed ({exc}); pip install pocketsphinx") from None
        config = {"lm": None, "loglevel": "FATAL", "samprate": RATE, **options}
        # Two decoders on the same model: the screen (sentences against the phone loop, no lattice: the loop makes
        # lattices huge) and the words (sentences only, with the lattice that gives each word's posterior).
        self._screen = pocketsphinx.Decoder(**{**config, "bestpath": False})
        self._words = pocketsphinx.Decoder(**config)
        self._added: set[str] = set()
        self._guessed: dict[str, str] = {}  # words added with a pronunciation guessed from their spelling
        self._grammar: SpeechGrammar | None = None
        for word in GARBAGE:
            self._screen.add_word(word, word[2:].upper(), word == GARBAGE[-1])

    def speakable(self, word: str) -> bool:
        return self._words.lookup_word(word) is not None or pronounce(word) is not None

    def guessed(self, word: str) -> str | None:
        if word in self._guessed:
            return self._guessed[word]
        return None if self._words.lookup_word(word) is not None else pronounce(word)

    def set_grammar(self, grammar: SpeechGrammar) -> None:
        for word in grammar.words():
            self._add_variants(word)
        try:
            self._screen.add_jsgf_string("physink", grammar.jsgf(GARBAGE, GARBAGE_WEIGHT))
            self._words.add_jsgf_string("physink", grammar.jsgf())
        except (ValueError, RuntimeError) as exc:
            raise SpeechError(f"the speech grammar cannot be used by pocketsphinx: {exc}") from None
        self._screen.activate_search("physink")
        self._words.activate_search("physink")
        self._grammar = grammar

    def _add_variants(self, word: str) -> None:
        if word in self._added:
            return
        self._added.add(word)
        lookup = self._words.lookup_word
        known = [p for p in (lookup(word if n == 1 else f"{word}({n})") for n in range(1, 6)) if p]
        if not known:
            guess = pronounce(word)
            if guess is None:
                return
            for decoder in (self._screen, self._words):
                decoder.add_word(word, guess, True)
            self._guessed[word] = guess
            known = [guess]
        extra = [v for v in (british(p) for p in known) if v is not None and v not in known]
        extra = list(dict.fromkeys(extra))
        for n, phones in enumerate(extra, start=len(known) + 1):
            for decoder in (self._screen, self._words):
                decoder.add_word(f"{word}({n})", phones, n == len(known) + len(extra))

    def decode(self, samples: np.ndarray) -> Decoded:
        if self._grammar is None:
            raise SpeechError("no grammar set before decoding")
        started = time.perf_counter()
        audio = dithered(samples).tobytes()
        screened = list(_run(self._screen, audio))
        if any(_VARIANT.sub("", seg.word) in _GARBAGE for seg in screened):
            return Decoded("", (), len(samples) / RATE, time.perf_counter() - started, True)
        words = []
        for seg in _run(self._words, audio):
            word = _VARIANT.sub("", seg.word)
            if word.startswith(("<", "[", "(")):
                continue  # <s>, </s>, <sil>, fillers, (NULL) transitions
            frames = seg.end_frame - seg.start_frame + 1
            score = math.log(seg.ascore) / frames if seg.ascore > 0 else -math.inf
            words.append(Word(word, seg.start_frame * FRAME_SECONDS, (seg.end_frame + 1) * FRAME_SECONDS, score,
                              seg.prob))
        return Decoded(" ".join(w.word for w in words), tuple(words), len(samples) / RATE,
                       time.perf_counter() - started)


def _run(decoder: Any, audio: bytes) -> list[Any]:
    """The word segments of ``decoder``'s best path through 16-bit ``audio`` (none without a hypothesis).

    The front end is reset first (the noise estimate and cepstral mean would otherwise carry over from the last
    utterance) and the whole utterance goes in at once (``full_utt``), so the model's batch cepstral mean
    normalisation takes its mean from this audio alone: a decode depends on its audio only, in one pass.
    """
    decoder.reinit_feat()
    decoder.start_utt()
    decoder.process_raw(audio, full_utt=True)
    decoder.end_utt()
    return list(decoder.seg()) if decoder.hyp() is not None else []
