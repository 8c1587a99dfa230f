"""`physink listen FILE.wav`: one utterance to JSON through the microphone's path; errors name the file."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physink_tui import cli

SPEECH = Path(__file__).parent / "speech"


def _listen(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, dict | None, str]:
    status = cli.main(["listen", *argv])
    out, err = capsys.readouterr()
    return status, (json.loads(out) if out.strip() else None), err


def test_a_sentence_prints_its_command(capsys: pytest.CaptureFixture[str]) -> None:
    status, printed, _ = _listen(capsys, str(SPEECH / "cmd18_0.wav"), "--labels", "platform a")
    assert status == 0
    assert printed == {"text": "the ball bounces off platform a", "rejected": None, "command": {
        "kind": "phrase", "text": "the ball bounces off platform a", "subject": "ball", "verb": "bounces",
        "preposition": "off", "object": "platform a"}}


def test_a_label_the_grammar_lacks_is_not_heard(capsys: pytest.CaptureFixture[str]) -> None:
    status, printed, _ = _listen(capsys, str(SPEECH / "cmd05_0.wav"))  # "label paddle b": no such label now
    assert status == 0 and printed is not None
    assert printed["command"] != {"kind": "label", "label": "paddle b"}


def test_silence_is_rejected(capsys: pytest.CaptureFixture[str]) -> None:
    assert _listen(capsys, str(SPEECH / "silence.wav")) == (0, {"text": "", "command": None,
                                                                "rejected": "no speech"}, "")


def test_an_unspeakable_label_is_told_on_stderr(capsys: pytest.CaptureFixture[str]) -> None:
    status, printed, err = _listen(capsys, str(SPEECH / "cmd00_0.wav"), "--labels", "r2d2,ball")
    assert status == 0 and printed is not None and printed["command"] == {"kind": "label", "label": "ball"}
    assert "not speakable" in err and "r2d2" in err


def test_a_label_the_dictionary_lacks_is_said_as_guessed_and_told(capsys: pytest.CaptureFixture[str]) -> None:
    status, printed, err = _listen(capsys, str(SPEECH / "cmd00_0.wav"), "--labels", "Zorblaxx,ball")
    assert status == 0 and printed is not None and printed["command"] == {"kind": "label", "label": "ball"}
    assert "not speakable" not in err and "guessed from the spelling: zorblaxx (Z AO R B L AH K S)" in err


def test_a_broken_wav_is_one_line_and_exit_1(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    bad = tmp_path / "bad.wav"
    bad.write_bytes(b"RIFF....WAVEjunk")
    status, printed, err = _listen(capsys, str(bad))
    assert status == 1 and printed is None
    assert err.startswith(f"physink: {bad}: not a PCM WAV file") and err.count("\n") == 1
    status, _, err = _listen(capsys, str(tmp_path / "none.wav"))
    assert status == 1 and "cannot read the recording" in err
