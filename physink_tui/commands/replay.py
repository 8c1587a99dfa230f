"""`physink replay`: runs the input side over a capture or a journal and reports the gestures found.

A replay prints the gestures, one line each, and writes them to ``DIR/gestures.jsonl``; a journal
also runs through the session, whose sketch is written to ``DIR/project.json`` and, after a demonstration, its
timeline to ``DIR/timeline.json`` and ``DIR/timeline.txt``; with ``--video`` and ``--frames`` its demonstration
also as ``DIR/video.mp4`` and ``DIR/frames/NNNNN.png`` (`render.export`). ``DIR`` holds only this run's files
(`physink_tui.formats.outputs.OutputFolder`); the input is read once, so a pipe or FIFO works. A capture is replayed
device by device in file order as live reports would arrive; a journal's ``hid`` lines go through their device's
decoder, its ``pen`` lines are canvas samples already, and its commands and utterances are listed as they come.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from physink_tui.commands.decode import decoder_for
from physink_tui.commands.gesture_output import gesture_json, gesture_text
from physink_tui.commands.input_file import BOM, read_bytes, regular_copy, sniff
from physink_tui.errors import DescriptorError, PhysinkError
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.outputs import OutputFolder, prepare_frames_folder
from physink_tui.formats.session_outputs import write_session_outputs
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.pen_layout import tablet_size
from physink_tui.input.pen.gestures import Gesture
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.pen.pen_input import PenInput
from physink_tui.input.sources import RawReport, SourceEnded
from physink_tui.session.replay_driver import replay
from physink_tui.session.session import Session
from physink_tui.timeline.phrases import Vocabulary, parse_vocabulary

PLURAL = {"body": "bodies"}


def replay_capture(capture: Capture) -> tuple[list[Gesture], list[str]]:
    """Gestures of a capture (all its devices), and notes for the summary."""
    pen: PenInput | None = None
    ids = {}
    decoders = []
    for device in capture.devices:
        try:
            decoder = decoder_for(device)
        except DescriptorError as exc:
            raise DescriptorError(f"{capture.path}: device {device.index}: {exc}") from None
        decoders.append((device.index, decoder))
    size = tablet_size(decoders[0][1].layouts) if decoders else None
    mapping = TabletMapping(tablet_width=size[0], tablet_height=size[1]) if size else TabletMapping()
    pen = PenInput(mapping)
    for index, decoder in decoders:
        ids[index] = f"tablet{index}"
        pen.add_hid_device(ids[index], decoder)
    gestures: list[Gesture] = []
    last_t = 0.0
    for event in capture.events:
        last_t = event.t
        gestures += pen.handle(RawReport(event.t, event.data, ids[event.device]))
    for index in ids:
        gestures += pen.handle(SourceEnded(last_t, ids[index], None))
    notes = [f"{ids[i]}: {d.stats.reports} reports, {d.stats.samples} pen samples" for i, d in decoders]
    if capture.bad_lines:
        first = capture.bad_lines[0]
        notes.append(f"{len(capture.bad_lines)} capture lines skipped; first bad line {first.line}: {first.reason}")
    return gestures, notes


def replay_journal(path: Path, out_dir: str, vocabulary: Vocabulary | None, ticks: float | None = None,
                   pictures: Pictures | None = None) -> None:
    """Read the journal once, run it through the session (which decodes it, once) and write the gestures the
    session's input side found, DIR/project.json and, after a demonstration, the timeline."""
    from physink_tui.input.journal_replay import decoder_notes, entry_line, logged_pen_input_for

    journal = read_journal(path)
    pen = logged_pen_input_for(journal.header, str(path))
    session = Session.from_header(journal.header)
    session.pen = pen
    if vocabulary is not None:
        session.add_words(vocabulary)
    replay(session, journal.entries, ticks)
    events = [line for entry in journal.entries if (line := entry_line(entry)) is not None]
    last_t = journal.entries[-1].t if journal.entries else 0.0
    for device_id in list(pen.devices):
        pen.handle(SourceEnded(last_t, device_id, None))
    notes = list(journal.warnings)
    if journal.truncated is not None:
        notes.append(f"line {journal.truncated} is incomplete (the writer stopped mid-line); read up to it")
    out = OutputFolder.prepare(out_dir)
    _write_gestures(out, events, pen.log, notes + decoder_notes(pen))
    target = write_session_outputs(out, session.scene, session.timeline, session.canvas,
                                   session.vocabulary_lines(), session.demonstration)
    _print_session(session, target)
    if pictures is not None:
        write_pictures(session, out, pictures)


