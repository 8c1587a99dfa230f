"""The default recogniser: pocketsphinx 5 with its bundled US English model and a JSGF grammar; parsing is not here.

British pronunciations are added for every grammar word the US dictionary has in one accent only (non-rhotic
"platform" P L AE T F AO M, the broad A of "basket" B AA S K IH T; DESIGN.md "Speech conventions"). Each word is
scored by its mean log acoustic likelihood per 10 ms frame (pocketsphinx normalises a frame's senone scores to its
best one, so 0 is a perfect fit) and by its posterior probability in the decoder's lattice. A grammar forces any sound
into a sentence, so the grammar given to pocketsphinx also has a loop of single phones (`GARBAGE`, at weight
`GARBAGE_WEIGHT`): speech outside the grammar fits the loop better and comes out as `Decoded.outside`. A word the
dictionary lacks is given the pronunciation `letter_to_sound.pronounce` guesses from its spelling.

A command that passes is also aligned against its rivals (`rivals.rival_jsgf`: the sentences that differ from it in
one name or the verb) and alone, by the same search: `Decoded.margin` is how much better it fits, per frame of the
words that differ, with names the user gave (labels, vocabulary files) favoured by `PREFERENCE` over the built-in
default names (issue 29). `THRESHOLD`, `MIN_CONFIDENCE` and `MIN_MARGIN` are calibrated on synthetic voices of four
synthesisers, each checked with thresholds chosen without it (benchmarks/bench_speech_corpus.py, docs/BENCHMARKS.md).
"""

from __future__ import annotations

import math
import re
import time
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from physink_tui.errors import SpeechError
from physink_tui.input.speech.audio import RATE
from physink_tui.input.speech.grammar import Command, LabelCommand, SpeechGrammar
from physink_tui.input.speech.letter_to_sound import pronounce
from physink_tui.input.speech.recogniser import Decoded, Word
from physink_tui.input.speech.rivals import differing, rival_jsgf
from physink_tui.timeline.phrases import ARTICLES

THRESHOLD = -4.0
"""Words other than articles whose mean log likelihood per frame is below this are rejected. Calibrated with
`MIN_CONFIDENCE` and `MIN_MARGIN` on four synthesisers' voices among the thresholds that keep issue 16's fixtures at
their test's floor (benchmarks/bench_speech_corpus.py; each family's figures with thresholds chosen without it are in
docs/BENCHMARKS.md)."""
MIN_CONFIDENCE = 0.5
"""Words other than articles with a lattice posterior below this are rejected (calibrated with `THRESHOLD`)."""
MIN_MARGIN = -1.0
"""Commands whose best rival fits better than this a frame (of the words that differ, the user's names favoured by
`PREFERENCE`) are rejected as ambiguous, naming both (calibrated with `THRESHOLD`)."""
PREFERENCE = 1.0
"""A name the user gave is favoured over a default name in the margin by this much a frame: a rival that is the
user's name needs the default name heard to fit this much better, and a user's name is kept against a default rival
that fits as well (a homophone)."""
SCALE = 1024.0
"""pocketsphinx's Viterbi segment scores arrive shifted down by 2^10 (measured); this brings them back to log
likelihoods, so that margins read as log likelihood a frame."""
GARBAGE = tuple(f"gb{p.lower()}" for p in """AA AE AH AO AW AY B CH D DH EH ER EY F G HH IH IY JH K L M N NG OW OY P R S
    SH T TH UH UW V W Y Z ZH""".split())
"""One pseudo-word per phone of the en-us model, spelled ``gb`` + the phone (``gbaa`` is AA)."""
GARBAGE_WEIGHT = 0.01
"""The phone loop's weight against each sentence shape's 1 (calibrated on the out-of-grammar fixtures)."""
FRAME_SECONDS = 0.01
ROOM_SD = 8.0
"""A quiet room's noise floor (SD on the 16-bit scale), put into a recording's digital silence before decoding."""
_FRAME = round(RATE * FRAME_SECONDS)
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
    """``samples`` with one least significant bit of seeded noise, and a quiet room's noise floor (`ROOM_SD`) in
    every 10 ms of digital silence (no sample beyond +-1): exact zeros throw the front end's noise estimate and
    cepstral mean off, and one bit of dither is not enough (ten espeak-ng variants padded with digital silence: 35
    of 70 commands right with one bit, 46 over a quiet room; benchmarks/bench_speech_pipeline.py). Seeded by the
    length, so a decode depends on its input only; audio with no silent stretch gets the one bit alone.

    >>> quiet = dithered(np.zeros(1600, dtype=np.int16))
    >>> 4 < float(np.std(quiet)) < 12
    True
    """
    rng = np.random.default_rng(len(samples))
    noise = rng.integers(-1, 2, len(samples))
    out = np.asarray(samples, dtype=np.int32) + noise
    whole = len(samples) // _FRAME * _FRAME
    silent = np.abs(np.asarray(samples[:whole], dtype=np.int32)).reshape(-1, _FRAME).max(axis=1, initial=0) <= 1
    if silent.any():
        room = np.random.default_rng(len(samples) + 1).normal(0.0, ROOM_SD, whole)
        out[:whole] += np.rint(room * np.repeat(silent, _FRAME)).astype(np.int32)
    return np.clip(out, -32768, 32767).astype("<i2")


