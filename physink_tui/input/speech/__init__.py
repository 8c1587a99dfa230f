"""Speech input: recordings and the microphone to grammar-restricted commands, offline; acting on them is the
session's.

One utterance goes one way whatever brought it: `physink listen FILE.wav` and the microphone both call
`Listener.hear(samples, began)`. The session never sees audio: a recognised utterance reaches it as a `say` entry
(text), so a replay needs no audio and no recogniser.

     WAV file ── audio.read_wav (any PCM rate/width/channels → 16 kHz mono int16, FFT resampling)
     microphone ── microphone.MicrophoneListener (sounddevice RawInputStream, 50 ms blocks, own thread)
                     └─ vad.VoiceActivityDetector (energy over a tracked noise floor) cuts utterances
            ▼
     listener.Listener.hear: vad.speech_bounds → no speech? rejected
            → Recogniser.decode (grammar-restricted) → outside the grammar? not a whole sentence
              (grammar.parse)? a word's acoustic score under the threshold? a word's posterior too low? rejected
            → a rival sentence (one name or the verb other) fitting nearly as well? rejected naming both
            → Utterance(text, command, rejected, began)
                 ── `physink listen` prints {"text", "command", "rejected"};
                    a TUI submits accepted text with SessionRunner.say(text, began)

- `wav_file.py`: a WAV file's RIFF chunks parsed by hand (Python 3.11's `wave` refuses WAVE_FORMAT_EXTENSIBLE and
  passes a truncated file's partial frames on silently): plain and extensible PCM of 8-32 bits, any channels; a file
  cut off inside its header or its samples, or a header with no samples, named as such
- `grammar.py`: `SpeechGrammar.build(labels, vocabulary, speakable=)`: names (labels, `DEFAULT_COMPONENTS`,
  vocabulary-file `component` lines), the phrase verbs and prepositions (plus a few spoken pairs, "out of"), words
  the recogniser cannot say left out and listed; `preferred`: the names the user gave (labels, vocabulary files);
  `jsgf()` (`label <component>` or `[the] <component> <verb>
  [[<prep>] [the] <component>]`, an article never on both sides of a word, optionally a weighted garbage loop);
  `parse(text)` → `LabelCommand` / `PhraseCommand` or None
- `rivals.py`: `rival_jsgf(grammar, command)`: JSGF of the sentences that differ from a command in exactly one name
  or the verb (issue 29); `differing`
- `recogniser.py`: the `Recogniser` protocol (`speakable`, `set_grammar`, `decode` → `Decoded` of `Word`s with
  times, acoustic score and posterior, and the best rival sentence with the margin to it; `threshold`,
  `min_confidence`, `min_margin`), `backends.make_recogniser(vosk_model=None)`
  importing the backend lazily (its own module, so the backends importing the contract make no cycle)
- `pocketsphinx_backend.py`: the default: pocketsphinx 5 and its bundled en-us model. Two decoders share the grammar:
  the *screen* also has a loop of single phones at weight 0.01 (speech outside the grammar takes the loop: rejected),
  the *words* decoder gives the best sentence with lattice posteriors (the loop makes lattices huge, so it is not in
  this one). British variants (non-rhotic, broad A) are added to every grammar word; a word the dictionary lacks gets
  `letter_to_sound.pronounce`'s guess. Each decode resets the front end (noise estimate, cepstral mean) and gives it the
  whole utterance at once, so the model's batch cepstral mean comes from this audio alone (one pass; seeded one-bit
  dither, and a quiet room's floor in digital silence): a result depends on its audio only (tests and replays agree). A
  command whose words score well enough is aligned by the screen decoder once alone and once against its rivals
  (`rivals.py`): `Decoded.margin` is the difference per frame of the words that differ, plus `PREFERENCE` a frame for
  each name the user gave against a default one
- `vosk_backend.py`: `--vosk-model DIR`: a `KaldiRecognizer` in grammar mode given the grammar's speakable words
  (and `[unk]` when the model has it); the listener's parser enforces the sentence shape; `parse_result` reads
  vosk's JSON
- `listener.py`: `Listener` (keeps the recogniser on the grammar of the current labels, rebuilt only when they
  change) and `Utterance`; a command whose rival fits nearly as well (margin under `min_margin`, or an unsure word
  the rival replaces) is rejected as "heard 'label pear' or 'label pair'? say it again"
- `vad.py`: `VoiceActivityDetector` (streaming, 10 ms frames, noise floor over 3 s, 12 dB above it and 40 dB
  absolute, 80 ms to start, 0.5 s of quiet to end, 0.25 s padding) and `speech_bounds` for a whole recording;
  reusable by the kiosk
- `microphone.py`: `MicrophoneListener(listener, on_utterance, clock=, stream=)`: `start()` / `stop()`
  (push-to-talk: `stop` ends and hears the utterance under way), `on_utterance` called on the listening thread with
  `Utterance.began` on `clock`'s scale; `sounddevice_stream(device)`: no PortAudio or no device is a
  `MicrophoneError` at `start()`
- `letter_to_sound.py`: `pronounce(word)`: ARPAbet phones guessed from English spelling by rules of our own
  (digraphs, soft c/g, silent final e, r-coloured vowels, `-s`/`-es`/`-ed`/`-ing` endings, letter names for single
  letters), None for words not spelled with letters; about 9 % of phones wrong on the grammar's own words, 20 % on
  dictionary words at large (tests/test_speech_letter_to_sound.py)
- `audio.py`, `dictionary.py`: WAV reading, resampling, writing; whether a typed label's words are in the speech
  dictionary, or guessed, or not speakable

The thresholds (`pocketsphinx_backend.THRESHOLD`, `MIN_CONFIDENCE`, `MIN_MARGIN`) are calibrated by
`benchmarks/bench_speech_corpus.py` on a corpus of four synthesisers (espeak-ng, flite, festival, SVOX Pico; made by
`scripts/make_speech_corpus.py` from `tests/speechgen/`, cached outside the repository), each family scored with
thresholds chosen on the other three, and shipped among those that keep issue 16's fixtures (`tests/speech/`, made by
`scripts/make_speech_fixtures.py`) at their test's floor; `GARBAGE_WEIGHT` 0.01 and `vosk_backend.THRESHOLD` 0.65 are
issue 16's. `benchmarks/bench_speech_pipeline.py` compares a plain pocketsphinx decoder with this pipeline one
difference at a time. `benchmarks/bench_speech.py` measures the fixtures' accuracy and real-time factors
(docs/BENCHMARKS.md); `tests/test_speech_voices.py` hears a sample of every family, made at test time.

The journal's `t` never decreases, so a live `say` is stamped with the time the utterance began only where no later
entry has been stamped yet (`StampingInbox.put(entry, at=)`); otherwise it is stamped when it arrives.
"""
