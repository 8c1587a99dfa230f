"""The ``physink`` command line: parses arguments and dispatches to a command module; no logic of its own.

Every subcommand of the DESIGN.md table is parsed here. A built subcommand names its ``module:function`` in
``HANDLERS`` and is imported only when run, so ``physink --help`` never loads Textual, numpy or a device
library. A subcommand whose module is missing exits 2 with one line saying so.

Exit status: 0 success, 1 a user error (a ``PhysinkError``, printed as one line), 2 bad usage or a subcommand
not available yet, 130 interrupted. A reader that closes stdout early (``| head -1``) only ends the printing:
the command finishes its files and its status is what it would have been (0 on success).
"""

from __future__ import annotations

import argparse
import gc
import importlib
import math
import re
import sys
from collections.abc import Callable, Sequence

from physink_tui import __version__
from physink_tui.errors import PhysinkError
from physink_tui.formats.stdout_guard import StdoutGuard
from physink_tui.render.limits import MAX_FPS, MAX_SIDE, MIN_SIDE

PROG = "physink"

EXIT_USER_ERROR = 1
EXIT_USAGE = 2
EXIT_INTERRUPTED = 130

#: Built subcommands: name -> "module:function", the function being ``run(args: Namespace) -> int``.
HANDLERS: dict[str, str] = {
    "demo": "physink_tui.commands.demo:run",
    "decode": "physink_tui.commands.decode:run",
    "replay": "physink_tui.commands.replay:run",
    "export": "physink_tui.commands.export:run",
    "devices": "physink_tui.commands.devices:run",
    "record": "physink_tui.commands.record:run",
    "recognize": "physink_tui.commands.recognize:run",
    "timeline": "physink_tui.commands.timeline:run",
    "equiv": "physink_tui.commands.equiv:run",
    "simulate": "physink_tui.commands.simulate:run",
    "tui": "physink_tui.commands.tui:run",
    "listen": "physink_tui.commands.listen:run",
    "kiosk": "physink_tui.commands.kiosk:run",
}





def _whole(text: str, low: int, high: int, expected: str) -> int:
    """``text`` as an integer in [low, high], else an argparse error saying ``expected``."""
    try:
        value = int(text)
    except ValueError:
        value = low - 1
    if not low <= value <= high:
        raise argparse.ArgumentTypeError(f"expected {expected}, got {text!r}")
    return value


def _positive_int(text: str) -> int:
    return _whole(text, 1, sys.maxsize, "a positive integer")


def _seed(text: str) -> int:
    """A search's seed: what a journal's ``simulate`` line takes (up to its `MAX_COUNT`, imported only here: the
    journal's checks are not every command's start-up)."""
    from physink_tui.formats.journal.value_checks import MAX_COUNT

    return _whole(text, 0, MAX_COUNT, f"an integer in [0, {MAX_COUNT}]")


