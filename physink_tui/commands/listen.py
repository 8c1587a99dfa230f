"""`physink listen FILE.wav`: one recorded utterance through the microphone's path, printed as JSON; no session.

Prints ``{"text", "command", "rejected"}`` (DESIGN.md) and, on stderr, the grammar's words the recogniser cannot
say, and those it says with a pronunciation guessed from their spelling (a label the dictionary lacks is still
accepted when typed).
"""

from __future__ import annotations

import argparse
import json
import sys

from physink_tui.commands.input_file import read_bytes
from physink_tui.input.speech.audio import read_wav
from physink_tui.input.speech.backends import make_recogniser
from physink_tui.input.speech.grammar import normalise
from physink_tui.input.speech.listener import Listener


def run(args: argparse.Namespace) -> int:
    samples = read_wav(args.wav, read_bytes(args.wav, "recording"))
    listener = Listener(make_recogniser(args.vosk_model), args.labels or ())
    said = {normalise(label) for label in args.labels or ()}
    unspeakable = [w for w in listener.unspeakable if w in said]
    if unspeakable:
        print(f"physink listen: not speakable with this recogniser's dictionary: {', '.join(unspeakable)}",
              file=sys.stderr)
    guessed = listener.guessed(w for w in said if w not in unspeakable)
    if guessed:
        print("physink listen: not in the dictionary, pronunciation guessed from the spelling: "
              + ", ".join(f"{w} ({p})" for w, p in guessed.items()), file=sys.stderr)
    utterance = listener.hear(samples)
    print(json.dumps(utterance.as_json()))
    return 0
