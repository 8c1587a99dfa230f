"""The synthesised fixtures (tests/speech/, scripts/make_speech_fixtures.py) through `physink listen`'s path with the
embedded pocketsphinx recogniser: each is recognised to its command or rejected; no microphone is needed.

The fixtures the recogniser gets wrong today are listed (strict xfail: one that starts passing must leave the
list; revisited for issue 29's thresholds, calibrated across four synthesisers: one more is rejected, none heard
wrong). Accuracy and real-time figures are benchmarks/bench_speech.py's (docs/BENCHMARKS.md).
"""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path

import pytest

from physink_tui.input.speech.audio import read_wav
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.listener import Listener, Utterance

SPEECH = Path(__file__).parent / "speech"
MANIFEST = json.loads((SPEECH / "manifest.json").read_text())
FIXTURES = {f["file"]: f for f in MANIFEST["fixtures"]}

MISHEARD = {  # rejected although a command was said (synthetic voices the model hears badly, or heavy noise)
    "cmd10_1.wav", "cmd11_0.wav", "cmd12_0.wav", "cmd12_1.wav", "cmd13_0.wav", "cmd14_0.wav",
    "cmd14_1.wav", "cmd17_1.wav",
    "cmd06_1.wav",  # "label spring" heard, but "spring" scores -4.11 against the -4.0 calibrated across synthesisers
}
WRONGLY_APPLIED = {  # a command other than the one said (or one for out-of-grammar speech) passed every check
    "cmd09_1.wav",  # "the ball falls" heard as "the ball fills" (posterior 0.83, -3.8 per frame; clean, it is heard)
}


@cache
def results() -> dict[str, Utterance]:
    listener = Listener(make_recogniser(), MANIFEST["labels"])
    return {name: listener.hear(read_wav(SPEECH / name)) for name in FIXTURES}


def _got(name: str) -> dict | None:
    command = results()[name].command
    return None if command is None else command.as_json()


@pytest.mark.slow
@pytest.mark.parametrize("name", [
    pytest.param(n, marks=pytest.mark.xfail(strict=True, reason="misheard")) if n in MISHEARD | WRONGLY_APPLIED
    else n for n in FIXTURES])
def test_each_fixture_gives_its_command_or_is_rejected(name: str) -> None:
    fixture = FIXTURES[name]
    utterance = results()[name]
    assert _got(name) == fixture["command"], (fixture["made"], fixture["text"], utterance.text, utterance.rejected)
    assert (utterance.rejected is None) == (fixture["command"] is not None)


@pytest.mark.slow
def test_no_other_command_is_applied_and_accuracy_holds() -> None:
    wrong = {n for n, f in FIXTURES.items() if _got(n) is not None and _got(n) != f["command"]}
    right = [n for n, f in FIXTURES.items() if _got(n) == f["command"]]
    assert wrong <= WRONGLY_APPLIED
    assert len(right) / len(FIXTURES) >= 0.82


@pytest.mark.slow
def test_silence_noise_and_hum_are_rejected_with_a_reason() -> None:
    for name in ("silence.wav", "white_noise.wav", "hum.wav", "bursts.wav"):
        utterance = results()[name]
        assert utterance.command is None and utterance.rejected, name
    assert results()["silence.wav"].rejected == "no speech"
