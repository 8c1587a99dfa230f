"""The journal's rules for single values, and the words of its errors; knows no JSON text and does no I/O.

The codec checks with these functions in both directions, so whatever the writer accepts the reader reads
back. Each check takes ``where`` (``"line 12"`` when reading, ``"pen entry"`` when writing) and the key's
dotted path (``"pen.x"``), and raises `JournalError` worded ``<where>: key "<key>": expected <what>, got
<value>``, the value shown as it appears in JSON.
"""

from __future__ import annotations

import json
import math
import numbers
import re
from typing import Any

from physink_tui.errors import JournalError

SHOW_MAX = 60
"""Offending values are shown with at most this many characters."""

KINDS = ("hid", "pen", "cmd", "say", "device")
"""The keys that say what an entry is; a line has exactly one of them."""

COMMANDS = ("mode", "play", "pause", "stop", "seek", "clear", "undo", "redo", "label", "simulate", "save")
"""Command names, as the session knows them."""

MODES = ("sketch", "demo")
"""The arguments ``mode`` takes."""

LABEL_TARGETS = ("last", "selected")
"""``label`` targets besides a component id."""

MAX_SECONDS = 366 * 24 * 3600.0
"""The latest ``t`` (and ``seek`` time) a journal may hold, in seconds: a year and a day. Larger finite values
(``1e308``) are refused, since time arithmetic on them overflows and no session lasts that long."""

SECONDS_EXPECTED = f"a number in [0, {MAX_SECONDS:.0f}] (seconds since the session start)"
"""What a ``t`` must be, in error messages."""

_USAGE = {
    "mode": 'one argument, "sketch" or "demo",',
    "seek": f"one argument, a number in [0, {MAX_SECONDS:.0f}] (seconds of timeline time),",
    "label": 'two arguments, TARGET ("last", "selected" or a component id) and a non-empty TEXT,',
    "save": "one argument, a non-empty PATH,",
}
_HEX = re.compile(r"[0-9a-fA-F]{2}(?: [0-9a-fA-F]{2})*\Z")
_MISSING = object()


def show(value: Any) -> str:
    """The value as it would appear in JSON, shortened.

    >>> show(3.2), show("pad1"), show(True), show(None), show([1, "a"])
    ('3.2', '"pad1"', 'true', 'null', '[1, "a"]')
    """
    try:
        text = json.dumps(value, ensure_ascii=False)
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= SHOW_MAX else text[: SHOW_MAX - 3] + "..."


def bad(where: str, key: str, expected: str, got: Any = _MISSING) -> JournalError:
    """The error for one key: what was expected and what was found (or that the key is missing).

    >>> print(bad("line 12", "t", "a number >= the previous t 3.5", 3.2))
    line 12: key "t": expected a number >= the previous t 3.5, got 3.2
    >>> print(bad("line 3", "pen.tip", "true or false"))
    line 3: key "pen.tip": expected true or false, but it is missing
    """
    found = "but it is missing" if got is _MISSING else f"got {show(got)}"
    return JournalError(f'{where}: key "{printable(key)}": expected {expected}, {found}')


def printable(key: str) -> str:
    """A key path as one printable line: control and other unprintable characters escaped.

    >>> printable("devices.tab\\nlet")
    'devices.tab\\\\nlet'
    """
    if key.isprintable():
        return key
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in key)


def unknown_key(where: str, key: str) -> str:
    """The warning for a key the format does not define (it is ignored)."""
    return f'{where}: unknown key "{printable(key)}" ignored'


def kinds_error(where: str, found: list[str]) -> JournalError:
    """The error for a line with none or several of ``hid``, ``pen``, ``cmd``, ``say``."""
    what = " and ".join(found) if found else "none"
    return JournalError(f"{where}: expected exactly one of {', '.join(KINDS)}; found {what}")


def get(obj: dict[str, Any], where: str, key: str, path: str, expected: str) -> Any:
    """``obj[key]``, or the "missing" error naming ``path`` and what was expected."""
    try:
        return obj[key]
    except KeyError:
        raise bad(where, path, expected) from None


def _real(value: Any) -> float | None:
    """The value as a finite float, or None if it is no finite real number (bools are not numbers)."""
    if type(value) is float:
        return value if math.isfinite(value) else None
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    try:
        value = float(value)
    except (OverflowError, ValueError):
        return None
    return value if math.isfinite(value) else None


def seconds(where: str, key: str, value: Any, previous: float | None = None) -> float:
    """A time in seconds: finite, in [0, `MAX_SECONDS`], and >= ``previous`` when given.

    >>> seconds("line 12", "t", 3.2, previous=3.5)
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 12: key "t": expected a number >= the previous t 3.5, got 3.2
    """
    t = _real(value)
    if t is None or not 0 <= t <= MAX_SECONDS:
        raise bad(where, key, SECONDS_EXPECTED, value)
    if previous is not None and t < previous:
        raise bad(where, key, f"a number >= the previous t {previous!r}", value)
    return t


