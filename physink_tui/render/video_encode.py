"""Turns RGBA frames into encoded packets in an open PyAV container for one VideoSpec; no threads, no file naming."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import av
import numpy as np
from av.video.reformatter import Interpolation, VideoReformatter

from physink_tui.render.gif_palette import Palette
from physink_tui.render.video_spec import VideoSpec

X264_PRESET = "ultrafast"
"""x264 speed preset: at 1920x1080 only "ultrafast" keeps the whole export 3x faster than real time on two cores
(benchmarks/bench_video.py); drawings are flat colours, so the file stays small all the same."""

X264_CRF = "20"
"""x264 constant quality (lower is better; 18-23 is visually clean for line drawings)."""

VP9_OPTIONS = {"deadline": "realtime", "cpu-used": "8", "row-mt": "1", "crf": "32", "b": "0"}
"""libvpx-vp9 in its fastest mode at constant quality (``b`` 0 lifts the bit-rate cap so ``crf`` rules)."""

ENCODER_THREADS = 1
"""Encoder threads: one, on the pipeline's encoding thread. Drawing, conversion and encoding already run at once
on three threads, and letting x264 add its own (0: it decides) was no faster on two cores (bench_video --sweep)."""

SCALER_THREADS = 1
"""Threads swscale uses for RGBA->yuv420p; one, because drawing and encoding keep the other core busy."""

SCALER_INTERPOLATION = Interpolation.FAST_BILINEAR
"""swscale's chroma filter; FAST_BILINEAR converts 1920x1080 RGBA in 4-5 ms where BILINEAR takes 5-6 ms, and
flat drawn colours come out the same (the decoded-colour tests hold either way)."""


class FrameEncoder:
    """Encodes one video stream in three steps that may run on three threads, in frame order each:
    `stage` copies a caller's frame into a pooled buffer (the caller may then reuse its array), `convert` makes
    the encoder's pixel format from a staged buffer (the buffer may then be staged into again), `encode` encodes
    and muxes; `finish` flushes the encoder. `write_video` keeps the pool of buffers.
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
        rows = np.frombuffer(memoryview(plane), np.uint8).reshape(height, plane.line_size)
        return frame, rows[:, : width * 4].reshape(height, width, 4)

    def stage(self, buffer: tuple[Any, np.ndarray], rgba: np.ndarray) -> None:
        """Copies ``rgba`` into ``buffer``; afterwards the caller may overwrite ``rgba``."""
        np.copyto(buffer[1], rgba)

    def convert(self, buffer: tuple[Any, np.ndarray]) -> Any:
        """A new frame in the encoder's pixel format from the staged pixels; the buffer may then be reused."""
        frame, pixels = buffer
        if self.is_gif:
            if self.palette is None:
                self.palette = Palette.from_frame(pixels)
            return av.VideoFrame.from_ndarray(
                (self.palette.indices(pixels), self.palette.argb),  # type: ignore[arg-type]  # pal8: (indices, palette)
                format="pal8")
        return self.reformatter.reformat(frame, format="yuv420p", threads=SCALER_THREADS,
                                         interpolation=SCALER_INTERPOLATION)

    def encode(self, frame: Any) -> None:
        """Encodes a converted frame as the next one and muxes the packets the encoder hands back."""
        frame.pts = self.frames
        frame.time_base = self.time_base
        self.frames += 1
        self.container.mux(self.stream.encode(frame))

    def finish(self) -> None:
        """Flushes the frames the encoder still holds into the container."""
        self.container.mux(self.stream.encode(None))