@dataclass(frozen=True, slots=True)
class Pictures:
    """What ``--video`` and ``--frames`` ask a replay for, drawn at ``size`` (pixels), ``fps`` and ``theme``."""

    video: bool
    frames: bool
    size: tuple[int, int]
    fps: int
    theme: str


def write_pictures(session: Session, out: OutputFolder, pictures: Pictures) -> None:
    """DIR/video.mp4 and DIR/frames/NNNNN.png of the session's demonstration (a still without one)."""
    from physink_tui.progress import ProgressBar  # the renderer's libraries load only when pictures are asked for
    from physink_tui.render.export import Export, Look

    look = Look(*pictures.size, pictures.fps, pictures.theme)
    export = Export(session.scene, session.timeline, session.canvas, look)
    if pictures.video:
        with ProgressBar("video.mp4", "frames") as bar:
            export.video(out.file("video.mp4"), progress=bar)
        print(f"replay: the demonstration's video written to {out.file('video.mp4')}", file=sys.stderr)
    if pictures.frames:
        folder = prepare_frames_folder(out.path / "frames")
        with ProgressBar("frames", "frames") as bar:
            count = export.frames(folder, progress=bar)
        print(f"replay: {count} frames written to {folder}", file=sys.stderr)
    for note in export.notes:
        print(f"replay: {note}", file=sys.stderr)


def run(args: argparse.Namespace) -> int:
    path = Path(args.file)
    vocabulary = read_vocabulary(args.vocabulary)  # a bad file stops the replay before anything is written
    pictures = None
    if args.video or args.frames:
        pictures = Pictures(args.video, args.frames, args.size, args.fps, args.theme)
    data = read_bytes(path)  # once: the input may be a pipe or a FIFO
    if sniff(data, path) == "capture":
        capture = Capture.from_text(data.removeprefix(BOM).decode("utf-8", errors="replace"), path=str(path))
        gestures, notes = replay_capture(capture)
        if pictures is not None:
            notes.append("--video and --frames draw a session: a capture alone has no scene (replay a journal)")
        out = OutputFolder.prepare(args.out)
        _write_gestures(out, [], gestures, notes)
        return 0
    with regular_copy(path, data) as copy:
        try:
            replay_journal(copy, args.out, vocabulary, getattr(args, "ticks", None), pictures)
        except PhysinkError as exc:
            if copy == path:
                raise
            raise PhysinkError(str(exc).replace(str(copy), str(path))) from None
    return 0


def _write_gestures(out: OutputFolder, events: list[str], gestures: list[Gesture], notes: list[str]) -> None:
    """Prints the gesture lines and writes DIR/gestures.jsonl."""
    for line in _merge(events, gestures):
        print(line)
    body = "".join(f"{j}\n" for g in gestures if (j := gesture_json(g)) is not None)
    target = out.write("gestures.jsonl", body)
    strokes = sum(1 for g in gestures if type(g).__name__ == "StrokeEnded")
    taps = sum(1 for g in gestures if type(g).__name__ == "Tap")
    print(f"replay: {strokes} strokes, {taps} taps; gestures written to {target}", file=sys.stderr)
    for note in notes:
        print(f"  {note}", file=sys.stderr)


def read_vocabulary(path: str | None) -> Vocabulary | None:
    """The words of a vocabulary file (``--vocabulary``), or None without one."""
    if path is None:
        return None
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        reason = getattr(exc, "strerror", None) or exc
        raise PhysinkError(f"{path}: cannot read the vocabulary file: {reason}") from None
    return parse_vocabulary(text, path)


def _print_session(session: Session, project: Path) -> None:
    """Prints what the session told the user, and a summary of the sketch written to ``project``."""
    for message in session.messages:
        print(f"{message.t:9.3f}  told          {message.text}")
    kinds = Counter(type(c).__name__.lower() for c in session.scene.components.values())
    summary = ", ".join(f"{n} {PLURAL.get(k, k + 's') if n > 1 else k}" for k, n in sorted(kinds.items())) or "nothing"
    print(f"replay: the sketch has {summary}; written to {project}", file=sys.stderr)


def _merge(events: list[str], gestures: list[Gesture]) -> list[str]:
    """Journal command/utterance lines (each starting with its time) merged with gesture lines by time."""
    rows = [(float(e.split()[0]), 0, e) for e in events]
    rows += [(g.t, 1, text) for g in gestures if (text := gesture_text(g)) is not None]
    return [text for _, _, text in sorted(rows, key=lambda r: (r[0], r[1]))]
