"""The project's error hierarchy: one root, one subclass per concern; no handling policy (the CLI owns that).

One root, one subclass per concern (`physink_tui/errors.py`). Each carries the offending value as attributes; its
message says what was expected.

    PhysinkError                 anything a user can cause
    ├── DescriptorError          a HID report descriptor that cannot be used (.offset: byte offset or None)
    ├── CaptureFormatError       a .hid capture that cannot be read (.path, .line; message starts "path:line: ")
    ├── JournalError             a session journal that cannot be written or read
    ├── SceneError               a sketch that cannot become a physical scene (and a bad project file)
    ├── SimulationError          a parameter search that cannot run
    ├── RenderError              a frame, image or video that cannot be produced
    ├── DeviceError              a tablet or serial device that cannot be found, opened or read
    └── SpeechError              a recording, speech model or grammar that cannot be used (.path)
        └── MicrophoneError      no PortAudio or no input device to listen with (.device)

`cli.main()` turns a `PhysinkError` into one line on stderr, `physink: <message>`, and exit status 1. Argument
errors are argparse's usage message and exit 2; a subcommand not available yet is one line and exit 2; Ctrl-C is
exit 130. Any other exception is a bug and shows its traceback. stdout is wrapped in `formats/outputs.StdoutGuard`
for the run: `| head -1` ends the printing quietly (the command finishes its files, its status unchanged), `>
/dev/full` is one line and exit 1 after the files are written. Commands read their input once
(`commands/input_file.py`: bytes read once, sniffed as journal or capture, a project or an unversioned timeline
named as the wrong kind; a journal that came through a pipe or FIFO, or with a BOM, is copied to a temporary file
for the path-based journal reader). `physink replay` of a journal reads it once (`read_journal`) and runs it through
the session once; the gestures it lists are those the session's own input side produced. `physink decode` streams:
the capture is parsed a megabyte of lines at a time into `CaptureColumns`, decoded 65,536 reports at a time
(`input/hid/chunks.py`) and written as it goes, its JSON lines made a column at a time (`commands/decode_jsonl.py`,
byte for byte what `json.dumps` gave).

Inside the session, nothing an input can do raises out of `Session.handle` (see `physink_tui.session`).
"""

from __future__ import annotations


class PhysinkError(Exception):
    """Root of every error a user can cause; the CLI prints it as one line and exits 1."""


class DescriptorError(PhysinkError):
    """A HID report descriptor that cannot be used.

    Attributes:
        offset: byte offset into the descriptor where the problem was found, or None
            when the problem is not tied to one byte (e.g. no pen report at all).
    """

    def __init__(self, message: str, offset: int | None = None) -> None:
        self.offset = offset
        super().__init__(message if offset is None else f"{message} (at descriptor byte {offset})")


class CaptureFormatError(PhysinkError):
    """A capture file (hid-recorder text format) that cannot be read.

    Attributes:
        path: the file, or None for text not read from a file.
        line: 1-based line number of the offending line, or None.
    """

    def __init__(self, message: str, path: str | None = None, line: int | None = None) -> None:
        self.path = path
        self.line = line
        where = ":".join(str(p) for p in (path, line) if p is not None)
        super().__init__(f"{where}: {message}" if where else message)


class JournalError(PhysinkError):
    """A session journal that cannot be written or read (names the line and key)."""


class SceneError(PhysinkError):
    """A sketch that cannot become a physical scene."""


class SimulationError(PhysinkError):
    """A parameter search that cannot run."""


class RenderError(PhysinkError):
    """A frame, image or video that cannot be produced."""


class DeviceError(PhysinkError):
    """A tablet or serial device that cannot be found, opened or read.

    Attributes:
        device: the device's path, port or VID:PID as the user named it, or None.
    """

    def __init__(self, message: str, device: str | None = None) -> None:
        self.device = device
        super().__init__(message)


class SpeechError(PhysinkError):
    """A recording, speech model or grammar that cannot be used (a broken WAV, a missing model directory).

    Attributes:
        path: the file or directory as the user named it, or None.
    """

    def __init__(self, message: str, path: str | None = None) -> None:
        self.path = path
        super().__init__(message)


class MicrophoneError(SpeechError):
    """No microphone to listen with: PortAudio is not installed, or no input device can be opened.

    Attributes:
        device: the input device as PortAudio names it, or None for the default one.
    """

    def __init__(self, message: str, device: str | None = None) -> None:
        self.device = device
        super().__init__(message, None)
