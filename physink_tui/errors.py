"""The project's error hierarchy: one root, one subclass per concern; no handling policy (the CLI owns that)."""

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
