"""Turns RGBA frames into encoded packets in an open PyAV container for one VideoSpec; no threads, no file naming."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import av
import numpy as np
from av.video.reformatter import VideoReformatter

from physink_tui.render.gif_palette import Palette
from physink_tui.render.video_spec import VideoSpec

X264_PRESET = "ultrafast"
"""x264 speed preset: at 1920x1080 only "ultrafast" keeps the whole export 3x faster than real time on two cores
(benchmarks/bench_video.py); drawings are flat colours, so the file stays small all the same."""

X264_CRF = "20"
"""x264 constant quality (lower is better; 18-23 is visually clean for line drawings)."""

VP9_OPTIONS = {"deadline": "realtime", "cpu-used": "8", "row-mt": "1", "crf": "32", "b": "0"}
"""libvpx-vp9 in its fastest mode at constant quality (``b`` 0 lifts the bit-rate cap so ``crf`` rules)."""

ENCODER_THREADS = 0
"""Encoder threads (0: the encoder decides, two on two cores); see benchmarks/bench_video.py for the comparison."""

SCALER_THREADS = 1
"""Threads swscale uses for RGBA->yuv420p; one, because the drawing thread already keeps the other core busy."""


class FrameEncoder:
    """Encodes one video stream: `stage` copies a caller's frame into a pooled buffer (the caller may then reuse
    its array), `encode` converts a staged buffer and muxes the packets, `finish` flushes the encoder.

    `stage` and `encode` may run on different threads; the caller must not stage into a buffer that is still
    being encoded (`write_video` keeps a pool of buffers for that).
    """

    def __init__(self, container: Any, spec: VideoSpec) -> None:
        self.container = container
        self.spec = spec
        kind = spec.container
        rate = spec.output_fps
        if kind.codec == "libx264":
            options = {"preset": X264_PRESET, "crf": X264_CRF}
        elif kind.codec == "libvpx-vp9":
            options = dict(VP9_OPTIONS)
        else:
            options = {}
        self.stream = container.add_stream(kind.codec, rate=rate, options=options)
        self.stream.width = spec.width
        self.stream.height = spec.height
        self.stream.pix_fmt = kind.pix_fmt
        context = self.stream.codec_context
        context.time_base = Fraction(1, rate)
        if kind.pix_fmt == "yuv420p":
            context.thread_count = ENCODER_THREADS
            # swscale's default RGB->YUV matrix is BT.601 with limited range: say so, or players guess BT.709.
            context.colorspace = 6  # AVCOL_SPC_SMPTE170M
            context.color_range = 1  # AVCOL_RANGE_MPEG
            context.color_primaries = 1  # AVCOL_PRI_BT709, the sRGB primaries
            context.color_trc = 1  # AVCOL_TRC_BT709
        self.is_gif = kind.format == "gif"
        self.time_base = Fraction(1, rate)
        self.reformatter = VideoReformatter()
        self.palette: Palette | None = None
        self.frames = 0

    def new_buffer(self) -> tuple[Any, np.ndarray]:
        """A reusable staging buffer: (PyAV frame or None, a writable (H, W, 4) uint8 view of its pixels)."""
        height, width = self.spec.height, self.spec.width
        if self.is_gif:
            return None, np.empty((height, width, 4), np.uint8)
        frame = av.VideoFrame(width, height, "rgba")
        plane = frame.planes[0]
        rows = np.frombuffer(plane, np.uint8).reshape(height, plane.line_size)
        return frame, rows[:, : width * 4].reshape(height, width, 4)

    def stage(self, buffer: tuple[Any, np.ndarray], rgba: np.ndarray) -> None:
        """Copies ``rgba`` into ``buffer``; afterwards the caller may overwrite ``rgba``."""
        np.copyto(buffer[1], rgba)

    def encode(self, buffer: tuple[Any, np.ndarray]) -> None:
        """Converts the staged pixels, encodes them as the next frame and muxes what the encoder hands back."""
        frame, pixels = buffer
        if self.is_gif:
            if self.palette is None:
                self.palette = Palette.from_frame(pixels)
            out = av.VideoFrame.from_ndarray((self.palette.indices(pixels), self.palette.argb), format="pal8")
        else:
            out = self.reformatter.reformat(frame, format="yuv420p", threads=SCALER_THREADS)
        out.pts = self.frames
        out.time_base = self.time_base
        self.frames += 1
        self.container.mux(self.stream.encode(out))

    def finish(self) -> None:
        """Flushes the frames the encoder still holds into the container."""
        self.container.mux(self.stream.encode(None))
