"""Decoders for the tests of the terminal graphics encoders: parse Kitty APC escapes and Sixel DCS strings back to
pixels, checking their form on the way (each raises AssertionError naming what is malformed)."""

from __future__ import annotations

import base64
import re

import numpy as np

from physink_tui.render import kitty, sixel
from physink_tui.render.images import decode_png

APC = re.compile(r"\x1b_G([^;\x1b]*)(?:;([A-Za-z0-9+/=]*))?\x1b\\")


def kitty_commands(text: str) -> list[tuple[dict[str, str], str]]:
    """Each APC graphics command of ``text`` as (keys, payload); the whole text must be such commands."""
    commands, at = [], 0
    for match in APC.finditer(text):
        assert match.start() == at, f"stray bytes before offset {match.start()}: {text[at:match.start()]!r}"
        keys = dict(pair.split("=", 1) for pair in match.group(1).split(","))
        commands.append((keys, match.group(2) or ""))
        at = match.end()
    assert at == len(text), f"stray bytes at the end: {text[at:at + 40]!r}"
    return commands


def kitty_image(text: str) -> tuple[dict[str, str], np.ndarray]:
    """The first command's keys and the RGBA pixels a chunked ``a=T`` transmission carries."""
    commands = kitty_commands(text)
    first = commands[0][0]
    assert first["a"] == "T" and first["f"] == "100", first
    for k, (keys, payload) in enumerate(commands):
        assert len(payload) <= kitty.CHUNK, f"chunk {k} has {len(payload)} bytes"
        assert keys["m"] == ("1" if k < len(commands) - 1 else "0"), f"chunk {k}: m={keys['m']}"
        assert k == 0 or set(keys) == {"m"}, f"chunk {k} repeats keys: {keys}"
    data = base64.standard_b64decode("".join(payload for _, payload in commands))
    return first, decode_png(data)


def sixel_image(text: str) -> np.ndarray:
    """The RGB pixels (height, width, 3) of one Sixel image (colours as its registers give them, 0..255)."""
    assert text.startswith(sixel.DCS_START) and text.endswith(sixel.ST), text[:20]
    body = text[len(sixel.DCS_START):-len(sixel.ST)]
    raster = re.match(r'"1;1;(\d+);(\d+)', body)
    assert raster, f"no raster attributes: {body[:30]!r}"
    width, height = int(raster.group(1)), int(raster.group(2))
    body = body[raster.end():]
    registers: dict[int, tuple[int, int, int]] = {}
    image = np.full((height + 6, width, 3), -1, np.int32)
    x = y = 0
    colour: int | None = None
    for token in re.finditer(r"#(\d+)(?:;2;(\d+);(\d+);(\d+))?|!(\d+)([?-~])|([?-~])|(\$)|(-)|(.)", body, re.S):
        number, r, g, b, count, run_char, char, cr, nl, other = token.groups()
        assert other is None, f"unexpected {other!r} in the sixel data"
        if number is not None and r is not None:
            registers[int(number)] = tuple(round(int(v) * 255 / 100) for v in (r, g, b))
        elif number is not None:
            colour = int(number)
            assert colour in registers, f"colour {colour} used before it is defined"
        elif cr:
            x = 0
        elif nl:
            x, y = 0, y + 6
        else:
            n, c = (int(count), run_char) if count else (1, char)
            bits = ord(c) - 63
            assert colour is not None and x + n <= width, f"column {x + n} past the width {width}"
            for k in range(6):
                if bits >> k & 1:
                    image[y + k, x:x + n] = registers[colour]
            x += n
    assert (image[:height] >= 0).all(), "pixels left unpainted"
    return image[:height].astype(np.uint8)
