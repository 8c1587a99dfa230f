"""PNG images of rendered pixels: encoding, decoding, and writing one atomically; no drawing.

Files are written through `formats.atomic_write`, the one place that writes files.
"""

from __future__ import annotations

import os

import numpy as np
import skia

from physink_tui.errors import RenderError
from physink_tui.formats.atomic_write import write_bytes_atomic


def _check(pixels: np.ndarray) -> np.ndarray:
    if not (isinstance(pixels, np.ndarray) and pixels.dtype == np.uint8 and pixels.ndim == 3
            and pixels.shape[2] == 4 and pixels.shape[0] > 0 and pixels.shape[1] > 0):
        shape = getattr(pixels, "shape", None)
        raise RenderError(f"pixels: expected a (height, width, 4) uint8 RGBA array, got {type(pixels).__name__} "
                          f"of shape {shape!r}")
    return np.ascontiguousarray(pixels)


def encode_png(pixels: np.ndarray) -> bytes:
    """PNG bytes of (height, width, 4) uint8 RGBA ``pixels`` (as `Renderer.render` returns them).

    Raises:
        RenderError: ``pixels`` is not such an array, or cannot be encoded.
    """
    image = skia.Image.fromarray(_check(pixels), colorType=skia.kRGBA_8888_ColorType)
    data = image.encodeToData(skia.EncodedImageFormat.kPNG, 100) if image is not None else None
    if data is None:
        raise RenderError(f"pixels of shape {pixels.shape!r} could not be encoded as PNG")
    return bytes(data)


def decode_png(data: bytes) -> np.ndarray:
    """The (height, width, 4) uint8 RGBA pixels of PNG ``data`` (a new array).

    Raises:
        RenderError: ``data`` is not an image skia can decode.
    """
    image = skia.Image.MakeFromEncoded(skia.Data.MakeWithCopy(bytes(data)))
    if image is None:
        raise RenderError(f"not an image skia can decode ({len(data)} bytes starting {bytes(data[:8])!r})")
    return np.array(image.toarray(colorType=skia.kRGBA_8888_ColorType, alphaType=skia.kUnpremul_AlphaType))


def write_png(path: str | os.PathLike[str], pixels: np.ndarray) -> None:
    """Write ``pixels`` as a PNG file at ``path``, atomically (a complete new file or the old one untouched).

    Raises:
        RenderError: the pixels cannot be encoded, or the file cannot be written (naming the path and cause).
    """
    data = encode_png(pixels)
    try:
        write_bytes_atomic(path, data)
    except OSError as exc:
        raise RenderError(f"cannot write {os.fspath(path)!r}: {exc.strerror or exc}") from exc