def unit(where: str, key: str, value: Any) -> float:
    """A number in [0, 1]."""
    v = _real(value)
    if v is None or not 0.0 <= v <= 1.0:
        raise bad(where, key, "a number in [0, 1]", value)
    return v


def positive(where: str, key: str, value: Any) -> int | float:
    """A finite number > 0, kept an int when it is one (so it is written back the same way)."""
    v = _real(value)
    if v is None or v <= 0:
        raise bad(where, key, "a number > 0", value)
    return value if type(value) is int else v


def flag(where: str, key: str, value: Any) -> bool:
    """``true`` or ``false``, nothing else (not 0 or 1)."""
    if value is True or value is False:
        return value
    raise bad(where, key, "true or false", value)


def text(where: str, key: str, value: Any, *, empty: bool = True) -> str:
    """A string of valid Unicode (no lone surrogates), non-empty unless ``empty``."""
    if not isinstance(value, str) or (not empty and not value):
        raise bad(where, key, "a string" if empty else "a non-empty string", value)
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise bad(where, key, "valid Unicode text (no lone surrogates)", value) from None
    return value


def optional_int(where: str, key: str, value: Any, high: int) -> int | None:
    """``null`` or an integer in 0..high."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= high:
        raise bad(where, key, f"null or an integer in 0..{high}", value)
    return int(value)


def hex_bytes(where: str, key: str, value: Any) -> bytes:
    """Bytes from their hex form, two digits each, separated by one space (``"02 c1 00"``), at least one."""
    if not isinstance(value, str) or not _HEX.match(value):
        raise bad(where, key, 'hex bytes separated by spaces, e.g. "02 c1 00"', value)
    return bytes.fromhex(value)


def report_bytes(where: str, key: str, value: Any) -> bytes:
    """Bytes built in code: a non-empty ``bytes``-like value."""
    if not isinstance(value, bytes | bytearray | memoryview) or not len(value):
        raise bad(where, key, "non-empty bytes", value)
    return bytes(value)


def command(where: str, name: Any, args: Any) -> tuple[str | float, ...]:
    """A command's name and arguments, minimally checked; the arguments as a tuple (seek's as a float).

    >>> command("line 5", "seek", [2])
    (2.0,)
    >>> command("line 5", "mode", ["draw"])
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 5: key "args": expected one argument, "sketch" or "demo", for "mode", \
got ["draw"]
    """
    if not isinstance(name, str) or name not in COMMANDS:
        raise bad(where, "cmd", f"one of {', '.join(COMMANDS)}", name)
    if not isinstance(args, list | tuple):
        raise bad(where, "args", "a list", args)
    ok = _args_ok(name, args)
    if ok is None:
        raise bad(where, "args", f"{_USAGE.get(name, 'no arguments')} for {show(name)}", list(args))
    return ok


def _args_ok(name: str, args: list[Any] | tuple[Any, ...]) -> tuple[str | float, ...] | None:
    def is_text(value: Any) -> bool:
        try:
            return isinstance(value, str) and bool(value) and bool(value.encode("utf-8"))
        except UnicodeEncodeError:
            return False

    if name == "mode":
        return (args[0],) if len(args) == 1 and args[0] in MODES and isinstance(args[0], str) else None
    if name == "seek":
        t = _real(args[0]) if len(args) == 1 else None
        return (t,) if t is not None and 0 <= t <= MAX_SECONDS else None
    if name == "label":
        return (args[0], args[1]) if len(args) == 2 and is_text(args[0]) and is_text(args[1]) else None
    if name == "save":
        return (args[0],) if len(args) == 1 and is_text(args[0]) else None
    return () if not args else None


def json_value(where: str, key: str, value: Any) -> None:
    """Checks that ``value`` is plain JSON this format can write and read back exactly.

    Objects with string keys, lists (or tuples), strings of valid Unicode, finite floats, ints, bools, null.
    """
    if value is None or isinstance(value, bool | int):
        return
    if isinstance(value, float):
        if not math.isfinite(value):
            raise bad(where, key, "a finite number", value)
        return
    if isinstance(value, str):
        text(where, key, value)
        return
    if isinstance(value, list | tuple):
        for i, item in enumerate(value):
            json_value(where, f"{key}[{i}]", item)
        return
    if isinstance(value, dict):
        for k, item in value.items():
            if not isinstance(k, str):
                raise bad(where, key, "an object with string keys", value)
            text(where, f"{key}.{k}", k)
            json_value(where, f"{key}.{k}", item)
        return
    raise bad(where, key, "a JSON value (object, list, string, number, true, false or null)", value)
