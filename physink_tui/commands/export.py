"""`physink export PROJECT`: a project's demonstration as a video (MP4, GIF, WebM), numbered PNG frames, one
picture, or its timeline file; drawing and encoding are `render.export`'s, this module picks the files.

``--video FILE`` (the suffix picks the format), ``--frames DIR`` (``DIR/00000.png`` ... at the video's rate; frames
an earlier export left there are removed first), ``--still FILE.png [--at T]`` (one picture, by default at the end
of the demonstration, trails and contacts showing everything that happened) and ``--timeline FILE`` (``.json``,
``.txt`` or ``.dot``, or drawn as ``.svg`` or ``.png`` through Graphviz, `render.timeline_graph`); ``--overlay FILE``
draws another timeline of the scene (`physink simulate`'s ``timeline.json``) in red over the demonstration;
``--size WxH``, ``--fps N`` and ``--theme light|dark`` say how.
A project without a timeline gives a one-second still of its scene, and says so. Before anything is written, outputs
that would replace an input, a file that is not a regular file (a device, a FIFO, a symlink) or another output
of the same run are refused (`formats.outputs.check_outputs`).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from physink_tui.commands.timeline_source import load_timeline
from physink_tui.errors import PhysinkError
from physink_tui.formats.atomic_write import write_text_atomic
from physink_tui.formats.outputs import FRAME_FILE, check_outputs, prepare_frames_folder, reason
from physink_tui.formats.project.files import load_project
from physink_tui.formats.project.sanity import named
from physink_tui.formats.timeline_dot import encode_timeline_dot
from physink_tui.formats.timeline_json import encode_timeline_json
from physink_tui.formats.timeline_text import encode_timeline_text
from physink_tui.progress import ProgressBar
from physink_tui.render.export import Export, Look
from physink_tui.render.timeline_graph import FORMATS as PICTURES
from physink_tui.render.timeline_graph import write_timeline_picture
from physink_tui.render.video_spec import CONTAINERS
from physink_tui.scene.components import BACKGROUND

TIMELINE_WRITERS = {".json": encode_timeline_json, ".txt": encode_timeline_text, ".dot": encode_timeline_dot}


def _check_files(args: argparse.Namespace) -> None:
    """Refuses outputs that would replace an input, a non-regular file or each other (nothing is written yet)."""
    inputs = [args.project, *([args.overlay] if args.overlay else [])]
    outputs = [(option, path) for option, path in (("--video", args.video), ("--still", args.still),
                                                   ("--timeline", args.timeline)) if path]
    if args.frames:
        folder = os.path.realpath(args.frames)
        for option, path in [*(("the input", p) for p in inputs), *outputs]:
            name = os.fspath(path)
            if os.path.dirname(os.path.realpath(name)) == folder and FRAME_FILE.match(os.path.basename(name)):
                raise PhysinkError(f"{name}: --frames {args.frames} replaces its numbered frames, and {option} is "
                                   "one of them; write it elsewhere")
    check_outputs(inputs, outputs)


def run(args: argparse.Namespace) -> int:
    if not (args.video or args.frames or args.still or args.timeline):
        raise PhysinkError("export: nothing to write; give --video FILE, --frames DIR, --still FILE.png or "
                           "--timeline FILE")
    if args.timeline and Path(args.timeline).suffix.lower() not in (*TIMELINE_WRITERS, *PICTURES):
        raise PhysinkError(f"{args.timeline}: a timeline is written as .json, .txt or .dot, or drawn as .svg or .png")
    if args.video and Path(args.video).suffix.lower() not in CONTAINERS:
        raise PhysinkError(f"{args.video}: a video is written as {', '.join(CONTAINERS)} (the suffix chooses)")
    if args.still and Path(args.still).suffix.lower() != ".png":
        raise PhysinkError(f"{args.still}: --still writes a PNG picture; name it .png")
    _check_files(args)
    project = load_project(args.project)
    overlay = load_timeline(Path(args.overlay))[0] if args.overlay else None
    for timeline, what in ((project.timeline, "the timeline"), (overlay, f"--overlay {args.overlay}")):
        gone = sorted(named(timeline) - set(project.scene.components) - {BACKGROUND}) if timeline else []
        if gone:
            print(f"export: {what} names {', '.join(map(repr, gone))}, which the scene of {args.project} does not "
                  "have: those are not drawn", file=sys.stderr)
    width, height = args.size
    export = Export(project.scene, project.timeline, project.canvas, Look(width, height, args.fps, args.theme),
                    overlay)
    written = []
    if args.video:
        with ProgressBar(f"video {args.video}", "frames") as bar:
            export.video(args.video, progress=bar)
        written.append(args.video)
    if args.frames:
        folder = prepare_frames_folder(args.frames)
        with ProgressBar(f"frames {args.frames}", "frames") as bar:
            count = export.frames(folder, progress=bar)
        written.append(f"{count} frames in {folder}")
    if args.still:
        at = export.still(args.still, args.at)
        written.append(f"{args.still} (at {at:.2f} s)")
    if args.timeline:
        if project.timeline is None:
            raise PhysinkError(f"{args.project}: the project has no timeline to write to {args.timeline}")
        suffix = Path(args.timeline).suffix.lower()
        if suffix in PICTURES:
            write_timeline_picture(args.timeline, project.timeline, project.scene.names())
        else:
            text = TIMELINE_WRITERS[suffix](project.timeline, project.scene.names())
            try:
                write_text_atomic(args.timeline, text if text.endswith("\n") else text + "\n")
            except OSError as exc:
                raise PhysinkError(f"{args.timeline}: cannot write: {reason(exc)}") from None
        written.append(args.timeline)
    for note in export.notes:
        print(f"export: {note}", file=sys.stderr)
    print(f"export: wrote {', '.join(written)}", file=sys.stderr)
    return 0