def _positive(text: str, expected: str) -> float:
    """``text`` as a finite number > 0, else an argparse error saying ``expected``."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"expected {expected}, got {text!r}")
    return value


def _positive_rate(text: str) -> float:
    return _positive(text, "a positive number per second")


def _positive_float(text: str) -> float:
    return _positive(text, "a positive number")


def _noise(text: str) -> float | None:
    """``auto`` (None: judged from each stroke) or the pen's jitter in the strokes' units."""
    return None if text.strip().lower() == "auto" else _positive(text, "auto or a positive number of units")


def _frame_size(text: str) -> tuple[int, int]:
    match = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", text)
    width, height = (int(match[1]), int(match[2])) if match else (0, 0)
    if not (MIN_SIDE <= width <= MAX_SIDE and MIN_SIDE <= height <= MAX_SIDE):
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, each {MIN_SIDE} to {MAX_SIDE} "
                                         f"(e.g. 1280x800), got {text!r}")
    return width, height


def _frame_rate(text: str) -> int:
    return _whole(text, 1, MAX_FPS, f"whole frames a second from 1 to {MAX_FPS} (30 or 60 are usual)")


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value >= 0):
        raise argparse.ArgumentTypeError(f"expected seconds >= 0, got {text!r}")
    return value


def _add_look(p: argparse.ArgumentParser) -> None:
    """--size, --fps, --theme: how pictures and videos are drawn."""
    p.add_argument("--size", type=_frame_size, default=(1280, 800), metavar="WxH",
                   help="picture size in pixels, the canvas's proportions kept (default: 1280x800)")
    p.add_argument("--fps", type=_frame_rate, default=30, metavar="N", help="video frames a second (default: 30)")
    p.add_argument("--theme", choices=("light", "dark"), default="light", help="(default: %(default)s)")


def _label_list(text: str) -> list[str]:
    labels = [label.strip() for label in text.split(",") if label.strip()]
    if not labels:
        raise argparse.ArgumentTypeError(f"expected comma-separated labels like 'ball,cup', got {text!r}")
    return labels


def build_parser() -> argparse.ArgumentParser:
    """Returns the parser for every subcommand of the DESIGN.md CLI table (built or not)."""
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Sketch a machine with a pen tablet, demonstrate how it works, and simulate it.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    # Options shared by the subcommands that read a live tablet.
    # --device None means auto; a command reading a tablet gets at most one of device and serial.
    device = argparse.ArgumentParser(add_help=False)
    source = device.add_mutually_exclusive_group()
    source.add_argument(
        "--device",
        metavar="auto|PATH|VID:PID",
        help="the pen tablet: 'auto' (the first one found; the default), a hidraw path, or a USB VID:PID",
    )
    source.add_argument("--serial", metavar="PORT", help="read a serial tablet on PORT instead of a HID one")

    p = sub.add_parser(
        "demo",
        help="the embedded default: the TUI replaying a bundled session (the egg cracker)",
        description="Open the TUI on a bundled session being replayed; with --headless (automatic when "
        "stdout is not a terminal) run the whole pipeline and write the outputs to --out.",
    )
    p.add_argument("--headless", action="store_true", help="no UI: run the pipeline and write the outputs")
    p.add_argument(
        "--out", metavar="DIR", default="./physink-demo/", help="output folder (default: %(default)s)"
    )

    p = sub.add_parser("tui", parents=[device], help="the control panel")
    p.add_argument("project", nargs="?", metavar="PROJECT", help="a project (.physink.json) to open")
    p.add_argument("--replay", metavar="FILE", help="replay a journal or capture instead of reading a tablet")

    p = sub.add_parser(
        "kiosk", parents=[device], help="headless recording service: journals sessions, exports at their end"
    )
    p.add_argument("--out", metavar="DIR", required=True, help="folder for journals and exports")
    p.add_argument("--replay", metavar="CAPTURE.hid", help="feed a capture as if it were a live tablet, paced by "
                   "its timestamps")
    p.add_argument("--speed", type=_positive_float, default=1.0, metavar="X",
                   help="with --replay: X times faster (default: %(default)s)")
    p.add_argument("--idle", type=_positive_float, default=120.0, metavar="SECONDS",
                   help="a session ends after this long without input (default: %(default)s)")
    p.add_argument("--hot-zones", metavar="FILE", help="hot zones file (JSON; default: a strip along the top edge: "
                   "sketch/demo, undo, redo, end session)")
    p.add_argument("--keep", type=_positive_int, metavar="N", help="keep at most N finished sessions (oldest retired)")
    p.add_argument("--max-disk", metavar="SIZE", help="retire the oldest finished sessions beyond SIZE (e.g. 2G)")
    p.add_argument("--video-size", type=_frame_size, default=(960, 600), metavar="WxH",
                   help="the sessions' videos (default: 960x600)")
    p.add_argument("--speech", action="store_true",
                   help="listen on the microphone all the time: spoken labels and events go to the session")
    p.add_argument("--vosk-model", metavar="DIR", help="with --speech: the vosk model in DIR instead of the "
                   "embedded pocketsphinx one")

    sub.add_parser("devices", help="list pen tablets found (hidraw/hidapi, USB, serial)")

    p = sub.add_parser("record", parents=[device], help="raw capture in hid-recorder format")
    p.add_argument("-o", "--output", metavar="FILE.hid", required=True, help="capture file to write")

    p = sub.add_parser("decode", help="decode a capture into pen samples")
    p.add_argument("file", metavar="FILE.hid", help="a capture in hid-recorder format")
    p.add_argument("--format", choices=("jsonl", "text"), default="jsonl", help="(default: %(default)s)")

    p = sub.add_parser(
        "replay", help="run a journal (or a capture plus a script) headless and write project and timeline"
    )
    p.add_argument("file", metavar="FILE", help="a journal (.physink.jsonl) or capture (.hid)")
    p.add_argument("--out", metavar="DIR", required=True, help="output folder")
    p.add_argument("--video", action="store_true", help="also write the demonstration as DIR/video.mp4")
    p.add_argument("--frames", action="store_true", help="also write every frame as DIR/frames/NNNNN.png")
    _add_look(p)
    p.add_argument("--vocabulary", metavar="FILE",
                   help="extra verbs and prepositions for phrases, lines 'verb WORD...' or 'prep WORD...'")
    p.add_argument("--ticks", type=_positive_rate, metavar="HZ",
                   help="advance the clock HZ times a second between inputs, as a live driver does "
                        "(the outputs are the same)")

    p = sub.add_parser("recognize", help="recognise strokes: one JSON line per input line")
    p.add_argument("strokes", metavar="STROKES.jsonl", help="one stroke per line")
    p.add_argument("--noise", type=_noise, default=None, metavar="UNITS",
                   help="the pen's jitter in the strokes' units, or auto: judged from each stroke in whatever units "
                        "it is stored (the lattice its coordinates are rounded to, whole pixels giving 1, else its "
                        "own jitter) (default: auto)")

    p = sub.add_parser("timeline", help="print a project's causal timeline")
    p.add_argument("project", metavar="PROJECT", help="a project (.physink.json)")
    p.add_argument("--format", choices=("text", "json", "dot"), default="text", help="(default: %(default)s)")

    p = sub.add_parser("equiv", help="are two timelines (or projects) qualitatively equivalent")
    p.add_argument("a", metavar="A", help="a timeline or project (alone: a project that adopted a simulation, "
                                          "compared with the demonstration it keeps)")
    p.add_argument("b", metavar="B", nargs="?", help="a timeline or project")
    p.add_argument("--up-to-demonstrated", action="store_true",
                   help="B simulates the demonstration A: compare up to the last demonstrated event, as SIMULATE "
                        "does, and say what the simulation does afterwards")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")

    p = sub.add_parser("simulate", help="search physical parameters that reproduce the demonstrated timeline")
    p.add_argument("project", metavar="PROJECT", help="a project (.physink.json) with a demonstration")
    p.add_argument(
        "--out", metavar="DIR", required=True, help="folder for result.json, timeline.json and project.json"
    )
    p.add_argument("--budget", metavar="N", type=_positive_int, help="at most N rollouts")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", metavar="N", type=_positive_int,
                       help="N local worker processes (default: one per core)")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="run the rollouts on the Dask cluster whose scheduler is at ADDRESS (e.g. "
                       "tcp://host:8786) instead of local processes; needs physink-tui[dask]")
    p.add_argument("--seed", metavar="S", type=_seed, help="random seed, for a reproducible search")
    p.add_argument("--strategy", choices=("default", "grid"), default="default",
                   help="CMA-ES (default) or the thesis's grid (default: %(default)s)")

    p = sub.add_parser("listen", help="recognise one spoken utterance from a WAV file")
    p.add_argument("wav", metavar="FILE.wav", help="the recording")
    p.add_argument("--labels", metavar="a,b,...", type=_label_list,
                   help="comma-separated labels the grammar holds besides the default component names")
    p.add_argument("--vosk-model", metavar="DIR",
                   help="use the vosk model in DIR instead of the embedded pocketsphinx one")

    p = sub.add_parser("export", help="a project's demonstration as a video, PNG frames, a picture or a timeline")
    p.add_argument("project", metavar="PROJECT", help="a project (.physink.json)")
    p.add_argument("--video", metavar="FILE.mp4|.gif|.webm", help="the demonstration as a video")
    p.add_argument("--frames", metavar="DIR", help="every frame as DIR/NNNNN.png")
    p.add_argument("--still", metavar="FILE.png", help="one picture (at the end of the demonstration, or --at)")
    p.add_argument("--at", metavar="T", type=_seconds, help="timeline time of --still, in seconds")
    p.add_argument("--timeline", metavar="FILE", help="the timeline as FILE (.json, .txt or .dot), or drawn as a "
                   "picture of the causal graph (.svg or .png, through Graphviz)")
    p.add_argument("--overlay", metavar="FILE", help="another timeline of the scene (a simulation's timeline.json "
                   "or project) drawn in red over the demonstration")
    _add_look(p)

    return parser


def one_line(message: str) -> str:
    """The message on one line: a line break quoted from a file is shown as ``\\n``."""
    return message.replace("\r", "\\r").replace("\n", "\\n")


def _not_available(command: str, why: str) -> int:
    print(f"{PROG} {command}: not available yet ({why})", file=sys.stderr)
    return EXIT_USAGE


def _resolve(target: str) -> Callable[[argparse.Namespace], int] | None:
    """Imports ``"module:function"``; None when the module itself is not written yet."""
    module_name, _, function_name = target.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        # Only the command's own module missing means "not built"; a missing dependency inside it is a bug.
        if exc.name is not None and (module_name == exc.name or module_name.startswith(exc.name + ".")):
            return None
        raise
    return getattr(module, function_name)


def _dispatch(args: argparse.Namespace) -> int:
    command = args.command
    run = _resolve(HANDLERS[command])
    if run is None:
        return _not_available(command, f"{HANDLERS[command].partition(':')[0]} is not written yet")
    return run(args)


def entry() -> None:
    """The ``physink`` program (its console script, ``python -m physink_tui``): `main` on the process arguments,
    then the exit. What the command made dies with the process, so it is frozen first and the interpreter's last
    collections skip it (about a tenth of a short command's CPU: ``physink decode``, docs/BENCHMARKS.md)."""
    status = main()
    gc.freeze()
    sys.exit(status)


def main(argv: Sequence[str] | None = None) -> int:
    """Runs ``physink`` with ``argv`` (default: the process arguments) and returns the exit status."""
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:  # --help, --version, or a usage error argparse already reported
        if exc.code is None:
            return 0
        return exc.code if isinstance(exc.code, int) else EXIT_USAGE
    guard = StdoutGuard(sys.stdout)
    sys.stdout = guard
    try:
        status = _dispatch(args)
    except PhysinkError as exc:
        guard.flush()  # what was printed before the error stays, in order
        print(f"{PROG}: {one_line(str(exc))}", file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt:
        return EXIT_INTERRUPTED
    finally:
        sys.stdout = guard.stream
    guard.flush()  # a full stdout is an error of this run, not a warning at exit
    if guard.error is not None:
        print(f"{PROG}: {guard.error}", file=sys.stderr)
        return EXIT_USER_ERROR
    return status

