"""Picks a recogniser backend and imports it only then (pocketsphinx by default, vosk with a model directory);
the backends themselves and what their results mean are left to their modules and the listener."""

from __future__ import annotations

from physink_tui.input.speech.recogniser import Recogniser


def make_recogniser(vosk_model: str | None = None) -> Recogniser:
    """The embedded pocketsphinx recogniser, or vosk with the model in the directory ``vosk_model``.

    Raises:
        SpeechError: the backend is not installed, or the model directory cannot be used.
    """
    if vosk_model is not None:
        from physink_tui.input.speech.vosk_backend import VoskRecogniser

        return VoskRecogniser(vosk_model)
    from physink_tui.input.speech.pocketsphinx_backend import PocketsphinxRecogniser

    return PocketsphinxRecogniser()
