"""Voices the thresholds were not chosen on (issue 29): a sample of every synthesiser family of the corpus
(tests/speechgen: espeak-ng, flite, festival, SVOX Pico), made at test time, through `physink listen`'s path. Other
speech and noise are rejected, a share of the commands is heard, and no wrong command is applied but the ones listed
(the thresholds are held at issue 16's fixture floor, which lets about 5 % through on these voices). The full table per
family, with thresholds calibrated leaving the family out, is benchmarks/bench_speech_corpus.py's (docs/BENCHMARKS.md).
The synthesisers come from scripts/setup.sh and the test extra (py-nanotts)."""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest
from speechgen import conditions, corpus, sentences, voices

from physink_tui.input.speech.audio import RATE, to_int16
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.listener import Listener, Utterance

NEAR = ("label bell", "the bell falls", "label packet", "the ball sings")
HEARD_AT_LEAST = {"espeak-ng": 1, "flite": 3, "festival": 2, "pico": 2}
"""Commands of the sample (8 a family) heard right, at least (measured on this sample; the rest are rejected)."""
WRONGLY_APPLIED = {  # wrong commands the shipped thresholds let through on this sample (docs/BENCHMARKS.md: about 5 %)
    "espeak-ng": {"espeak-ng-8-55"},  # "the ball sings" (no such verb) heard as "the ball sinks"
    "flite": {"flite-4-47"},  # "label packet" heard as "label paddle"
    "festival": {"festival-4-00", "festival-4-44"},  # "label ball" as "label block", "label bell" as "label rope"
    "pico": {"pico-4-35"},  # "the hammer strikes the egg" (pink noise, 30 dB) as "... the pan"
}


def _planned(family: str) -> list[tuple[corpus.Item, voices.Voice | None]]:
    """The family's round after the corpus's last (other voice settings and noise draws: none of it calibrated on)."""
    rounds = corpus.REPEATS[family] + 1
    return [p for p in corpus.plan((family,), {family: rounds}) if p[0].id.startswith(f"{family}-{rounds - 1}-")
            or p[0].kind == "non-speech"]


def sample(family: str) -> list[corpus.Item]:
    """Eight commands, four near-misses, three other sentences and five recordings without speech (noise, a hum,
    speech played backwards), clean and noisy by turns."""
    planned = [item for item, _ in _planned(family) if not item.degraded]
    commands = [i for i in planned if i.kind == "command"][::5][:8]
    near = [i for i in planned if i.text in NEAR]
    other = [i for i in planned if i.kind == "out-of-grammar"][::4]
    none = [i for i in planned if i.kind == "non-speech" and i.condition in ("white noise", "hum", "backwards")]
    return commands + near + other + none[:5]


@cache
def heard(family: str) -> dict[str, tuple[corpus.Item, Utterance]]:
    if not voices.available(family):
        pytest.fail(f"{family} cannot synthesise here: run scripts/setup.sh (and pip install -e '.[test]')")
    listener = Listener(make_recogniser(), sentences.LABELS)
    wanted = {item.id for item in sample(family)}
    out = {}
    for item, voice in _planned(family):
        if item.id in wanted:
            out[item.id] = (item, listener.hear(corpus.record(item, voice)))
    return out


def meaning(command: dict | None) -> dict | None:
    return None if command is None else {k: v for k, v in command.items() if k != "text"}


@pytest.mark.slow
@pytest.mark.parametrize("family", voices.FAMILIES)
def test_no_wrong_command_is_applied_but_the_known_ones(family: str) -> None:
    wrong = {item.id for item, u in heard(family).values()
             if u.command is not None and meaning(u.command.as_json()) != meaning(item.command)}
    assert wrong == WRONGLY_APPLIED[family]  # one fixed must leave the list too


@pytest.mark.slow
@pytest.mark.parametrize("family", voices.FAMILIES)
def test_other_speech_and_noise_are_rejected_with_a_reason(family: str) -> None:
    others = [(item, u) for item, u in heard(family).values() if item.kind in ("out-of-grammar", "non-speech")]
    assert len(others) >= 5
    for item, u in others:
        assert u.command is None and u.rejected, (item.text, item.voice, u.text)


@pytest.mark.slow
@pytest.mark.parametrize("family", voices.FAMILIES)
def test_commands_in_voices_never_calibrated_on_are_heard(family: str) -> None:
    commands = [(item, u) for item, u in heard(family).values() if item.kind == "command"]
    right = [item.text for item, u in commands if u.command and meaning(u.command.as_json()) == meaning(item.command)]
    assert len(commands) == 8
    assert len(right) >= HEARD_AT_LEAST[family], [(i.text, i.voice, u.text, u.rejected) for i, u in commands]


@pytest.mark.slow
def test_a_command_padded_with_digital_silence_is_heard() -> None:
    """A file whose speech is padded with exact zeros (a synthesiser's or an editor's output) is heard like one over a
    quiet room: the recogniser fills digital silence with a room's noise floor (one bit of dither was not enough)."""
    if not voices.available("espeak-ng"):
        pytest.fail("espeak-ng cannot synthesise here: run scripts/setup.sh")
    speech = conditions.trimmed(voices.synthesise("label platform", voices.Voice("espeak-ng", "en-us+adam", 175, 50)))
    edge = np.zeros(round(0.3 * RATE))
    u = Listener(make_recogniser(), sentences.LABELS).hear(to_int16(np.concatenate([edge, speech, edge])))
    assert u.command is not None and u.command.as_json() == {"kind": "label", "label": "platform"}, u.rejected