class PocketsphinxRecogniser:
    """pocketsphinx 5's `Decoder` with the bundled en-us model, restricted by a JSGF grammar; each command is also
    weighed against its rivals."""

    name = "pocketsphinx"
    threshold = THRESHOLD
    min_confidence = MIN_CONFIDENCE
    min_margin = MIN_MARGIN

    def __init__(self, **options: object) -> None:
        """``options`` are pocketsphinx configuration parameters over the defaults (benchmarks tune with them)."""
        try:
            import pocketsphinx
        except ImportError as exc:
            raise SpeechError(f"pocketsphinx is not installed ({exc}); pip install pocketsphinx") from None
        config = {"lm": None, "loglevel": "FATAL", "samprate": RATE, **options}
        # Two decoders on the same model: the screen (sentences against the phone loop, no lattice: the loop makes
        # lattices huge; it also aligns a command's rivals) and the words (sentences only, with the lattice that gives
        # each word's posterior).
        self._screen = pocketsphinx.Decoder(**{**config, "bestpath": False})
        self._words = pocketsphinx.Decoder(**config)
        self._logmath = self._screen.get_logmath()
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
        self._screen.activate_search("physink")
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
        decoded = Decoded(" ".join(w.word for w in words), tuple(words), len(samples) / RATE)
        command = self._grammar.parse(decoded.text)
        content = [w for w in words if w.word not in ARTICLES] or words
        if command is not None and min(w.score for w in content) >= self.threshold:
            decoded = self._rival(decoded, command, audio)  # also names what an unsure word may have been
        return replace(decoded, decode_seconds=time.perf_counter() - started)

    def _rival(self, decoded: Decoded, command: Command, audio: bytes) -> Decoded:
        """``decoded`` with its best rival sentence and the margin to it per frame of the words that differ, both
        aligned by the same narrow search (the sentence alone, then its rivals)."""
        assert self._grammar is not None
        jsgf = rival_jsgf(self._grammar, command)
        if jsgf is None:
            return decoded
        self._screen.add_jsgf_string("rival", jsgf)
        rival = self._search("rival", audio)
        self._screen.add_jsgf_string("said", f"#JSGF V1.0;\ngrammar said;\npublic <said> = {decoded.text};")
        said_path = self._search("said", audio)
        if not rival or not said_path:
            return decoded
        said = [s for s in said_path if not s.word.startswith(("<", "[", "("))]
        other = [s.word for s in rival if not s.word.startswith(("<", "[", "("))]
        at = differing([s.word for s in said], other)
        frames = sum(said[i].end - said[i].start + 1 for i in at) or 1
        margin = (sum(s.score for s in said_path) - sum(s.score for s in rival)) / frames
        rival_command = self._grammar.parse(" ".join(other))
        margin += PREFERENCE * (_preferred(self._grammar, command) - _preferred(self._grammar, rival_command))
        return replace(decoded, alternative=" ".join(other), margin=margin)

    def _search(self, search: str, audio: bytes) -> list[_Segment]:
        """The segments of the screen decoder's best path of ``search`` through ``audio``, in natural log units."""
        self._screen.activate_search(search)
        return [_Segment(_VARIANT.sub("", s.word), s.start_frame, s.end_frame,
                         self._logmath.log_to_ln(self._logmath.log(s.ascore)) * SCALE if s.ascore > 0 else -1e9)
                for s in _run(self._screen, audio) if s.end_frame >= s.start_frame]


@dataclass(frozen=True, slots=True)
class _Segment:
    word: str
    start: int
    end: int
    score: float


def _preferred(grammar: SpeechGrammar, command: Command | None) -> int:
    """How many of ``command``'s names the user gave (labels, vocabulary files) rather than the defaults."""
    if command is None:
        return 0
    names = [command.label] if isinstance(command, LabelCommand) else [command.subject, command.object]
    return sum(1 for n in names if n is not None and n in grammar.preferred)


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
