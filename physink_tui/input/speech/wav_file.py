"""Parses a WAV file's RIFF chunks into its PCM format and sample bytes, naming what is wrong with a broken one;
converting and resampling the samples is `audio`'s.

Python's `wave` module (3.11) refuses WAVE_FORMAT_EXTENSIBLE (format tag 65534, what sox and ffmpeg write for
24- and 32-bit or more than two channels) and hands back a truncated file's partial frames without a word. This
reader takes plain PCM (tag 1) and extensible PCM (its sub-format GUID's first two bytes 1), and says when a file
ends inside its header, holds a header and no samples, or is cut off inside its samples. A data chunk declaring
0 or 0xFFFFFFFF bytes (a WAV written to a pipe) holds the rest of the file.

>>> import struct
>>> fmt = struct.pack("<HHIIHH", 1, 1, 16000, 32000, 2, 16)
>>> raw = b"RIFF" + struct.pack("<I", 40) + b"WAVE" + b"fmt " + struct.pack("<I", 16) + fmt + b"data" + \\
...     struct.pack("<I", 4) + b"\\x01\\x00\\x02\\x00"
>>> parse_wav(raw)
WavData(channels=1, width=2, rate=16000, pcm=b'\\x01\\x00\\x02\\x00')
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

PCM = 1
EXTENSIBLE = 0xFFFE
STREAMED = (0, 0xFFFFFFFF)
"""Data chunk sizes that mean "to the end of the file" (a writer that could not seek back)."""
NAMES = {3: "IEEE float", 6: "A-law", 7: "mu-law", 0x11: "IMA ADPCM", 0x55: "MP3", 2: "Microsoft ADPCM"}


class WavProblem(ValueError):
    """What is wrong with a WAV file, in words (`audio.read_wav` adds the file's name)."""


@dataclass(frozen=True, slots=True)
class WavData:
    """A WAV file's PCM samples: ``channels`` interleaved, ``width`` bytes each (little-endian; 8-bit unsigned),
    ``rate`` frames a second; ``pcm`` holds whole frames only."""

    channels: int
    width: int
    rate: int
    pcm: bytes


def parse_wav(raw: bytes) -> WavData:
    """The format and samples of the WAV file ``raw``.

    Raises:
        WavProblem: the file is no RIFF/WAVE file, ends inside its header, is no PCM, holds no samples (a header
            only) or is cut off inside its samples (each said in those words).
    """
    if len(raw) < 12:
        if raw[:4] == b"RIFF"[: len(raw)]:
            raise WavProblem("not a PCM WAV file (it ends inside its header: the file is cut off)")
        raise WavProblem("not a PCM WAV file (it does not start with RIFF....WAVE)")
    if raw[:4] != b"RIFF" or raw[8:12] != b"WAVE":
        raise WavProblem("not a PCM WAV file (it does not start with RIFF....WAVE)")
    fmt: WavData | None = None
    at = 12
    while at + 8 <= len(raw):
        chunk, size = raw[at:at + 4], struct.unpack_from("<I", raw, at + 4)[0]
        body = at + 8
        if chunk == b"fmt ":
            if body + size > len(raw) or size < 16:
                raise WavProblem("not a PCM WAV file (it ends inside its header: the file is cut off in the fmt "
                                 "chunk)" if body + size > len(raw) else f"not a PCM WAV file (its fmt chunk is "
                                 f"{size} bytes; expected at least 16)")
            fmt = _format(raw[body:body + size])
        elif chunk == b"data":
            if fmt is None:
                raise WavProblem("not a PCM WAV file (its data chunk comes before any fmt chunk)")
            held = len(raw) - body
            length = held if size in STREAMED else size
            if held == 0 or length == 0:
                cut = f", though its data chunk declares {size} bytes: the file was cut off after its header" if (
                    length > 0) else ""
                raise WavProblem(f"a WAV header with no samples (the recording is empty{cut})")
            if length > held:
                raise WavProblem(f"the recording is cut off: its data chunk declares {size} bytes and the file holds "
                                 f"{held} (the file was truncated)")
            frame = fmt.channels * fmt.width
            if length % frame:
                raise WavProblem(f"the recording is cut off inside a sample: {length} bytes of data is not a whole "
                                 f"number of {frame}-byte frames (the file was truncated)")
            return WavData(fmt.channels, fmt.width, fmt.rate, raw[body:body + length])
        at = body + size + (size & 1)
    if fmt is None:
        if at != len(raw):
            raise WavProblem("not a PCM WAV file (it ends inside its header: the file is cut off)")
        raise WavProblem("not a PCM WAV file (it has no fmt chunk)")
    raise WavProblem("a WAV header with no samples (no data chunk: the recording is empty or the file was cut off "
                     "after its header)")


def _format(chunk: bytes) -> WavData:
    tag, channels, rate, _, _, bits = struct.unpack_from("<HHIIHH", chunk)
    if tag == EXTENSIBLE:
        if len(chunk) < 40:
            raise WavProblem(f"not a PCM WAV file (an extensible format chunk of {len(chunk)} bytes; expected 40)")
        tag = struct.unpack_from("<H", chunk, 24)[0]  # the sub-format GUID begins with the format tag
    if tag != PCM:
        raise WavProblem(f"not a PCM WAV file (its samples are {NAMES.get(tag, f'format {tag}')}); expected PCM "
                         "samples")
    if bits not in (8, 16, 24, 32) or channels < 1:
        raise WavProblem(f"unsupported WAV: {channels} channel(s), {bits}-bit; expected 8, 16, 24 or 32-bit PCM")
    return WavData(channels, bits // 8, rate, b"")
