"""Draws scene snapshots into frames, videos and terminal images; decides nothing about the scene itself.

The one place that draws. It reads snapshots — a `Scene` with its `Timeline`, or a `SessionView` — never a live
world, and returns pixels; files go through `formats/atomic_write.py` (PNG) and `render/video.py` (video).

- `frame.py`: the values one picture shows: `FrameContent` (scene, canvas, poses, ink, `Trail`s, `ContactMarker`s,
  subtitle, `TimeBar`, `highlight`: bodies outlined in the emphasis colour, the TUI's chosen timeline event) and
  `frame_times(duration, fps)` (0, 1/fps, … and the end itself)
- `frames.py`: builders: `Demonstration(scene, timeline, canvas)` prepares a timeline once (its `Tape` — the
  playback the session's seek uses — trails, contacts, narration) and gives `.frame(t)` at any t without running the
  physics; `view_frame(view, canvas)` from a session snapshot (reusing the paths of movements that did not change)
- `attachments.py`: where joints, springs and rope ends go when their bodies move (rigid transforms; a rope reshaped
  from its drawn path, not simulated)
- `shapes.py`: skia paths: body outlines, polylines, zig-zag springs, X crosses
- `theme.py`: the light and dark palettes (demonstration green, simulation red)
- `renderer.py`: `Renderer(width, height, canvas, theme, controls=True)`: one raster surface over one reused numpy
  RGBA buffer; the canvas fitted with its aspect kept above a strip for the narration and time bar (`CONTROLS`, 10 %
  of the height); a cached static layer (paper, fixed bodies, finished trails) copied in with `np.copyto`; one path
  per body drawn by pose; text in DejaVu Sans only, loaded through a font manager of its own (no fontconfig), so
  pictures are the same on every machine
- `images.py`: `encode_png`, `decode_png`, `write_png` (atomic)
- `kitty.py`, `sixel.py`: frames as terminal graphics: the Kitty graphics protocol (base64 PNG in 4096-byte APC
  chunks, `a=T,U=1` virtual placement, the U+10EEEE placeholder rows and the id's colour) and Sixel (`gif_palette`'s
  256 colours, six-row bands, run-length `!k`); escapes only, no terminal I/O; `tests/test_terminal_graphics.py`
  decodes them back to the frame's pixels (`tests/terminal_graphics.py`)
- `limits.py`: the picture sizes (16 to 7680 pixels a side) and frame rates (1 to 120) that the renderer, the video
  writer and the command line's `--size`/`--fps` all check against
- `video_spec.py`, `video.py`, `video_encode.py`, `gif_palette.py`: `write_video(path, count, frame_at, fps)`: the
  suffix picks MP4 (H.264 ultrafast, crf 20, yuv420p, faststart), WebM (VP9 realtime) or GIF (palette, at most 30
  fps); sizes, rates and counts checked by value; three threads — the caller draws, one worker converts to yuv420p,
  one encodes — into a temporary file renamed when complete, removed on any error
- `compose.py`: `side_by_side` of two frames (demonstration beside simulation, for SIMULATE)
- `export.py`: `Export(scene, timeline, canvas, Look, overlay=None)`: a project's `video`, numbered `frames` and
  `still`, sharing one renderer and one prepared timeline; an `overlay` timeline (a simulation's) drawn as red
  trails over the demonstration; a project without a timeline is a one-second still, an empty one an empty canvas,
  each with a note
- `braille.py`: the demo's terminal plot of points
- `timeline_graph.py`: the causal timeline as a picture (`physink export --timeline graph.svg|graph.png`): a styled
  Graphviz digraph (`rankdir=LR`: every cause left of its effects; each event type its fill and outline, with a
  legend of the types present; each node the user's phrase over the default narration, and its start time; DejaVu
  Sans) drawn by Debian's `dot` (installed by scripts/setup.sh) and written atomically; no `dot` is one
  `RenderError` saying what to install (`tests/test_timeline_picture.py` reads the SVG back)

`physink_tui/progress.py` is the one progress bar of long commands (counts and ETA on a terminal, silent elsewhere).
Golden images of six thesis scenes in both themes (`tests/golden/`, 320x200, compared decoded with a tolerance;
`PHYSINK_UPDATE_GOLDEN=1` regenerates them) check the drawing; `tests/test_video.py` and
`tests/test_export_command.py` open every video with PyAV and decode it back.
"""
