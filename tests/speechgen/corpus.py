"""The corpus: which sentence each family says in which voice setting and condition, what it must give, and making
the recordings (cached in a folder with a manifest); decoding them is the benchmark's and the tests' job.

Every family says every sentence (`sentences`) `REPEATS` times, each time in the next of its voice settings
(`voices.voice_settings`) and the next condition: half clean (a quiet room), half with pink, white or babble noise at
20-30 dB SNR. The first round of commands and near-misses is also made under one degraded condition each (reported,
not a goal), and each family has recordings with no speech (silence, noise, hum, and its own speech played
backwards). Seeded: the same synthesisers give the same corpus.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Iterator
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from physink_tui.input.speech.audio import read_wav, to_int16, write_wav
from physink_tui.input.speech.grammar import SpeechGrammar
from speechgen import conditions, sentences, voices

REPEATS = {"espeak-ng": 8, "flite": 4, "festival": 4, "pico": 4}
CONDITIONS = ("clean", "pink 20", "clean", "white 25", "clean", "babble 20", "clean", "pink 30")
"""Conditions by turns: half clean, half noise at >= 20 dB SNR (the goals' conditions)."""
KINDS = ("command", "near-miss", "out-of-grammar", "non-speech")
DEFAULT_DIR = Path.home() / ".cache" / "physink" / "speech-corpus"


@dataclass(frozen=True, slots=True)
class Item:
    """One recording of the corpus.

    Attributes:
        id: its file's stem, unique.
        family: the synthesiser (for no-speech recordings, the family whose fold they belong to).
        kind: one of `KINDS`.
        text: what was said, or what the recording is (no speech).
        voice: the voice setting (`voices.Voice.describe`), "" for no speech.
        condition: "clean", "<noise> <SNR>", one of `conditions.DEGRADED`, or "backwards".
        degraded: whether the condition is one reported beside the goals rather than one of them.
        command: the command it must give (`Command.as_json`), None when it must be rejected.
    """

    id: str
    family: str
    kind: str
    text: str
    voice: str
    condition: str
    degraded: bool
    command: dict | None


def _grammar() -> SpeechGrammar:
    return SpeechGrammar.build(sentences.LABELS)


def plan(families: tuple[str, ...] = voices.FAMILIES,
         repeats: dict[str, int] | None = None) -> list[tuple[Item, voices.Voice | None]]:
    """Every item of the corpus with the voice that says it (None for no speech), in a fixed order."""
    grammar, repeats = _grammar(), repeats or REPEATS
    said = ([(t, "command") for t in sentences.COMMANDS] + [(t, "near-miss") for t in sentences.NEAR_MISSES]
            + [(t, "out-of-grammar") for t in sentences.OUT_OF_GRAMMAR])
    out: list[tuple[Item, voices.Voice | None]] = []
    for family in families:
        settings = voices.voice_settings(family)
        n = 0
        for rep in range(repeats[family]):
            for i, (text, kind) in enumerate(said):
                voice = settings[n % len(settings)]
                condition = CONDITIONS[n % len(CONDITIONS)]
                parsed = grammar.parse(text)
                command = None if parsed is None or kind == "out-of-grammar" else parsed.as_json()
                item = Item(f"{family}-{rep}-{i:02d}", family, kind, text, voice.describe(), condition, False, command)
                out.append((item, voice))
                if rep == 0 and kind != "out-of-grammar":
                    how = conditions.DEGRADED[i % len(conditions.DEGRADED)]
                    out.append((Item(f"{family}-{rep}-{i:02d}-{how}", family, kind, text, voice.describe(), how, True,
                                     command), voice))
                n += 1
        for k, what in enumerate(conditions.NON_SPEECH * 2):
            out.append((Item(f"{family}-none-{k:02d}", family, "non-speech", what, "", what, False, None), None))
        for k in range(6):
            text = sentences.COMMANDS[(7 * k + 3) % len(sentences.COMMANDS)]
            voice = settings[(11 * k + 5) % len(settings)]
            out.append((Item(f"{family}-backwards-{k}", family, "non-speech", text, voice.describe(), "backwards",
                             False, None), voice))
    return out


def _seed(item_id: str) -> np.random.Generator:
    return np.random.default_rng(int.from_bytes(hashlib.sha256(item_id.encode()).digest()[:8], "little"))


def record(item: Item, voice: voices.Voice | None) -> np.ndarray:
    """The recording of ``item`` as int16 samples at 16 kHz."""
    rng = _seed(item.id)
    if voice is None:
        return to_int16(conditions.non_speech(item.text, rng))
    speech = conditions.trimmed(voices.synthesise(item.text, voice))
    if item.condition == "backwards":
        speech = speech[::-1]
    audio = conditions.in_room(speech, rng)
    if item.degraded:
        audio = conditions.degrade(audio, item.condition, rng)
    elif item.condition != "clean" and item.condition != "backwards":
        kind, snr = item.condition.split()
        babble = None
        if kind == "babble":
            other = sentences.OUT_OF_GRAMMAR[len(item.id) % len(sentences.OUT_OF_GRAMMAR)]
            babble = conditions.trimmed(voices.synthesise(other, voice))
        audio = conditions.with_noise(audio, float(snr), kind, rng, babble)
    return to_int16(audio)


def make(folder: Path, items: list[tuple[Item, voices.Voice | None]], progress: bool = False) -> list[Item]:
    """Record every item not yet in ``folder`` (``<id>.wav``) and write ``manifest.json``; returns the items."""
    folder.mkdir(parents=True, exist_ok=True)
    for n, (item, voice) in enumerate(items):
        path = folder / f"{item.id}.wav"
        if not path.exists():
            tmp = path.with_suffix(".tmp")
            write_wav(tmp, record(item, voice))
            tmp.rename(path)
        if progress and n % 100 == 0:
            print(f"{n}/{len(items)}", flush=True)
    done = [item for item, _ in items]
    (folder / "manifest.json").write_text(json.dumps({"labels": list(sentences.LABELS),
                                                      "items": [asdict(i) for i in done]}, indent=0) + "\n")
    return done


def load(folder: Path, shard: tuple[int, int] = (0, 1)) -> Iterator[tuple[Item, np.ndarray]]:
    """The items of a corpus made by `make` (of shard ``i`` of ``n``: every n-th from the i-th), with samples."""
    manifest = json.loads((folder / "manifest.json").read_text())
    for entry in manifest["items"][shard[0]::shard[1]]:
        item = Item(**entry)
        yield item, read_wav(folder / f"{item.id}.wav")
